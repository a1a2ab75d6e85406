"""``twoball.liftoff``: the lift-off of one case, in SI, by the solver given.

The command line (``twoball liftoff``) calls exactly this function, so the same
inputs give bit-identical numbers in Python and in a shell.  The solver object
says how (:mod:`twoball._solvers`): the closed-form series, modal superposition
or generalized-alpha on finite elements for the paper's massless body, and the
nonsmooth steps of :class:`~twoball.MoreauJean` for a body of finite mass.
Here are the verb, its refusals before work (the budget) and the monitor that
watches the work (time limit, interrupts, progress).
"""

from __future__ import annotations

import time as clock
from dataclasses import replace
from typing import Any

from twoball._common.budget import timed
from twoball._common.errors import ParameterError
from twoball._common.keywords import checked
from twoball._common.progress import Step, check_progress, silent
from twoball.modal.parameters import Case
from twoball.modal.report import LiftoffReport

__all__ = ["liftoff"]


@checked
@timed
def liftoff(
    case: Case | None = None,
    *,
    solver: Any = None,
    body: Any = None,
    damping: Any = None,
    progress: Step | None = None,
) -> LiftoffReport | Any:
    """Lift-off time and velocity of the body on the ball, in SI.

    Parameters
    ----------
    case : Case, optional
        The impact; default ``Case.preset("basketball")``.
    solver : ClosedForm, Superposition, GeneralizedAlpha or MoreauJean, optional
        How: the closed-form Legendre series, eqs. (3.12)-(3.16)
        (:class:`~twoball.ClosedForm`, the default without a body of finite
        mass), modal superposition or generalized-alpha on finite elements
        (:class:`~twoball.Superposition`, :class:`~twoball.GeneralizedAlpha`),
        or the nonsmooth steps of a body of finite mass on a ball
        (:class:`~twoball.MoreauJean`, the default with one).  Each carries its
        own options: the filter of eq. (3.16), the re-contact horizon, the
        window, the mesh, the eigen route, the time step, the ball.
    body : Body, optional
        An upper body in unilateral contact (docs/contact.rst,
        :class:`~twoball.Body`): mass ratio mu > 0 steps its contacts; mu = 0 is
        the massless body on its contact cap (criteria (i)-(ii) on the cap's
        mean motion).  Default: the massless body of the paper on the pole.
    damping : ModalRatio or Rayleigh, optional
        The damping law (default the case's: the paper's ratio D on every mode,
        eq. (3.14), or its ``rayleigh``); :class:`~twoball.Rayleigh` in SI
        (alpha [1/s], beta [s]; ``Rayleigh()`` fitted to D).
    progress : callable, optional
        Called with a short text as each stage starts (a :class:`~twoball.Reporter`).

    Returns
    -------
    LiftoffReport
        ``t_liftoff_s``, ``v_liftoff_m_s``, ``ratio``, ``case`` (with
        ``phi_a_source``), ``notes``, ``warnings``; ``as_dict()`` for JSON.  With
        ``body`` a ContactReport (the same properties, plus every contact event).

    Examples
    --------
    >>> import twoball
    >>> report = twoball.liftoff(twoball.Case.preset("basketball"))
    >>> round(report.t_liftoff_s * 1e3, 4), round(report.v_liftoff_m_s, 4)
    (9.8825, 3.8322)
    >>> fe = twoball.liftoff(solver=twoball.Superposition("axisym"))
    >>> abs(fe.t_liftoff_s / report.t_liftoff_s - 1) < 1e-3
    True
    >>> twoball.liftoff(body=twoball.Body(mass_ratio=0.1)).lifted
    True
    """
    from twoball._solvers import ClosedForm, GeneralizedAlpha, MoreauJean, Superposition

    check_progress(progress)
    case = Case.preset("basketball") if case is None else case
    if not isinstance(case, Case):
        raise ParameterError("case", "a twoball.Case", type(case).__name__)
    body = _check_body(body)
    massive = body is not None and body.mass_ratio > 0.0
    if solver is None:
        solver = MoreauJean() if massive else ClosedForm()
    kinds = (ClosedForm, Superposition, GeneralizedAlpha, MoreauJean)
    if not isinstance(solver, kinds):
        valid = "a twoball.ClosedForm, Superposition, GeneralizedAlpha or MoreauJean"
        raise ParameterError("solver", valid, solver)
    from twoball.modal.damping import with_damping

    case = with_damping(case, damping)
    if isinstance(solver, MoreauJean):
        if body is None and solver.ball is not None:  # the ball dropped, the body massless
            report = _dropped(case, solver, progress)
        elif not massive:
            valid = (
                "a body of mass ratio > 0 with twoball.MoreauJean (it steps the body's "
                "contacts; the massless body: ClosedForm or Superposition, or a ball given to "
                "MoreauJean without a body: the ball dropped on the floor)"
            )
            raise ParameterError("body", valid, None if body is None else body.mass_ratio)
        else:
            report = _stepped(case, body, solver, progress)
    elif massive:
        valid = "twoball.MoreauJean for a body of finite mass (its contacts are stepped)"
        raise ParameterError("solver", valid, type(solver).__name__)
    elif body is not None:  # the massless body on its cap
        report = _cap_criteria(case, body, solver, progress)
    elif isinstance(solver, ClosedForm):
        report = _closed_form(case, solver, progress)
    else:
        report = fem_liftoff(case, solver, progress)
    from twoball._common.provenance import block

    arguments: dict[str, Any] = {"solver": solver.as_dict()}
    if body is not None:
        arguments["body"] = body.as_dict()
    if damping is not None:
        arguments["damping"] = damping.as_dict()
    return replace(report, provenance=block(case, "twoball.liftoff", arguments))


def _dropped(case: Case, solver: Any, progress: Step | None) -> LiftoffReport:
    """Any ball dropped on the floor, the paper's massless body on its top (criteria (i)-(ii)).

    The drop of :func:`twoball.bounce` (its window, step and ball) with the top's
    motion sampled to the window's end (:mod:`twoball.modal.floor.massless`);
    times after the ball's maximal compression.
    """
    from twoball._common.watch import Watch
    from twoball._costs import check_bounce_cost
    from twoball.modal.floor.bounce import bounce_problem
    from twoball.modal.floor.drop import DropSettings
    from twoball.modal.floor.massless import massless_liftoff
    from twoball.modal.floor.system import floor_system

    if solver.sigma is not None:
        valid = "left out for a dropped ball (it starts undeformed: nothing to filter)"
        raise ParameterError("sigma", valid, solver.sigma)
    problem = bounce_problem(case, ball=solver.ball, dt=solver.dt, t_end=solver.t_end)
    check_bounce_cost(problem)
    say = progress or silent
    say(f"the drop of {problem.ball.label} and the massless body's criteria on its top")
    case = problem.case
    ball = problem.ball.describe(case, Watch())
    system = floor_system(ball, case.gamma, problem.drop.floor_restitution)
    settings = DropSettings(problem.v0, case.gamma, problem.dt, problem.t_end)
    run = massless_liftoff(system, settings, Watch())
    drop = run.drop
    unit = case.scalings.time
    t_touch = None if run.result.t is None else (run.result.t + run.shift) * unit
    release = drop.intervals[-1].end * unit if drop.left else None
    summary = getattr(problem.ball, "summary", None)
    extra: dict[str, Any] = {
        "ball": problem.ball.as_dict(),
        "resolution": problem.ball.label,
        "t_liftoff_from_touch_s": t_touch,
        "t_max_compression_s": run.shift * unit,
        "drop": {
            "left_floor": drop.left,
            "contact_time_s": None if drop.contact_time is None else drop.contact_time * unit,
            "e2": drop.e2,
            "v2_m_s": None if drop.v2 is None else drop.v2 * case.scalings.velocity,
            "t_floor_release_s": release,
        },
        "before_floor_release": None
        if t_touch is None or release is None
        else bool(t_touch < release),
        "dt_s": problem.dt * unit,
        "t_end_s": problem.t_end * unit,
        "mass_kg": problem.mass_kg,
    }
    if summary is not None:
        extra["model"] = summary(case)
    warnings = list(problem.warnings)
    extra["interpolation"] = run.interpolation
    if run.interpolation == "hermite":
        warnings.append(
            "the top's samples are interpolated by one quintic through u, u_t and u_tt (the "
            "separate splines' re-contact search did not settle): u_tt between the steps is "
            "first order in dt"
        )
    if not drop.left:
        warnings.append("the ball has not left the floor within the window (raise t_end)")
    return LiftoffReport(
        case, run.result, problem.ball.backend, "none", "window", extra, tuple(warnings)
    )


def _check_body(body: Any) -> Any:
    from twoball.modal.contact.body import Body

    if body is not None and not isinstance(body, Body):
        raise ParameterError("body", "a twoball.Body", type(body).__name__)
    return body


def _closed_form(case: Case, solver: Any, progress: Step | None) -> LiftoffReport:
    """The Legendre series, eqs. (3.12)-(3.16), with its truncation guard."""
    from twoball._common.watch import Watch
    from twoball._costs import check_legendre_liftoff
    from twoball.modal.report import legendre_liftoff

    check_legendre_liftoff(case, solver.t_end)
    if progress is not None:  # the truncation guard's reference may take a while
        progress(f"the closed form on {case.modes} Legendre modes")
    return legendre_liftoff(case, solver.sigma, solver.recontact, solver.t_end, monitor=Watch())


def _cap_criteria(case: Case, body: Any, solver: Any, progress: Step | None) -> Any:
    """The massless body on its contact cap: criteria (i)-(ii) on the cap's mean motion."""
    from twoball._common.watch import Watch
    from twoball._solvers import ClosedForm, Superposition

    if solver.recontact != "window":
        valid = "window with a body on a contact cap (its events are the criteria's)"
        raise ParameterError("recontact", valid, solver.recontact)
    if isinstance(solver, ClosedForm):
        from twoball._costs import check_legendre_contact
        from twoball.modal.contact.report import legendre_contact

        check_legendre_contact(case, body, solver.t_end)
        say = progress or silent
        say(f"the cap's criteria on {case.modes + 1} Legendre modes")
        return legendre_contact(
            case, body, sigma=solver.sigma, t_end_s=solver.t_end, monitor=Watch()
        )
    if not isinstance(solver, Superposition):
        valid = "twoball.ClosedForm or Superposition for the massless body on a cap"
        raise ParameterError("solver", valid, type(solver).__name__)
    return _fem_contact(case, body, solver.mesh, solver.sigma, solver.t_end, None, progress)


def _stepped(case: Case, body: Any, solver: Any, progress: Step | None) -> Any:
    """A body of finite mass on the paper's start, stepped (Moreau-Jean) on the solver's ball."""
    from twoball._common.watch import Watch
    from twoball._costs import check_stepped_contact
    from twoball.fem_membrane.ball import FEBall
    from twoball.modal.balls.membrane import LegendreBall
    from twoball.modal.report import t_end_dimensionless

    ball = LegendreBall(case.modes) if solver.ball is None else solver.ball
    sigma = solver.sigma or "lanczos"
    dt = None if solver.dt is None else solver.dt * case.wave_speed
    window = t_end_dimensionless(case, solver.t_end)
    if isinstance(ball, LegendreBall):
        if ball.degree != case.modes:
            case = case.derive(modes=ball.degree)
        check_stepped_contact(case.modes + 1, window, dt, modes=case.modes)
        from twoball.modal.contact.report import legendre_contact

        say = progress or silent
        say(f"the body's contacts on {case.modes + 1} Legendre modes (Moreau-Jean)")
        return legendre_contact(
            case, body, sigma=sigma, t_end_s=solver.t_end, dt=dt, monitor=Watch()
        )
    if isinstance(ball, FEBall):
        return _fem_contact(case, body, ball.mesh, sigma, solver.t_end, dt, progress)
    valid = "twoball.LegendreBall or twoball.FEBall for a body on the paper's start"
    raise ParameterError("ball", valid, type(ball).__name__)


def _fem_contact(
    case: Case,
    body: Any,
    mesh: Any,
    sigma: str,
    t_end_s: float | None,
    dt: float | None,
    progress: Step | None,
) -> Any:
    """The body on the finite elements' start (full eigen route), its budget first."""
    from twoball._common.watch import Watch
    from twoball._costs import check_fem, check_fem_contact, check_stepped_contact
    from twoball.fem_membrane.contact import fem_contact_solution
    from twoball.fem_membrane.cost import fem_dofs
    from twoball.fem_membrane.options import MeshOptions
    from twoball.modal.report import t_end_dimensionless

    spec = MeshOptions.of(mesh)
    if spec.pole is not None:
        raise ParameterError("pole", "left out with mass_ratio (no mesh file)", spec.pole)
    if spec.kind != "file" and body.mass_ratio == 0.0:  # the massless body's cap criteria
        check_fem_contact(case, body, spec, t_end_s)
    elif spec.kind != "file":
        check_fem(spec.kind, spec.level, spec.elements, spec.order, case.modes, "full")
        if body.mass_ratio > 0.0:
            dofs = fem_dofs(spec.kind, spec.level, spec.elements, spec.order)
            pairs = case.modes + 1 if spec.kind == "axisym" else (case.modes + 1) ** 2
            window = t_end_dimensionless(case, t_end_s)
            check_stepped_contact(min(dofs, pairs), window, dt, modes=case.modes)
    say = progress or silent
    say(f"finite elements on {spec.label} (full eigen route) and the body's contacts")
    _, report = fem_contact_solution(
        case, body, spec, sigma=sigma, t_end_s=t_end_s, dt=dt, monitor=Watch()
    )
    return report


def fem_liftoff(case: Case, solver: Any, progress: Step | None = None) -> LiftoffReport:
    """Lift-off from the finite-element membrane, eq. (3.9), with criteria (i)-(ii) of §3(a).

    ``solver``: :class:`~twoball.Superposition` (modal superposition on its
    eigen route) or :class:`~twoball.GeneralizedAlpha` (time steps).
    """
    from twoball._common.watch import Watch
    from twoball._costs import check_fem
    from twoball._solvers import GeneralizedAlpha
    from twoball.fem_membrane.solve import fem_pole_motion
    from twoball.modal.filters import SpectralFilter
    from twoball.modal.report import report_liftoff, t_end_dimensionless

    spec = solver.mesh
    alpha = isinstance(solver, GeneralizedAlpha)
    scheme, route = ("alpha", "full") if alpha else ("modal", solver.route)
    dt = solver.dt if alpha else None
    sigma, recontact, t_end = solver.sigma, solver.recontact, solver.t_end
    law = case.rayleigh
    rayleigh = law is not None
    dt_scaled = None
    if dt is not None:
        from twoball.fem_membrane.validate import check_dt_in_window

        dt_scaled = check_dt_in_window(dt, case.scalings.time, t_end_dimensionless(case, t_end))
    if spec.kind != "file":  # the budget in the user's units, before any work
        check_fem(
            spec.kind,
            spec.level,
            spec.elements,
            spec.order,
            case.modes,
            route,
            scheme=scheme,
            dt=dt_scaled,
            t_end=t_end_dimensionless(case, t_end),
            time_unit_s=case.scalings.time,
        )
    say = progress or silent
    say(f"finite elements on {spec.label}: mesh, assembly, eigenpairs")
    started = clock.perf_counter()
    loaded = spec.load()  # the user's mesh, checked, on the unit sphere (None for a kind)
    if loaded is not None:  # a mesh file's size is known once it is read
        check_fem(
            loaded.mesh,
            spec.level,
            spec.elements,
            None,
            case.modes,
            route,
            scheme=scheme,
            dt=dt_scaled,
            t_end=t_end_dimensionless(case, t_end),
        )
    motion, info = fem_pole_motion(
        case.phi_a,
        case.damping,
        SpectralFilter(sigma, case.modes),
        mesh=spec.kind if loaded is None else loaded.mesh,
        level=spec.level,
        elements=spec.elements,
        order=spec.order if loaded is None else None,
        scheme=scheme,
        damping_model="rayleigh" if rayleigh else "modal",
        rayleigh=law.scaled(case.wave_speed) if rayleigh and not law.fitted else None,
        dt=dt_scaled,
        t_end=t_end_dimensionless(case, t_end),
        route=route,
        geometry=spec.geometry,
        initial=spec.initial or "projection",
        stiffness=case.stiffness if case.stiff else None,
        monitor=Watch(),
    )
    extra: dict[str, Any] = {
        "dofs": info["dofs"],
        "modes_used": info["modes_used"],
        "mesh": info["mesh"],
        "order": info["order"],
        "geometry": info["geometry"],
        "time_scheme": info["time_scheme"],
        "route": info["route"],
        "damping_model": info["damping_model"],
        "seconds": clock.perf_counter() - started,
    }
    if loaded is not None:
        extra["mesh_file"] = loaded.as_dict()
        extra["mesh_description"] = loaded.description
    if "dt" in info:
        extra["dt_s"] = info["dt"] * case.scalings.time
    if "rayleigh" in info:  # coefficients in units of c, and in SI
        c = case.wave_speed
        extra["rayleigh"] = {
            **info["rayleigh"],
            "alpha_1_s": info["rayleigh"]["alpha"] * c if law.fitted else law.alpha,
            "beta_s": info["rayleigh"]["beta"] / c if law.fitted else law.beta,
        }
    if case.membrane.pressurised:
        extra["membrane"] = case.membrane.kind
    from twoball.fem_membrane.guards import fem_warnings

    # a user's mesh has no level: its size stands in for it
    warnings = fem_warnings(
        info,
        SpectralFilter(sigma, case.modes),
        level=spec.level,
        elements=spec.elements,
        time_unit_s=case.scalings.time,
        surface=None if loaded is None else (loaded.mesh.points, loaded.mesh.cells),
    )
    say("lift-off criteria and the converged closed form beside it")
    return report_liftoff(
        case,
        motion,
        backend="fem",
        sigma=sigma,
        recontact=recontact,
        t_end_s=t_end,
        extra=extra,
        warnings=warnings,
        monitor=Watch(),
    )
