"""Lift-off of a massless body resting on the pole, criteria (i) and (ii) of §3(a).

Written once for every backend: it takes any pole motion that yields u, u_t and
u_tt -- a :class:`~twoball.modal.series.ModalSeries` in closed form, or samples from a
time integrator wrapped in :class:`SampledPoleMotion`.  Everything here is
dimensionless (length R, time 1/c, gravity gamma = g/(R c^2)).

Criterion (i): the contact force ``u_tt + gamma`` crosses zero from above at t_l > 0.
Criterion (ii): the body moves up, ``u_t(t_l) > 0``, and its ballistic path
``s(t) = u(t_l) + v_l (t - t_l) - gamma (t - t_l)^2 / 2`` stays strictly above the
pole over the re-contact horizon: to the end of the modelled window (``window``,
the default) or for ``t - t_l < t_l`` as written in §3(a)(ii) (``paper``).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Literal, Protocol, runtime_checkable

import numpy as np
from numpy.typing import ArrayLike

from twoball._common.choices import HORIZONS
from twoball._common.errors import NumericalError, ParameterError
from twoball.modal.roots import bracketed_roots, newton_bracketed
from twoball.modal.series import PoleState

Horizon = Literal["window", "paper"]
DEFAULT_T_END = 4.0 * math.pi  # dimensionless window: two transits of the wave (4 pi / c seconds)
TIME_TOLERANCE = 1e-12  # dimensionless time accuracy of every refined root
#: A gap below this times the pole's largest displacement is closed (the rounding of the
#: modal sums is ~1e-16 of their terms; a physical gap is many orders larger).
ROUNDING = 1e-12


@runtime_checkable
class PoleMotion(Protocol):
    """Anything that gives the pole's u, u_t, u_tt at arbitrary times (dimensionless)."""

    @property
    def max_frequency(self) -> float:
        """Highest angular frequency present; sets the bracketing grid."""

    def pole(self, t: ArrayLike) -> PoleState:
        """Pole displacement, velocity and acceleration at times ``t``."""


class SampledPoleMotion:
    """Pole motion known at sample times, interpolated between them.

    Two interpolations, for two kinds of samples:

    ``hermite`` (default)
        One quintic Hermite spline through u, u_t and u_tt: right when the
        samples are exact derivatives of one motion (e.g. a closed form sampled).
        u_tt is continuous and equals the samples there; error O(h^6) in u.
    ``splines``
        Each of u, u_t and u_tt through its own cubic spline: right for a time
        integrator, whose u, u_t and u_tt are each accurate to O(dt^2) but are not
        derivatives of one another.  Forcing them into one Hermite polynomial would
        turn that mismatch into an O(dt) error of u_tt between the steps and a
        first-order lift-off time; separate splines keep every field O(dt^2).

    The lift-off search brackets on the sample times themselves.

    Parameters
    ----------
    t, u, u_t, u_tt : array_like, shape (M,)
        Increasing sample times and the pole's displacement, velocity and
        acceleration there (dimensionless).
    interpolation : {"hermite", "splines"}
        See above.
    """

    def __init__(
        self,
        t: ArrayLike,
        u: ArrayLike,
        u_t: ArrayLike,
        u_tt: ArrayLike,
        interpolation: Literal["hermite", "splines"] = "hermite",
    ) -> None:
        t = np.asarray(t, dtype=float)
        data = np.column_stack([np.asarray(v, dtype=float) for v in (u, u_t, u_tt)])
        if t.ndim != 1 or t.size < 2 or data.shape[0] != t.size:
            raise ValueError("samples must be 1-D arrays of equal length >= 2")
        if not np.all(np.diff(t) > 0):
            raise ValueError("sample times must increase")
        if not np.all(np.isfinite(data)):
            raise NumericalError("pole samples contain NaN or inf")
        self.times = t
        self.interpolation = interpolation
        from scipy.interpolate import BPoly, CubicSpline  # only sampled motions need scipy

        if interpolation == "hermite":
            spline = BPoly.from_derivatives(t, data.tolist(), extrapolate=False)
            self._fields = (spline, spline.derivative(1), spline.derivative(2))
            self._jerk = spline.derivative(3)
        elif interpolation == "splines":
            self._fields = tuple(CubicSpline(t, data[:, j], extrapolate=False) for j in range(3))
            self._jerk = self._fields[2].derivative(1)
        else:
            raise ValueError("interpolation must be 'hermite' or 'splines'")

    @property
    def grid_times(self) -> np.ndarray:
        """The sample times, used as the bracketing grid."""
        return self.times

    @property
    def max_frequency(self) -> float:
        """The frequency resolved at 16 samples per period by the coarsest sample spacing."""
        return 2.0 * math.pi / (16.0 * float(np.max(np.diff(self.times))))

    def jerk(self, t: ArrayLike) -> np.ndarray:
        """Third derivative of the interpolant (piecewise quadratic) at ``t``."""
        return self._jerk(np.asarray(t, dtype=float))

    def pole(self, t: ArrayLike) -> PoleState:
        """Interpolated u, u_t, u_tt at ``t`` (inside the sampled range)."""
        t = np.asarray(t, dtype=float)
        return PoleState(*(f(t) for f in self._fields))


@dataclass(frozen=True)
class Candidate:
    """A zero of the contact force ``u_tt + gamma`` crossed from above (dimensionless).

    ``reason`` says why it was rejected (empty for the accepted one); ``clearance``
    is the smallest gap ``s - u`` found over the horizon (negative: re-contact);
    ``recontact`` the time at which the body would touch the pole again.
    """

    t: float
    displacement: float
    velocity: float
    accepted: bool
    reason: str
    clearance: float | None = None
    recontact: float | None = None


@dataclass(frozen=True)
class LiftoffResult:
    """Outcome of the lift-off search (dimensionless).

    ``lifted`` False with ``t``/``velocity`` None is a normal result: no candidate
    passed both criteria within the window.
    """

    lifted: bool
    t: float | None
    velocity: float | None
    displacement: float | None
    candidates: tuple[Candidate, ...]
    gamma: float
    t_end: float
    horizon: str

    @property
    def rejected(self) -> tuple[Candidate, ...]:
        """The candidates before the accepted one, each with its reason."""
        return tuple(c for c in self.candidates if not c.accepted)


def bracketing_grid(motion: PoleMotion, t_end: float, samples_per_period: int) -> np.ndarray:
    """Grid on [0, t_end] with at least ``samples_per_period`` points per shortest period."""
    grid = getattr(motion, "grid_times", None)
    if grid is not None:
        grid = np.asarray(grid, dtype=float)
        return grid[(grid >= 0.0) & (grid <= t_end)]
    omega = max(float(motion.max_frequency), 1.0)
    count = math.ceil(t_end * omega * samples_per_period / (2.0 * math.pi)) + 1
    return np.linspace(0.0, t_end, max(count, 2))


def _refine(f, lower: np.ndarray, upper: np.ndarray) -> np.ndarray:
    """Roots of ``f(t, index)`` in the brackets [lower, upper], all at once, to 1e-12."""
    return bracketed_roots(f, np.asarray(lower), np.asarray(upper), xtol=TIME_TOLERANCE)


def _check_options(gamma: float, t_end: float, horizon: str, samples_per_period: int) -> None:
    if not (math.isfinite(gamma) and gamma > 0):
        raise ParameterError("gamma", "a finite number > 0", gamma)
    if not (math.isfinite(t_end) and t_end > 0):
        raise ParameterError("t_end", "a finite time > 0", t_end)
    if horizon not in HORIZONS:
        raise ParameterError("recontact", "one of " + ", ".join(HORIZONS), horizon)
    if samples_per_period < 16:
        raise ParameterError("samples_per_period", "an integer >= 16", samples_per_period)


def find_liftoff(
    motion: PoleMotion,
    gamma: float,
    t_end: float = DEFAULT_T_END,
    horizon: Horizon = "window",
    samples_per_period: int = 16,
) -> LiftoffResult:
    """First time the body lifts off the pole and is not caught again, §3(a) (i)-(ii).

    Parameters
    ----------
    motion : PoleMotion
        Pole motion (a ModalSeries, a SampledPoleMotion, ...), dimensionless.
    gamma : float
        Dimensionless gravity ``g / (R c^2)``; lift-off needs ``u_tt = -gamma``.
    t_end : float
        End of the modelled window (dimensionless; default 4 pi).
    horizon : {"window", "paper"}
        Re-contact horizon: to ``t_end``, or ``t - t_l < t_l`` (capped at t_end).
    samples_per_period : int
        Bracketing grid density for the highest frequency (>= 16).

    Returns
    -------
    LiftoffResult
        The accepted time and velocity (dimensionless) and every earlier candidate
        with the reason it was rejected.
    """
    _check_options(gamma, t_end, horizon, samples_per_period)
    grid = bracketing_grid(motion, t_end, samples_per_period)
    u, u_t, u_tt = motion.pole(grid)
    force = u_tt + gamma
    down = np.flatnonzero((force[:-1] > 0.0) & (force[1:] <= 0.0))
    jerk = getattr(motion, "jerk", None)
    if jerk is None:
        times = _refine(lambda t, i: motion.pole(t).u_tt + gamma, grid[down], grid[down + 1])
    else:
        times = newton_bracketed(
            lambda t, i: (motion.pole(t).u_tt + gamma, jerk(t)),
            grid[down],
            grid[down + 1],
            xtol=TIME_TOLERANCE,
        )
    state = motion.pole(times)
    # Too close to t_l the gap s - u ~ |u_ttt| (t - t_l)^3 / 6 is below round-off; skip it.
    skip = 1e-2 / max(float(motion.max_frequency), 1.0)
    path = _Ballistic(motion, gamma)
    verdicts: list[tuple[bool, str, float | None]] = []
    brackets: list[tuple[int, float, float]] = []  # (candidate, lower, upper) of a re-contact
    for k, (t_l, u_l, v_l) in enumerate(zip(times, state.u, state.u_t, strict=True)):
        if v_l <= 0.0:
            verdicts.append((False, "moving down (u_t <= 0)", None))
            continue
        end = t_end if horizon == "window" else min(2.0 * t_l, t_end)
        clearance, bracket = path.clearance(grid, u, u_t, t_l, u_l, v_l, t_l + skip, end)
        if bracket is None:
            verdicts.append((True, "", clearance))
            break
        verdicts.append((False, "re-contact", clearance))
        brackets.append((k, *bracket))
    recontact = path.first_contacts(brackets, times, state)
    candidates = tuple(
        Candidate(
            float(times[k]),
            float(state.u[k]),
            float(state.u_t[k]),
            accepted,
            reason,
            clearance,
            recontact.get(k),
        )
        for k, (accepted, reason, clearance) in enumerate(verdicts)
    )
    if candidates and candidates[-1].accepted:
        last = candidates[-1]
        return LiftoffResult(
            True, last.t, last.velocity, last.displacement, candidates, gamma, t_end, horizon
        )
    return LiftoffResult(False, None, None, None, candidates, gamma, t_end, horizon)


def flight_clearance(
    motion: PoleMotion,
    gamma: float,
    t_l: float,
    end: float,
    samples_per_period: int = 16,
) -> float:
    """Smallest gap ``s - u`` over (t_l, end] for a body leaving the pole at ``t_l``.

    The body leaves with the pole's displacement and velocity at ``t_l`` and flies
    ``s(t) = u(t_l) + u_t(t_l) (t - t_l) - gamma (t - t_l)^2 / 2`` (criterion (ii) of
    §3(a)); the gap is checked exactly as :func:`find_liftoff` checks it (grid points
    and refined local minima).  Positive: the body stays clear.  Dimensionless.
    """
    if end <= t_l:
        return math.inf
    omega = max(float(motion.max_frequency), 1.0)
    count = math.ceil((end - t_l) * omega * samples_per_period / (2.0 * math.pi)) + 2
    grid = np.linspace(t_l, end, count)
    u, u_t, _ = motion.pole(grid)
    start = t_l + 1e-2 / omega  # as in find_liftoff: the gap is round-off closer than this
    clearance, _ = _Ballistic(motion, gamma).clearance(
        grid, u, u_t, t_l, float(u[0]), float(u_t[0]), start, end
    )
    return clearance


class _Ballistic:
    """Gap ``s - u`` between the free body's parabola and the pole after a lift-off."""

    def __init__(self, motion: PoleMotion, gamma: float) -> None:
        self.motion = motion
        self.gamma = gamma

    def clearance(
        self,
        grid: np.ndarray,
        u: np.ndarray,
        u_t: np.ndarray,
        t_l: float,
        u_l: float,
        v_l: float,
        start: float,
        end: float,
    ) -> tuple[float, tuple[float, float] | None]:
        """Smallest gap on (start, end] and a bracket of the first re-contact, if any.

        The gap is checked at the grid points; where it stays positive there, also at
        every local minimum between them (zeros of ``s' - u_t`` crossed from below,
        refined to 1e-12).  ``start`` only anchors brackets: its gap is round-off.
        """
        gamma, motion = self.gamma, self.motion
        inside = (grid > start) & (grid < end)
        edge = motion.pole(np.array([start, end]))
        t = np.concatenate([[start], grid[inside], [end]])
        dt = t - t_l
        gaps = (
            u_l
            + v_l * dt
            - 0.5 * gamma * dt * dt
            - np.concatenate([[edge.u[0]], u[inside], [edge.u[1]]])
        )
        closed = np.flatnonzero(gaps[1:] <= 0.0)
        if closed.size:
            first = closed[0] + 1
            return float(gaps[1:].min()), (float(t[first - 1]), float(t[first]))
        slopes = v_l - gamma * dt - np.concatenate([[edge.u_t[0]], u_t[inside], [edge.u_t[1]]])
        rising = np.flatnonzero((slopes[:-1] < 0.0) & (slopes[1:] >= 0.0))

        def slope_and_curvature(x: np.ndarray, i: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
            state = motion.pole(x)
            return v_l - gamma * (x - t_l) - state.u_t, -gamma - state.u_tt

        minima = newton_bracketed(
            slope_and_curvature, t[rising], t[rising + 1], xtol=TIME_TOLERANCE
        )
        dm = minima - t_l
        low = u_l + v_l * dm - 0.5 * gamma * dm * dm - motion.pole(minima).u
        clearance = float(min(gaps[1:].min(), low.min(initial=np.inf)))
        closed = np.flatnonzero(low <= 0.0)
        if closed.size == 0:
            return clearance, None
        first = closed[0]
        return clearance, (float(t[rising[first]]), float(minima[first]))

    def first_contacts(
        self, brackets: list[tuple[int, float, float]], times: np.ndarray, state: PoleState
    ) -> dict[int, float]:
        """Refine every re-contact bracket at once: candidate index -> re-contact time."""
        if not brackets:
            return {}
        which = np.array([b[0] for b in brackets])
        t_l, u_l, v_l = times[which], state.u[which], state.u_t[which]
        gamma, motion = self.gamma, self.motion

        def gap_and_slope(x: np.ndarray, i: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
            dt = x - t_l[i]
            state = motion.pole(x)
            gap = u_l[i] + v_l[i] * dt - 0.5 * gamma * dt * dt - state.u
            return gap, v_l[i] - gamma * dt - state.u_t

        lower = np.array([b[1] for b in brackets])
        upper = np.array([b[2] for b in brackets])
        every = np.arange(lower.size)
        # The gap is a difference of sums of many modes: its rounding is ~eps times the
        # modes' size, and the same time evaluated in another batch may change its sign.
        # Measured (tennis, D = 0.01, near the start): gaps of 1e-18 to 2e-17 at both ends
        # of a bracket, with either sign.  Below ROUNDING times the pole's largest
        # displacement a gap counts as closed.
        rounding = ROUNDING * max(float(np.max(np.abs(state.u), initial=0.0)), 1e-300)
        # A lower end at t_l + skip can sit at round-off level: then the body touches
        # again at once and the lower end is the re-contact time.
        touching = gap_and_slope(lower, every)[0] <= rounding
        roots = lower.copy()
        # an upper end found closed by the scan but open to rounding on this evaluation
        grazing = ~touching & (np.abs(gap_and_slope(upper, every)[0]) <= rounding)
        roots[grazing] = upper[grazing]
        open_ = np.flatnonzero(~touching & ~grazing)
        if open_.size:

            def gap_open(x: np.ndarray, i: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
                return gap_and_slope(x, open_[i])

            roots[open_] = newton_bracketed(
                gap_open, lower[open_], upper[open_], xtol=TIME_TOLERANCE
            )
        return {int(k): float(r) for k, r in zip(which, roots, strict=True)}
