"""The paper's massless body on the top of any ball dropped on the floor: criteria (i)-(ii).

Dimensionless (R, 1/c, the ball's mass).  The drop (:func:`~twoball.modal.floor.drop.run_drop`)
runs until the ball is known to have left the floor; the ball then flies freely
(its weight on the centre, no floor: it cannot come back within the flight, so
leaving the floor's rows out is exact) to the end of the window.  The top's
vertical motion ``u = top . q`` (the centre's height included: a body resting on
the top falls with the ball before the floor touch) is sampled at every step end,
its acceleration is the derivative of the sampled velocity (second order on the
steps), and the paper's criteria for a massless body (§3(a): the contact force
``u_tt + gamma`` crosses zero from above while the top moves up, and the body's
ballistic path is not caught again within the window;
:func:`~twoball.modal.liftoff.find_liftoff`) are applied to it, as
:func:`~twoball.modal.floor.restitution.free_vibration` does for the paper's start.

Times are reported after the ball's maximal compression (the paper's ``t_l``;
the drop's ``t_max_compression``), with the time after the floor touch beside.
Before the floor touch and until the first wave reaches the top, the top falls
freely with the body: the force is zero to rounding, and its sign changes there
come with a falling top (``u_t < 0``), which criterion (ii) refuses.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

from twoball._common.errors import NumericalError
from twoball.modal.floor.drop import DropResult, DropSettings, run_drop
from twoball.modal.floor.system import FloorSystem
from twoball.modal.liftoff import LiftoffResult, SampledPoleMotion, find_liftoff
from twoball.modal.nonsmooth import ContactProblem, MoreauJean

__all__ = ["MasslessDrop", "massless_liftoff"]


@dataclass(frozen=True, eq=False)
class MasslessDrop:
    """The drop and the massless body's lift-off from its top (dimensionless).

    Attributes
    ----------
    drop : DropResult
        The drop until the ball left the floor.
    result : LiftoffResult
        Criteria (i)-(ii) on the top's motion, times after the maximal compression.
    motion : SampledPoleMotion
        The top's u, u_t, u_tt (times after the maximal compression).
    t : ndarray
        Sample times after the floor touch.
    shift : float
        The maximal compression's time after the floor touch.
    interpolation : str
        ``splines`` (u, u_t, u_tt each through its own cubic spline), or
        ``hermite`` (one quintic) where the splines' re-contact search did not settle.
    """

    drop: DropResult
    result: LiftoffResult
    motion: SampledPoleMotion
    t: np.ndarray
    shift: float
    interpolation: str = "splines"


def _flight(system: FloorSystem, q: np.ndarray, v: np.ndarray, t0: float, t_end: float, dt: float):
    """The ball from (q, v) at t0 without the floor (its weight on the centre) to t_end."""
    p = system.problem

    def matrix(op: Any) -> Any:
        return op.diagonal if op.kind == "diagonal" else op.to_dense()

    free = ContactProblem.create(
        matrix(p.mass),
        matrix(p.damping),
        matrix(p.stiffness),
        p.load,
        np.zeros((0, p.dofs)),
        np.zeros(0),
    )
    return MoreauJean(free, dt).run(q, v, t_end, t0=t0)


def massless_liftoff(
    system: FloorSystem, settings: DropSettings, monitor: Any = None
) -> MasslessDrop:
    """Drop the ball of ``system`` and apply the massless body's criteria to its top.

    Parameters
    ----------
    system : FloorSystem
        The ball on the floor, without a body.
    settings : DropSettings
        Impact speed, gravity, step and window (the window is the criteria's too).
    monitor : Monitor, optional
        Told of every step.
    """
    drop = run_drop(
        system, settings, label="the drop (a massless body on the top)", monitor=monitor
    )
    tr = drop.trajectory
    t, q, v = tr.t, tr.q, tr.v
    if tr.t[-1] < settings.t_end * (1.0 - 1e-12) and drop.left:
        rest = _flight(system, tr.q_final, tr.v_final, float(tr.t[-1]), settings.t_end, settings.dt)
        t = np.concatenate([t, rest.t[1:]])
        q = np.concatenate([q, rest.q[1:]])
        v = np.concatenate([v, rest.v[1:]])
    keep = np.concatenate([[True], np.diff(t) > 0.1 * settings.dt])  # localised sub-steps out
    keep[-1] = True
    t, q, v = t[keep], q[keep], v[keep]
    top = system.ball.top
    u, u_t = q @ top, v @ top
    u_tt = np.gradient(u_t, t)
    shift = float(drop.t_max_compression)
    window = float(t[-1]) - shift
    try:
        motion = SampledPoleMotion(t - shift, u, u_t, u_tt, interpolation="splines")
        result = find_liftoff(motion, settings.gamma, t_end=window, horizon="window")
        how = "splines"
    except NumericalError:
        # the separate splines' u_tt is not the slope of their u_t: with the top's
        # high-frequency content (every finite-element mode, undamped) Newton's search
        # of a re-contact may not settle; one quintic through u, u_t, u_tt is consistent
        motion = SampledPoleMotion(t - shift, u, u_t, u_tt, interpolation="hermite")
        result = find_liftoff(motion, settings.gamma, t_end=window, horizon="window")
        how = "hermite"
    return MasslessDrop(drop, result, motion, t, shift, how)
