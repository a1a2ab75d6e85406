"""``twoball.export``, ``twoball.render`` and ``twoball.plot``: the fields on the sphere as files.

Each solves the case with the requested backend(s) on a sphere mesh
(:class:`~twoball.MeshOptions`) through the one builder of the solved ball,
:func:`twoball.verify.output.fields.ball_model`, writes to ``out`` and returns
a small result object with ``as_dict()``.
"""

from __future__ import annotations

import json
import os
from collections.abc import Sequence
from dataclasses import dataclass, field, replace
from pathlib import Path
from typing import Any

from twoball._common.budget import timed
from twoball._common.choices import DEFAULT_ANIMATION_FRAMES
from twoball._common.errors import ParameterError
from twoball._common.progress import Step, check_progress, silent
from twoball._common.provenance import block
from twoball._common.staging import check_path_type
from twoball.modal.parameters import Case
from twoball.modal.report import LiftoffReport

__all__ = ["ExportResult", "PlotResult", "RenderResult", "export", "plot", "render"]

DEFAULT_FPS = 20.0


def _case(case: Case | None) -> Case:
    case = Case.preset("basketball") if case is None else case
    if not isinstance(case, Case):
        raise ParameterError("case", "a twoball.Case", type(case).__name__)
    return case


@dataclass(frozen=True)
class _Given:
    """A field verb's options: the solver's mesh, window, route and rules, the body, the law."""

    solver: Any
    body: Any
    damping: Any

    @property
    def mesh(self) -> Any:
        """The solver's mesh (None when it is the default: the level-3 P2 icosphere)."""
        from twoball.fem_membrane.options import MeshOptions

        return None if self.solver.mesh == MeshOptions() else self.solver.mesh

    def as_dict(self) -> dict[str, Any]:
        out: dict[str, Any] = {"solver": self.solver.as_dict()}
        if self.body is not None:
            out["body"] = self.body.as_dict()
        if self.damping is not None:
            out["damping"] = self.damping.as_dict()
        return out


def _field_options(solver: Any, body: Any, damping: Any) -> _Given:
    """A field verb's solver (:class:`~twoball.Superposition`, default), body and damping law."""
    from twoball._solvers import Superposition
    from twoball.modal.contact.body import Body

    solver = Superposition() if solver is None else solver
    if not isinstance(solver, Superposition):
        valid = "a twoball.Superposition (the fields: finite elements beside the closed form)"
        raise ParameterError("solver", valid, solver)
    if body is not None and not isinstance(body, Body):
        raise ParameterError("body", "a twoball.Body", type(body).__name__)
    return _Given(solver, body, damping)


def _not_the_mesh(out: str | os.PathLike[str], given: Any, name: str = "out") -> None:
    """Refuse an output onto the user's mesh file (it would replace the input)."""
    from twoball._common.staging import check_distinct

    check_distinct({name: out}, {"the input mesh file": getattr(given.mesh, "file", None)})


def _window(given: _Given) -> tuple[float | None, str]:
    return given.solver.t_end, given.solver.route


def _frames(frames: Any) -> tuple[int | None, Sequence[float] | None, str]:
    """``frames`` as a count or as times [s]; the name the errors give them by."""
    name = "frames"
    if frames is None:
        return None, None, name
    if isinstance(frames, (str, bytes)):
        raise ParameterError(name, "a frame count or a list of times [s]", frames)
    if isinstance(frames, Sequence) or hasattr(frames, "__array__"):
        return None, frames, name
    return frames, None, name


@timed
def export(
    out: str | os.PathLike[str],
    case: Case | None = None,
    *,
    backend: str = "fem",
    solver: Any = None,
    body: Any = None,
    damping: Any = None,
    frames: int | Sequence[float] | None = None,
    progress: Step | None = None,
) -> ExportResult:
    """Write u, u_t, u_tt (SI) of both backends on the sphere mesh over time.

    Parameters
    ----------
    out : path
        Main output file; its suffix chooses the format: ``.xdmf`` (with
        ``.h5``), ``.pvd`` (with ``.vtu`` per frame) or ``.vtu``.
    case : Case, optional
        The impact (default the basketball preset).
    backend : {"fem", "legendre"}
        Which solver's u, u_t, u_tt and lift-off are the main fields.  ``fem``
        (default) also solves the closed form for the comparison fields
        ``u_legendre_m`` and ``u_diff_m``; ``legendre`` solves the closed form
        alone (no finite elements: ``u_legendre_m``, no ``u_fem_m``/``u_diff_m``),
        and refuses the finite elements' options (the solver's ``route``,
        ``mesh.initial``).
    solver : Superposition, optional
        The finite elements and the options of both backends
        (:class:`~twoball.Superposition`): its ``mesh`` is the sphere (default
        the level-3 P2 icosphere; orders 1 and 2, ``sphere`` or ``ring``), or
        the user's sphere: a file any format meshio reads, of any radius, centre
        and length unit, 3- or 6-node triangles, checked as by
        :func:`twoball.liftoff` (a broken or non-spherical mesh raises
        :class:`~twoball.ParameterError` naming ``mesh``); the fields are in SI
        in the case's frame: nodes at R times the unit sphere, the pole on +z;
        the file's radius, centre, pole and path are in the file's metadata
        (field data ``mesh_file_*``, text ``mesh_file``) and provenance.  Its
        ``route`` (every pair below the cutoff, ``full``; the Ritz pairs of the
        rational Krylov route converged on the whole field, ``krylov``; Krylov
        from 2000 unknowns on, ``auto``), the filter ``sigma``, the re-contact
        horizon and the window ``t_end`` [s] (default 4 pi / c).
    body : Body, optional
        An upper body of finite mass (docs/contact.rst): the fields are the
        membrane coupled to it (full eigen route), each frame gets field data
        ``s_m`` [m], ``s_t_m_s`` [m/s] and ``contact`` (1/0), and the text
        ``contact_events`` lists every event (JSON, SI).
    damping : ModalRatio or Rayleigh, optional
        The damping law, as in :func:`twoball.liftoff` (a Rayleigh law is
        refused with a body: the contact model takes the ratio D).
    frames : int or sequence of float, optional
        A count of frames evenly spaced over [0, t_end] (default 25, plus the
        lift-off), or the frame times [s].
    progress : callable, optional
        Called with a short text as each stage starts (:class:`~twoball.Reporter`).

    Every file carries the case and the provenance; field names end in their
    unit (``u_m``, ``u_t_m_s``, ``u_tt_m_s2``, ...).

    Examples
    --------
    >>> import tempfile, pathlib, twoball
    >>> folder = pathlib.Path(tempfile.mkdtemp())
    >>> solver = twoball.Superposition(twoball.MeshOptions("sphere", level=1))
    >>> result = twoball.export(folder / "ball.xdmf", solver=solver, frames=3)
    >>> [f.name for f in result.files], result.point_data[:3]
    (['ball.xdmf', 'ball.h5'], ['u_m', 'u_t_m_s', 'u_tt_m_s2'])
    """
    from twoball._common.staging import check_file
    from twoball._liftoff import with_damping
    from twoball.verify.output.fields import (
        BACKENDS,
        DEFAULT_FRAMES,
        ball_model,
        check_backend,
        check_frame_budget,
        check_frames,
        check_times,
        contact_series,
        field_mesh,
        field_series,
        field_warnings,
        frame_times,
        liftoff_frame,
        window_s,
    )
    from twoball.verify.output.series import check_side_entries, series_format, write_series

    check_path_type(out)
    check_progress(progress)
    given = _field_options(solver, body, damping)
    case = with_damping(_case(case), given.damping)
    fmt = series_format(out, None)
    target = check_file(out)
    check_side_entries(target, fmt)
    _not_the_mesh(out, given)
    check_backend(backend)
    t_end, route = _window(given)
    solved = BACKENDS if backend == "fem" else (backend,)  # the closed form needs no FE solve
    if "fem" not in solved and route != "auto":
        raise ParameterError("route", "left out with backend legendre (no finite elements)", route)
    field = field_mesh(given.mesh, cells=True, load=False)
    frames, times, name = _frames(frames)
    if times is not None:
        times = check_times(window_s(case, t_end), times, name)
    frames = None if frames is None else check_frames(frames)
    if fmt == "vtu" and frames is not None and frames != 1:
        raise ParameterError("frames", "1 for a single .vtu file (or give one time)", frames)
    if fmt == "vtu" and times is not None and len(times) != 1:
        raise ParameterError(name, "exactly one time for a single .vtu file", list(times))
    field = field_mesh(given.mesh, cells=True)  # reads a file
    if times is not None:
        check_frame_budget(case, len(times), "times", field)
    else:
        check_frame_budget(case, frames or DEFAULT_FRAMES, "frames", field)
    say = progress or silent
    model = ball_model(
        case,
        field,
        backends=solved,
        body=given.body,
        sigma=given.solver.sigma,
        recontact=given.solver.recontact,
        t_end_s=t_end,
        route=route,
        progress=say,
    )
    if fmt == "vtu" and times is None and frames is None:
        selected = liftoff_frame(model, backend)
    elif fmt == "vtu" and frames == 1:
        selected = frame_times(model, 1, None, backend, include_liftoff=False)
    else:
        selected = frame_times(model, frames, times, backend)
    say(f"fields at {len(selected)} frames")
    series = field_series(model, selected, backend)
    series = series if given.body is None else contact_series(series, model, backend)
    arguments = {"out": out, "backend": backend, "frames": _shown(frames, times), "format": fmt}
    arguments |= given.as_dict()
    provenance = block(case, "twoball.export", arguments) | mesh_block(field)
    series = replace(series, text={**series.text, "provenance": json.dumps(provenance)})
    say(f"writing {target}")
    files = write_series(target, series, fmt)
    return ExportResult(
        files=list(files),
        format=fmt,
        times_s=[float(t) for t in selected],
        nodes=len(series.points),
        cells=len(series.cells),
        cell_type=series.cell_type,
        point_data=list(series.point_data),
        report=model.backend(backend).report,
        warnings=field_warnings(model, backend, field),
        provenance=provenance,
    )


def check_export_format(out: str | os.PathLike[str], fmt: str) -> str:
    """``fmt`` checked against the suffix of ``out``, which chooses the format of :func:`export`."""
    from twoball.verify.output.series import series_format

    return series_format(out, fmt)


def _shown(frames: int | None, times: Any) -> Any:
    return frames if times is None else [float(t) for t in times]


@timed
def render(
    out: str | os.PathLike[str],
    case: Case | None = None,
    *,
    backend: str = "fem",
    solver: Any = None,
    body: Any = None,
    damping: Any = None,
    view: Any = None,
    progress: Step | None = None,
) -> RenderResult:
    """Off-screen picture (``.png``) or animation (``.gif``, ``.mp4``) of the bouncing ball.

    Parameters
    ----------
    out : path
        ``FILE.png`` (one instant, default the lift-off), ``.gif`` or ``.mp4``.
    case : Case, optional
        The impact (default the basketball preset).
    backend : {"fem", "legendre"}
        Which solver's displacement is drawn.
    solver, body
        As in :func:`export` (``mesh.initial`` needs ``backend="fem"``); with a
        body it is drawn at its height s(t) over the coupled membrane, the
        caption saying when it is in contact.
    damping, progress
        As in :func:`export`.
    view : RenderOptions, optional
        The frames drawn (a PNG: one time, default the lift-off; an
        animation: a count, default 60, or the times), warp, image size and
        frames per second (:class:`~twoball.RenderOptions`).

    Examples
    --------
    >>> import tempfile, pathlib, twoball
    >>> out = pathlib.Path(tempfile.mkdtemp()) / "ball.png"
    >>> solver = twoball.Superposition(twoball.MeshOptions("sphere", level=1))
    >>> result = twoball.render(out, solver=solver, view=twoball.RenderOptions(size="320x240"))
    >>> result.file.name, result.size
    ('ball.png', (320, 240))
    """
    import numpy as np

    from twoball._common.staging import check_file
    from twoball._liftoff import with_damping
    from twoball.verify.output.fields import (
        ball_model,
        ball_scene,
        check_backend,
        check_frame_budget,
        check_frames,
        check_times,
        contact_scene,
        field_mesh,
        field_warnings,
        liftoff_frame,
        window_s,
    )
    from twoball.verify.output.options import RenderOptions
    from twoball.verify.output.render import DEFAULT_SIZE, image_kind, render_scene, round_size

    check_path_type(out)
    check_progress(progress)
    given = _field_options(solver, body, damping)
    view = RenderOptions() if view is None else view
    if not isinstance(view, RenderOptions):
        raise ParameterError("view", "a twoball.RenderOptions", type(view).__name__)
    case = with_damping(_case(case), given.damping)
    kind = image_kind(out)
    target = check_file(out)
    _not_the_mesh(out, given)
    size = DEFAULT_SIZE if view.size is None else view.size
    check_backend(backend)
    if kind == ".png" and view.fps is not None:
        raise ParameterError("fps", "used with .gif or .mp4 only", view.fps)
    fps = DEFAULT_FPS if view.fps is None else view.fps
    t_end, route = _window(given)
    if backend != "fem" and route != "auto":
        raise ParameterError("route", "left out with backend legendre (no finite elements)", route)
    if given.mesh is not None and given.mesh.initial is not None and backend != "fem":
        raise ParameterError(
            "initial",
            "left out without the fem backend (it sets the FE initial state)",
            given.mesh.initial,
        )
    count, times, name = _frames(view.frames)
    if kind == ".png" and count is not None:
        raise ParameterError(
            "frames", "one time [s] in a list with .png (a count: .gif or .mp4)", count
        )
    if kind == ".png" and times is not None and len(times) != 1:
        raise ParameterError(name, "exactly one time [s] with .png", list(times))
    count = None if count is None else check_frames(count)
    field = field_mesh(given.mesh, cells=True, load=False)
    if times is not None:
        times = check_times(window_s(case, t_end), times, name)
    field = field_mesh(given.mesh, cells=True)  # reads a file
    if kind != ".png":
        number = len(times) if times is not None else count or DEFAULT_ANIMATION_FRAMES
        check_frame_budget(case, number, "frames", field)
    say = progress or silent
    model = ball_model(
        case,
        field,
        backends=(backend,),
        body=given.body,
        sigma=given.solver.sigma,
        recontact=given.solver.recontact,
        t_end_s=t_end,
        route=route,
        progress=say,
    )
    if kind == ".png":
        times = liftoff_frame(model, backend) if times is None else times
    elif times is None:
        times = np.linspace(0.0, model.t_end_s, count or DEFAULT_ANIMATION_FRAMES)
    scene = (ball_scene if given.body is None else contact_scene)(model, times, backend)
    say(f"drawing {len(times)} frame(s) into {target}")
    drawn = None if len(times) < 2 else lambda k: say(f"frame {k}/{len(times)} into {target}")
    render_scene(target, scene, warp=view.warp, size=size, fps=fps, progress=drawn)
    shown = round_size(size) if kind == ".mp4" else size
    arguments = {"out": out, "backend": backend, "frames": _shown(count, times)}
    arguments |= {"view": view.as_dict()}
    return RenderResult(
        file=target,
        times_s=[float(t) for t in times],
        size=tuple(shown),
        warp=float(scene.auto_warp() if view.warp is None else view.warp),
        backend=backend,
        report=model.backend(backend).report,
        warnings=field_warnings(model, backend, field),
        provenance=block(case, "twoball.render", {**arguments, **given.as_dict()})
        | mesh_block(field),
    )


@timed
def plot(
    kind: str,
    out: str | os.PathLike[str],
    case: Case | None = None,
    *,
    solver: Any = None,
    body: Any = None,
    damping: Any = None,
    figure: Any = None,
    progress: Step | None = None,
) -> PlotResult:
    """Figures: ``waterfall`` (Fig. 6), ``pole`` motion, FE ``eigen`` errors, ``precursor``.

    Parameters
    ----------
    kind : {"waterfall", "pole", "eigen", "precursor"}
        The figure.  ``precursor``: the pole's displacement under the case's
        damping law beside the other law matched to it and the undamped
        membrane, with the motion before the wave front ``phi_a / c`` (closed
        form; :mod:`twoball.verify.output.figures.precursor`).
    out : path
        Output file; its suffix chooses the format: any format matplotlib
        writes (``.pdf``, ``.svg``, ``.eps``, ``.png``, ...).
    case : Case, optional
        The impact (default the basketball preset); refused by ``eigen``.
    solver : Superposition or ClosedForm, optional
        ``waterfall`` and ``pole``: as in :func:`export` (a
        :class:`~twoball.Superposition`; a mesh file too); ``precursor``: a
        :class:`~twoball.ClosedForm` (its filter, horizon and window); ``eigen``
        takes none (use the figure's levels and orders).
    body : Body, optional
        ``pole`` only: an upper body of finite mass; the panels show the cap
        average of the coupled membrane with the body's path s(t), every impact
        and separation marked.
    damping : ModalRatio or Rayleigh, optional
        The damping law, as in :func:`twoball.liftoff` (not with ``eigen``);
        ``precursor`` draws it beside the other law matched to it.
    figure : PlotOptions, optional
        The solvers drawn, resolution, waterfall instants, eigenvalue meshes
        and degree (:class:`~twoball.PlotOptions`).
    progress : callable, optional
        Called with a short text as each stage starts (:class:`~twoball.Reporter`).

    Every argument that the chosen ``kind`` does not use is refused
    (:class:`~twoball.ParameterError`), never ignored.  ``pole`` with both
    backends puts a panel of the difference finite elements minus closed form
    under each quantity; ``waterfall`` with both stacks that difference at the
    nodes beside the waterfall.

    Examples
    --------
    >>> import tempfile, pathlib, twoball
    >>> out = pathlib.Path(tempfile.mkdtemp()) / "pole.svg"
    >>> solver = twoball.Superposition(twoball.MeshOptions("sphere", level=1))
    >>> figure = twoball.PlotOptions(backends=["legendre"])
    >>> result = twoball.plot("pole", out, solver=solver, figure=figure)
    >>> result.file.name, result.rows[0][0]
    ('pole.svg', 'lift-off (legendre)')
    """
    from twoball._common.staging import check_file
    from twoball._liftoff import with_damping
    from twoball._solvers import ClosedForm
    from twoball.verify.output.fields import (
        ball_model,
        check_field_body,
        check_frame_budget,
        eigen_sizes,
        field_mesh,
        field_warnings,
    )
    from twoball.verify.output.figures import PLOT_KINDS, figure_format, save_figure
    from twoball.verify.output.figures.contact_pole import contact_pole_figure
    from twoball.verify.output.figures.eigen import eigen_figure, eigen_table
    from twoball.verify.output.figures.pole import pole_figure
    from twoball.verify.output.figures.waterfall import WATERFALL_INSTANTS, waterfall_figure
    from twoball.verify.output.options import BACKENDS, PlotOptions

    check_path_type(out)
    check_progress(progress)
    if kind not in PLOT_KINDS:
        raise ParameterError("kind", "one of " + ", ".join(PLOT_KINDS), kind)
    closed = None
    if kind == "precursor":  # the closed form: its filter, horizon and window
        closed = ClosedForm() if solver is None else solver
        if not isinstance(closed, ClosedForm):
            valid = "a twoball.ClosedForm with kind precursor (the closed form only)"
            raise ParameterError("solver", valid, solver)
        given = _field_options(None, body, damping)
    elif kind == "eigen":
        if solver is not None:
            shown = solver.as_dict() if hasattr(solver, "as_dict") else solver
            raise ParameterError("solver", "left out with kind eigen (use levels, orders)", shown)
        given = _field_options(None, body, damping)
    else:
        given = _field_options(solver, body, damping)
    figure = PlotOptions() if figure is None else figure
    if not isinstance(figure, PlotOptions):
        raise ParameterError("figure", "a twoball.PlotOptions", type(figure).__name__)
    figure_format(out, "out")
    target = check_file(out)
    _not_the_mesh(out, given)
    t_end, route = _window(given)
    if given.body is not None and kind != "pole":
        raise ParameterError(
            "mass_ratio", f"left out with kind {kind} (pole only)", given.body.mass_ratio
        )
    rows: list[tuple[str, str]] = []
    reports: dict[str, LiftoffReport] = {}
    warnings: list[str] = []
    field = None
    say = progress or silent
    if kind == "precursor":
        from twoball.modal.report import t_end_dimensionless
        from twoball.verify.output.figures.precursor import (
            law_curves,
            precursor_figure,
            precursor_rows,
        )

        refused = {"backends": figure.backends, "mesh": given.mesh, "instants": figure.instants}
        refused |= {"levels": figure.levels, "orders": figure.orders}
        refused |= {"max_degree": figure.max_degree}
        for name, value in refused.items():
            if value is not None:
                shown = value.label if hasattr(value, "label") else value
                valid = "left out with kind precursor (the closed form only)"
                raise ParameterError(name, valid, shown)
        if given.body is not None:
            raise ParameterError(
                "mass_ratio",
                "left out with kind precursor (a massless body)",
                given.body.mass_ratio,
            )
        case = with_damping(_case(case), given.damping)
        window = t_end_dimensionless(case, closed.t_end)
        say("the closed form under each damping law")
        curves = law_curves(case, closed.sigma, closed.recontact, window)
        drawn = precursor_figure(case, curves, window)
        rows += precursor_rows(case, curves)
    elif kind == "eigen":
        refused = {"case": case, "backends": figure.backends}
        refused |= {"damping": given.damping, "instants": figure.instants}
        for name, value in refused.items():
            if value is not None:
                shown = None if name == "case" else value  # a Case is not a value to show
                shown = shown.label if hasattr(shown, "label") else shown
                shown = shown.as_dict() if hasattr(shown, "as_dict") else shown
                raise ParameterError(name, "left out with kind eigen (use levels, orders)", shown)
        levels, orders = eigen_sizes(figure.levels, figure.orders, figure.max_degree)
        tables = []
        for od in orders:
            for lv in levels:
                say(f"eigenvalues of sphere L{lv} P{od}")
                tables.append(eigen_table(lv, od, figure.max_degree))
        drawn = eigen_figure(tables)
        rows += [(t.label, f"l <= {t.degrees[-1]}, worst {t.errors[1:].max():.2e}") for t in tables]
    else:
        for name in ("levels", "orders", "max_degree"):
            if getattr(figure, name) is not None:
                raise ParameterError(
                    name, f"left out with kind {kind} (eigen only)", getattr(figure, name)
                )
        if kind == "waterfall" and given.solver.recontact != "window":
            valid = (
                "left out with kind waterfall (it draws u(phi) at fixed instants; the "
                "re-contact horizon acts on the lift-off: kind pole)"
            )
            raise ParameterError("recontact", valid, given.solver.recontact)
        if kind == "pole" and figure.instants is not None:
            raise ParameterError(
                "instants", "left out with kind pole (waterfall only)", figure.instants
            )
        case = with_damping(_case(case), given.damping)
        chosen = BACKENDS if figure.backends is None else figure.backends
        instants = WATERFALL_INSTANTS if figure.instants is None else figure.instants
        if "fem" not in chosen and route != "auto":
            raise ParameterError("route", "left out without the fem backend", route)
        field = field_mesh(given.mesh)  # reads a file
        if given.body is not None:
            check_field_body(case, given.body, field, recontact=given.solver.recontact, route=route)
        check_frame_budget(case, instants, "instants", field)
        model = ball_model(
            case,
            field,
            backends=chosen,
            body=given.body,
            sigma=given.solver.sigma,
            recontact=given.solver.recontact,
            t_end_s=t_end,
            route=route,
            progress=say,
        )
        if given.body is not None:
            drawn = contact_pole_figure(model)
        elif kind == "waterfall":
            drawn = waterfall_figure(model, instants)
        else:
            drawn = pole_figure(model)
        for name, solved in model.backends.items():
            report = solved.report
            reports[name] = report
            warnings += [f"{name}: {text}" for text in field_warnings(model, name, field)]
            if report.result.lifted:
                text = f"{report.t_liftoff_s * 1e3:.3f} ms, {report.v_liftoff_m_s:.4f} m/s"
            else:
                text = "no lift-off"
            rows.append((f"lift-off ({name})", text))
    say(f"writing {target}")
    save_figure(drawn, target, "out", figure.dpi, "dpi")
    arguments = {"kind": kind, "out": out, "figure": figure.as_dict(), **given.as_dict()}
    if kind in ("precursor", "eigen"):  # the closed form's options, or none
        arguments.pop("solver")
        if closed is not None:
            arguments["solver"] = closed.as_dict()
    provenance = block(None if kind == "eigen" else case, "twoball.plot", arguments)
    if field is not None:
        provenance |= mesh_block(field)
    return PlotResult(target, kind, rows, reports, warnings, provenance)


def check_figure_path(path: str | os.PathLike[str], name: str = "out") -> Path:
    """A figure path (any format matplotlib writes, not a folder or link) in a writable folder."""
    from twoball._common.staging import check_file
    from twoball.verify.output.figures import figure_format

    check_path_type(path, name)
    figure_format(path, name)
    return check_file(path, name)


def save_report_figure(report: Any, path: str | os.PathLike[str], name: str = "out") -> Path:
    """Draw a finite-mass lift-off (the body's path over the cap, every event) into ``path``."""
    from twoball.verify.output.figures import save_figure
    from twoball.verify.output.figures.contact import contact_figure

    if getattr(report, "history", None) is None:
        raise ParameterError(name, "given with a body of mass ratio > 0", os.fspath(path))
    return save_figure(contact_figure(report), path, name)


#: The old keywords of :func:`plot` that :class:`~twoball.PlotOptions` holds now.


def mesh_block(field: Any) -> dict[str, object]:
    """``mesh_file`` for a provenance block: the user's file (path, radius, centre, pole)."""
    return {} if field.source is None else {"mesh_file": field.source}


@dataclass(frozen=True)
class ExportResult:
    """Files written by :func:`export` and what they hold (SI).

    Like every result that writes files, it has ``files`` (every one) and
    ``file`` (the main one).

    Examples
    --------
    >>> import tempfile, pathlib, twoball
    >>> out = pathlib.Path(tempfile.mkdtemp()) / "ball.vtu"
    >>> result = twoball.export(out, mesh=twoball.MeshOptions("sphere", level=1))
    >>> result.format, result.nodes, result.cell_type, len(result.times_s)
    ('vtu', 162, 'triangle6', 1)
    """

    files: list[Path]
    format: str
    times_s: list[float]
    nodes: int
    cells: int
    cell_type: str
    point_data: list[str]
    report: LiftoffReport
    warnings: list[str] = field(default_factory=list)
    provenance: dict[str, Any] | None = None

    @property
    def file(self) -> Path:
        """The main file (``.xdmf``, ``.pvd`` or ``.vtu``); :attr:`files` lists every one."""
        return self.files[0]

    def as_dict(self) -> dict[str, Any]:
        """JSON-ready summary with the lift-off of the exported backend."""
        return {
            "provenance": self.provenance,
            "warnings": self.warnings,
            "file": str(self.file),
            "files": [str(f) for f in self.files],
            "format": self.format,
            "times_s": self.times_s,
            "nodes": self.nodes,
            "cells": self.cells,
            "cell_type": self.cell_type,
            "point_data": self.point_data,
            "liftoff": self.report.as_dict(),
        }


@dataclass(frozen=True)
class RenderResult:
    """The picture or animation written by :func:`render`: ``file`` (and ``files``, one).

    Examples
    --------
    >>> import tempfile, pathlib, twoball
    >>> out = pathlib.Path(tempfile.mkdtemp()) / "ball.png"
    >>> mesh, view = twoball.MeshOptions("sphere", level=1), twoball.RenderOptions(frames=[0.005])
    >>> result = twoball.render(out, mesh=mesh, view=view)
    >>> result.times_s, result.backend
    ([0.005], 'fem')
    """

    file: Path
    times_s: list[float]
    size: tuple[int, int]
    warp: float
    backend: str
    report: LiftoffReport
    warnings: list[str] = field(default_factory=list)
    provenance: dict[str, Any] | None = None

    @property
    def files(self) -> list[Path]:
        """Every file written (one: :attr:`file`), as :attr:`ExportResult.files`."""
        return [self.file]

    def as_dict(self) -> dict[str, Any]:
        """JSON-ready summary."""
        return {
            "provenance": self.provenance,
            "warnings": self.warnings,
            "file": str(self.file),
            "files": [str(f) for f in self.files],
            "times_s": self.times_s,
            "size": list(self.size),
            "warp": self.warp,
            "backend": self.backend,
            "liftoff": self.report.as_dict(),
        }


@dataclass(frozen=True)
class PlotResult:
    """The figure written by :func:`plot` (``file``, and ``files``, one), with one line per
    curve family.

    Examples
    --------
    >>> import tempfile, pathlib, twoball
    >>> out = pathlib.Path(tempfile.mkdtemp()) / "eigen.png"
    >>> figure = twoball.PlotOptions(levels=[1], orders=[1], dpi=72)
    >>> result = twoball.plot("eigen", out, figure=figure)
    >>> result.kind, result.rows[0][0]
    ('eigen', 'P1, level 1 (42 unknowns)')
    """

    file: Path
    kind: str
    rows: list[tuple[str, str]] = field(default_factory=list)
    reports: dict[str, LiftoffReport] = field(default_factory=dict)
    warnings: list[str] = field(default_factory=list)
    provenance: dict[str, Any] | None = None

    @property
    def files(self) -> list[Path]:
        """Every file written (one: :attr:`file`), as :attr:`ExportResult.files`."""
        return [self.file]

    def as_dict(self) -> dict[str, Any]:
        """JSON-ready summary."""
        return {
            "provenance": self.provenance,
            "warnings": self.warnings,
            "file": str(self.file),
            "files": [str(f) for f in self.files],
            "kind": self.kind,
            "rows": [list(r) for r in self.rows],
            "liftoff": {name: r.as_dict() for name, r in self.reports.items()},
        }
