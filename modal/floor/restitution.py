"""The paper's restitution-only model as a special case of the drop's machinery.

Dimensionless.  The paper's model (§3) starts at maximal compression: the
membrane truncated by the floor plane, ``u = F(phi)`` of eq. (3.10), at rest,
and then lets it vibrate freely -- the floor is gone and the ball's weight is
ignored -- while a massless body on the top feels gravity (criteria (i) and (ii),
:mod:`twoball.modal.liftoff`).  :func:`restitution_only` runs exactly that on
the drop's modes (:func:`~twoball.modal.balls.membrane.legendre_ball`) and the
drop's contact core with no constraint left, samples the top's motion at the
step ends and applies the same lift-off criteria.

The degree-1 content of F (``a_1 P_1``) is where the two membranes differ:

``anchored=True``
    degree 1 is a mode of the membrane about a centre that does not move, with
    the operator's own frequency: ``omega_1^2 = 2`` on the paper's operator (the
    paper's model, reproduced to O(dt^2)), 0 on the pressurised one.
``anchored=False``
    degree 1 is carried by the centre's height Z, as in the drop: ``Z(0) = a_1``,
    no force on Z.  On the pressurised operator this is the same motion as
    ``anchored=True`` (omega_1 = 0: a_1 stays put); on the paper's it differs at
    the top by ``a_1 (1 - cos(sqrt(2) t))``.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

from twoball.modal.balls.description import ModalBall
from twoball.modal.balls.membrane import legendre_ball
from twoball.modal.damping import ModalRatio, Rayleigh
from twoball.modal.filters import FilterKind, SpectralFilter, legendre_frequency
from twoball.modal.legendre import legendre_coefficients
from twoball.modal.liftoff import DEFAULT_T_END, LiftoffResult, SampledPoleMotion, find_liftoff
from twoball.modal.nonsmooth import ContactProblem, MoreauJean
from twoball.modal.stiffness import Stiffness

__all__ = [
    "BodyLiftoff",
    "RestitutionRun",
    "body_liftoff",
    "body_on_start",
    "free_vibration",
    "legendre_start",
    "restitution_only",
]


@dataclass(frozen=True, eq=False)
class RestitutionRun:
    """The top's motion of the restitution-only model and its lift-off (dimensionless).

    Attributes
    ----------
    result : LiftoffResult
        Criteria (i)-(ii) on the sampled motion.
    motion : SampledPoleMotion
        u, u_t, u_tt of the top at the step ends (cubic splines between them).
    """

    result: LiftoffResult
    motion: SampledPoleMotion


def legendre_start(
    ball: ModalBall, modes: int, phi_a: float, sigma: FilterKind = "lanczos"
) -> np.ndarray:
    """The paper's start ``u = F(phi)`` (eq. (3.10)) in the coordinates of a Legendre ball.

    The coefficients of F (:func:`~twoball.modal.legendre.legendre_coefficients`)
    filtered by sigma, eq. (3.16) (each degree weighted by its ``sqrt(n (n +
    1))``, as the closed form does); with the centre free, its height Z takes the
    degree-1 share ``a_1`` (the centre of mass's offset) and the modes the rest.
    """
    n = np.arange(modes + 1)
    a = legendre_coefficients(phi_a, modes) * SpectralFilter(sigma, modes)(legendre_frequency(n))
    if ball.centre is None:
        return a
    return np.concatenate([[a[1]], a[[0, *range(2, modes + 1)]]])


def free_vibration(
    ball: ModalBall, q0: np.ndarray, gamma: float, dt: float, t_end: float = DEFAULT_T_END
) -> RestitutionRun:
    """The ball from ``q0`` at rest, without floor or weight; the top's lift-off criteria.

    The contact core with no constraint steps the free vibration; the top's
    vertical motion (:attr:`~twoball.modal.balls.description.ModalBall.top`) is
    sampled at the step ends and criteria (i)-(ii) are applied to it with a
    massless body of weight ``gamma``.
    """
    masses, w2, decay, top = ball.masses, ball.omega_squared, ball.decay, ball.top
    problem = ContactProblem.create(
        masses, masses * decay, masses * w2, None, np.zeros((0, masses.size)), np.zeros(0)
    )
    tr = MoreauJean(problem, dt).run(q0, np.zeros(masses.size), t_end)
    acceleration = -(tr.v * decay + tr.q * w2)
    motion = SampledPoleMotion(
        tr.t, tr.q @ top, tr.v @ top, acceleration @ top, interpolation="splines"
    )
    return RestitutionRun(find_liftoff(motion, gamma, t_end=t_end, horizon="window"), motion)


def restitution_only(
    spectrum: Stiffness,
    law: ModalRatio | Rayleigh,
    modes: int,
    phi_a: float,
    gamma: float,
    dt: float,
    *,
    t_end: float = DEFAULT_T_END,
    anchored: bool = True,
    sigma: FilterKind = "lanczos",
) -> RestitutionRun:
    """Start the drop's membrane at ``u = F(phi)`` (eq. (3.10)) at rest, without floor or weight.

    Parameters
    ----------
    spectrum, law
        The ball's spectrum and damping law (as for the drop).
    modes : int
        Legendre degree N.
    phi_a : float
        Contact angle of the start [rad].
    gamma : float
        ``g / (R c^2)`` on the body resting on the top.
    dt : float
        Time step of the contact core (units 1/c).
    t_end : float
        Window of the lift-off search (default 4 pi).
    anchored : bool
        Degree 1 as a mode about a fixed centre (True) or carried by Z (False);
        see the module documentation.
    sigma : {"lanczos", "printed", "none"}
        Spectral filter of eq. (3.16) on the start's coefficients.
    """
    ball = legendre_ball(modes, spectrum, law, anchored=anchored)
    q0 = legendre_start(ball, modes, phi_a, sigma)
    return free_vibration(ball, q0, gamma, dt, t_end)


@dataclass(frozen=True, eq=False)
class BodyLiftoff:
    """A rigid body on the special case's ball: its last separation (dimensionless).

    Attributes
    ----------
    lifted : bool
        The body separated within the window.
    t_liftoff : float or None
        Its last separation in the window (units 1/c).
    v1 : float or None
        Its velocity there (units R c).
    contacts : int
        Separate contacts in the window.
    system : FloorSystem
    trajectory : Trajectory
    """

    lifted: bool
    t_liftoff: float | None
    v1: float | None
    contacts: int
    system: Any
    trajectory: Any


def body_on_start(
    ball: ModalBall,
    q0: np.ndarray,
    gamma: float,
    dt: float,
    body: Any,
    *,
    t_end: float = DEFAULT_T_END,
    monitor: Any = None,
    zeno_velocity: float | None = None,
) -> BodyLiftoff:
    """A rigid body resting on the ball's top, the ball released from ``q0`` at rest, no floor.

    The body (:class:`~twoball.modal.floor.system.BodyOnTop`, its ``gap``
    ignored) rests on the cap at rest, its weight on it alone; the floor rows
    are removed (``floor_system(..., floor=False)``) and the contact core runs
    to the window.  On an anchored membrane (degree 1 the membrane's own mode
    about a centre that does not move) this is the finite-mass model of
    :mod:`twoball.modal.contact`, reproduced to O(dt) at the impacts.
    ``zeno_velocity``: arrivals slower than it are held, not impacts (ends the
    endless chain of ever smaller bounces of ``e > 0``; the core's ``v_Z``).
    """
    from dataclasses import replace

    from twoball.modal.floor.measure import contact_intervals
    from twoball.modal.floor.system import floor_system

    # the body's cap on this ball (a row built for another layout is averaged again)
    cap = body.cap if body.cap.shape == (ball.modes,) else ball.cap_average(body.cap_angle)
    row = replace(body, cap=cap, gap=0.0)
    system = floor_system(ball, gamma, body=row, floor=False)
    q = np.zeros(system.problem.dofs)
    q[: ball.modes] = q0
    q[system.body_coordinate] = 1.0 + cap @ q0
    stepper = MoreauJean(system.problem, dt, zeno_velocity=zeno_velocity)
    tr = stepper.run(q, np.zeros(q.size), t_end, label="the body on the ball", monitor=monitor)
    intervals = contact_intervals(tr.t, tr.impulse[:, system.body_row], dt)
    if not intervals or intervals[-1].last + 1 >= tr.t.size - 1:
        return BodyLiftoff(False, None, None, len(intervals), system, tr)
    last = intervals[-1]
    k = last.last + 1
    v1 = float(tr.v[k, system.body_coordinate] + gamma * (tr.t[k] - last.end))
    return BodyLiftoff(True, last.end, v1, len(intervals), system, tr)


def body_liftoff(
    spectrum: Stiffness,
    law: ModalRatio | Rayleigh,
    modes: int,
    phi_a: float,
    gamma: float,
    dt: float,
    body: Any,
    *,
    t_end: float = DEFAULT_T_END,
    anchored: bool = True,
    sigma: FilterKind = "lanczos",
) -> BodyLiftoff:
    """The whole bounce's body row on the paper's special case: (3.10) at rest, no floor.

    The membrane on N Legendre modes starts at ``u = F(phi)`` (eq. (3.10),
    filtered as the closed form filters it) at rest (:func:`body_on_start`).
    ``anchored=True`` keeps degree 1 as the membrane's own mode about a centre
    that does not move: the finite-mass model of :mod:`twoball.modal.contact`
    (``twoball.liftoff(case, body=Body(mu))``).
    """
    from twoball.modal.nonsmooth.moreau_jean import ZENO_VELOCITY

    ball = legendre_ball(modes, spectrum, law, anchored=anchored)
    q0 = legendre_start(ball, modes, phi_a, sigma)
    zeno = ZENO_VELOCITY if body.restitution > 0.0 else None
    return body_on_start(ball, q0, gamma, dt, body, t_end=t_end, zeno_velocity=zeno)
