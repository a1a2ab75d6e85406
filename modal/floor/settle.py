"""A ball resting on the floor under gravity: the floor force and the contact area it settles to.

Dimensionless (R, 1/c, m2).  Started touching at rest (Z = 1), the ball sinks
under its weight and, with damping, settles: the floor then carries the weight
exactly, ``sum lambda = gamma`` (eq. (F1) at rest).  With the pressurised
operator the contact pressure on the flat part is the excess pressure P
(``-T (Delta_s + 2) u = 2 T / R`` where the membrane is flat), so the contact
area tends to ``m2 g / P = 2 pi gamma`` (units R^2) under refinement; the
discrete contact set lies between the caps through the outermost point in
contact and through the next point out.
"""

from __future__ import annotations

import math
import time
from dataclasses import dataclass

import numpy as np

from twoball.modal.floor.measure import contact_edge
from twoball.modal.floor.system import FloorSystem
from twoball.modal.nonsmooth import MoreauJean

__all__ = ["RestResult", "settle"]


@dataclass(frozen=True)
class RestResult:
    """A ball settled on the floor (dimensionless).

    Attributes
    ----------
    floor_force : float
        Total floor force of the last step (its impulse over its length).
    weight : float
        gamma (m2 = 1).
    contact_area : tuple of float
        ``(inner, outer)``: the caps ``2 pi (1 - cos psi)`` through the outermost
        point in contact and through the next point out (units R^2).
    edge_area : float
        The cap through the contact edge estimated between the points
        (:func:`~twoball.modal.floor.measure.contact_edge` from the free points
        next to the contact, ``skip=0``: the contact spans a few points), units R^2.
    pressure_area : float
        ``m2 g / P = 2 pi gamma`` in units R^2.
    residual_speed : float
        Largest |velocity| at the end.
    contact_points : int
        Floor points carrying a force.
    wall_s : float
    """

    floor_force: float
    weight: float
    contact_area: tuple[float, float]
    edge_area: float
    pressure_area: float
    residual_speed: float
    contact_points: int
    wall_s: float


def settle(system: FloorSystem, dt: float = 0.2, t_end: float = 800.0) -> RestResult:
    """Put the ball of ``system`` at rest on the floor, touching, and let it settle under gravity.

    The damping must be positive for the motion to die out (with the modal
    ratio D = 0.9 the residual speed falls by e every ~13 time units).
    """
    gamma = system.gamma
    ball = system.ball
    vibrating = ball.omega_squared[ball.omega_squared > 0.0]
    speed = gamma / math.sqrt(float(vibrating.min())) if vibrating.size else gamma
    stepper = MoreauJean(system.problem, dt, zeno_velocity=1e-4 * speed)
    q0, _ = system.falling(0.0)
    start = time.perf_counter()
    tr = stepper.run(q0, np.zeros_like(q0), t_end, keep_states=False)
    wall = time.perf_counter() - start
    h = tr.t[-1] - tr.t[-2]
    last = tr.impulse[-1][system.floor]
    inside = np.flatnonzero(last > 0.0)
    phi = ball.phi
    i = int(inside.min()) if inside.size else phi.size
    psi_in = math.pi - phi[i] if inside.size else 0.0
    psi_out = math.pi - phi[i - 1]
    gaps = system.floor_gaps(tr.q_final)
    # a resting contact spans a few points: the edge from the free points next to it
    power = 3.0 if ball.bending else 2.0
    psi_edge = math.pi - contact_edge(phi, gaps, 1e-10, skip=0, power=power)
    return RestResult(
        floor_force=float(last.sum() / h),
        weight=gamma,
        contact_area=(
            2.0 * math.pi * (1.0 - math.cos(psi_in)),
            2.0 * math.pi * (1.0 - math.cos(psi_out)),
        ),
        edge_area=2.0 * math.pi * (1.0 - math.cos(psi_edge)),
        pressure_area=2.0 * math.pi * gamma,
        residual_speed=float(np.max(np.abs(tr.v_final))),
        contact_points=int(inside.size),
        wall_s=wall,
    )
