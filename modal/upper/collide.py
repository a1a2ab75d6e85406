"""Two identical balls colliding head-on in free space: the symmetric check of the ball body.

No floor, no gravity: the lower ball (its centre at 0, moving up at V) and an
identical ball above it (its centre at 2, touching, moving down at V) meet
through the rows (E3) of :mod:`twoball.modal.upper.system` (``rho = mu = tau =
1``), on the contact core (theta = 1/2, touches localised).  The exact
solution keeps the centre of mass at rest (no external force: the momentum
is exact in the scheme) and is symmetric under the reflection ``z -> 2 - z``:
the upper ball's centre mirrors the lower's, and its Legendre amplitude of
degree n is ``(-1)^n`` times the lower's (``P_n(-x) = (-1)^n P_n(x)``).  The
rows pair a point of the upper ball at polar angle psi with the lower ball's
at ``pi - psi`` (exactly so, not ``arcsin(sin psi)``), so the discrete problem
keeps the symmetry and the two responses are mirror images to rounding.

The energy: ``E + W_imp + W_damp = E_0`` to rounding at theta = 1/2 (the
books, eq. (MJ5)); the rows' impacts (Newton's e at the touching points,
default 0 as at the floor) lose the touching points' share, the model's and not
the scheme's, so with ``restitution=1`` the mechanical energy itself is kept.
After the separation the centres carry the rigid kinetic energy left; the
rest is the vibration the balls carry away (reported).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from twoball._common.errors import NumericalError, ParameterError
from twoball.modal.balls.description import ModalBall
from twoball.modal.nonsmooth import MoreauJean, Trajectory
from twoball.modal.upper.system import BallSystem, ball_system

__all__ = ["CollisionResult", "free_collision"]


@dataclass(frozen=True)
class CollisionResult:
    """The symmetric collision measured (dimensionless: the ball's own units).

    Attributes
    ----------
    separated : bool
        The balls moved apart for good within the window.
    contact_time : float or None
        First touch to the last row's release.
    velocities : tuple of float
        The lower and upper centres' velocities at the end.
    restitution : float
        ``(v_upper - v_lower) / (2 V)`` at the end.
    centre_of_mass : float
        Largest ``|Z_lower' + Z_upper'|`` over the run (0 exactly: the momentum).
    mirror : float
        Largest ``|q_upper - mirror(q_lower)|`` over the run, relative to the
        largest coordinate.
    energy_balance : float
        Largest ``|E - E_0 - works|`` over the run, relative to ``E_0``.
    impact_loss : float
        Energy lost at the rows' impacts, over ``E_0``.
    rigid_left : float
        The centres' kinetic energy at the end, over ``E_0``.
    vibration_left : float
        The balls' vibration energy at the end, over ``E_0``.
    trajectory : Trajectory
    system : BallSystem
    """

    separated: bool
    contact_time: float | None
    velocities: tuple[float, float]
    restitution: float
    centre_of_mass: float
    mirror: float
    energy_balance: float
    impact_loss: float
    rigid_left: float
    vibration_left: float
    trajectory: Trajectory
    system: BallSystem


def _mirror(ball: ModalBall) -> np.ndarray:
    """``(-1)^n`` of each coordinate of a Legendre ball (the centre: -1, about the contact)."""
    if ball.laplace is None:
        raise ParameterError("ball", "a ball with Legendre degrees (laplace)", ball.label)
    n = np.rint((-1.0 + np.sqrt(1.0 + 4.0 * ball.laplace)) / 2.0)
    sign = np.where(n % 2 == 0, 1.0, -1.0)
    sign[ball.centre] = -1.0
    return sign


def free_collision(
    ball: ModalBall,
    speed: float,
    *,
    reach: float = 1.0,
    dt: float = 0.005,
    t_end: float = 20.0,
    restitution: float = 0.0,
) -> CollisionResult:
    """Collide two copies of ``ball`` at ``+-speed`` in free space (module documentation).

    Parameters
    ----------
    ball : ModalBall
        A Legendre ball with a free centre (units of its own R, 1/c, m).
    speed : float
        V > 0 (units R c).
    reach : float
        Polar half-angle [rad] of the rows.
    dt, t_end : float
        Step and window (units 1/c).
    restitution : float
        Newton's e at the rows.
    """
    if not (math.isfinite(speed) and speed > 0.0):
        raise ParameterError("speed", "a finite number > 0", speed)
    system = ball_system(ball, ball, 0.0, 0.0, 1.0, 1.0, 1.0, reach, 0.0, floor=False, weight=False)
    p = system.problem
    # the rows pair psi with pi - psi exactly (the mirror of the lower point)
    body = system.top_ball
    from twoball.modal.upper.system import lower_rows

    theta = math.pi - body.psi
    W = lower_rows(ball, theta)
    rows = system.body_rows
    k = ball.modes
    p.constraints[rows, :k] = -W
    p.offset[rows] = np.cos(body.psi) - np.cos(theta)
    p.restitution[rows] = float(restitution)
    low, up = ball.centre, k + ball.centre
    q0 = np.zeros(p.dofs)
    v0 = np.zeros(p.dofs)
    q0[low], q0[up] = 0.0, 2.0
    v0[low], v0[up] = speed, -speed
    stepper = MoreauJean(p, dt)
    flags = {"apart": False}

    def stop(state, record) -> bool:  # noqa: ANN001
        flags["apart"] = bool(system.body_apart(state, record, stepper))
        return flags["apart"]

    tr = stepper.run(q0, v0, t_end, stop=stop, keep_states=True)
    sign = _mirror(ball)
    lower, upper = tr.q[:, :k], tr.q[:, k:]
    mirrored = sign * lower
    mirrored[:, ball.centre] = 2.0 - lower[:, ball.centre]
    scale = float(np.max(np.abs(lower)))
    mirror = float(np.max(np.abs(upper - mirrored))) / max(scale, 1e-300)
    e0 = float(tr.energy[0])
    balance = float(np.max(np.abs(tr.balance))) / e0
    carried = np.flatnonzero(tr.impulse[:, rows].sum(axis=1) > 0.0)
    if carried.size == 0:
        raise NumericalError("the balls never touched")
    contact = float(tr.t[carried[-1] + 1] - tr.t[carried[0]]) if flags["apart"] else None
    vl, vu = float(tr.v_final[low]), float(tr.v_final[up])
    rigid = 0.5 * (vl * vl + vu * vu)
    return CollisionResult(
        separated=flags["apart"],
        contact_time=contact,
        velocities=(vl, vu),
        restitution=(vu - vl) / (2.0 * speed),
        centre_of_mass=float(np.max(np.abs(tr.v[:, low] + tr.v[:, up]))),
        mirror=mirror,
        energy_balance=balance,
        impact_loss=-float(tr.impact_work[-1]) / e0,
        rigid_left=rigid / e0,
        vibration_left=(float(tr.energy[-1]) - rigid) / e0,
        trajectory=tr,
        system=system,
    )
