"""Cost model of the closed-form series: memory and time of eq. (3.16) before it runs.

Calibration (peak RSS of a child process, wall time on the 2-core build
machine; ``benchmarks/bench_budget.py`` prints them; meant to be right within a
factor of 2-3, which is all a refusal needs): ``liftoff`` with N = 1000 / 3000 /
6000 measured 218 / 480 / 873 MiB and 1.1 / 8.0 / 48 s; the model is
``base + max(8 m (N + 1), 24 min(S, 4096) (N + 1))`` bytes and
``40 ns x S x (N + 1)``, with ``S`` the samples of the bracketing grid, 16 per
period of the highest retained mode (:func:`twoball.modal.liftoff.bracketing_grid`),
and ``m`` the Gauss points of eq. (3.12) (:func:`twoball.modal.legendre.quadrature_points`).

With bending, ``omega_N ~ sqrt(beta) N^2`` sets the grid instead of ``N``
(tennis ball, N = 960: 147 s measured, 1.4 min estimated).  The converged
reference of the truncation guard (:func:`reference_estimate`) sums, at each
time, only the modes not yet decayed (:class:`twoball.modal.decay.DecayingSeries`):
its cost grows like N, not N^2.

The model only estimates; whether the work fits is decided at the edge, before
it starts (:func:`twoball._costs.check_series`, against the budget of
:mod:`twoball._common.budget`).
"""

from __future__ import annotations

import math

import numpy as np

from twoball._common.estimate import BASE_MEMORY, Estimate, options
from twoball.modal.legendre import MAX_QUADRATURE
from twoball.modal.parameters import Case
from twoball.modal.series import CHUNK
from twoball.modal.stiffness import Stiffness

__all__ = [
    "case_liftoff_work",
    "decaying_memory",
    "decaying_work",
    "grid_samples",
    "legendre_omega",
    "liftoff_work",
    "reference_estimate",
    "series_estimate",
]

SECONDS_PER_TERM = 40e-9  # one complex exp-multiply-add of the series evaluation
SAMPLES_PER_PERIOD = 16  # of the bracketing grid (twoball.modal.liftoff.bracketing_grid)
DECAYED = 40.0  # D omega t beyond which a mode no longer counts (exp(-40) ~ 4e-18)
TRACK_WIDTH = 0.16  # the followed root's window, 5 % of t_l ~ pi (the basketball's)


def legendre_omega(modes: int) -> float:
    """``omega_N = sqrt(N (N + 1))``, the highest retained frequency (dimensionless)."""
    return math.sqrt(modes * (modes + 1.0))


def grid_samples(omega_max: float, t_end: float) -> float:
    """Samples of the bracketing grid: 16 per period of ``omega_max`` over [0, t_end]."""
    return math.ceil(t_end * max(omega_max, 1.0) * SAMPLES_PER_PERIOD / (2.0 * math.pi)) + 1


def series_estimate(
    modes: int, t_end: float, terms: int | None = None, omega_max: float | None = None
) -> Estimate:
    """The closed-form lift-off with N modes over a window ``t_end`` (dimensionless).

    Memory: the larger of the Gauss rule's Vandermonde matrix of eq. (3.12),
    ``8 m (N + 1)`` bytes with ``m = min(N + 50, 20000)``, and the evaluation: the
    exponential tables, ``24 min(S, 4096) K`` bytes for K retained modes, and the
    grid's u, u_t, u_tt and force, ``48 S`` bytes.  Time: ``40 ns x S x K``.  ``terms`` is K when it
    differs from N + 1 (e.g. finite-element modes); ``omega_max`` the highest
    frequency when it is not ``sqrt(N (N + 1))`` (bending, gas).
    """
    modes = int(modes)
    kept = modes + 1 if terms is None else int(terms)
    top = legendre_omega(modes) if omega_max is None else float(omega_max)
    samples = grid_samples(top, t_end)
    points = min(modes + 50, MAX_QUADRATURE) if terms is None else 0
    # the Vandermonde matrix is freed before the evaluation starts: the larger one is the peak
    evaluation = 24.0 * min(samples, CHUNK) * kept + 48.0 * samples
    memory = BASE_MEMORY + max(8.0 * points * (modes + 1), evaluation)
    return Estimate(memory, SECONDS_PER_TERM * samples * kept)


def _omegas(modes: int, stiffness: Stiffness | None) -> np.ndarray:
    n = np.arange(int(modes) + 1, dtype=float)
    if stiffness is not None and stiffness.active:
        return stiffness.legendre_omega(n)
    return np.sqrt(n * (n + 1.0))


def legendre_top(modes: int, stiffness: Stiffness | None = None) -> float:
    """The highest frequency of N Legendre modes (units c), stiffened where bending or gas act."""
    return float(_omegas(modes, stiffness)[-1])


def _decaying_blocks(omega: np.ndarray, damping: float, t_end: float) -> list[tuple[int, int]]:
    """(samples, modes summed) of each block of a blockwise-decayed series.

    Blocks ``[0, tau), [tau, 2 tau), ...`` (``tau = 1 / omega_max``); on each, the
    modes with ``D omega t_start < 40`` at 16 samples per period of the highest
    (:class:`twoball.modal.decay.DecayingSeries`).
    """
    omega = np.sort(np.asarray(omega, dtype=float))
    top = max(float(omega[-1]), 1.0)
    starts, tau = [0.0], 1.0 / top
    while tau < t_end:
        starts.append(tau)
        tau *= 2.0
    blocks = []
    for start, end in zip(starts, [*starts[1:], t_end], strict=True):
        count = omega.size
        if damping > 0.0 and start > 0.0:
            count = int(np.searchsorted(omega, DECAYED / (damping * start), side="right"))
        highest = max(float(omega[count - 1]) if count else 0.0, 1.0)
        block = math.ceil((end - start) * highest * SAMPLES_PER_PERIOD / (2 * math.pi)) + 1
        blocks.append((block, count))
    return blocks


def decaying_work(omega: np.ndarray, damping: float, t_end: float) -> tuple[float, float]:
    """Samples and summed terms of a blockwise-decayed series (:func:`_decaying_blocks`)."""
    blocks = _decaying_blocks(omega, damping, t_end)
    return float(sum(b for b, _ in blocks)), float(sum(b * n for b, n in blocks))


def decaying_memory(omega: np.ndarray, damping: float, t_end: float) -> float:
    """Peak bytes of a blockwise-decayed series: the largest block's exponential table.

    Each block is summed in chunks of at most :data:`~twoball.modal.series.CHUNK`
    samples: ``24 min(samples, CHUNK) K`` bytes for its K modes, plus the grid's
    ``48`` bytes per sample.
    """
    blocks = _decaying_blocks(omega, damping, t_end)
    samples = sum(b for b, _ in blocks)
    return max(24.0 * min(b, CHUNK) * n for b, n in blocks) + 48.0 * samples


def reference_estimate(
    t_end: float,
    modes: int = 30,
    damping: float = 0.13,
    stiffness: Stiffness | None = None,
) -> Estimate:
    """The converged-series reference of the truncation guard for a result with N modes.

    :func:`twoball.modal.converged.converged_legendre` from N0 = max(N, 30): the
    filtered lift-off at 2 N0 and 4 N0 (each blockwise, :func:`decaying_work`;
    the one at N0 is the result itself), then the unfiltered series followed at
    its root (a few thousand samples of the modes not yet decayed: small, except
    for D = 0, where every mode is summed there for four doublings).
    """
    start = max(int(modes), 30)
    memory = seconds = 0.0
    for n in (2 * start, 4 * start):
        omega = _omegas(n, stiffness)
        _, work = decaying_work(omega, damping, t_end)
        memory = max(memory, decaying_memory(omega, damping, t_end))
        seconds += SECONDS_PER_TERM * work
    if damping == 0.0:  # nothing decays: the root is followed with every mode, 4 doublings
        for n in (2 * start, 4 * start, 8 * start, 16 * start):  # (the changes stop shrinking)
            if n > 3840:
                break
            samples = max(2001.0, 40 * TRACK_WIDTH * float(_omegas(n, stiffness)[-1]))
            seconds += SECONDS_PER_TERM * samples * (n + 1)
    return Estimate(BASE_MEMORY + memory, seconds)


def liftoff_work(
    modes: int,
    t_end: float,
    t_end_s: float | None = None,
    damping: float = 0.13,
    stiffness: Stiffness | None = None,
) -> tuple[str, Estimate]:
    """A closed-form lift-off (N modes, window ``t_end`` dimensionless): what it is, its cost.

    The text names the options that set its size (``modes 3000 t_end 0.01``;
    ``t_end_s`` [s] only names the window); the estimate includes the truncation
    guard's converged reference over the same window, ``stiffness`` as in
    :func:`reference_estimate`.  The edge refuses it if it cannot fit
    (:func:`twoball._costs.check_series`).
    """
    top = float(_omegas(modes, stiffness)[-1])
    estimate = series_estimate(modes, t_end, omega_max=top) + reference_estimate(
        t_end, modes, damping, stiffness
    )
    return options(modes=int(modes), t_end=t_end_s), estimate


def case_liftoff_work(case: Case, t_end_s: float | None = None) -> tuple[str, Estimate]:
    """:func:`liftoff_work` of :func:`twoball.modal.report.legendre_liftoff` on ``case``.

    ``t_end_s`` the window [s] (None: 4 pi / c), checked as the lift-off checks it.
    """
    from twoball.modal.report import t_end_dimensionless

    return liftoff_work(
        case.modes,
        t_end_dimensionless(case, t_end_s),
        t_end_s,
        case.damping,
        case.stiffness if case.stiff else None,
    )
