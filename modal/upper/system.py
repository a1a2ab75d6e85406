"""An elastic upper body in the drop's contact problem: the lumped body and the ball body.

Dimensionless (R, 1/c, m2 of the lower ball), as :mod:`twoball.modal.floor.system`,
whose floor rows (F1)-(F3) are kept unchanged.

The lumped body (:class:`LumpedSystem`)
    One coordinate s (the height of its lowest point, mass mu, weight ``-mu
    gamma``) and one row, as the rigid body's (B1)-(B2), but *compliant*: the
    row carries the body's own law (C1) of :mod:`twoball.modal.nonsmooth.compliant`
    instead of a rigid constraint with Newton's e12::

        mu s'' = -mu gamma - lambda,   lambda = max(0, k delta^p + c delta^r delta')   (E1)
        delta' = -(s' - b(a) . q'),   a = sqrt(f R* delta)                           (E2)

    with ``b(a)`` each coordinate's vertical displacement averaged over the
    cap of the contact disc of radius a (:meth:`ModalBall.cap_average
    <twoball.modal.balls.description.ModalBall.cap_average>`, half-angle
    ``arcsin(a / R)``): the load is spread over the lower ball's
    top by the disc, which grows with the compression (f = 2 for a flattened
    cap, 1 for Hertz; ``R* = R1 R2 / (R1 + R2)``).  Below a half-angle of
    :data:`SMALLEST_CAP` the row is the pole's (:attr:`ModalBall.top`).  The
    disc's half-angle is taken on a geometric grid of ratio :data:`CAP_RATIO`
    (each average computed once), so the row moves in small jumps; the
    compression stays continuous across them (the core's moving row).
The ball body (:class:`BallSystem`)
    The body's own :class:`~twoball.modal.balls.description.ModalBall` (its
    centre Z1, its deformation), rescaled to the lower ball's units (lengths
    by ``rho = R1 / R``, masses by ``mu``, frequencies by ``tau = c1 / c``),
    and one rigid unilateral row per point of its lower surface within
    ``reach`` of its south pole::

        g_j = (Z1 + rho cos(psi_j) + V1_j . q1) - (Z + cos(theta_j) + W_j . q) >= 0   (E3)

    between the body's point j (polar angle psi_j from its north pole, its
    floor row V1_j: the vertical displacement) and the lower ball's point of
    the same horizontal radius, ``sin(theta_j) = rho sin(psi_j)`` (its
    vertical row ``W_j = e_Z + cos(theta) u_r(theta) - sin(theta) u_phi(theta)``
    from the ball's samplers).  Both surfaces' contact disc is where the rows
    carry impulse.  Newton's e = 0 at these rows (as at the floor's points);
    gravity on both centres; the body's modes keep their own damping.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from twoball._common.errors import NumericalError, ParameterError
from twoball.modal.balls.description import ModalBall
from twoball.modal.floor.system import BodyOnTop, FloorSystem, floor_system
from twoball.modal.nonsmooth import ContactProblem
from twoball.modal.nonsmooth.compliant import CompliantMoreauJean, CompliantRow, PowerLaw

__all__ = [
    "CAP_RATIO",
    "SMALLEST_CAP",
    "BallOnTop",
    "BallSystem",
    "LumpedSystem",
    "ball_system",
    "lower_rows",
    "lumped_system",
]

#: Half-angle [rad] below which a lumped body loads the ball's pole.
SMALLEST_CAP = 1e-3
#: Ratio of the geometric grid of the contact disc's half-angles.
CAP_RATIO = 1.02
#: Largest half-angle [rad] of a lumped body's contact disc.
LARGEST_CAP = 1.2


class _DiscRows:
    """The lumped body's row for a compression: the cap of its disc, on a geometric grid."""

    def __init__(self, ball: ModalBall, rstar: float, factor: float) -> None:
        self.ball = ball
        self.rstar = rstar
        self.factor = factor
        self.pole = np.concatenate([-ball.top, [1.0]])
        self.cache: dict[int, np.ndarray] = {}

    def __call__(self, delta: float) -> tuple[np.ndarray, float]:
        a = math.sqrt(self.factor * self.rstar * delta) if delta > 0.0 else 0.0
        theta = math.asin(min(a, math.sin(LARGEST_CAP)))
        if theta < SMALLEST_CAP:
            return self.pole, a
        k = int(round(math.log(theta / SMALLEST_CAP) / math.log(CAP_RATIO)))
        row = self.cache.get(k)
        if row is None:
            angle = min(SMALLEST_CAP * CAP_RATIO**k, LARGEST_CAP)
            row = np.concatenate([-self.ball.cap_average(angle), [1.0]])
            self.cache[k] = row
        return row, a


def _apart(
    problem: ContactProblem,
    rows: slice,
    state: Any,
    record: Any,
    rigid: np.ndarray,
    bounds: list[tuple[np.ndarray, np.ndarray, np.ndarray]],
    relative: float,
) -> bool:
    """The body rows cannot close again: no impulse, moving apart, beyond any vibration.

    ``rigid``: the mask of the coordinates whose motion is rigid (the centres);
    ``bounds``: per ball (coordinates, masses, omega^2 of its deformation) for
    ``|G_d q_d| <= b sqrt(2 E)``; ``relative``: the centres' relative velocity.
    """
    if record.impact_impulse[rows].any() or record.step_impulse[rows].any():
        return False
    if relative <= 0.0:
        return False
    G = problem.constraints[rows]
    gap = G @ state.q + problem.offset[rows]
    reach = np.zeros(G.shape[0])
    for idx, masses, w2 in bounds:
        if idx.size == 0:
            continue
        if np.any(w2 <= 0.0):
            return False
        energy = 0.5 * float(masses @ (state.v[idx] ** 2 + w2 * state.q[idx] ** 2))
        b = np.sqrt((G[:, idx] ** 2) @ (1.0 / (masses * w2)))
        reach += b * math.sqrt(2.0 * energy)
    deformation = G[:, ~rigid] @ state.q[~rigid]
    return bool(np.all(gap - deformation - reach > 0.0))


@dataclass(frozen=True, eq=False)
class LumpedSystem(FloorSystem):
    """The drop's system with a lumped elastic body on the ball (E1)-(E2).

    Attributes (beside :class:`~twoball.modal.floor.system.FloorSystem`'s)
    ----------
    law : PowerLaw
        The body's law (C1) in the run's units.
    rstar : float
        ``R*`` of the contact disc (units R).
    disc_factor : float
        f of ``a^2 = f R* delta``.
    substep : float
        The longest step while the body is compressed (units 1/c).
    """

    law: PowerLaw | None = None
    rstar: float = 0.0
    disc_factor: float = 2.0
    substep: float = 0.0

    def integrator(self, dt: float, **core: Any) -> CompliantMoreauJean:
        """The compliant Moreau-Jean steps, the body's row moving with its disc."""
        assert self.law is not None
        rows = _DiscRows(self.ball, self.rstar, self.disc_factor)
        row = CompliantRow(self.body_row, self.law, min(self.substep, dt), rows)
        return CompliantMoreauJean(self.problem, dt, [row], **core)

    def body_apart(self, state: Any, record: Any, stepper: Any) -> bool | None:
        """Apart when the row (its free gap: the pole's, with its drift) cannot close."""
        rigid = np.zeros(self.problem.dofs, dtype=bool)
        rigid[[self.centre, self.body_coordinate]] = True
        d = np.flatnonzero(~rigid)
        bounds = [(d, self.ball.masses[d], self.ball.omega_squared[d])]
        relative = float(state.v[self.body_coordinate] - state.v[self.centre])
        return _apart(stepper.problem, self.body_rows, state, record, rigid, bounds, relative)

    def body_measures(self, stepper: Any, result: Any) -> tuple[Any, dict[str, float]]:
        """The body's own measures and energy books (:mod:`twoball.modal.upper.measure`)."""
        from twoball.modal.upper.measure import lumped_measures

        return lumped_measures(self, stepper, result)


@dataclass(frozen=True, eq=False)
class BallOnTop:
    """A ball body above the lower ball (dimensionless, in the lower ball's units).

    Attributes
    ----------
    mass : float
        mu = m1 / m2.
    upper : ModalBall
        The body in its own units (R1, 1/c1, m1), without its samplers.
    rho, tau : float
        ``R1 / R`` and ``c1 / c``.
    gap : float
        Height of its lowest point above the lower ball's top at the first floor
        touch (units R).
    psi, theta : ndarray
        The rows' polar angles on the body (from its north pole) and on the
        lower ball.
    points : ndarray of int
        The body's floor points used (indices into ``upper.phi``).
    weight : bool
    speed : float, optional
        Its falling speed at the first floor touch (None: the ball's).
    cap : ndarray
        The lower ball's pole row (the drop's bound of the cap, unused here).
    restitution : float
        Newton's e at its rows (0).
    """

    mass: float
    upper: ModalBall
    rho: float
    tau: float
    gap: float
    psi: np.ndarray
    theta: np.ndarray
    points: np.ndarray
    weight: bool = True
    speed: float | None = None
    cap: np.ndarray = field(default_factory=lambda: np.zeros(0))
    restitution: float = 0.0

    @property
    def radii(self) -> np.ndarray:
        """Horizontal radius of each row (units R): ``rho sin(psi)``."""
        return self.rho * np.sin(self.psi)

    @property
    def cap_angle(self) -> float:
        """The widest half-angle [rad] of its rows on the lower ball (the exports' cap)."""
        return float(np.max(self.theta))


@dataclass(frozen=True, eq=False)
class BallSystem(FloorSystem):
    """The drop's system with a ball body on the lower ball (E3): both balls' coordinates."""

    @property
    def top_ball(self) -> BallOnTop:
        """The body (a :class:`BallOnTop`)."""
        assert isinstance(self.body, BallOnTop)
        return self.body

    @property
    def body_slice(self) -> slice:
        """The body's coordinates in q (after the lower ball's)."""
        return slice(self.ball.modes, self.problem.dofs)

    @property
    def body_coordinate(self) -> int:
        """Index in q of the body's centre Z1."""
        upper = self.top_ball.upper
        if upper.centre is None:
            raise NumericalError("BallSystem: the body's centre is held")
        return self.ball.modes + upper.centre

    @property
    def body_rows(self) -> slice:
        """Rows (E3) in G, after the floor's."""
        return slice(self.floor.stop, self.problem.count)

    def body_deformation(self) -> np.ndarray:
        """Indices in q of the body's deformation."""
        return self.ball.modes + self.top_ball.upper.deformation

    def falling(self, v0: float, height: float = 1.0) -> tuple[np.ndarray, np.ndarray]:
        """Both undeformed; the body's centre ``1 + gap + rho`` above the ball's."""
        q = np.zeros(self.problem.dofs)
        v = np.zeros(self.problem.dofs)
        body = self.top_ball
        q[self.centre] = height
        v[self.centre] = -abs(v0)
        q[self.body_coordinate] = height + 1.0 + body.gap + body.rho
        v[self.body_coordinate] = -(abs(v0) if body.speed is None else body.speed)
        return q, v

    def body_gap(self, q: np.ndarray) -> np.ndarray:
        """The smallest gap (E3) of the body's rows for states q (last axis), units R."""
        G = self.problem.constraints[self.body_rows]
        return np.min(q @ G.T + self.problem.offset[self.body_rows], axis=-1)

    def energies(self, q: np.ndarray, v: np.ndarray) -> dict[str, np.ndarray]:
        """The drop's parts (the body's centre as its height) and ``body_vibration``.

        ``body_vibration``: the body's deformation, kinetic, elastic and gas.
        """
        out = super().energies(q, v)
        q, v = np.atleast_2d(q), np.atleast_2d(v)
        d = self.body_deformation()
        p = self.problem
        masses = p.mass.diagonal[d]
        stiffness = p.stiffness.diagonal[d]
        out["body_vibration"] = 0.5 * (v[:, d] ** 2) @ masses + 0.5 * (q[:, d] ** 2) @ stiffness
        return out

    def body_apart(self, state: Any, record: Any, stepper: Any) -> bool | None:
        """Apart when no row can close: centres separating beyond both balls' vibration."""
        rigid = np.zeros(self.problem.dofs, dtype=bool)
        rigid[[self.centre, self.body_coordinate]] = True
        lower = np.flatnonzero(~rigid[: self.ball.modes])
        upper = self.body_deformation()
        p = self.problem
        bounds = [
            (lower, p.mass.diagonal[lower], p.stiffness.diagonal[lower] / p.mass.diagonal[lower]),
            (upper, p.mass.diagonal[upper], p.stiffness.diagonal[upper] / p.mass.diagonal[upper]),
        ]
        relative = float(state.v[self.body_coordinate] - state.v[self.centre])
        return _apart(p, self.body_rows, state, record, rigid, bounds, relative)

    def body_measures(self, stepper: Any, result: Any) -> tuple[Any, dict[str, float]]:
        """The body's own measures and energy books (:mod:`twoball.modal.upper.measure`)."""
        from twoball.modal.upper.measure import ball_measures

        return ball_measures(self, stepper, result)


def lumped_system(
    ball: ModalBall,
    gamma: float,
    restitution: float,
    mass: float,
    law: PowerLaw,
    rstar: float,
    disc_factor: float,
    substep: float,
    gap: float = 0.0,
    speed: float | None = None,
) -> LumpedSystem:
    """(F1)-(F3) with the lumped body (E1)-(E2) on ``ball`` (dimensionless).

    Parameters
    ----------
    ball : ModalBall
    gamma : float
        ``g / (R c^2)``.
    restitution : float
        Newton's e at the floor's points.
    mass : float
        mu.
    law : PowerLaw
        The body's law in units of R, 1/c, m2.
    rstar, disc_factor : float
        The disc ``a^2 = disc_factor rstar delta`` (units R).
    substep : float
        The longest step while it is compressed (units 1/c).
    gap, speed : float
        As :class:`~twoball.modal.floor.system.BodyOnTop`.
    """
    if not (substep > 0.0 and math.isfinite(substep)):
        raise ParameterError("substep", "a step > 0", substep)
    body = BodyOnTop(mass, ball.top.copy(), 0.0, 0.0, gap, True, speed)
    base = floor_system(ball, gamma, restitution, body)
    return LumpedSystem(
        base.ball,
        base.problem,
        base.gamma,
        base.body,
        base.floor_rows,
        law=law,
        rstar=float(rstar),
        disc_factor=float(disc_factor),
        substep=float(substep),
    )


def lower_rows(ball: ModalBall, theta: np.ndarray) -> np.ndarray:
    """Vertical rows of the ball's points at polar angles ``theta`` [rad], (len(theta), K).

    ``W = e_Z + cos(theta) u_r - sin(theta) u_phi`` per unit of each coordinate
    (the translation's entry from :attr:`ModalBall.centre`); equal to
    :attr:`ModalBall.floor_rows` at the floor points (tested).
    """
    theta = np.asarray(theta, dtype=float).reshape(-1)
    radial = ball.modes_at(theta)
    tangential = ball.tangential_at(theta)
    rows = np.cos(theta)[:, None] * radial - np.sin(theta)[:, None] * tangential
    if ball.centre is not None:
        rows[:, ball.centre] = 1.0
    return rows


def ball_system(
    lower: ModalBall,
    upper: ModalBall,
    gamma: float,
    restitution: float,
    mass: float,
    rho: float,
    tau: float,
    reach: float,
    gap: float = 0.0,
    speed: float | None = None,
    *,
    floor: bool = True,
    weight: bool = True,
) -> BallSystem:
    """The lower ball on the floor (F1)-(F3) with a ball body through rows (E3).

    Parameters
    ----------
    lower, upper : ModalBall
        The lower ball (units R, 1/c, m2) and the body (its own units R1, 1/c1, m1).
    gamma : float
        ``g / (R c^2)``.
    restitution : float
        Newton's e at the floor's points.
    mass, rho, tau : float
        ``mu = m1 / m2``, ``R1 / R``, ``c1 / c``.
    reach : float
        Polar half-angle [rad] around the body's south pole of its points with a row.
    gap, speed : float
        As :class:`~twoball.modal.floor.system.BodyOnTop`.
    floor : bool
        False: no floor rows and no weight of the lower ball (two balls in free
        space; with ``gamma = 0`` neither has weight).
    weight : bool
        The body feels gravity.
    """
    if upper.centre is None or lower.centre is None:
        raise ParameterError("ball", "balls with a free centre", upper.label)
    for name, value in (("mass_ratio", mass), ("rho", rho), ("tau", tau)):
        if not (math.isfinite(value) and value > 0.0):
            raise ParameterError(name, "a finite number > 0", value)
    chosen = np.flatnonzero(upper.phi >= math.pi - reach)
    if chosen.size == 0:
        raise ParameterError("reach", "wide enough to hold a point of the body's surface", reach)
    psi = upper.phi[chosen]
    radius = rho * np.sin(psi)
    if np.any(radius >= 1.0):
        raise ParameterError("reach", "within the lower ball's radius (rho sin(reach) < 1)", reach)
    theta = np.arcsin(radius)
    W = lower_rows(lower, theta)
    V = upper.floor_rows[chosen]
    k2, k1 = lower.modes, upper.modes
    masses = np.concatenate([lower.masses, mass * upper.masses])
    stiffness = np.concatenate(
        [lower.masses * lower.omega_squared, mass * upper.masses * upper.omega_squared * tau**2]
    )
    damping = np.concatenate([lower.masses * lower.decay, mass * upper.masses * upper.decay * tau])
    load = np.zeros(k2 + k1)
    if floor:
        load[lower.centre] = -float(gamma) * lower.masses[lower.centre]
    if weight:
        load[k2 + upper.centre] = -float(gamma) * mass
    body_G = np.column_stack([-W, V])
    body_offset = rho * np.cos(psi) - np.cos(theta)
    if floor:
        G = np.vstack([np.column_stack([lower.floor_rows, np.zeros((lower.points, k1))]), body_G])
        offset = np.concatenate([np.cos(lower.phi), body_offset])
        e = np.concatenate([np.full(lower.points, float(restitution)), np.zeros(psi.size)])
    else:
        G, offset, e = body_G, body_offset, np.zeros(psi.size)
    problem = ContactProblem.create(masses, damping, stiffness, load, G, offset, e)
    body = BallOnTop(
        mass=float(mass),
        upper=upper.without_samplers(),
        rho=float(rho),
        tau=float(tau),
        gap=float(gap),
        psi=psi,
        theta=theta,
        points=chosen,
        weight=weight,
        speed=speed,
        cap=lower.top.copy(),
    )
    if body.gap < 0.0 or not math.isfinite(body.gap):
        raise ParameterError("gap", "a finite number >= 0", gap)
    return BallSystem(lower, problem, float(gamma), body, None if floor else 0)  # type: ignore[arg-type]
