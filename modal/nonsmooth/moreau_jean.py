"""Moreau-Jean theta-scheme with localised touches for the contact problem (N1)-(N3).

One step from ``t_n`` to ``t_n + h`` (Jean 1999, Comput. Methods Appl. Mech.
Engrg. 177:235, eqs. (19)-(22); Acary 2016, ZAMM 96:585, §3)::

    M (v1 - v0) = h (f - K q_theta - C v_theta) + G^T P                   (MJ1)
    q1 = q0 + h v_theta,   x_theta = (1 - theta) x0 + theta x1            (MJ2)
    0 <= P  ⊥  U1 = G v1 >= 0   on the constraints in contact             (MJ3)

P is the contact impulse of the step.  Solving (MJ1)-(MJ2) for v1 gives
``W (v1 - v0) = h (f - K q0 - C v0 - theta h K v0) + G^T P`` with
``W = M + theta h C + theta^2 h^2 K``, and (MJ3) is an LCP in P with the
Delassus matrix ``G W^-1 G^T`` (:mod:`twoball.modal.nonsmooth.lcp`).

Two variants (``localise``):

``localise=True`` (default)
    Impacts are separated from the smooth motion.

    * Touches are *localised*: when a free constraint's gap would end the step
      below zero, the step is shortened so that it ends with that gap at zero
      (cubic Hermite estimate of the crossing, then regula falsi on the gap the
      scheme itself produces).
    * At the start of each step Newton's law (N3) acts as an instantaneous
      impact on every constraint in contact, an LCP with the Delassus matrix
      ``G M^-1 G^T``::

          M (v+ - v-) = G^T P_imp,   0 <= P_imp ⊥ U+ + e U- >= 0          (MJ4)

    * The step's LCP holds the constraints in contact that do not move away
      faster than the Zeno speed v_Z, with ``U1 + max(U0, 0) >= 0`` in place of
      (MJ3): a constraint held while leaving slowly stays at its level.
      Arrivals and departures slower than v_Z are no impacts; without this
      rule two neighbouring constraints coupled through the Delassus matrix
      lift each other in turn, an endless (Zeno) chain of re-touches.

    With theta = 1/2 the energy identity is exact for any h::

        E_{n+1} - E_n = -h v_mid^T C v_mid + W_imp + W_step               (MJ5)

    with ``v_mid = (v0 + v1)/2``, the impact work ``W_imp = 1/2 P_imp . (U+ +
    U-) = -1/2 (1 - e) P_imp . U- <= 0`` (0 at e = 1) and the step's contact
    work ``W_step = 1/2 P . (U0 + U1)``, which vanishes but for arrivals slower
    than v_Z (then ``|W_step| <= P v_Z / 2``).  The trapezoidal rule between
    events is second order.

``localise=False``
    The classical scheme: the constraints with predicted gap
    ``g0 + h U0 / 2 <= 0`` enter (MJ3) with Newton's law ``U1 + e U0 >= 0``
    in place of ``U1 >= 0``; impacts happen inside steps, the scheme is first
    order (Acary 2016, §3.3), and the contact work of a step is
    ``1/2 P . (U0 + U1)``.

Energies are booked per step: kinetic, elastic, load potential (``-f^T q``),
and the cumulative work of the damping, of the step impulses and of the
impacts; their sum is conserved to rounding for theta = 1/2 (MJ5), and the
remainder is reported as the scheme's own (numerical) dissipation for
theta > 1/2.  Units are those of the problem (dimensionless in this package).
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field

import numpy as np

from twoball._common.errors import NumericalError, ParameterError, real_number
from twoball._common.monitor import Monitor
from twoball.modal.nonsmooth.crossing import first_crossings
from twoball.modal.nonsmooth.lcp import solve_lcp
from twoball.modal.nonsmooth.linear import Factorised, combine
from twoball.modal.nonsmooth.problem import ContactProblem

_MAX_LOCALISATIONS = 64  # shortened sub-steps inside one step (a guard)
_ROOT_ITERATIONS = 60  # Illinois iterations of one localisation (a guard)
ZENO_FRACTION = 1e-4  # Zeno speed over the largest initial normal speed
#: Arrivals of a body slower than this (units R c) are held, not bounced: with
#: Newton's e > 0 the bounces of a body settling on a cap shrink without end (a
#: Zeno chain); the event-driven solver ends it at the same speed.
ZENO_VELOCITY = 1e-6


@dataclass(frozen=True)
class ContactEvent:
    """A touch (an impact of Newton's law) or a release of one constraint.

    Attributes
    ----------
    t : float
        Time.
    index : int
        The constraint.
    kind : str
        ``"impact"`` (the gap reached zero with ``U- < 0``) or ``"release"``
        (a constraint that carried an impulse in the previous step carries none
        and moves away).
    velocity : float
        ``U-`` for an impact, ``U1`` for a release.
    """

    t: float
    index: int
    kind: str
    velocity: float


@dataclass
class StepperState:
    """The integrator's state between steps (mutable; units of the problem).

    Attributes
    ----------
    t : float
    q, v : ndarray, shape (n,)
    arrived : ndarray of bool, shape (m,)
        Constraints whose gap a localised step has just brought to zero.
    carried : ndarray of bool, shape (m,)
        Constraints with a positive impulse in the last step (warm start).
    damping_work, contact_work, impact_work : float
        Cumulative work of C, of the step impulses and of the impacts.
    """

    t: float
    q: np.ndarray
    v: np.ndarray
    arrived: np.ndarray
    carried: np.ndarray
    damping_work: float = 0.0
    contact_work: float = 0.0
    impact_work: float = 0.0


@dataclass
class StepRecord:
    """What one call of :meth:`MoreauJean.advance` did (impulses over all m constraints)."""

    t0: float
    t1: float
    impact_impulse: np.ndarray
    step_impulse: np.ndarray
    events: list[ContactEvent] = field(default_factory=list)
    localised: bool = False


@dataclass(frozen=True)
class Trajectory:
    """A run of the integrator (units of the problem).

    Attributes
    ----------
    t : ndarray, shape (K + 1,)
        Step end times (t[0] the start).
    q, v : ndarray, shape (K + 1, n) or None
        States (None when not kept).
    impulse : ndarray, shape (K, m)
        Total contact impulse of each constraint in step k (impacts at ``t[k]``
        plus the step impulse over ``(t[k], t[k+1]]``).
    impact_impulse : ndarray, shape (K, m)
        The impact part of ``impulse``.
    kinetic, elastic, potential : ndarray, shape (K + 1,)
        ``1/2 v^T M v``, ``1/2 q^T K q``, ``-f^T q``.
    damping_work, contact_work, impact_work : ndarray, shape (K + 1,)
        Cumulative works (<= 0 for damping and impacts).
    events : list of ContactEvent
    q_final, v_final : ndarray, shape (n,)
        Last state (kept even when the history is not).
    """

    t: np.ndarray
    q: np.ndarray | None
    v: np.ndarray | None
    impulse: np.ndarray
    impact_impulse: np.ndarray
    kinetic: np.ndarray
    elastic: np.ndarray
    potential: np.ndarray
    damping_work: np.ndarray
    contact_work: np.ndarray
    impact_work: np.ndarray
    events: list[ContactEvent]
    q_final: np.ndarray
    v_final: np.ndarray

    @property
    def energy(self) -> np.ndarray:
        """Mechanical energy ``E = kinetic + elastic + potential`` at every step end."""
        return self.kinetic + self.elastic + self.potential

    @property
    def balance(self) -> np.ndarray:
        """``E - E_0 - (damping + contact + impact work)``: the scheme's own energy error."""
        works = self.damping_work + self.contact_work + self.impact_work
        return self.energy - self.energy[0] - works

    @property
    def steps(self) -> int:
        """Number of steps K."""
        return int(self.t.size - 1)


class MoreauJean:
    """Moreau-Jean theta-scheme for :class:`ContactProblem`, with localised touches.

    Parameters
    ----------
    problem : ContactProblem
    dt : float
        Time step (> 0), in the problem's time unit.
    theta : float
        In [1/2, 1]; 1/2 (trapezoidal, second order, energy-conserving) by default.
    localise : bool
        Localise touches and apply Newton's law as separate impacts (second order,
        exact energy identity (MJ5)); False: the classical first-order scheme.
    gap_tolerance : float, optional
        A gap at most this is "in contact" (default ``1e-12 max(1, |g0|)``).
    velocity_tolerance : float, optional
        A normal velocity at most this is "not moving away" (default 1e-13 times
        the largest initial normal velocity, at least 1e-15).
    zeno_velocity : float, optional
        Arrivals and departures slower than this are no impacts: the step's LCP
        holds the constraint, which ends Zeno chains of re-touches (default
        :data:`ZENO_FRACTION` times the largest initial normal speed).
    """

    def __init__(
        self,
        problem: ContactProblem,
        dt: float,
        *,
        theta: float = 0.5,
        localise: bool = True,
        gap_tolerance: float | None = None,
        velocity_tolerance: float | None = None,
        zeno_velocity: float | None = None,
    ) -> None:
        if not isinstance(problem, ContactProblem):
            raise ParameterError("problem", "a ContactProblem", type(problem).__name__)
        self.problem = problem
        self.dt = real_number("dt", dt, "a finite number > 0")
        if self.dt <= 0:
            raise ParameterError("dt", "a finite number > 0", dt)
        self.theta = real_number("theta", theta, "a number in [0.5, 1]")
        if not 0.5 <= self.theta <= 1.0:
            raise ParameterError("theta", "a number in [0.5, 1]", theta)
        self.localise = bool(localise)
        scale = max(1.0, float(np.max(np.abs(problem.offset), initial=0.0)))
        self.gap_tolerance = 1e-12 * scale if gap_tolerance is None else float(gap_tolerance)
        self._velocity_tolerance = velocity_tolerance
        self.velocity_tolerance = 1e-15 if velocity_tolerance is None else velocity_tolerance
        self._zeno_velocity = zeno_velocity
        self.zeno_velocity = 0.0 if zeno_velocity is None else float(zeno_velocity)
        self._mass = Factorised(problem.mass)
        G = problem.constraints
        self._mass_y = self._mass.solve(G.T.copy()) if G.size else np.zeros((problem.dofs, 0))
        self._mass_delassus = G @ self._mass_y
        self._cache: dict[float, tuple[Factorised, tuple[np.ndarray, np.ndarray] | None]] = {}
        self._last_short = -1.0

    # --- matrices for one step length -------------------------------------------------
    def _factors(self, h: float) -> tuple[Factorised, tuple[np.ndarray, np.ndarray] | None]:
        """``W = M + theta h C + theta^2 h^2 K`` factorised, with ``Y = W^-1 G^T`` and ``G Y``.

        Y and ``G Y`` over all constraints are formed (and kept) for the regular
        step ``dt`` only; a shortened step builds the columns it needs.
        """
        hit = self._cache.get(h)
        if hit is not None:
            return hit
        p = self.problem
        W = combine([p.mass, p.damping, p.stiffness], [1.0, self.theta * h, (self.theta * h) ** 2])
        factor = Factorised(W)
        full = None
        if h == self.dt:
            G = p.constraints
            Y = factor.solve(G.T.copy()) if G.size else np.zeros((p.dofs, 0))
            full = (Y, G @ Y)
        out = (factor, full)
        if h == self.dt:
            self._cache[h] = out
        else:
            self._cache.pop(self._last_short, None)
            self._cache[h] = out
            self._last_short = h
        return out

    # --- the pieces of a step -------------------------------------------------------
    def start(self, q0: np.ndarray, v0: np.ndarray, t0: float = 0.0) -> StepperState:
        """Initial state; refuses non-finite or wrongly sized vectors."""
        n, m = self.problem.dofs, self.problem.count
        q = np.asarray(q0, dtype=float).reshape(-1).copy()
        v = np.asarray(v0, dtype=float).reshape(-1).copy()
        for name, x in (("q0", q), ("v0", v)):
            if x.shape != (n,) or not np.all(np.isfinite(x)):
                raise ParameterError(name, f"a finite vector of length {n}", x.shape)
        if self._velocity_tolerance is None:
            speed = float(np.max(np.abs(self.problem.normal_velocity(v)), initial=0.0))
            self.velocity_tolerance = max(1e-13 * speed, 1e-15)
        if self._zeno_velocity is None:
            speed = float(np.max(np.abs(self.problem.normal_velocity(v)), initial=0.0))
            self.zeno_velocity = ZENO_FRACTION * speed
        none = np.zeros(m, dtype=bool)
        return StepperState(float(t0), q, v, none.copy(), none.copy())

    def _touching(self, state: StepperState) -> np.ndarray:
        """The constraints in contact at the state: closed or arrived in the last step."""
        return (self.problem.gap(state.q) <= self.gap_tolerance) | state.arrived

    def _impacts(self, state: StepperState, record: StepRecord) -> np.ndarray:
        """Newton's law (MJ4) on the constraints in contact; returns the contact mask."""
        p = self.problem
        touching = self._touching(state)
        U = p.normal_velocity(state.v)
        # arrivals slower than the Zeno speed are no impacts: the step's LCP holds
        # them (its contact work, 1/2 P U0 <= 0, books the small loss)
        striking = touching & (U < -max(self.velocity_tolerance, self.zeno_velocity))
        if not striking.any():
            return touching
        idx = np.flatnonzero(touching)
        D = self._mass_delassus[idx[:, None], idx]
        b = (1.0 + p.restitution[idx]) * U[idx]
        sol = solve_lcp(D, b, guess=striking[idx])
        dv = self._mass_y[:, idx] @ sol.z
        v_after = state.v + dv
        U_after = p.normal_velocity(v_after)
        state.impact_work += 0.5 * float(sol.z @ (U[idx] + U_after[idx]))
        state.v = v_after
        record.impact_impulse[idx] += sol.z
        for i in np.flatnonzero(striking):
            record.events.append(ContactEvent(state.t, int(i), "impact", float(U[i])))
        return touching

    def _smooth(
        self, q: np.ndarray, v: np.ndarray, h: float, active: np.ndarray, guess: np.ndarray
    ) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """One theta-step (MJ1)-(MJ3) of length h with the LCP on ``active``."""
        p = self.problem
        factor, full = self._factors(h)
        th = self.theta
        force = p.load - p.stiffness.matvec(q + th * h * v) - p.damping.matvec(v)
        v1 = v + factor.solve(h * force)
        impulse = np.zeros(p.count)
        if active.any():
            idx = np.flatnonzero(active)
            if full is not None:
                Y_a, D = full[0][:, idx], full[1][idx[:, None], idx]
            else:
                Y_a = factor.solve(p.constraints[idx].T.copy())
                D = p.constraints[idx] @ Y_a
            b = p.constraints[idx] @ v1
            U0 = p.normal_velocity(v)[idx]
            if self.localise:
                # U1 + max(U0, 0) >= 0: a constraint held while leaving slowly stays
                # at its level (U1 = -U0) instead of being lifted by h U0 / 2, and the
                # step's contact work 1/2 P (U0 + U1) vanishes
                b = b + np.maximum(U0, 0.0)
            else:
                b = b + p.restitution[idx] * U0
            sol = solve_lcp(D, b, guess=guess[idx])
            v1 = v1 + Y_a @ sol.z
            impulse[idx] = sol.z
        q1 = q + h * ((1.0 - th) * v + th * v1)
        return q1, v1, impulse

    def _commit(
        self,
        state: StepperState,
        h: float,
        q1: np.ndarray,
        v1: np.ndarray,
        impulse: np.ndarray,
        record: StepRecord,
    ) -> None:
        """Book the works of a step and move the state to its end."""
        p = self.problem
        th = self.theta
        v_theta = (1.0 - th) * state.v + th * v1
        v_mid = 0.5 * (state.v + v1)
        U0, U1 = p.normal_velocity(state.v), p.normal_velocity(v1)
        state.damping_work -= h * float(v_mid @ p.damping.matvec(v_theta))
        state.contact_work += 0.5 * float(impulse @ (U0 + U1))
        released = state.carried & (impulse == 0.0) & (U1 > self.velocity_tolerance)
        for i in np.flatnonzero(released):
            record.events.append(ContactEvent(state.t + h, int(i), "release", float(U1[i])))
        state.t += h
        state.q, state.v = q1, v1
        state.carried = impulse > 0.0
        record.step_impulse += impulse
        record.t1 = state.t

    def advance(self, state: StepperState, h: float | None = None) -> StepRecord:
        """Advance ``state`` by ``h`` (default dt), or less when a touch is localised.

        Returns
        -------
        StepRecord
            Impulses of the step (impact and step parts) and its events.
        """
        h = self.dt if h is None else float(h)
        p = self.problem
        m = p.count
        record = StepRecord(state.t, state.t, np.zeros(m), np.zeros(m))
        if not self.localise:
            gap = p.gap(state.q)
            U = p.normal_velocity(state.v)
            active = gap + 0.5 * h * U <= self.gap_tolerance
            q1, v1, impulse = self._smooth(state.q, state.v, h, active, state.carried)
            record.events.extend(
                ContactEvent(state.t, int(i), "impact", float(U[i]))
                for i in np.flatnonzero(active & ~state.carried & (impulse > 0))
            )
            self._commit(state, h, q1, v1, impulse, record)
            self._check(state)
            return record
        touching = self._impacts(state, record)
        state.arrived = np.zeros(m, dtype=bool)
        U0 = p.normal_velocity(state.v)
        # in contact and not moving away faster than the Zeno speed: held by the
        # step's LCP (a slower departure that the elastic forces reverse within
        # the step would otherwise start a Zeno chain of re-touches)
        active = touching & (U0 <= max(self.velocity_tolerance, self.zeno_velocity))
        q1, v1, impulse = self._smooth(state.q, state.v, h, active, state.carried)
        gap0, gap1 = p.gap(state.q), p.gap(q1)
        # a free gap is localised when it ends below its level: 0, or its start
        # value if rounding or a slow arrival left it slightly below zero
        level = np.minimum(gap0, 0.0)
        crossing = ~active & (gap1 - level < -self.gap_tolerance)
        if crossing.any():
            h, q1, v1, impulse, arrived = self._localise(
                state, h, active, gap0 - level, U0, (q1, v1, impulse), crossing, level
            )
            state.arrived = arrived
            record.localised = True
        self._commit(state, h, q1, v1, impulse, record)
        self._check(state)
        return record

    def _localise(
        self,
        state: StepperState,
        h: float,
        active: np.ndarray,
        gap0: np.ndarray,
        U0: np.ndarray,
        trial: tuple[np.ndarray, np.ndarray, np.ndarray],
        crossing: np.ndarray,
        level: np.ndarray,
    ) -> tuple[float, np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
        """Shorten the step so that it ends when the first crossing gap reaches its level.

        ``gap0`` and the gaps below are measured from ``level`` (0, or the start
        value of a gap that a shallow arrival left below zero).
        """
        p = self.problem
        q1, v1, impulse = trial
        for _ in range(_MAX_LOCALISATIONS):
            gap1, U1 = p.gap(q1) - level, p.normal_velocity(v1)
            candidates = np.flatnonzero(crossing)
            c = candidates
            times = first_crossings(h, gap0[c], U0[c], gap1[c], U1[c])
            j = int(candidates[int(np.argmin(times))])
            s = float(times.min())
            found = self._root(state, active, j, level[j], s, h, (gap0[j], gap1[j]))
            if found is None:  # leaves and returns within rounding: held in this step
                active = active.copy()
                active[j] = True
                q1, v1, impulse = self._smooth(state.q, state.v, h, active, state.carried)
                crossing = ~active & (p.gap(q1) - level < -self.gap_tolerance)
                if not crossing.any():
                    return h, q1, v1, impulse, np.zeros(p.count, dtype=bool)
                continue
            s, (q1, v1, impulse) = found
            h = s
            gap_h = p.gap(q1) - level
            crossing = ~active & (gap_h < -self.gap_tolerance)
            crossing[j] = False
            if not crossing.any():
                arrived = np.zeros(p.count, dtype=bool)
                arrived[j] = True
                arrived |= ~active & (np.abs(gap_h) <= self.gap_tolerance)
                return h, q1, v1, impulse, arrived
        raise NumericalError(f"localisation did not settle at t = {state.t:.6g}")

    def _root(
        self,
        state: StepperState,
        active: np.ndarray,
        j: int,
        level: float,
        guess: float,
        h: float,
        gaps: tuple[float, float],
    ) -> tuple[float, tuple[np.ndarray, np.ndarray, np.ndarray]] | None:
        """Step length in (0, h) at which the scheme's own gap j reaches ``level``.

        ``gaps`` are the gap minus ``level`` at the step's start (>= 0) and at its
        full length h (< 0); ``guess`` is the Hermite estimate.  A bracket with
        the gap above ``level`` at its left end is formed from the guess (halving
        towards the start when the constraint starts at its level and moves away),
        then the Illinois variant of regula falsi (Dowell & Jarratt 1971, BIT
        11:168) narrows it until ``|gap - level| <= gap_tolerance``.  None when
        the gap never rises above its level by more than rounding (a departure
        too slow to resolve: the caller holds the constraint instead).
        """
        p = self.problem
        tol = self.gap_tolerance

        def f(s: float) -> tuple[float, tuple[np.ndarray, np.ndarray, np.ndarray]]:
            out = self._smooth(state.q, state.v, s, active, state.carried)
            return float(p.gap(out[0])[j] - level), out

        start, end = gaps
        s = min(max(guess, 1e-9 * h), h * (1.0 - 1e-9))
        value, out = f(s)
        if abs(value) <= tol:
            return s, out
        if value > 0.0:
            a, fa, b, fb = s, value, h, end
        else:
            b, fb = s, value
            a, fa = 0.0, start
            if start <= tol:  # starts at its level while moving away: find the gap above it
                a = 0.5 * s
                fa, _ = f(a)
                while fa <= 0.0:
                    b, fb, a = a, fa, 0.5 * a
                    if a < 1e-14 * h:
                        return None  # the departure is below rounding: hold the constraint
                    fa, _ = f(a)
        side = 0
        for _ in range(_ROOT_ITERATIONS):
            s = (a * fb - b * fa) / (fb - fa)
            if not a < s < b:
                s = 0.5 * (a + b)
            value, out = f(s)
            if abs(value) <= tol or b - a <= 1e-15 * h:
                return s, out
            if value > 0.0:
                a, fa = s, value
                if side == 1:
                    fb *= 0.5  # Illinois: halve the stale end's value
                side = 1
            else:
                b, fb = s, value
                if side == -1:
                    fa *= 0.5
                side = -1
        raise NumericalError(
            f"localisation: no convergence for constraint {j} at t = {state.t:.6g}"
        )

    def _check(self, state: StepperState) -> None:
        if not (np.all(np.isfinite(state.q)) and np.all(np.isfinite(state.v))):
            raise NumericalError(f"Moreau-Jean: non-finite state at t = {state.t:.6g}")

    # --- a whole run -----------------------------------------------------------------
    def run(
        self,
        q0: np.ndarray,
        v0: np.ndarray,
        t_end: float,
        *,
        t0: float = 0.0,
        stop: Callable[[StepperState, StepRecord], bool] | None = None,
        keep_states: bool = True,
        max_steps: int | None = None,
        label: str = "contact",
        monitor: Monitor | None = None,
    ) -> Trajectory:
        """Integrate from ``(q0, v0)`` at ``t0`` to ``t_end`` or until ``stop`` returns True.

        Parameters
        ----------
        q0, v0 : ndarray, shape (n,)
            Initial state (a start touching with ``U < 0`` begins with an impact).
        t_end : float
            Final time (> t0); the last step is shortened to land on it.
        stop : callable, optional
            ``stop(state, record) -> bool`` after every step.
        keep_states : bool
            Keep q and v of every step (else only the final state).
        max_steps : int, optional
            Guard on the number of steps (default: 100 (t_end - t0)/dt + 1000).
        label : str
            What the run is called where the monitor is told of its steps.
        monitor : Monitor, optional
            Called before every step with the run's label, the step and the share
            of the window done (:class:`~twoball._common.monitor.Monitor`: it may
            stop the run by raising).

        Returns
        -------
        Trajectory
        """
        t_end = real_number("t_end", t_end, "a finite number > t0")
        if t_end <= t0:
            raise ParameterError("t_end", f"a finite number > t0 = {t0}", t_end)
        state = self.start(q0, v0, t0)
        p = self.problem
        limit = max_steps if max_steps is not None else int(100 * (t_end - t0) / self.dt) + 1000
        times, qs, vs = [state.t], [state.q], [state.v]
        impulses, impacts = [], []
        kin, ela, pot = [p.kinetic(state.v)], [p.elastic(state.q)], [p.potential(state.q)]
        wd, wc, wi = [0.0], [0.0], [0.0]
        events: list[ContactEvent] = []
        end_tol = 1e-12 * max(1.0, abs(t_end))
        span = t_end - t0
        for taken in range(limit):
            if state.t >= t_end - end_tol:
                break
            if monitor is not None:
                monitor(
                    f"{label}: step {taken}, {100.0 * (state.t - t0) / span:.0f} % of the window"
                )
            h = min(self.dt, t_end - state.t)
            if t_end - (state.t + h) < end_tol:
                h = t_end - state.t
            record = self.advance(state, h)
            times.append(state.t)
            if keep_states:
                qs.append(state.q)
                vs.append(state.v)
            impulses.append(record.impact_impulse + record.step_impulse)
            impacts.append(record.impact_impulse)
            kin.append(p.kinetic(state.v))
            ela.append(p.elastic(state.q))
            pot.append(p.potential(state.q))
            wd.append(state.damping_work)
            wc.append(state.contact_work)
            wi.append(state.impact_work)
            events.extend(record.events)
            if stop is not None and stop(state, record):
                break
        else:
            raise NumericalError(f"Moreau-Jean: {limit} steps did not reach t_end = {t_end}")
        m = p.count
        return Trajectory(
            t=np.array(times),
            q=np.array(qs) if keep_states else None,
            v=np.array(vs) if keep_states else None,
            impulse=np.array(impulses).reshape(len(impulses), m),
            impact_impulse=np.array(impacts).reshape(len(impacts), m),
            kinetic=np.array(kin),
            elastic=np.array(ela),
            potential=np.array(pot),
            damping_work=np.array(wd),
            contact_work=np.array(wc),
            impact_work=np.array(wi),
            events=events,
            q_final=state.q.copy(),
            v_final=state.v.copy(),
        )


__all__ = ["ContactEvent", "MoreauJean", "StepRecord", "StepperState", "Trajectory"]
