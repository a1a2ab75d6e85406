"""The figures of ``twoball.plot``, kind by kind: what each draws and what it refuses.

:func:`closed_form_figure` draws the kinds that need no field on a sphere
(``precursor``: the pole under each damping law, closed form;
``eigen``: the finite elements' eigenvalue errors on generated spheres);
:func:`field_figure` the kinds drawn from the solved ball on a mesh
(``waterfall``, Fig. 6; ``pole``, the pole's motion, with a body its path
over the cap).  Each refuses, by its name, every option its kind does not use.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

from twoball._common.errors import ParameterError

__all__ = ["closed_form_figure", "field_figure"]


def closed_form_figure(
    kind: str,
    case: Any,
    solver: Any,
    mesh: Any,
    body: Any,
    damping: Any,
    figure: Any,
    say: Callable[[str], None],
) -> tuple[Any, list[tuple[str, str]]]:
    """The figure of kind ``precursor`` (the closed form, ``solver`` a ClosedForm) or
    ``eigen`` (no case, no solver), and its rows."""
    rows: list[tuple[str, str]] = []
    if kind == "precursor":
        from twoball.modal.damping import with_damping
        from twoball.modal.parameters import Case
        from twoball.modal.report import t_end_dimensionless
        from twoball.verify.output.figures.precursor import (
            law_curves,
            precursor_figure,
            precursor_rows,
        )

        refused = {"backends": figure.backends, "mesh": mesh, "instants": figure.instants}
        refused |= {"levels": figure.levels, "orders": figure.orders}
        refused |= {"max_degree": figure.max_degree}
        for name, value in refused.items():
            if value is not None:
                shown = value.label if hasattr(value, "label") else value
                valid = "left out with kind precursor (the closed form only)"
                raise ParameterError(name, valid, shown)
        if body is not None:
            valid = "left out with kind precursor (a massless body)"
            raise ParameterError("mass_ratio", valid, body.mass_ratio)
        case = Case.preset("basketball") if case is None else case
        case = with_damping(case, damping)
        window = t_end_dimensionless(case, solver.t_end)
        say("the closed form under each damping law")
        curves = law_curves(case, solver.sigma, solver.recontact, window)
        return precursor_figure(case, curves, window), rows + precursor_rows(case, curves)
    from twoball.verify.output.fields import eigen_sizes
    from twoball.verify.output.figures.eigen import eigen_figure, eigen_table

    refused = {"case": case, "backends": figure.backends}
    refused |= {"damping": damping, "instants": figure.instants}
    for name, value in refused.items():
        if value is not None:
            shown = None if name == "case" else value  # a Case is not a value to show
            shown = shown.label if hasattr(shown, "label") else shown
            shown = shown.as_dict() if hasattr(shown, "as_dict") else shown
            raise ParameterError(name, "left out with kind eigen (use levels, orders)", shown)
    if body is not None:
        raise ParameterError("mass_ratio", "left out with kind eigen (pole only)", body.mass_ratio)
    levels, orders = eigen_sizes(figure.levels, figure.orders, figure.max_degree)
    tables = []
    for od in orders:
        for lv in levels:
            say(f"eigenvalues of sphere L{lv} P{od}")
            tables.append(eigen_table(lv, od, figure.max_degree))
    rows += [(t.label, f"l <= {t.degrees[-1]}, worst {t.errors[1:].max():.2e}") for t in tables]
    return eigen_figure(tables), rows


def field_figure(
    kind: str,
    case: Any,
    solver: Any,
    body: Any,
    figure: Any,
    say: Callable[[str], None],
) -> tuple[Any, list[tuple[str, str]], dict[str, Any], list[str], Any]:
    """The figure of kind ``waterfall`` or ``pole`` on the solver's mesh (a Superposition),
    its rows, the backends' reports, their warnings and the field mesh."""
    from twoball.verify.output.fields import (
        ball_model,
        check_field_body,
        check_frame_budget,
        field_mesh,
        field_warnings,
    )
    from twoball.verify.output.figures.contact_pole import contact_pole_figure
    from twoball.verify.output.figures.pole import pole_figure
    from twoball.verify.output.figures.waterfall import WATERFALL_INSTANTS, waterfall_figure
    from twoball.verify.output.options import BACKENDS

    for name in ("levels", "orders", "max_degree"):
        if getattr(figure, name) is not None:
            valid = f"left out with kind {kind} (eigen only)"
            raise ParameterError(name, valid, getattr(figure, name))
    if body is not None and kind != "pole":
        raise ParameterError(
            "mass_ratio", f"left out with kind {kind} (pole only)", body.mass_ratio
        )
    if kind == "waterfall" and solver.recontact != "window":
        valid = (
            "left out with kind waterfall (it draws u(phi) at fixed instants; the "
            "re-contact horizon acts on the lift-off: kind pole)"
        )
        raise ParameterError("recontact", valid, solver.recontact)
    if kind == "pole" and figure.instants is not None:
        raise ParameterError(
            "instants", "left out with kind pole (waterfall only)", figure.instants
        )
    chosen = BACKENDS if figure.backends is None else figure.backends
    instants = WATERFALL_INSTANTS if figure.instants is None else figure.instants
    route = solver.route
    if "fem" not in chosen and route != "auto":
        raise ParameterError("route", "left out without the fem backend", route)
    from twoball.fem_membrane.options import MeshOptions

    field = field_mesh(None if solver.mesh == MeshOptions() else solver.mesh)  # reads a file
    if body is not None:
        check_field_body(case, body, field, recontact=solver.recontact, route=route)
    check_frame_budget(case, instants, "instants", field)
    model = ball_model(
        case,
        field,
        backends=chosen,
        body=body,
        sigma=solver.sigma,
        recontact=solver.recontact,
        t_end_s=solver.t_end,
        route=route,
        progress=say,
    )
    if body is not None:
        drawn = contact_pole_figure(model)
    elif kind == "waterfall":
        drawn = waterfall_figure(model, instants)
    else:
        drawn = pole_figure(model)
    rows: list[tuple[str, str]] = []
    reports: dict[str, Any] = {}
    warnings: list[str] = []
    for name, solved in model.backends.items():
        report = solved.report
        reports[name] = report
        warnings += [f"{name}: {text}" for text in field_warnings(model, name, field)]
        if report.result.lifted:
            text = f"{report.t_liftoff_s * 1e3:.3f} ms, {report.v_liftoff_m_s:.4f} m/s"
        else:
            text = "no lift-off"
        rows.append((f"lift-off ({name})", text))
    return drawn, rows, reports, warnings, field
