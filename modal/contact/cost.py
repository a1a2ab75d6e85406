"""Cost model of the contact solver: memory and time of the event loop before it runs.

The event-driven solver (:func:`twoball.modal.contact.events.integrate`) works on
the augmented state of ``n = 2 K + 3`` entries for K modes with dense ``n x n``
matrices: two phase matrices, their one-step propagators ``exp(A h)`` and the
scratch of :func:`scipy.linalg.expm`.  It steps a grid of ``samples_per_period``
points per shortest modal period over the window; each step is one dense
matrix-vector product plus the event checks.

Calibration (wall time on the 2-core build machine, one BLAS thread, Legendre
modes, mass ratio 0.1, default window): N = 100 / 200 / 300 / 400 took 0.38 /
1.7 / 10 / 31 s with 3 events; the bare matrix-vector product costs 0.4-1.0 ns
per matrix entry, the solver's step 1-1.9 ns (checks, slices, cache misses), and
``expm`` 0.9-1.2 ns x n^3.  The model takes ``10 us + 2 ns x n^2`` per step and
``3 ns x n^3`` for the two propagators (an upper bound within a factor of about
two, which is all a refusal needs), and ``80 n^2`` bytes (ten dense n x n arrays
of doubles; N = 400 measured 61 MiB above the interpreter, the model 52 MB).

The model only estimates; whether the work fits is decided at the edge, before
it starts (:func:`twoball._costs.check_contact`,
:func:`twoball._costs.check_legendre_contact`).
"""

from __future__ import annotations

import math
from typing import Any

from twoball._common.estimate import BASE_MEMORY, Estimate, options

__all__ = ["contact_estimate", "contact_work", "legendre_contact_work", "solve_work"]

STEP_SECONDS = 1e-5  # per grid step: Python overhead of the event checks
STEP_SECONDS_PER_ENTRY = 2e-9  # per entry of the dense one-step propagator
EXPM_SECONDS_PER_CUBE = 3e-9  # the two propagators exp(A h), per n^3
BYTES_PER_ENTRY = 80  # ten dense n x n arrays of doubles


def contact_estimate(
    modes_kept: int, omega_max: float, t_end: float, samples_per_period: int = 32
) -> Estimate:
    """The contact solver on ``modes_kept`` modes up to ``omega_max`` over ``t_end``.

    All arguments are dimensionless (frequencies in units of c, times in 1/c).
    """
    n = 2.0 * int(modes_kept) + 3.0
    steps = math.ceil(t_end * max(float(omega_max), 1.0) * samples_per_period / (2.0 * math.pi))
    seconds = steps * (STEP_SECONDS + STEP_SECONDS_PER_ENTRY * n * n)
    seconds += EXPM_SECONDS_PER_CUBE * n**3
    return Estimate(BASE_MEMORY + BYTES_PER_ENTRY * n * n, seconds)


def contact_work(
    modes_kept: int,
    omega_max: float,
    t_end: float,
    *,
    modes: int | None = None,
    mass_ratio: float | None = None,
    samples_per_period: int = 32,
) -> tuple[str, Estimate]:
    """A contact run: the options that set its size and its estimate.

    ``modes`` (the case's N) and ``mass_ratio`` only name the work.
    """
    estimate = contact_estimate(modes_kept, omega_max, t_end, samples_per_period)
    named = options(modes=modes, mass_ratio=mass_ratio) or f"a contact system of {modes_kept} modes"
    return named, estimate


def solve_work(
    modes: int,
    kept: int,
    top: float,
    t_end: float,
    mass_ratio: float,
    samples_per_period: int = 32,
) -> tuple[str, Estimate]:
    """One run of :func:`twoball.modal.contact.report.solve_contact` on ``kept`` modes.

    Up to ``top`` (dimensionless) over ``t_end``, the case having N = ``modes``:
    the event loop with a body of finite mass, or, for the massless mode, the
    series at the cap (:func:`twoball.modal.cost.series_estimate` of its modes).
    """
    if mass_ratio == 0.0:
        from twoball.modal.cost import series_estimate

        return options(modes=modes), series_estimate(modes, t_end, kept, top)
    return contact_work(
        kept,
        top,
        t_end,
        modes=modes,
        mass_ratio=mass_ratio,
        samples_per_period=samples_per_period,
    )


def legendre_contact_work(
    case: Any,
    body: Any,
    t_end_s: float | None = None,
    *,
    samples_per_period: int = 32,
    reference: bool = True,
) -> list[tuple[str, Estimate]]:
    """The solves of :func:`twoball.modal.contact.report.legendre_contact`, with their costs.

    The contact solution on the N + 1 Legendre modes and, with ``reference``,
    the closed-form reference of its truncation block (``max(2 N, 60)`` modes,
    none above 240).  The options of ``body`` and the window ``t_end_s`` [s] are
    checked first, as the solve checks them.
    """
    from twoball.modal.contact.report import (
        CONTACT_REFERENCE_MAX_MODES,
        CONTACT_REFERENCE_MIN_MODES,
        check_contact_options,
    )
    from twoball.modal.report import t_end_dimensionless

    check_contact_options(case, body)
    t_end = t_end_dimensionless(case, t_end_s)
    sizes = [(case.modes, samples_per_period)]
    if reference:
        finer = max(2 * case.modes, CONTACT_REFERENCE_MIN_MODES)
        if finer <= CONTACT_REFERENCE_MAX_MODES:
            sizes.append((finer, 32))
    return [
        solve_work(n, n + 1, _legendre_top(n), t_end, body.mass_ratio, samples)
        for n, samples in sizes
    ]


def _legendre_top(modes: int) -> float:
    """The highest frequency of the Legendre series of N modes, as the solver reads it."""
    import numpy as np

    from twoball.modal.filters import legendre_frequency

    return float(np.max(legendre_frequency(np.arange(modes + 1)), initial=0.0))
