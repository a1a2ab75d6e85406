"""The lower ball on a rigid floor as one contact problem for the nonsmooth core.

Dimensionless (R, 1/c, m2).  Coordinates ``q``: those of the ball
(:class:`~twoball.modal.balls.description.ModalBall`: masses ``m_k``, decays
``d_k``, frequencies ``omega_k``, the rigid translation among them as the
coordinate ``centre`` whose value is the centre of mass's height Z), then, with
an upper body, its height s.

Equations (the contact core's (N1)-(N3), :mod:`twoball.modal.nonsmooth`)::

    m_k (q_k'' + d_k q_k' + omega_k^2 q_k) = -gamma [k = centre] + sum_i lambda_i V_ik  (F1-F2)
    g_i = cos(phi_i) + V_i . q >= 0,  lambda_i >= 0,  lambda_i g_i = 0                 (F3)

with ``V_ik`` the vertical displacement of floor point i per unit of coordinate
k (:attr:`ModalBall.floor_rows`).  For the radial membranes ``q = (Z, a_1, ...,
a_K)`` and ``V_i = (1, cos(phi_i) S_ik)``: the material point of polar angle
phi_i sits at distance ``R (1 + u)`` from the centre along its radius, so its
height is ``Z + (1 + u) cos(phi_i)``, linear in q and exact.  Gravity, uniform
over the ball, acts on the centre of mass only (its load on a deformation is the
deformation's centre-of-mass motion, zero).  At an impact Newton's law (N3)
with restitution e holds at each floor point (default e = 0: the floor stops
the arriving membrane).

The upper body (:class:`BodyOnTop`) is one more coordinate, the height s of its
lowest point above the floor (mass mu = m1 / m2, its weight ``-mu gamma``), and
one more row, the gap between it and the ball's top averaged over the contact
cap of half-angle theta::

    mu s'' = -mu gamma - Lambda                                           (B1)
    g_B = s - 1 - b . q >= 0,  Lambda >= 0,  Lambda g_B = 0              (B2)

with ``b_k`` coordinate k's vertical displacement averaged over the cap
(:meth:`ModalBall.cap_average`; for the membranes ``(1, <P_n>_cap)``: the cap
sits at ``Z + 1 + <u>_cap`` to first order in the slope, eq. (C3) of
:mod:`twoball.modal.contact` with the centre free), and Newton's law with
restitution e12 at its impacts.  :func:`floor_system` keeps the layout in
:class:`FloorSystem`: the floor rows first, then the body's.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from twoball._common.errors import NumericalError, ParameterError
from twoball.modal.balls.description import ModalBall
from twoball.modal.nonsmooth import ContactProblem, MoreauJean

__all__ = ["BodyOnTop", "FloorSystem", "floor_system", "release_delay"]


def release_delay(tau: float, v0: float, gamma: float) -> tuple[float, float]:
    """Gap and falling speed at the ball's floor touch of a body released ``tau`` later.

    Both start at rest, touching; the ball is let go first, the body ``tau``
    later.  When the ball touches the floor at ``|v0|`` the body has fallen for
    ``tau`` less: it is ``|v0| tau - gamma tau^2 / 2`` higher than the ball's
    top and falls at ``|v0| - gamma tau`` (dimensionless: units R, 1/c, R c).

    Parameters
    ----------
    tau : float
        The body's release after the ball's, in [0, |v0| / gamma] (units 1/c).
    v0 : float
        The ball's impact speed ``|v0| / (R c)`` > 0.
    gamma : float
        ``g / (R c^2)`` >= 0.

    Returns
    -------
    gap, speed : float
        For :class:`BodyOnTop` (``gap``, ``speed``).

    Examples
    --------
    >>> release_delay(2.0, 0.5, 0.125)  # 1 - 0.25 higher, 0.5 - 0.25 slower
    (0.75, 0.25)
    """
    tau, v0, gamma = float(tau), abs(float(v0)), float(gamma)
    if not (math.isfinite(tau) and tau >= 0.0 and gamma * tau <= v0):
        raise ParameterError("tau", "a delay in [0, |v0| / g] (the body still falls)", tau)
    return v0 * tau - 0.5 * gamma * tau * tau, v0 - gamma * tau


@dataclass(frozen=True, eq=False)
class BodyOnTop:
    """A rigid upper body resting on (or falling onto) the ball's top (dimensionless).

    Attributes
    ----------
    mass : float
        mu = m1 / m2 > 0.
    cap : ndarray, shape (K,)
        ``b_k``: each coordinate's vertical displacement averaged over the contact
        cap (:meth:`~twoball.modal.balls.description.ModalBall.cap_average`).
    cap_angle : float
        Half-angle theta of the cap [rad] (``arcsin(a / R)``).
    restitution : float
        Newton's e12 in [0, 1] at the body's impacts.
    gap : float
        Height of the body's lowest point above the ball's top at the first
        floor touch, ``Delta x / R`` >= 0.
    weight : bool
        The body feels gravity (default True; False for the paper's special case
        in which only the massless criteria see g).
    speed : float, optional
        The body's falling speed at the first floor touch, ``|v| / (R c)`` >= 0
        (None: the ball's ``|v0|``, both released together).  A body released a
        time tau after the ball falls ``g tau`` slower and starts ``|v0| tau - g
        tau^2 / 2`` higher (:func:`release_delay`).
    """

    mass: float
    cap: np.ndarray
    cap_angle: float
    restitution: float = 0.0
    gap: float = 0.0
    weight: bool = True
    speed: float | None = None

    def __post_init__(self) -> None:
        if not (math.isfinite(self.mass) and self.mass > 0.0):
            raise ParameterError("mass_ratio", "a number > 0 for a body on the ball", self.mass)
        if not (math.isfinite(self.gap) and self.gap >= 0.0):
            raise ParameterError("gap", "a finite number >= 0", self.gap)
        if self.speed is not None and not (math.isfinite(self.speed) and self.speed >= 0.0):
            raise ParameterError("speed", "a finite number >= 0 (units R c)", self.speed)
        if not np.all(np.isfinite(self.cap)):
            raise NumericalError("BodyOnTop: the cap averages are not finite")


@dataclass(frozen=True, eq=False)
class FloorSystem:
    """The contact problem of a ball on the floor and where each part sits in q.

    Attributes
    ----------
    ball : ModalBall
    problem : ContactProblem
        M, C, K diagonal; rows of G: the floor points (ascending phi), then the body's.
    gamma : float
        ``g / (R c^2)``.
    body : BodyOnTop, optional
    floor_rows : int, optional
        0 in the paper's special case (no floor rows); None: every floor point.
    """

    ball: ModalBall
    problem: ContactProblem
    gamma: float
    body: BodyOnTop | None = None
    floor_rows: int | None = None

    @property
    def centre(self) -> int:
        """Index of the centre of mass's height Z in q (the ball's translation)."""
        if self.ball.centre is None:
            raise NumericalError("FloorSystem: the ball's centre is held (no coordinate Z)")
        return self.ball.centre

    @property
    def body_coordinate(self) -> int:
        """Index of the body's height s in q (after the ball's coordinates)."""
        return self.ball.modes

    @property
    def body_row(self) -> int:
        """Row of the body's constraint (B2) in G (after the floor rows)."""
        return self.floor.stop

    @property
    def body_rows(self) -> slice:
        """Rows of the body's constraints in G: the one row (B2) here (an elastic ball
        body has several: :mod:`twoball.modal.upper.system`)."""
        return slice(self.body_row, self.body_row + 1)

    def integrator(self, dt: float, **core: object) -> MoreauJean:
        """The contact core's steps for this system (a compliant body overrides it)."""
        return MoreauJean(self.problem, dt, **core)  # type: ignore[arg-type]

    def body_apart(self, state: object, record: object, stepper: object) -> bool | None:
        """Whether an elastic body has moved apart for good (None: the drop's own rule)."""
        return None

    def body_measures(self, stepper: object, result: object) -> tuple[object, dict] | None:
        """An elastic body's own measures and energy books (None: a rigid body has none)."""
        return None

    @property
    def body_mass(self) -> float:
        """mu (0 without a body)."""
        return 0.0 if self.body is None else self.body.mass

    @property
    def membrane(self) -> np.ndarray | slice:
        """Indices in q of the ball's deformation (its coordinates but the translation)."""
        centre, k = self.ball.centre, self.ball.modes
        if centre == 0:
            return slice(1, k)
        return slice(0, k) if centre is None else self.ball.deformation

    @property
    def floor(self) -> slice:
        """Rows of the floor constraints in G (none in the paper's special case)."""
        return slice(0, self.ball.points if self.floor_rows is None else self.floor_rows)

    def falling(self, v0: float, height: float = 1.0) -> tuple[np.ndarray, np.ndarray]:
        """Undeformed state, the centre at ``height`` (1: the pole touching), falling at v0.

        A body starts its gap above the ball's top, falling at the same speed
        (or at its own :attr:`BodyOnTop.speed`).
        """
        q = np.zeros(self.problem.dofs)
        v = np.zeros(self.problem.dofs)
        q[self.centre] = height  # a translation of the undeformed ball
        v[self.centre] = -abs(v0)
        if self.body is not None:
            q[self.body_coordinate] = height + 1.0 + self.body.gap
            speed = abs(v0) if self.body.speed is None else self.body.speed
            v[self.body_coordinate] = -speed
        return q, v

    def body_gap(self, q: np.ndarray) -> np.ndarray:
        """Gap (B2) of the body for states q (last axis), units R."""
        if self.body is None:
            raise NumericalError("FloorSystem: no body")
        return q @ self.problem.constraints[self.body_row] + self.problem.offset[self.body_row]

    def floor_gaps(self, q: np.ndarray) -> np.ndarray:
        """Gaps (F3) of the floor points for states q (last axis), dimensionless."""
        G = self.problem.constraints[self.floor]
        return q @ G.T + self.problem.offset[self.floor]

    def energies(self, q: np.ndarray, v: np.ndarray) -> dict[str, np.ndarray]:
        """Energy parts of states (rows of q, v), in units of ``m2 (R c)^2``.

        ``rigid_kinetic`` 1/2 Z'^2, ``membrane_kinetic`` 1/2 sum m_k a_k'^2 over
        the deformation, ``membrane_elastic`` 1/2 sum m_k (omega_k^2 - gas_k)
        a_k^2 (negative parts: the pressurised breathing mode without its gas),
        ``gas`` 1/2 sum m_k gas_k a_k^2 and ``gravity`` gamma Z (from the floor
        level).  The names say membrane for any ball: its vibration.
        """
        q = np.atleast_2d(q)
        v = np.atleast_2d(v)
        b = self.ball
        d = self.membrane
        a, da = q[:, d], v[:, d]
        masses, w2, gas = b.masses[d], b.omega_squared[d], b.gas_squared[d]
        c = self.centre
        out = {
            "rigid_kinetic": 0.5 * b.masses[c] * v[:, c] ** 2,
            "membrane_kinetic": 0.5 * (da**2) @ masses,
            "membrane_elastic": 0.5 * (a**2) @ (masses * (w2 - gas)),
            "gas": 0.5 * (a**2) @ (masses * gas),
            "gravity": self.gamma * q[:, c],
        }
        if self.body is not None:
            s, ds = q[:, self.body_coordinate], v[:, self.body_coordinate]
            out["body_kinetic"] = 0.5 * self.body.mass * ds**2
            weight = self.gamma if self.body.weight else 0.0
            out["body_gravity"] = self.body.mass * weight * s
        return out


def floor_system(
    ball: ModalBall,
    gamma: float,
    restitution: float = 0.0,
    body: BodyOnTop | None = None,
    *,
    floor: bool = True,
) -> FloorSystem:
    """Assemble (F1)-(F3), and (B1)-(B2) with a body, under gravity ``gamma`` (dimensionless).

    Parameters
    ----------
    ball : ModalBall
    gamma : float
        ``g / (R c^2)`` >= 0.
    restitution : float
        Newton's e at every floor point, in [0, 1].
    body : BodyOnTop, optional
        The upper body: one more coordinate and one more row.
    floor : bool
        False: the paper's special case (§3, eq. (3.10)): no floor rows and no
        weight of the ball (only the body feels g).  A ball whose centre is held
        (``ball.centre is None``, degree 1 a mode of the membrane) has no weight
        to carry either: the paper's model and :mod:`twoball.modal.contact`.
    """
    masses = ball.masses
    stiffness = ball.masses * ball.omega_squared
    damping = ball.masses * ball.decay
    load = np.zeros(masses.size)
    if floor and ball.centre is not None:
        load[ball.centre] = -float(gamma) * ball.masses[ball.centre]
    if floor:
        G, offset = ball.floor_rows, np.cos(ball.phi)
        e = np.full(offset.size, float(restitution))
    else:
        G, offset, e = np.zeros((0, masses.size)), np.zeros(0), np.zeros(0)
    rows = G.shape[0]
    if body is not None:
        if body.cap.shape != (ball.modes,):
            raise NumericalError("floor_system: the body's cap needs one average per coordinate")
        weight = float(gamma) if body.weight else 0.0
        masses = np.append(masses, body.mass)
        stiffness = np.append(stiffness, 0.0)
        damping = np.append(damping, 0.0)
        load = np.append(load, -body.mass * weight)
        G = np.column_stack([G, np.zeros(rows)])
        G = np.vstack([G, np.concatenate([-body.cap, [1.0]])])
        offset = np.append(offset, -1.0)
        e = np.append(e, body.restitution)
    problem = ContactProblem.create(masses, damping, stiffness, load, G, offset, e)
    return FloorSystem(ball, problem, float(gamma), body, None if floor else 0)
