"""twoball.verify.checks -- the checks of twoball verify.

:mod:`~twoball.verify.checks.run` runs them all (:func:`~twoball.verify.checks.run.run_verify`)
with the runs and tolerances of :mod:`~twoball.verify.checks.config`; the checks of the
finite-element spectra and energies are in :mod:`~twoball.verify.checks.fem`, those of
direct time stepping in :mod:`~twoball.verify.checks.alpha`, and what they return in
:mod:`~twoball.verify.checks.results`.
"""

__all__ = ["alpha", "config", "fem", "results", "run"]
