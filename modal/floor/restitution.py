"""The paper's restitution-only model as a special case of the drop's machinery.

Dimensionless.  The paper's model (§3) starts at maximal compression: the
membrane truncated by the floor plane, ``u = F(phi)`` of eq. (3.10), at rest,
and then lets it vibrate freely -- the floor is gone and the ball's weight is
ignored -- while a massless body on the top feels gravity (criteria (i) and (ii),
:mod:`twoball.modal.liftoff`).  :func:`restitution_only` runs exactly that on
the drop's modes (:func:`~twoball.modal.floor.ball.legendre_ball`) and the
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
from twoball.modal.damping import ModalRatio, Rayleigh
from twoball.modal.filters import FilterKind, SpectralFilter, legendre_frequency
from twoball.modal.floor.ball import legendre_ball
from twoball.modal.legendre import legendre_coefficients
from twoball.modal.liftoff import DEFAULT_T_END, LiftoffResult, SampledPoleMotion, find_liftoff
from twoball.modal.nonsmooth import ContactProblem, MoreauJean
from twoball.modal.stiffness import Stiffness

__all__ = ["BodyLiftoff", "RestitutionRun", "body_liftoff", "restitution_only"]


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
        Legendre degree N (the series is not filtered: sigma = 1).
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
        Spectral filter of eq. (3.16) on the start's coefficients (weighted by
        each degree's ``sqrt(n (n + 1))``, as the closed form does).
    """
    ball = legendre_ball(modes, spectrum, law, anchored=anchored)
    n = np.arange(modes + 1)
    a = legendre_coefficients(phi_a, modes) * SpectralFilter(sigma, modes)(legendre_frequency(n))
    if anchored:
        masses, w2, decay, top, q0 = ball.masses, ball.omega_squared, ball.decay, ball.top, a
    else:  # Z first, offset by the centre's share a_1 of F; no force acts on it
        masses = np.concatenate([[1.0], ball.masses])
        w2 = np.concatenate([[0.0], ball.omega_squared])
        decay = np.concatenate([[0.0], ball.decay])
        top = np.concatenate([[1.0], ball.top])
        q0 = np.concatenate([[a[1]], a[[0, *range(2, modes + 1)]]])
    problem = ContactProblem.create(
        masses, masses * decay, masses * w2, None, np.zeros((0, masses.size)), np.zeros(0)
    )
    tr = MoreauJean(problem, dt).run(q0, np.zeros(masses.size), t_end)
    acceleration = -(tr.v * decay + tr.q * w2)
    motion = SampledPoleMotion(
        tr.t, tr.q @ top, tr.v @ top, acceleration @ top, interpolation="splines"
    )
    return RestitutionRun(find_liftoff(motion, gamma, t_end=t_end, horizon="window"), motion)


@dataclass(frozen=True, eq=False)
class BodyLiftoff:
    """A rigid body on the special case's membrane: its last separation (dimensionless).

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

    The membrane starts at ``u = F(phi)`` (eq. (3.10), filtered as the closed form
    filters it) at rest, the body (:class:`~twoball.modal.floor.system.BodyOnTop`,
    its ``gap`` ignored) resting on the cap at rest, its weight on it alone; the
    floor rows are removed (``floor_system(..., floor=False)``) and the contact
    core runs to the window.  ``anchored=True`` keeps degree 1 as the membrane's
    own mode about a centre that does not move: the finite-mass model of
    :mod:`twoball.modal.contact` (``twoball.liftoff(case, body=Body(mu))``),
    reproduced to O(dt^2).
    """
    from dataclasses import replace

    from twoball.modal.floor.measure import contact_intervals
    from twoball.modal.floor.system import floor_system

    ball = legendre_ball(modes, spectrum, law, anchored=anchored)
    cap = ball.cap_average(body.cap_angle)
    row = replace(body, cap=cap, gap=0.0)
    system = floor_system(ball, gamma, body=row, floor=False, centre=not anchored)
    n = np.arange(modes + 1)
    a = legendre_coefficients(phi_a, modes) * SpectralFilter(sigma, modes)(legendre_frequency(n))
    q0 = np.zeros(system.problem.dofs)
    if anchored:
        q0[system.membrane] = a
    else:  # Z carries degree 1
        q0[system.centre] = a[1]
        q0[system.membrane] = a[[0, *range(2, modes + 1)]]
    q0[system.body_coordinate] = (
        q0[system.centre] * (not anchored) + 1.0 + cap @ q0[system.membrane]
    )
    tr = MoreauJean(system.problem, dt).run(q0, np.zeros(q0.size), t_end)
    intervals = contact_intervals(tr.t, tr.impulse[:, system.body_row], dt)
    if not intervals or intervals[-1].last + 1 >= tr.t.size - 1:
        return BodyLiftoff(False, None, None, len(intervals), system, tr)
    last = intervals[-1]
    k = last.last + 1
    v1 = float(tr.v[k, system.body_coordinate] + gamma * (tr.t[k] - last.end))
    return BodyLiftoff(True, last.end, v1, len(intervals), system, tr)
