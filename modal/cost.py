"""Cost model of the closed-form series: memory and time of eq. (3.16) before it runs.

Calibration (peak RSS of a child process, wall time on the 2-core build
machine; ``benchmarks/bench_budget.py`` prints them; meant to be right within a
factor of 2-3, which is all a refusal needs): ``liftoff`` with N = 1000 / 3000 /
6000 measured 218 / 480 / 873 MiB and 1.1 / 8.0 / 48 s; the model is
``base + max(8 m (N + 1), 24 min(S, 4096) (N + 1))`` bytes and
``40 ns x S x (N + 1)``, with ``S`` the samples of the bracketing grid, 16 per
period of the highest retained mode (:func:`twoball.modal.liftoff.bracketing_grid`),
and ``m`` the Gauss points of eq. (3.12) (:func:`twoball.modal.legendre.quadrature_points`).
"""

from __future__ import annotations

import math

from twoball.modal.legendre import MAX_QUADRATURE
from twoball.modal.series import CHUNK

from twoball._common.budget import BASE_MEMORY, Estimate, check, options

__all__ = [
    "check_series",
    "grid_samples",
    "legendre_omega",
    "reference_estimate",
    "series_estimate",
]

SECONDS_PER_TERM = 40e-9  # one complex exp-multiply-add of the series evaluation
SAMPLES_PER_PERIOD = 16  # of the bracketing grid (twoball.modal.liftoff.bracketing_grid)


def legendre_omega(modes: int) -> float:
    """``omega_N = sqrt(N (N + 1))``, the highest retained frequency (dimensionless)."""
    return math.sqrt(modes * (modes + 1.0))


def grid_samples(omega_max: float, t_end: float) -> float:
    """Samples of the bracketing grid: 16 per period of ``omega_max`` over [0, t_end]."""
    return math.ceil(t_end * max(omega_max, 1.0) * SAMPLES_PER_PERIOD / (2.0 * math.pi)) + 1


def series_estimate(modes: int, t_end: float, terms: int | None = None) -> Estimate:
    """The closed-form lift-off with N modes over a window ``t_end`` (dimensionless).

    Memory: the larger of the Gauss rule's Vandermonde matrix of eq. (3.12),
    ``8 m (N + 1)`` bytes with ``m = min(N + 50, 20000)``, and the evaluation: the
    exponential tables, ``24 min(S, 4096) K`` bytes for K retained modes, and the
    grid's u, u_t, u_tt and force, ``48 S`` bytes.  Time: ``40 ns x S x K``.  ``terms`` is K when it
    differs from N + 1 (e.g. finite-element modes).
    """
    modes = int(modes)
    kept = modes + 1 if terms is None else int(terms)
    samples = grid_samples(legendre_omega(modes), t_end)
    points = min(modes + 50, MAX_QUADRATURE) if terms is None else 0
    # the Vandermonde matrix is freed before the evaluation starts: the larger one is the peak
    evaluation = 24.0 * min(samples, CHUNK) * kept + 48.0 * samples
    memory = BASE_MEMORY + max(8.0 * points * (modes + 1), evaluation)
    return Estimate(memory, SECONDS_PER_TERM * samples * kept)


def reference_estimate(t_end: float, modes: int = 240) -> Estimate:
    """The converged-series reference of the truncation guard (N up to ~240, the window)."""
    return series_estimate(modes, t_end)


def check_series(modes: int, t_end: float, t_end_s: float | None = None) -> Estimate:
    """Refuse a closed-form lift-off (N modes, window ``t_end`` dimensionless) that cannot fit.

    The truncation guard's converged reference over the same window is included.
    """
    estimate = series_estimate(modes, t_end) + reference_estimate(t_end)
    return check(options(modes=int(modes), t_end=t_end_s), estimate)
