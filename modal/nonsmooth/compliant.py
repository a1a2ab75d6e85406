"""Compliant unilateral rows in the Moreau-Jean scheme: a body's own contact law.

The contact core (:mod:`twoball.modal.nonsmooth.moreau_jean`) holds rigid
unilateral constraints with Newton's law at touches.  A soft body meets the
ball through a *force law* instead: along row i with gap ``g_i`` the body is
compressed by ``delta = -g_i`` and pushes with

    lambda = max(0, f(delta) + c(delta) delta'),     f = Phi',              (C1)
    f(delta) = k delta^p,  c(delta) = c delta^r      (delta > 0; 0 else)

(``p = 1, r = 0``: Kelvin-Voigt; ``p = 3/2, r = 1/4``: Hertz with Tsuji's
dashpot; the force never pulls, the contact opens when it vanishes: Schwager &
Pöschel, Granular Matter 9, 465 (2007)).  ``Phi(delta) = k delta^(p+1)/(p+1)``
is the body's stored (internal) energy.

The step (theta = 1/2 for the energy identity) keeps (MJ1)-(MJ2) and replaces
(MJ3) on a compliant row by the impulse ``P = h lambda`` with the *discrete
gradient* of Phi and the dashpot at the midpoint::

    lambda = max(0, [Phi(delta1) - Phi(delta0)] / (delta1 - delta0)
                    + [Psi(delta1) - Psi(delta0)] / h),   Psi' = c           (C2)

(Gonzalez 1996, J. Nonlinear Sci. 6:449: the discrete gradient makes the
spring's work over the step exactly ``-(Phi(delta1) - Phi(delta0))`` for any
h and any law, so the books close to rounding; the dashpot's impulse over the
step is its exact ``int c(delta) delta' dt``, its work ``-(Psi(delta1) -
Psi(delta0)) (delta1 - delta0) / h <= 0``, and it vanishes with the
compression).  (C2) is implicit in delta1, which
depends on every impulse of the step through the Delassus matrix.  It is
solved by Newton's method on delta1: linearised at an iterate ``delta*``,
``lambda ~ lambda* + s* (delta1 - delta*)``, and with ``delta1 = -g0 - h
((1 - theta) U0 + theta U1)`` the row enters the step's LCP as a *soft
constraint* (Baraff-style regularisation; Acary & Brogliato 2008, §10.3)::

    w = (D + 1 / (s* theta h^2)) P + b + r,   0 <= P  ⊥  w >= 0              (C3)
    r = [s* (g0 + h (1 - theta) U0 + delta*) - lambda*] / (s* theta h)

together with the rigid rows of the step.  A linear law converges in one
iteration (checked by a second); Hertz in three or four, to the rounding of
the compression (64 eps times the terms of its gap).  Should the iteration
cycle (the clip of (C1) at a kink), a single compliant row falls back on
Illinois' regula falsi on its impulse, which (C2) brackets.  As ``k -> inf``
(C3) tends to the rigid row.

The row may move with the body's state: a body whose contact disc grows with
its compression loads the ball through an average over that disc, so its row
``G_i`` (:attr:`CompliantRow.update`) is rebuilt at each step start.  Its
offset is then reset so that the gap (the body's compression) is continuous
across the change: the compression is the time integral of the row's rate,
``delta' = -G_i(t) q'``, which is the measure work-conjugate to the load that
the row applies (power ``lambda G_i q'``), so energy and momentum are exact
with a moving row, and the gap's zero drifts from the geometric one only by
the loading/unloading asymmetry of the disc (reported as :attr:`drift`).

While a compliant row is compressed the step is shortened to its
:attr:`CompliantRow.substep` (a fraction of the body's own contact time), and
a touch of a free compliant row is localised like any other (no impact: the
force starts at zero).  Books per step, kept beside the core's
(:attr:`CompliantMoreauJean.books`): the stored energy Phi, the body's own
dissipation ``W_body`` (the row's work minus the change of Phi, >= 0), the
force and the disc.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field, replace

import numpy as np

from twoball._common.errors import NumericalError, ParameterError
from twoball.modal.nonsmooth.lcp import solve_lcp
from twoball.modal.nonsmooth.moreau_jean import (
    MoreauJean,
    StepperState,
    StepRecord,
)
from twoball.modal.nonsmooth.problem import ContactProblem

__all__ = ["CompliantMoreauJean", "CompliantRow", "PowerLaw"]

#: Newton iterations on delta1 in one step before the bracketed fallback (Hertz needs 3-4).
_NEWTON = 30
#: Relative tolerance of Newton's iteration on delta1.
_NEWTON_TOLERANCE = 1e-13


@dataclass(frozen=True)
class PowerLaw:
    """The force law (C1) of a compliant row, in the units of the problem.

    Parameters
    ----------
    stiffness : float
        k > 0 (force per length^p).
    power : float
        p >= 1 (1: a linear spring; 3/2: Hertz).
    damping : float
        c >= 0 (force per velocity per length^r).
    damping_power : float
        r in [0, p) (0: Kelvin-Voigt; 1/4: Tsuji et al. 1992).
    scale : float
        A typical compression (> 0): the scale of Newton's tolerance.

    Examples
    --------
    >>> law = PowerLaw(4.0, 1.0, 0.0, 0.0)
    >>> law.force(0.5), law.energy(0.5), law.force(-1.0)
    (2.0, 0.5, 0.0)
    """

    stiffness: float
    power: float = 1.0
    damping: float = 0.0
    damping_power: float = 0.0
    scale: float = 1.0

    def __post_init__(self) -> None:
        checks = (
            ("stiffness", self.stiffness > 0.0, "a finite number > 0"),
            ("power", self.power >= 1.0, "a number >= 1"),
            ("damping", self.damping >= 0.0, "a finite number >= 0"),
            ("damping_power", 0.0 <= self.damping_power < self.power, "in [0, power)"),
            ("scale", self.scale > 0.0, "a finite number > 0"),
        )
        for name, ok, valid in checks:
            value = getattr(self, name)
            if not (math.isfinite(value) and ok):
                raise ParameterError(name, valid, value)

    def force(self, delta: float) -> float:
        """The spring's force ``f(delta) = k delta^p`` (0 for delta <= 0)."""
        return self.stiffness * delta**self.power if delta > 0.0 else 0.0

    def energy(self, delta: float) -> float:
        """Stored energy ``Phi(delta) = k delta^(p+1) / (p + 1)`` (0 for delta <= 0)."""
        if delta <= 0.0:
            return 0.0
        return self.stiffness * delta ** (self.power + 1.0) / (self.power + 1.0)

    def dashpot(self, delta: float) -> float:
        """``c(delta) = c delta^r`` (0 for delta <= 0)."""
        return self.damping * delta**self.damping_power if delta > 0.0 else 0.0

    def slope(self, delta: float) -> float:
        """``f'(delta)`` (0 for delta <= 0; Hertz's is 0 at the touch)."""
        if delta <= 0.0:
            return 0.0
        return self.power * self.stiffness * delta ** (self.power - 1.0)

    def dashpot_potential(self, delta: float) -> float:
        """``Psi(delta) = c delta^(r+1) / (r + 1)``: the dashpot's impulse ``Psi(d1) - Psi(d0)``."""
        if delta <= 0.0:
            return 0.0
        r = self.damping_power
        return self.damping * delta ** (r + 1.0) / (r + 1.0)

    def step_force(self, d0: float, d1: float, h: float) -> tuple[float, float]:
        """(C2) before the clip, and its derivative in ``d1``.

        The spring by its discrete gradient; the dashpot by its exact impulse over
        the step, ``int c(delta) delta' dt = Psi(d1) - Psi(d0)`` (its mean force
        over h), which vanishes where the compression does.
        """
        diff = d1 - d0
        if abs(diff) <= 1e-7 * max(abs(d0), abs(d1), 1e-300):
            mid = 0.5 * (d0 + d1)
            elastic, d_elastic = self.force(mid), 0.5 * self.slope(mid)
        else:
            elastic = (self.energy(d1) - self.energy(d0)) / diff
            d_elastic = (self.force(d1) - elastic) / diff
        value = elastic + (self.dashpot_potential(d1) - self.dashpot_potential(d0)) / h
        return value, d_elastic + self.dashpot(d1) / h

    def contact_time(self, mass: float, speed: float) -> float:
        """Duration of an undamped impact of ``mass`` at ``speed`` on a rigid stop.

        ``pi sqrt(m / k)`` for p = 1; in general ``2 (delta_max / v) int_0^1 (1 -
        s^(p+1))^(-1/2) ds`` with ``Phi(delta_max) = m v^2 / 2`` (Hertz, p = 3/2:
        :func:`twoball.modal.solid.hertz.hertz_contact_time`).
        """
        from scipy.special import beta

        p = self.power
        peak = ((p + 1.0) * 0.5 * mass * speed * speed / self.stiffness) ** (1.0 / (p + 1.0))
        integral = float(beta(1.0 / (p + 1.0), 0.5)) / (p + 1.0)
        return 2.0 * peak / speed * integral

    def scaled(self, length: float, time: float, mass: float) -> PowerLaw:
        """The same law in units of ``length``, ``time`` and ``mass`` (from any consistent set).

        ``k' = k L^(p-1) / (M / T^2)``, ``c' = c L^r / (M / T)``.
        """
        force = mass * length / time**2
        return PowerLaw(
            stiffness=self.stiffness * length**self.power / force,
            power=self.power,
            damping=self.damping * length**self.damping_power * (length / time) / force,
            damping_power=self.damping_power,
            scale=self.scale / length,
        )


@dataclass(frozen=True)
class CompliantRow:
    """A row of G that carries a force law instead of a rigid unilateral constraint.

    Attributes
    ----------
    index : int
        The row in the problem's G (its Newton restitution is not used).
    law : PowerLaw
    substep : float
        The longest step while the row is compressed (units of the problem).
    update : callable, optional
        ``update(delta) -> (row, radius)``: the row of G for a compression delta
        (a contact disc that follows it) and the disc's radius (for the books);
        None: a fixed row.
    """

    index: int
    law: PowerLaw
    substep: float
    update: Callable[[float], tuple[np.ndarray, float]] | None = field(default=None, repr=False)

    def __post_init__(self) -> None:
        if not (math.isfinite(self.substep) and self.substep > 0.0):
            raise ParameterError("substep", "a finite step > 0", self.substep)


@dataclass
class CompliantBooks:
    """What the compliant rows did, step by step (lists, one entry per step; t[0] the start).

    Attributes
    ----------
    stored : list of ndarray
        Phi of each compliant row at each step end.
    dissipated : list of float
        Cumulative dissipation of the bodies' dashpots (>= 0).
    work : list of float
        Cumulative work of the compliant rows' impulses (part of the core's
        ``contact_work``): ``-(Phi - Phi_0) - dissipated``.
    force : list of ndarray
        Each compliant row's mean force over the step (impulse / step).
    radius : list of ndarray
        Each row's contact disc at the step (nan: a fixed row).
    compression : list of ndarray
        Each row's compression ``-g`` at the step end.
    drift : ndarray
        Each row's offset moved by its updates so far (the gap's zero against
        the geometric one).
    """

    stored: list[np.ndarray] = field(default_factory=list)
    dissipated: list[float] = field(default_factory=list)
    work: list[float] = field(default_factory=list)
    force: list[np.ndarray] = field(default_factory=list)
    radius: list[np.ndarray] = field(default_factory=list)
    compression: list[np.ndarray] = field(default_factory=list)
    drift: np.ndarray = field(default_factory=lambda: np.zeros(0))


class CompliantMoreauJean(MoreauJean):
    """:class:`~twoball.modal.nonsmooth.MoreauJean` with compliant rows (C1)-(C3).

    Parameters
    ----------
    problem : ContactProblem
        Its compliant rows are changed in a private copy (moving rows).
    dt : float
    rows : sequence of CompliantRow
    **options
        As :class:`~twoball.modal.nonsmooth.MoreauJean` (``localise`` must stay True).

    Without compliant rows it steps exactly as the parent (the rigid path is the
    parent's own code).
    """

    def __init__(
        self,
        problem: ContactProblem,
        dt: float,
        rows: Sequence[CompliantRow],
        **options: object,
    ) -> None:
        if options.get("localise", True) is not True:
            raise ParameterError("localise", "True with compliant rows", options["localise"])
        if abs(float(options.get("theta", 0.5)) - 0.5) > 0.0:  # type: ignore[arg-type]
            raise ParameterError("theta", "1/2 with compliant rows (exact books)", options["theta"])
        own = replace(problem, constraints=problem.constraints.copy(), offset=problem.offset.copy())
        super().__init__(own, dt, **options)  # type: ignore[arg-type]
        self.rows = tuple(rows)
        m = own.count
        self._mask = np.zeros(m, dtype=bool)
        for row in self.rows:
            if not 0 <= row.index < m or self._mask[row.index]:
                raise ParameterError("rows", "distinct rows of the problem", row.index)
            self._mask[row.index] = True
        self._index = np.array([r.index for r in self.rows], dtype=int)
        self.books = CompliantBooks()
        self._radius = np.full(len(self.rows), math.nan)
        self._dissipated = 0.0
        self._work = 0.0

    # --- the rows that move -----------------------------------------------------------
    def _set_row(self, i: int, row: np.ndarray, q: np.ndarray) -> None:
        """Put ``row`` in G at i, the offset keeping the gap at q; refresh the cached columns."""
        p = self.problem
        old = float(p.constraints[i] @ q + p.offset[i])
        new_offset = old - float(row @ q)
        k = int(np.flatnonzero(self._index == i)[0])
        self.books.drift[k] += new_offset - p.offset[i]
        p.constraints[i] = row
        p.offset[i] = new_offset
        G = p.constraints
        y = self._mass.solve(row.copy())
        self._mass_y[:, i] = y
        column = G @ y
        self._mass_delassus[:, i] = column
        self._mass_delassus[i, :] = column
        for factor, full in list(self._cache.values()):
            if full is None:
                continue
            Y, D = full
            yw = factor.solve(row.copy())
            Y[:, i] = yw
            cw = G @ yw
            D[:, i] = cw
            D[i, :] = cw

    def _refresh(self, state: StepperState) -> None:
        """Each moving row rebuilt for its compression at the step start (gap continuous)."""
        gaps = self.problem.gap(state.q)
        for k, row in enumerate(self.rows):
            if row.update is None:
                continue
            new, radius = row.update(max(-float(gaps[row.index]), 0.0))
            self._radius[k] = radius
            if not np.array_equal(new, self.problem.constraints[row.index]):
                self._set_row(row.index, np.asarray(new, dtype=float), state.q)

    def start(self, q0: np.ndarray, v0: np.ndarray, t0: float = 0.0) -> StepperState:
        """Initial state; the books start (Phi at q0, nothing dissipated)."""
        state = super().start(q0, v0, t0)
        n = len(self.rows)
        self.books = CompliantBooks(drift=np.zeros(n))
        self._refresh(state)
        self.books.drift[:] = 0.0  # the first row is the geometric one
        gaps = self.problem.gap(state.q)
        stored = np.array([r.law.energy(-float(gaps[r.index])) for r in self.rows])
        self.books.stored.append(stored)
        self.books.dissipated.append(0.0)
        self.books.work.append(0.0)
        self.books.compression.append(np.array([-float(gaps[r.index]) for r in self.rows]))
        self._dissipated = self._work = 0.0
        return state

    # --- one step -----------------------------------------------------------------------
    def _touching(self, state: StepperState) -> np.ndarray:
        """The rigid rows in contact: a compliant row has no impact (Newton's law, MJ4)."""
        return super()._touching(state) & ~self._mask

    def _smooth(
        self, q: np.ndarray, v: np.ndarray, h: float, active: np.ndarray, guess: np.ndarray
    ) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """One step (MJ1)-(MJ3) with the compliant rows' soft constraints (C3)."""
        p = self.problem
        factor, full = self._factors(h)
        th = self.theta
        force = p.load - p.stiffness.matvec(q + th * h * v) - p.damping.matvec(v)
        v1 = v + factor.solve(h * force)
        impulse = np.zeros(p.count)
        rigid = active & ~self._mask
        comp = self._index
        g0 = p.constraints[comp] @ q + p.offset[comp]
        U0c = p.constraints[comp] @ v
        free_end = g0 + h * ((1.0 - th) * U0c + th * (p.constraints[comp] @ v1))
        engaged = (g0 < 0.0) | (free_end < 0.0)
        if not rigid.any() and not engaged.any():
            q1 = q + h * ((1.0 - th) * v + th * v1)
            return q1, v1, impulse
        soft = comp[engaged]
        idx = np.concatenate([np.flatnonzero(rigid), soft])
        nr = int(rigid.sum())
        if full is not None:
            Y_a, D = full[0][:, idx], full[1][idx[:, None], idx]
        else:
            Y_a = factor.solve(p.constraints[idx].T.copy())
            D = p.constraints[idx] @ Y_a
        b = p.constraints[idx] @ v1
        U0 = p.normal_velocity(v)[idx]
        b[:nr] += np.maximum(U0[:nr], 0.0)
        laws = [self.rows[k].law for k in np.flatnonzero(engaged)]
        d0 = -g0[engaged]
        base = g0[engaged] + h * (1.0 - th) * U0c[engaged]  # delta1 = -(base + h th U1)
        d1 = -free_end[engaged]
        z_guess = guess[idx].copy()
        # rounding of the compression itself: the gap is a sum of O(|G| |q|) terms
        G_c = p.constraints[soft]
        noise = (
            64.0
            * np.finfo(float).eps
            * (np.abs(G_c) @ np.abs(q) + np.abs(p.offset[soft]) + h * (np.abs(G_c) @ np.abs(v)))
        )
        z = None if laws else solve_lcp(D, b, guess=z_guess > 0.0).z
        for _ in range(_NEWTON if laws else 0):
            diag = np.zeros(idx.size)
            rhs = np.zeros(idx.size)
            for j, law in enumerate(laws):
                value, slope = law.step_force(d0[j], d1[j], h)
                floor = (
                    1e-3
                    * law.stiffness
                    * max(law.scale, abs(d0[j]), abs(d1[j])) ** (law.power - 1.0)
                )
                slope = max(slope, floor)
                diag[nr + j] = 1.0 / (slope * th * h * h)
                rhs[nr + j] = (slope * (base[j] + d1[j]) - value) / (slope * th * h)
            sol = solve_lcp(D + np.diag(diag), b + rhs, guess=z_guess > 0.0)
            U1 = b[nr:] + D[nr:] @ sol.z
            new = -(base + h * th * U1)
            relative = _NEWTON_TOLERANCE * np.maximum(
                np.maximum(np.abs(d0), np.abs(new)), [law.scale for law in laws]
            )
            done = np.all(np.abs(new - d1) <= np.maximum(relative, noise))
            d1, z_guess = new, sol.z
            if done:
                z = sol.z
                break
        if z is not None and laws:
            # a row compressed at neither end carries no force: its rounding-level impulse
            # (a degenerate LCP at an opening contact) is dropped and the step solved again
            free = (d0 <= 0.0) & (d1 <= 0.0) & (z[nr:] > 0.0)
            if free.any():
                keep = np.concatenate([np.ones(nr, dtype=bool), ~free])
                z = np.zeros(idx.size)
                matrix = (D + np.diag(diag))[np.ix_(keep, keep)]
                z[keep] = solve_lcp(matrix, (b + rhs)[keep], guess=z_guess[keep] > 0.0).z
        if z is None:
            if len(laws) != 1:
                raise NumericalError("compliant contact: Newton's iteration on (C2) did not settle")
            z = self._bracketed(D, b, nr, laws[0], d0[0], base[0], h, guess[idx])
        v1 = v1 + Y_a @ z
        impulse[idx] = z
        q1 = q + h * ((1.0 - th) * v + th * v1)
        return q1, v1, impulse

    def _bracketed(
        self,
        D: np.ndarray,
        b: np.ndarray,
        nr: int,
        law: PowerLaw,
        d0: float,
        base: float,
        h: float,
        guess: np.ndarray,
    ) -> np.ndarray:
        """(C2) for one compliant row by Illinois' regula falsi on its impulse (Newton's fallback).

        With the row's impulse P given, the rigid rows' LCP gives its compression
        ``delta1(P)``, which falls as P grows; ``r(P) = P / h - max(0, F(delta1(P)))``
        rises, with ``r(0) <= 0 <= r(h max(0, F(delta1(0))))``: a bracket.
        """
        th = self.theta
        rigid = slice(0, nr)

        def solve(P: float) -> tuple[float, np.ndarray]:
            z = np.zeros(b.size)
            z[nr] = P
            if nr:
                inner = solve_lcp(
                    D[rigid, rigid], b[rigid] + D[rigid, nr] * P, guess=guess[:nr] > 0
                )
                z[:nr] = inner.z
            U1 = b[nr] + D[nr] @ z
            d1 = -(base + h * th * U1)
            value, _ = law.step_force(d0, d1, h)
            return P / h - max(value, 0.0), z

        r0, z0 = solve(0.0)
        if r0 >= 0.0:
            return z0
        a, fa, c = 0.0, r0, -r0 * h
        fc, zc = solve(c)
        side = 0
        for _ in range(200):
            if abs(fc) <= 1e-14 * max(abs(c / h), 1e-300) or c - a <= 1e-15 * c:
                return zc
            m = (a * fc - c * fa) / (fc - fa)
            if not a < m < c:
                m = 0.5 * (a + c)
            fm, zm = solve(m)
            if fm > 0.0:
                c, fc, zc = m, fm, zm
                if side == 1:
                    fa *= 0.5
                side = 1
            else:
                a, fa = m, fm
                if side == -1:
                    fc *= 0.5
                side = -1
        raise NumericalError("compliant contact: (C2) did not settle by regula falsi either")

    def _commit(
        self,
        state: StepperState,
        h: float,
        q1: np.ndarray,
        v1: np.ndarray,
        impulse: np.ndarray,
        record: StepRecord,
    ) -> None:
        """The core's books, then the compliant rows' (stored energy, dissipation, force)."""
        p = self.problem
        comp = self._index
        G = p.constraints[comp]
        d0 = -(G @ state.q + p.offset[comp])
        d1 = -(G @ q1 + p.offset[comp])
        U0, U1 = G @ state.v, G @ v1
        P = impulse[comp]
        work = 0.5 * P * (U0 + U1)
        stored0 = np.array([r.law.energy(float(x)) for r, x in zip(self.rows, d0, strict=True)])
        stored1 = np.array([r.law.energy(float(x)) for r, x in zip(self.rows, d1, strict=True)])
        self._work += float(work.sum())
        self._dissipated += float((-work - (stored1 - stored0)).sum())
        super()._commit(state, h, q1, v1, impulse, record)
        books = self.books
        books.stored.append(stored1)
        books.dissipated.append(self._dissipated)
        books.work.append(self._work)
        books.force.append(P / h)
        books.radius.append(self._radius.copy())
        books.compression.append(d1)

    def _engaged(self, state: StepperState) -> bool:
        """Some compliant row is compressed at the step start, or touches and closes."""
        p = self.problem
        comp = self._index
        gap = p.constraints[comp] @ state.q + p.offset[comp]
        closing = (gap <= self.gap_tolerance) & (p.constraints[comp] @ state.v < 0.0)
        return bool(np.any((gap < 0.0) | closing))

    def advance(self, state: StepperState, h: float | None = None) -> StepRecord:
        """One step as the parent's (localised touches), with the compliant rows (C1)-(C3).

        The moving rows are rebuilt first; while a compliant row is compressed the
        step is at most its substep; a compliant row's touch is localised (a
        free row whose gap would end below zero), its compression never is.
        """
        h = self.dt if h is None else float(h)
        self._refresh(state)
        if self._engaged(state):
            h = min(h, min(r.substep for r in self.rows))
        p = self.problem
        m = p.count
        record = StepRecord(state.t, state.t, np.zeros(m), np.zeros(m))
        touching = self._impacts(state, record)
        state.arrived = np.zeros(m, dtype=bool)
        U0 = p.normal_velocity(state.v)
        active = touching & (U0 <= max(self.velocity_tolerance, self.zeno_velocity))
        q1, v1, impulse = self._smooth(state.q, state.v, h, active, state.carried)
        gap0, gap1 = p.gap(state.q), p.gap(q1)
        level = np.minimum(gap0, 0.0)
        # a compressed compliant row is not a crossing; a free one that would end
        # compressed is localised at its touch
        held = active | (self._mask & (gap0 <= self.gap_tolerance))
        crossing = ~held & (gap1 - level < -self.gap_tolerance)
        if crossing.any():
            h, q1, v1, impulse, arrived = self._localise(
                state, h, held, gap0 - level, U0, (q1, v1, impulse), crossing, level
            )
            state.arrived = arrived & ~self._mask
            record.localised = True
        self._commit(state, h, q1, v1, impulse, record)
        self._check(state)
        return record

    # --- for the measures ---------------------------------------------------------------
    def final_books(self) -> dict[str, np.ndarray]:
        """The books as arrays over the step ends (``stored``: rows summed)."""
        b = self.books
        n = len(self.rows)
        return {
            "stored": np.array([float(s.sum()) for s in b.stored]),
            "dissipated": np.array(b.dissipated),
            "work": np.array(b.work),
            "force": np.array(b.force).reshape(len(b.force), n),
            "radius": np.array(b.radius).reshape(len(b.radius), n),
            "compression": np.array(b.compression).reshape(len(b.compression), n),
            "drift": b.drift.copy(),
        }
