"""The converged Legendre lift-off: the N -> infinity limit of the series (3.14)-(3.16).

Model knowledge shared by the accuracy guards (:mod:`twoball.modal.guards`, which
report it beside every N-truncated result) and the verification studies
(:mod:`twoball.verify.studies.reference`).  Dimensionless (length R, time 1/c).
"""

from __future__ import annotations

import math
import time
from dataclasses import dataclass

import numpy as np

from twoball._common.monitor import Monitor
from twoball.modal.decay import DecayingSeries, reduced, significant
from twoball.modal.filters import FilterKind, SpectralFilter, legendre_frequency
from twoball.modal.legendre import legendre_coefficients_recurrence, legendre_series
from twoball.modal.liftoff import (
    DEFAULT_T_END,
    Horizon,
    LiftoffResult,
    find_liftoff,
    flight_clearance,
)
from twoball.modal.parameters import Case
from twoball.modal.roots import bracketed_roots
from twoball.modal.series import ModalSeries

PAPER_MODES = 30  # the truncation used throughout the paper (§3(b))
REFERENCE_TOLERANCE = 1e-7  # relative change of v_l that stops the doubling of N
REFERENCE_MAX_MODES = 3840
#: Relative change of the filtered series' lift-off time between N and 2N below which
#: both lift off on the same root (the one the limit is followed on); far below the
#: spacing of the roots that criterion (ii) chooses between (~10 % for the tennis ball).
IDENTIFY_TOLERANCE = 0.01


@dataclass(frozen=True)
class ConvergedReference:
    """The N -> infinity limit of the Legendre lift-off (dimensionless).

    Every filter tends to 1 mode by mode as N grows, so all filtered series share
    one limit: the unfiltered damped series (3.14).  For t > 0 its terms decay
    like exp(-D omega_n t), so at the lift-off time it converges exponentially
    in N (for D > 0).  It is found in two steps:

    1. *Which root.*  The lift-off (criteria (i)-(ii) of §3(a)) of the
       Lanczos-filtered series is computed at N0 (never below the N asked) and
       at 2 N0, 4 N0, ... until two successive ones lift off within
       :data:`IDENTIFY_TOLERANCE` of each other in time (or both not at all):
       a truncated series may lift off on a neighbouring root that criterion
       (ii) rejects at larger N (the tennis ball at N = 30: 0.583 ms, against
       0.518 ms from N = 60 on).
    2. *Its value.*  That root (of the first of the two) is followed into the
       unfiltered series while N doubles from there, until t_l and v_l change by
       less than ``tolerance`` (relative).  For D = 0 the series converges only
       algebraically at t_l; the doubling stops once the changes no longer shrink
       by a factor 4 per step (``converged`` False: the check of ``verify`` then
       fails).

    Both steps sum, at each time, only the modes whose damped contribution is
    above round-off (:mod:`twoball.modal.decay`), which keeps N in the thousands
    cheap.

    Attributes
    ----------
    t, velocity : float or None
        Lift-off time and velocity of the limit (None if not found).
    energy_end : float
        Energy of the limit at t_end (unit T R^2).
    modes : int
        N of the last (accepted) step.
    converged : bool
        Whether the changes fell below ``tolerance`` before the largest N
        (``REFERENCE_MAX_MODES``, or 4 times the starting N with damping);
        True with ``t`` None when the filtered series settled on no lift-off in
        the window.
    history : list of (N, t, v)
        The sequence of the doubling of the unfiltered series.
    clear : bool
        Whether the free flight after lift-off stays above the pole on the
        checked samples (criterion (ii) for the limit).
    filtered : list of (N, t or None, v or None)
        Step 1: the lift-offs of the Lanczos-filtered series.
    identified : bool
        Whether step 1 settled (two successive lift-offs on one root, or none).
    """

    t: float | None
    velocity: float | None
    energy_end: float
    modes: int
    converged: bool
    tolerance: float
    history: tuple[tuple[int, float, float], ...]
    clear: bool
    seconds: float
    series: ModalSeries | None
    filtered: tuple[tuple[int, float | None, float | None], ...] = ()
    identified: bool = True


def _legendre(
    case: Case, modes: int, kind: FilterKind, monitor: Monitor | None = None
) -> ModalSeries:
    n = np.arange(modes + 1)
    stiff = case.stiff
    return ModalSeries(
        omega=case.stiffness.legendre_omega(n) if stiff else legendre_frequency(n),
        coefficients=legendre_coefficients_recurrence(case.phi_a, modes),
        pole_values=np.ones(n.size),
        damping=case.damping_law,
        filter=SpectralFilter(kind, modes),
        mode_norms=4.0 * np.pi / (2 * n + 1),
        filter_omega=legendre_frequency(n) if stiff else None,
        monitor=monitor,
    )


def unfiltered_series(case: Case, modes: int, monitor: Monitor | None = None) -> ModalSeries:
    """The damped Legendre series (3.14) truncated at ``modes`` without a filter.

    Coefficients from the exact three-term recurrence
    (:func:`twoball.modal.legendre.legendre_coefficients_recurrence`, an independent
    second method; agrees with the quadrature of eq. (3.12) to ~1e-13 and needs
    no Gauss rule, which is what makes thousands of modes cheap).  ``monitor``
    is told as the series is evaluated (:attr:`ModalSeries.monitor`).
    """
    return _legendre(case, modes, "none", monitor)


def filtered_liftoff(
    case: Case,
    modes: int,
    t_end: float = DEFAULT_T_END,
    recontact: Horizon = "window",
    monitor: Monitor | None = None,
) -> LiftoffResult:
    """Lift-off of the Lanczos-filtered series (3.16) with ``modes``, summed blockwise.

    The same criteria and window as :func:`twoball.modal.report.legendre_liftoff`;
    the coefficients from the recurrence and the modes that have decayed below
    round-off dropped (:class:`twoball.modal.decay.DecayingSeries`): agrees with
    the plain evaluation to ~1e-13 at a small part of its cost for large N.
    ``monitor`` is told as the series is evaluated.
    """
    motion = DecayingSeries(_legendre(case, modes, "lanczos", monitor), t_end)
    return find_liftoff(motion, case.gamma, t_end=t_end, horizon=recontact)


def _same_root(a: LiftoffResult, b: LiftoffResult) -> bool:
    """Both lift off within IDENTIFY_TOLERANCE of each other in time, or neither does."""
    if a.t is None or b.t is None:
        return a.t is None and b.t is None
    return abs(b.t - a.t) <= IDENTIFY_TOLERANCE * abs(b.t)


def _cheaper(series: ModalSeries, start: float) -> ModalSeries:
    """The series without the modes negligible from ``start`` on, when that halves it."""
    kept = significant(series, start)
    return reduced(series, kept) if 2 * kept.size <= series.omega.size else series


def _track_root(
    series: ModalSeries, gamma: float, guess: float, width: float, min_samples: int = 2001
) -> tuple[float, float] | None:
    """The downward zero of ``u_tt + gamma`` nearest ``guess`` within ``guess +- width``.

    Sampled at ``min_samples`` points or 40 per unit time and frequency, whichever
    is more (>= 6 per period of the highest mode), then refined to 1e-12.
    """
    samples = max(min_samples, int(40 * width * max(series.max_frequency, 1.0)))
    grid = np.linspace(max(guess - width, 1e-9), guess + width, samples)
    force = series.pole(grid).u_tt + gamma
    down = np.flatnonzero((force[:-1] > 0.0) & (force[1:] <= 0.0))
    if down.size == 0:
        return None
    k = down[np.argmin(np.abs(grid[down] - guess))]

    def force_at(t: np.ndarray, i: np.ndarray | None = None) -> np.ndarray:
        return series.pole(t).u_tt + gamma

    ends = grid[k : k + 2]
    at_ends = force_at(ends)
    if at_ends[0] * at_ends[1] > 0:  # a grid point sits on the root (round-off decides)
        root = float(ends[np.argmin(np.abs(at_ends))])
    else:
        root = bracketed_roots(force_at, ends[:1], ends[1:])[0]
    return float(root), float(series.pole(np.array([root])).u_t[0])


def _identify(
    case: Case,
    base: LiftoffResult,
    start_modes: int,
    max_modes: int,
    t_end: float,
    recontact: Horizon,
    monitor: Monitor | None = None,
) -> tuple[int, LiftoffResult, bool, tuple[tuple[int, float | None, float | None], ...]]:
    """Step 1 of :class:`ConvergedReference`: (N, lift-off) of the first of two that agree."""
    steps = [(start_modes, base)]
    while not (len(steps) >= 2 and _same_root(steps[-2][1], steps[-1][1])):
        modes = 2 * steps[-1][0]
        if modes > max_modes:
            break
        steps.append((modes, filtered_liftoff(case, modes, t_end, recontact, monitor)))
    record = tuple((n, r.t, r.velocity) for n, r in steps)
    settled = len(steps) >= 2 and _same_root(steps[-2][1], steps[-1][1])
    modes, found = steps[-2] if settled else steps[-1]
    return modes, found, settled, record


def converged_legendre(
    case: Case,
    sigma: str = "lanczos",
    recontact: Horizon = "window",
    t_end: float = DEFAULT_T_END,
    tolerance: float = REFERENCE_TOLERANCE,
    start_modes: int = PAPER_MODES,
    max_modes: int = REFERENCE_MAX_MODES,
    *,
    base: LiftoffResult | None = None,
    flight: bool = True,
    min_samples: int = 2001,
    monitor: Monitor | None = None,
) -> ConvergedReference:
    """The converged Legendre lift-off, from ``start_modes`` up until it settles.

    See :class:`ConvergedReference`.  The Lanczos-filtered series picks the root
    to follow, whatever ``sigma`` is: the limit is the same for every filter, and
    without a filter the truncated series lifts off spuriously on its Gibbs
    oscillations.  ``t_end`` is dimensionless (unit 1/c).  ``start_modes`` is the
    least N used (the guards pass the N of the result they judge).

    ``base`` is the Lanczos lift-off with ``start_modes`` when the caller has it
    already (same case, window and horizon).  ``flight=False`` skips the
    clearance check and the end energy of the limit (``clear`` False,
    ``energy_end`` NaN): the accuracy guards need t_l and v_l only.
    ``min_samples`` is the least number of samples that bracket the followed root.
    With damping, N may rise to ``4 start_modes`` if that is above ``max_modes``
    (the decayed modes are dropped, so a large N costs little).
    ``monitor`` (:class:`~twoball._common.monitor.Monitor`) is told before every
    doubling of N and as the series are evaluated; it may stop the work by raising.
    """
    del sigma  # every filter has the same limit
    clock = time.perf_counter()
    if case.damping > 0.0:
        max_modes = max(max_modes, 4 * start_modes)
    if base is None:
        lanczos = SpectralFilter("lanczos", start_modes)
        base_series = legendre_series(
            case.phi_a, case.damping_law, lanczos, stiffness=case.stiffness, monitor=monitor
        )
        base = find_liftoff(base_series, case.gamma, t_end=t_end, horizon=recontact)
    modes, root, settled, filtered = _identify(
        case, base, start_modes, max_modes, t_end, recontact, monitor
    )

    def unfinished(converged: bool = False) -> ConvergedReference:
        seconds = time.perf_counter() - clock
        return ConvergedReference(
            None,
            None,
            math.nan,
            modes,
            converged,
            tolerance,
            (),
            False,
            seconds,
            None,
            filtered,
            settled,
        )

    if root.t is None:  # the filtered series settled on no lift-off (or did not settle)
        return unfinished(converged=settled)
    guess, width = root.t, 0.05 * root.t
    history: list[tuple[int, float, float]] = []
    changes: list[float] = []
    converged, series = False, None
    while modes < max_modes:
        if monitor is not None:
            monitor(f"the converged reference series at N = {2 * modes}")
        modes *= 2
        series = _cheaper(unfiltered_series(case, modes, monitor), guess - width)
        found = _track_root(series, case.gamma, guess, width, min_samples)
        if found is None:  # too few modes for the series at t_l yet (its tail still counts)
            continue
        history.append((modes, *found))
        guess = found[0]
        if len(history) >= 2:
            (_, t0, v0), (_, t1, v1) = history[-2], history[-1]
            change = max(abs(t1 - t0) / abs(t1), abs(v1 - v0) / abs(v1))
            changes.append(change)
            if change <= tolerance:
                converged = True
                break
            # damped series converge exponentially; changes that merely halve (D = 0: the
            # kink of F keeps travelling undamped) will not reach the tolerance -- stop
            if len(changes) >= 3 and changes[-1] > 0.25 * changes[-2] > 0.0625 * changes[-3]:
                break
    if not history or series is None:
        return unfinished()
    _, t_l, v_l = history[-1]
    clear, energy = False, math.nan
    if flight:
        end = t_end if recontact == "window" else min(2 * t_l, t_end)
        clear = v_l > 0 and flight_clearance(series, case.gamma, t_l, end) > 0.0
        energy = float(series.energy(np.array([t_end]))[0])
    return ConvergedReference(
        t_l,
        v_l,
        energy,
        modes,
        converged and settled,
        tolerance,
        tuple(history),
        clear,
        time.perf_counter() - clock,
        series,
        filtered,
        settled,
    )
