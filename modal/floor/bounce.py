"""The drop and the whole two-ball bounce in SI: the problem resolved, then run and reported.

Two steps, so that a caller can look at the work before it is done (Siconos's
model apart from its simulation):

:func:`bounce_problem`
    Resolves a case, a drop, a lower ball (any :class:`~twoball.modal.balls.Ball`),
    an upper body or a Table 1 pair, the time step and the window into a
    :class:`BounceProblem`: every refusal of the inputs happens here, before any
    work, and its :meth:`~BounceProblem.work` says how large the run will be (for
    a budget at the edge).
:func:`simulate`
    Builds the ball's modal description, the contact problem (the floor's rows
    and the body's, :mod:`twoball.modal.floor.system`), runs the drop
    (:func:`~twoball.modal.floor.drop.run_drop`), measures it and returns the SI
    :class:`~twoball.modal.floor.report.BounceReport` with its warnings, notes
    and, with a body, the lumped baselines of §1(b) for the same drop.

Both take an optional monitor (:class:`~twoball._common.monitor.Monitor`) and no
other runtime policy.  docs/bounce.rst and docs/whole_bounce.rst explain the
model.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace
from typing import Any

from twoball._common.errors import NumericalError, ParameterError
from twoball._common.monitor import Monitor
from twoball.modal.balls.membrane import LegendreBall
from twoball.modal.balls.protocol import Ball, check_ball
from twoball.modal.floor.inputs import (
    DEFAULT_WINDOW,
    DropModel,
    WholeBody,
    check_drop_case,
    drop_times,
    resolve_body,
    resolve_drop,
    resolve_pair,
)
from twoball.modal.floor.options import Drop
from twoball.modal.floor.report import BounceReport
from twoball.modal.parameters import Case

__all__ = [
    "ARTEFACT_SECTION",
    "CAVEATS",
    "E12_FAR_BELOW",
    "LARGE_GAP_SECTION",
    "MIN_CONTACT_POINTS",
    "OVERLAP_NOTE",
    "BounceProblem",
    "bounce_problem",
    "simulate",
]

#: Fewest floor points across the largest contact before the result is flagged.
MIN_CONTACT_POINTS = 6
#: ``e12_effective`` below this fraction of the body's Newton e12 is flagged: the
#: collision on the ball kept less than half the restitution the pair measures, so
#: v1 is far from the ICM with Newton's e12 (docs/whole_bounce.rst, large gaps:
#: e12_effective 0.1-0.5 against Table 1's 0.56-0.89).
E12_FAR_BELOW = 0.5
#: Where the docs measure what depends on the radial membrane's degree-1 artefact.
ARTEFACT_SECTION = "docs/whole_bounce.rst, 'The degree-1 artefact, and what depends on it'"
#: Where the docs say why the large gaps stay below the ICM.
LARGE_GAP_SECTION = (
    "docs/whole_bounce.rst, 'What the whole bounce reproduces, and what it does not'"
)
#: The note of a whole bounce whose contacts overlap (e12_effective undefined).
OVERLAP_NOTE = (
    "the body touched while the ball was still on the floor (the contacts overlap): "
    "e12_effective (eq. (2.4)) and the ICM (2.5) with this run's e2 and e12 are not defined"
)
#: One line per caveat of :func:`answer_caveats`, for tables and figures.
CAVEATS: dict[str, str] = {
    "artefact": "first struck by the radial membrane's degree-1 precursor: the answer "
    f"depends on that artefact (see {ARTEFACT_SECTION})",
    "e12_low": f"e12_effective below {E12_FAR_BELOW:g} x the body's Newton e12 (see "
    f"{LARGE_GAP_SECTION})",
    "overlap": "the contacts overlap: e12_effective and the ICM with the run's e2 and e12 "
    "are not defined",
}


@dataclass(frozen=True)
class BounceProblem:
    """A drop or a whole bounce, resolved and checked, not yet run.

    Attributes
    ----------
    case : Case
        The ball as it drops (SI): the impact speed, the excess pressure, the gas,
        the membrane operator and the damping law in use.
    drop : Drop
        The drop's options as given.
    ball : Ball
        The lower ball and its discretisation.
    inputs : DropModel
        The resolved drop (:func:`~twoball.modal.floor.inputs.resolve_drop`).
    whole : WholeBody or None
        The upper body, resolved (None: the ball alone).
    dt, t_end : float
        The time step and the window in units of 1/c.
    notes, warnings : tuple of str
        How the inputs were read, and what the reader must know (unit slips).
    slips : tuple of str
        The unit slips among the warnings (:func:`twoball.modal.guards.case_warnings`).
    """

    case: Case
    drop: Drop
    ball: Ball
    inputs: DropModel
    whole: WholeBody | None
    dt: float
    t_end: float
    notes: tuple[str, ...] = ()
    warnings: tuple[str, ...] = ()
    slips: tuple[str, ...] = ()

    @property
    def gap(self) -> float:
        """``Delta x / R``."""
        return self.drop.gap / self.case.radius

    @property
    def v0(self) -> float:
        """The impact speed ``|v0| / (R c)``."""
        return self.case.v0 / self.case.scalings.velocity

    @property
    def runs(self) -> int:
        """Drops the run makes: 2 for a body that is not a Table 1 pair (the ball alone
        again, for the baselines' e2), else 1."""
        whole = self.whole
        return 2 if whole is not None and whole.pair is None and whole.kind == "rigid" else 1

    @property
    def mass_kg(self) -> float:
        """The lower ball's mass [kg] (the run's unit of mass)."""
        return float(self.ball.mass(self.case))

    def work(self) -> dict[str, Any]:
        """How large the run is, for a budget before it starts.

        ``size`` (coordinates, floor points; None when the ball cannot say before it
        is built), ``dense`` (its build solves a dense eigenproblem), ``dt`` and
        ``t_end`` (units 1/c), ``body``, ``gap`` (units R), ``v0`` (dimensionless),
        ``runs``.
        """
        return {
            "size": self.ball.size(self.case),
            "dense": bool(getattr(self.ball, "dense", False)),
            "dt": self.dt,
            "t_end": self.t_end,
            "body": self.whole is not None,
            "gap": self.gap,
            "v0": self.v0,
            "runs": self.runs,
        }


def bounce_problem(
    case: Case | None = None,
    drop: Drop | None = None,
    *,
    ball: Any = None,
    body: Any = None,
    pair: str | None = None,
    dt: float | None = None,
    t_end: float | None = None,
    damping: Any = None,
) -> BounceProblem:
    """Resolve and check a drop (with ``body`` or ``pair``: the whole bounce), in SI.

    Parameters
    ----------
    case : Case, optional
        The ball and its impact speed (default the basketball, or the pair's lower ball).
    drop : Drop, optional
        Drop height, gas, floor restitution, membrane operator, gap (default ``Drop()``).
    ball : Ball, optional
        The lower ball and its discretisation (default the membrane on N = 192
        Legendre modes, :class:`~twoball.modal.balls.membrane.LegendreBall`).
    body : Body, optional
        The upper body (``mass_ratio``, ``contact_radius``, ``restitution``).
    pair : str, optional
        A Table 1 pair (refused with ``body``).
    dt, t_end : float, optional
        Time step and window [s] (defaults :data:`~twoball.modal.floor.inputs.DEFAULT_DT`
        and :data:`~twoball.modal.floor.inputs.DEFAULT_WINDOW` over c, plus the gap's fall).
    damping : ModalRatio or Rayleigh, optional
        The damping law (default the case's own).

    Raises
    ------
    ParameterError
        Naming the argument and its valid range.
    """
    if case is not None and not isinstance(case, Case):
        raise ParameterError("case", "a twoball.Case", type(case).__name__)
    ball = LegendreBall() if ball is None else check_ball(ball)
    case, body, chosen = resolve_pair(case, body, pair)
    case = Case.preset("basketball") if case is None else case
    drop = Drop() if drop is None else drop
    if not isinstance(drop, Drop):
        raise ParameterError("drop", "a twoball.Drop", type(drop).__name__)
    whole = resolve_body(case, body, chosen, drop)
    check_drop_case(case, drop)
    given_v0_note = case.v0_note
    inputs = resolve_drop(
        case,
        drop,
        damping,
        membrane_ball=ball.kind == "membrane",
        pressurised=bool(getattr(ball, "pressurised", True)),
    )
    from twoball.modal.guards import case_warnings

    # inputs far from any ball first (unit slips), then the model's
    warnings = case_warnings(
        inputs.case,
        drop_height=drop.fall(inputs.case.radius),
        gap=None if whole is None else drop.gap,
    )
    slips = tuple(warnings)
    warnings += inputs.warnings
    step, window = drop_times(inputs.case, dt, t_end, drop.gap / inputs.case.radius)
    # how the case was read (a negative v0: the paper's sign), then the drop's own notes
    notes = tuple(n for n in (given_v0_note,) if n) + inputs.notes
    if whole is not None:
        notes += whole.notes
    return BounceProblem(
        inputs.case, drop, ball, inputs, whole, step, window, notes, tuple(warnings), slips
    )


def simulate(
    problem: BounceProblem, monitor: Monitor | None = None, *, baselines: bool = True
) -> BounceReport:
    """Run a resolved drop or whole bounce and report it in SI.

    Parameters
    ----------
    problem : BounceProblem
        From :func:`bounce_problem`.
    monitor : Monitor, optional
        Told of the ball's build and of every step (it may stop the run by raising).
    baselines : bool
        With a body, also the lumped models of §1(b) for the same drop (default);
        False leaves them out (``baselines`` None: a fit's many runs need none).
    """
    from twoball.modal.floor.drop import DropSettings, run_drop
    from twoball.modal.floor.system import BodyOnTop, floor_system

    case, drop, whole = problem.case, problem.drop, problem.whole
    ball = problem.ball.describe(case, monitor)
    if ball.centre is None or ball.points == 0:
        raise ParameterError(
            "ball", "a ball with a free centre and floor points for the drop", ball.label
        )
    row = None
    if whole is not None and whole.kind == "rigid":
        cap = ball.cap_average(whole.cap_angle)
        b = whole.body
        row = BodyOnTop(b.mass_ratio, cap, whole.cap_angle, b.restitution, problem.gap)
    system = floor_system(ball, case.gamma, drop.floor_restitution, row)
    if whole is not None and whole.kind != "rigid":  # its own law or its own ball
        from twoball.modal.upper.build import elastic_system

        mass = problem.mass_kg
        system = elastic_system(
            ball, case, mass, whole.body, problem.gap, drop.floor_restitution, monitor
        )
    label = "the whole bounce" if whole is not None else "the drop"
    settings = DropSettings(problem.v0, case.gamma, problem.dt, problem.t_end)
    result = run_drop(system, settings, label=label, monitor=monitor)
    warnings = list(problem.warnings) + _warnings(result, ball, problem.dt)
    summary = getattr(problem.ball, "summary", None)
    model = {
        "resolution": problem.ball.label,
        "floor_points": ball.points,
        "modes": ball.modes - 1,
        **(summary(case) if summary is not None else {}),
        "gas": problem.inputs.gas,
        "damping": _damping_block(case, problem.inputs.law),
        "floor_restitution": drop.floor_restitution,
        "scheme": "moreau-jean",
        "dt_s": problem.dt / case.wave_speed,
        "t_end_s": problem.t_end / case.wave_speed,
    }
    extra: dict[str, Any] = {}
    notes = problem.notes
    if whole is not None:
        warnings += _body_warnings(result, whole, ball)
        caveats, said, remarks = answer_caveats(result, whole, problem.ball.kind, case)
        warnings += said
        notes += remarks
        extra["caveats"] = caveats
        lumped = None
        if baselines:
            lumped = _baselines(case, drop, whole, problem.inputs, result, monitor, problem.mass_kg)
        extra |= {"whole": whole, "baselines": lumped}
    return BounceReport(
        case,
        drop,
        result,
        problem.ball.backend,
        model,
        problem.inputs.pressure,
        problem.mass_kg,
        tuple(warnings),
        notes,
        **extra,
    )


def _damping_block(case: Case, law: Any) -> dict[str, Any]:
    """The damping law of the drop for the JSON, in SI.

    The modal ratio: ``{"law": "modal", "ratio": D}``.  Rayleigh's law as
    :meth:`twoball.Case.rayleigh_dict` gives it: ``alpha_1_s`` [1/s] and
    ``beta_s`` [s] (the decay of a mode of angular frequency omega [rad/s] is
    ``alpha + beta omega^2``), the same law in units of c as ``alpha_c_units``
    (``alpha / c``) and ``beta_c_units`` (``beta c``), and ``fitted`` (True when
    fitted to D at :meth:`~twoball.modal.stiffness.Stiffness.fit_band`).
    """
    from twoball.modal.damping import Rayleigh

    if not isinstance(law, Rayleigh):
        return law.as_dict()
    si = case.rayleigh_dict()
    return {
        "law": law.name,
        "alpha_1_s": si["alpha_1_s"],
        "beta_s": si["beta_s"],
        "alpha_c_units": si["alpha"],
        "beta_c_units": si["beta"],
        "fitted": si["fitted"],
    }


def _baselines(
    case: Case,
    drop: Drop,
    whole: WholeBody,
    inputs: DropModel,
    result: Any,
    monitor: Monitor | None,
    mass: float | None = None,
) -> dict[str, Any] | None:
    """The lumped models of §1(b) for the same drop (SI), with their inputs.

    A Table 1 pair takes its own inputs (Table 1's mu, e2, e12, the pressure
    rule); any other body takes the ball's e2 as this solver gives it for the
    ball alone (from the run itself when the ball left the floor before the body
    touched, else from a drop of the ball alone) and Newton's e12 given.
    ``mass``: the ball's [kg] (default the membrane's ``2 pi R P / c^2``).  A
    ball without pressure (a solid) has no pressure rule for the springs: None.
    """
    from twoball.modal.lumped.baselines import baselines, body_inputs, pair_inputs

    if whole.pair is None and whole.kind != "rigid":
        return None  # no e12 to give them: an elastic body's is the run's output
    if whole.pair is not None:
        inputs_ = pair_inputs(whole.pair)
    elif inputs.pressure is None:
        return None
    else:
        e2, where = _e2_alone(result, monitor)
        mass = inputs.mass if mass is None else mass
        inputs_ = body_inputs(
            whole.body.mass_ratio * mass,
            mass,
            case.radius,
            inputs.pressure,
            whole.contact_radius,
            e2,
            whole.body.restitution,
            f"e2 = {e2:.4g} of this solver's ball alone ({where}), e12 = Newton's given",
        )
    return baselines(inputs_, case.v0, drop.gap, case.g)


def _e2_alone(result: Any, monitor: Monitor | None) -> tuple[float, str]:
    """The solver's e2 of the ball alone: the run's floor release if the body came later."""
    body = result.body
    if body is not None and body.sequence == "independent" and result.e2 is not None:
        return float(result.e2), "the floor release of this run, before the body touched"
    from twoball.modal.floor.drop import run_drop
    from twoball.modal.floor.system import floor_system

    system = result.system
    alone = floor_system(system.ball, system.gamma, float(system.problem.restitution[0]))
    # the ball alone is a reference: its own default window, whatever window the run had
    settings = replace(result.settings, t_end=max(result.settings.t_end, DEFAULT_WINDOW))
    label = "the ball alone (the baselines' e2)"
    run = run_drop(alone, settings, label=label, monitor=monitor)
    if run.e2 is None:
        raise NumericalError("the ball alone did not leave the floor within the window")
    return float(run.e2), "a drop of the ball alone at the same resolution"


def _warnings(result: Any, ball: Any, dt: float) -> list[str]:
    """Accuracy warnings of a drop: not left, too few floor points, too coarse a step."""
    out = []
    if not result.left:
        out.append(
            "the ball has not left the floor within the window (contact time, v2 and e2 are "
            "not defined; raise t_end)"
        )
    inside = int((ball.phi >= result.phi_a_extreme).sum())
    if inside < MIN_CONTACT_POINTS:
        out.append(
            f"the largest contact holds {inside} floor points (< {MIN_CONTACT_POINTS}): refine "
            "(modes, or elements) for its angle and time"
        )
    if result.contact_time is not None and dt > result.contact_time / 200.0:
        out.append(
            f"the time step is {result.contact_time / dt:.0f}th of the contact time: "
            "take a smaller dt for 1e-3"
        )
    return out


def _body_warnings(result: Any, whole: WholeBody, ball: Any) -> list[str]:
    """Warnings of the whole bounce: not apart within the window, a cap too small for the points."""
    out = []
    body = result.body
    if body is not None and not body.touched:
        out.append("the body never touched the ball within the window (raise t_end)")
    elif body is not None and not body.left:
        out.append(
            "the body and the ball have not moved apart for good within the window (v1, "
            "t_liftoff_s and e12_effective are not defined; raise t_end)"
        )
    spacing = (math.pi / 2.0) / ball.points
    if whole.cap_angle < 2.0 * spacing:
        out.append(
            f"the contact cap's half-angle {whole.cap_angle:.3g} rad spans fewer than two "
            f"spacings of the ball's points ({spacing:.3g} rad): refine (modes, or elements)"
        )
    return out


def newton_e12(whole: WholeBody) -> float | None:
    """The body's Newton e12: a rigid body's restitution, else its Table 1 pair's (None)."""
    if whole.kind == "rigid":
        return float(whole.body.restitution)
    return None if whole.pair is None else float(whole.pair.e12)


def answer_caveats(
    result: Any, whole: WholeBody, ball_kind: str, case: Case
) -> tuple[tuple[str, ...], list[str], tuple[str, ...]]:
    """What the whole bounce's answer is, beside its numbers: (tags, warnings, notes).

    ``artefact``: on the radial-only membrane (``ball_kind`` "membrane") the body's first
    impulsive contact came before the wave from the floor can reach the top, at
    ``pi / c`` (unit wave speed, eq. (3.9)): it was struck by the top's degree-1
    precursor (the top accelerates at ``-2 F / m2`` at the first floor force), so
    v1, v2 and t_l depend on that artefact.  A shell, a solid or a thick ball moves
    its translation as material motion: none there.  ``e12_low``: ``e12_effective``
    (eq. (2.4)) below :data:`E12_FAR_BELOW` times the body's Newton e12.
    ``overlap``: the floor contact was still on when the body first touched, so
    ``e12_effective`` and the ICM with the run's own coefficients are not defined
    (a note, not a warning: the numbers are still the model's).
    """
    body = result.body
    tags: list[str] = []
    warnings: list[str] = []
    notes: list[str] = []
    if body is None or not body.touched:
        return (), [], ()
    first = body.intervals[0].start if body.intervals else None
    if ball_kind == "membrane" and first is not None and first < math.pi:
        tags.append("artefact")
        warnings.append(
            f"the body was first struck at {first / case.wave_speed * 1e3:.3g} ms, before the "
            f"wave from the floor can reach the top (pi / c = "
            f"{math.pi / case.wave_speed * 1e3:.3g} ms): by the radial membrane's degree-1 "
            "precursor, so v1, v2 and t_l depend on that artefact (measured: v1 by up to "
            "0.25 |v0| for a tennis ball on the basketball, under 1 % for the light bodies); "
            f"see {ARTEFACT_SECTION}"
        )
    e12, newton = body.e12_effective, newton_e12(whole)
    if e12 is not None and newton is not None and e12 < E12_FAR_BELOW * newton:
        tags.append("e12_low")
        warnings.append(
            f"e12_effective = {e12:.3g} is below half the body's Newton e12 = {newton:g}: "
            "the collision on the ball loses most of its energy into the ball's waves, so v1 "
            "stays far below the ICM with Newton's e12 (the measured large-gap rebounds follow "
            f"it; this model does not); see {LARGE_GAP_SECTION}"
        )
    if body.left and body.sequence == "overlapping":
        tags.append("overlap")
        notes.append(OVERLAP_NOTE)
    return tuple(tags), warnings, tuple(notes)
