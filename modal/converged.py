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
from twoball.modal.filters import SpectralFilter, legendre_frequency
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


@dataclass(frozen=True)
class ConvergedReference:
    """The N -> infinity limit of the Legendre lift-off (dimensionless).

    Every filter tends to 1 mode by mode as N grows, so all filtered series share
    one limit: the unfiltered damped series (3.14).  For t > 0 its terms decay
    like exp(-D sqrt(n(n+1)) t), so at the lift-off time it converges
    exponentially in N (for D > 0).  It is found by following the lift-off
    root of the N = 30 filtered series into the unfiltered series while N
    doubles, until t_l and v_l change by less than ``tolerance`` (relative).
    For D = 0 the series converges only algebraically at t_l; the doubling stops
    once the changes no longer shrink by a factor 4 per step (``converged``
    False: the check of ``verify`` then fails).

    Attributes
    ----------
    t, velocity : float or None
        Lift-off time and velocity of the limit (None if not found).
    energy_end : float
        Energy of the limit at t_end (unit T R^2).
    modes : int
        N of the last (accepted) step.
    converged : bool
        Whether the changes fell below ``tolerance`` before ``REFERENCE_MAX_MODES``.
    history : list of (N, t, v)
        The sequence of the doubling.
    clear : bool
        Whether the free flight after lift-off stays above the pole on the
        checked samples (criterion (ii) for the limit).
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


def unfiltered_series(case: Case, modes: int) -> ModalSeries:
    """The damped Legendre series (3.14) truncated at ``modes`` without a filter.

    Coefficients from the exact three-term recurrence
    (:func:`twoball.modal.legendre.legendre_coefficients_recurrence`, an independent
    second method; agrees with the quadrature of eq. (3.12) to ~1e-13 and needs
    no Gauss rule, which is what makes thousands of modes cheap).
    """
    n = np.arange(modes + 1)
    stiff = case.stiff
    return ModalSeries(
        omega=case.stiffness.legendre_omega(n) if stiff else legendre_frequency(n),
        coefficients=legendre_coefficients_recurrence(case.phi_a, modes),
        pole_values=np.ones(n.size),
        damping=case.damping_law,
        filter=SpectralFilter("none", modes),
        mode_norms=4.0 * np.pi / (2 * n + 1),
        filter_omega=legendre_frequency(n) if stiff else None,
    )


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
) -> ConvergedReference:
    """The converged Legendre lift-off: N doubled from ``2 start_modes`` until it settles.

    See :class:`ConvergedReference`.  The lift-off of the Lanczos-filtered series
    with ``start_modes`` modes (criteria (i)-(ii) of §3(a)) picks the root to
    follow, whatever ``sigma`` is: the limit is the same for every filter, and
    without a filter the truncated series lifts off spuriously on its Gibbs
    oscillations.  ``t_end`` is dimensionless (unit 1/c).

    ``base`` is that starting lift-off when the caller has it already (same case,
    window, horizon, Lanczos filter and ``start_modes``).  ``flight=False`` skips
    the clearance check and the end energy of the limit (``clear`` False,
    ``energy_end`` NaN): the accuracy guards need t_l and v_l only.  ``min_samples``
    is the least number of samples that bracket the followed root.
    """
    del sigma  # every filter has the same limit
    clock = time.perf_counter()
    if base is None:
        lanczos = SpectralFilter("lanczos", start_modes)
        base_series = legendre_series(
            case.phi_a, case.damping_law, lanczos, stiffness=case.stiffness
        )
        base = find_liftoff(base_series, case.gamma, t_end=t_end, horizon=recontact)
    if base.t is None:
        return ConvergedReference(
            None, None, math.nan, start_modes, False, tolerance, (), False, 0.0, None
        )
    guess, width = base.t, 0.05 * base.t
    history: list[tuple[int, float, float]] = []
    changes: list[float] = []
    modes, converged, series = start_modes, False, None
    while modes < max_modes:
        modes *= 2
        series = unfiltered_series(case, modes)
        found = _track_root(series, case.gamma, guess, width, min_samples)
        if found is None:
            break
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
        return ConvergedReference(
            None, None, math.nan, modes, False, tolerance, tuple(history), False, 0.0, None
        )
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
        converged,
        tolerance,
        tuple(history),
        clear,
        time.perf_counter() - clock,
        series,
    )
