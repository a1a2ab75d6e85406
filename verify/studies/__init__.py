"""twoball.verify.studies -- convergence studies and observed orders.

* :mod:`~twoball.verify.studies.orders`, :mod:`~twoball.verify.studies.gci`: observed
  orders, Richardson extrapolation and the GCI (pure functions of numbers);
* :mod:`~twoball.verify.studies.reference`: the Legendre runs every study is measured
  against, and their converged limit N -> infinity;
* :mod:`~twoball.verify.studies.fem_runs`: one finite-element discretisation and run;
* :mod:`~twoball.verify.studies.trajectory`, :mod:`~twoball.verify.studies.quantities`,
  :mod:`~twoball.verify.studies.result`: what a study measures and returns;
* the studies: :mod:`~twoball.verify.studies.modes` (N),
  :mod:`~twoball.verify.studies.refinement` (h, and P1 against P2) and
  :mod:`~twoball.verify.studies.time_step` (dt).
"""

__all__ = [
    "fem_runs",
    "gci",
    "modes",
    "orders",
    "quantities",
    "reference",
    "refinement",
    "result",
    "time_step",
    "trajectory",
]
