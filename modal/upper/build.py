"""An elastic upper body's system from SI: its law or its ball in the lower ball's units.

The lower ball's case fixes the run's units (R, 1/c, m2).  A lumped body's
law (:class:`~twoball.modal.upper.laws.ContactLaw`) is evaluated against the
lower ball's curvature (``R*``), its dashpot calibrated with its own mass
``m1 = mu m2`` on a rigid floor, and scaled (:meth:`PowerLaw.scaled`); its
substep is its own contact time on a rigid floor at the case's |v0| over
:attr:`LumpedBody.steps`.  A ball body's case is resolved as a drop's
(:func:`~twoball.modal.floor.inputs.resolve_drop`: its excess pressure, the
adiabatic gas, the pressurised operator, its damping law), described by its
ball and set above the lower ball with ``rho = R1 / R``, ``tau = c1 / c`` and
``mu = m1 / m2`` (its own mass: a ball body's mass is its ball's).
"""

from __future__ import annotations

from typing import Any

from twoball.modal.balls.description import ModalBall
from twoball.modal.parameters import Case
from twoball.modal.upper.options import BallBody, LumpedBody
from twoball.modal.upper.system import BallSystem, LumpedSystem, ball_system, lumped_system

__all__ = ["ball_body_description", "elastic_system", "lumped_inputs"]


def lumped_inputs(case: Case, mass: float, body: LumpedBody) -> dict[str, Any]:
    """The lumped body's law, disc and substep in the units of ``case`` (R, 1/c, m2 = ``mass``).

    Returns
    -------
    dict
        ``law`` (PowerLaw), ``rstar`` (units R), ``disc_factor``, ``substep`` (units
        1/c), and in SI ``m1`` [kg], ``floor_time`` [s] (its contact time on a
        rigid floor at the case's |v0|).
    """
    m1 = body.mass_ratio * mass
    law = body.law
    si = law.power_law(m1, partner=case.radius)
    floor_time = law.contact_time(m1, case.v0)
    return {
        "law": si.scaled(case.radius, 1.0 / case.wave_speed, mass),
        "rstar": law.effective_radius(case.radius) / case.radius,
        "disc_factor": law.disc_factor,
        "substep": floor_time * case.wave_speed / body.steps,
        "m1": m1,
        "floor_time": floor_time,
    }


def ball_body_description(body: BallBody, monitor: Any = None) -> tuple[Case, ModalBall, float]:
    """The ball body's case as it drops, its modal description (own units) and its mass [kg]."""
    from twoball.modal.floor.inputs import resolve_drop
    from twoball.modal.floor.options import Drop

    inputs = resolve_drop(body.case, Drop(), body.damping)
    upper = body.ball.describe(inputs.case, monitor)
    return inputs.case, upper, float(body.ball.mass(inputs.case))


def elastic_system(
    ball: ModalBall,
    case: Case,
    mass: float,
    body: Any,
    gap: float,
    restitution: float,
    monitor: Any = None,
) -> LumpedSystem | BallSystem:
    """The drop's system with ``body`` (a LumpedBody or a BallBody) on ``ball``.

    Parameters
    ----------
    ball : ModalBall
        The lower ball (units of ``case``).
    case : Case
        The lower ball as it drops (SI; its R, c, |v0|, g).
    mass : float
        The lower ball's mass m2 [kg].
    body : LumpedBody or BallBody
    gap : float
        ``Delta x / R``.
    restitution : float
        Newton's e at the floor's points.
    """
    if isinstance(body, LumpedBody):
        inputs = lumped_inputs(case, mass, body)
        return lumped_system(
            ball,
            case.gamma,
            restitution,
            body.mass_ratio,
            inputs["law"],
            inputs["rstar"],
            inputs["disc_factor"],
            inputs["substep"],
            gap,
        )
    own, upper, m1 = ball_body_description(body, monitor)
    return ball_system(
        ball,
        upper,
        case.gamma,
        restitution,
        m1 / mass,
        own.radius / case.radius,
        own.wave_speed / case.wave_speed,
        body.reach,
        gap,
    )
