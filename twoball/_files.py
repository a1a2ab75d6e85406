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

from twoball._bundles import bundles, warn_deprecated, with_damping
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


def _field_bundles(
    verb: str, mesh: Any, stepping: Any, body: Any, damping: Any, series: Any, old: dict[str, Any]
) -> Any:
    """The bundles of a field verb: mesh, stepping (window and route only), body, damping
    law and series rules."""
    times = old.pop("times", None)
    given = bundles(
        verb,
        mesh=mesh,
        stepping=stepping,
        body=body,
        damping=damping,
        series=series,
        old=old,
    )
    if given.stepping is not None:
        given.stepping.refuse("with field outputs (modal superposition)", "scheme", "dt")
    return given, times


def _not_the_mesh(out: str | os.PathLike[str], given: Any, name: str = "out") -> None:
    """Refuse an output onto the user's mesh file (it would replace the input)."""
    from twoball._common.staging import check_distinct

    check_distinct({name: out}, {"the input mesh file": getattr(given.mesh, "file", None)})


def _window(given: Any) -> tuple[float | None, str]:
    stepping = given.stepping
    if stepping is None:
        return None, "auto"
    return stepping.t_end, stepping.route or "auto"


def _frames(
    frames: Any, legacy_times: Any = None
) -> tuple[int | None, Sequence[float] | None, str]:
    """``frames`` as a count or as times [s] (the old ``times`` keyword folded in).

    Returns the count, the times and the name the user gave them by (``frames``,
    or ``times`` for the old keyword), for the errors.
    """
    name = "frames"
    if legacy_times is not None:
        if frames is not None:
            raise ParameterError("frames", "left out when times are given", frames)
        if isinstance(legacy_times, (str, bytes)) or not (
            isinstance(legacy_times, Sequence) or hasattr(legacy_times, "__array__")
        ):  # refused before the deprecation is said
            raise ParameterError("times", "a list of times [s]", legacy_times)
        warn_deprecated("the keyword times is deprecated; pass the frame times as frames=[...]")
        frames, name = legacy_times, "times"
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
    mesh: Any = None,
    stepping: Any = None,
    body: Any = None,
    damping: Any = None,
    series: Any = None,
    frames: int | Sequence[float] | None = None,
    progress: Step | None = None,
    **deprecated: Any,
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
        and refuses the finite elements' options (``stepping.route``,
        ``mesh.initial``).
    mesh : MeshOptions, {"sphere", "ring"} or the user's mesh, optional
        The sphere (default the level-3 P2 icosphere; orders 1 and 2), or the
        user's sphere: a file any format meshio reads, of any radius, centre
        and length unit, 3- or 6-node triangles, checked as by
        :func:`twoball.liftoff` (a broken or non-spherical mesh raises
        :class:`~twoball.ParameterError` naming ``mesh``).  The fields are in SI
        in the case's frame: nodes at R times the unit sphere, the pole on +z;
        the file's radius, centre, pole and path are in the file's metadata
        (field data ``mesh_file_*``, text ``mesh_file``) and provenance.
    stepping : Stepping, optional
        The window ``t_end`` [s] (default 4 pi / c) and the finite elements'
        eigen ``route``: every pair below the cutoff (``full``), the Ritz pairs
        of the rational Krylov route converged on the whole field (``krylov``),
        or Krylov from 2000 unknowns on (``auto``, default).
    body : Body, optional
        An upper body of finite mass (docs/contact.rst): the fields are the
        membrane coupled to it (full eigen route), each frame gets field data
        ``s_m`` [m], ``s_t_m_s`` [m/s] and ``contact`` (1/0), and the text
        ``contact_events`` lists every event (JSON, SI).
    damping : ModalRatio or Rayleigh, optional
        The damping law, as in :func:`twoball.liftoff` (a Rayleigh law is
        refused with a body: the contact model takes the ratio D).
    series : Series, optional
        Filter and re-contact horizon, as in :func:`twoball.liftoff`.
    frames : int or sequence of float, optional
        A count of frames evenly spaced over [0, t_end] (default 25, plus the
        lift-off), or the frame times [s].
    progress : callable, optional
        Called with a short text as each stage starts (:class:`~twoball.Reporter`).
    **deprecated
        The keywords of version 0.2 (``level``, ``times``, ``sigma``, ...) and
        ``format`` (the suffix of ``out`` chooses it), with a
        :class:`DeprecationWarning`.

    Every file carries the case and the provenance; field names end in their
    unit (``u_m``, ``u_t_m_s``, ``u_tt_m_s2``, ...).

    Examples
    --------
    >>> import tempfile, pathlib, twoball
    >>> folder = pathlib.Path(tempfile.mkdtemp())
    >>> mesh = twoball.MeshOptions("sphere", level=1)
    >>> result = twoball.export(folder / "ball.xdmf", mesh=mesh, frames=3)
    >>> [f.name for f in result.files], result.point_data[:3]
    (['ball.xdmf', 'ball.h5'], ['u_m', 'u_t_m_s', 'u_tt_m_s2'])
    """
    from twoball._common.staging import check_file
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
    legacy_format = deprecated.pop("format", None)
    if legacy_format is not None:
        warn_deprecated(
            "twoball.export: the keyword format is deprecated; pass out with its suffix "
            "(.xdmf, .pvd or .vtu)"
        )
    given, legacy_times = _field_bundles(
        "twoball.export", mesh, stepping, body, damping, series, deprecated
    )
    case = with_damping(_case(case), given.damping)
    fmt = series_format(out, legacy_format)
    target = check_file(out)
    check_side_entries(target, fmt)
    _not_the_mesh(out, given)
    check_backend(backend)
    t_end, route = _window(given)
    solved = BACKENDS if backend == "fem" else (backend,)  # the closed form needs no FE solve
    if "fem" not in solved and route != "auto":
        raise ParameterError("route", "left out with backend legendre (no finite elements)", route)
    field = field_mesh(given.mesh, cells=True, load=False)
    frames, times, name = _frames(frames, legacy_times)
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
        sigma=given.rules.sigma,
        recontact=given.rules.recontact,
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
    mesh: Any = None,
    stepping: Any = None,
    body: Any = None,
    damping: Any = None,
    series: Any = None,
    view: Any = None,
    progress: Step | None = None,
    **deprecated: Any,
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
    mesh, stepping, body
        As in :func:`export` (``mesh.initial`` needs ``backend="fem"``); with a
        body it is drawn at its height s(t) over the coupled membrane, the
        caption saying when it is in contact.
    damping, series, progress
        As in :func:`export`.
    view : RenderOptions, optional
        The frames drawn (a PNG: one time, default the lift-off; an
        animation: a count, default 60, or the times), warp, image size and
        frames per second (:class:`~twoball.RenderOptions`).
    **deprecated
        The keywords of version 0.2 (``time``, ``warp``, ``size``, ``fps``,
        ``level``, ``sigma``, ...) and ``frames`` (now ``view.frames``), with a
        :class:`DeprecationWarning`.

    Examples
    --------
    >>> import tempfile, pathlib, twoball
    >>> out = pathlib.Path(tempfile.mkdtemp()) / "ball.png"
    >>> mesh = twoball.MeshOptions("sphere", level=1)
    >>> result = twoball.render(out, mesh=mesh, view=twoball.RenderOptions(size="320x240"))
    >>> result.file.name, result.size
    ('ball.png', (320, 240))
    """
    import numpy as np

    from twoball._common.staging import check_file
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
    time = deprecated.pop("time", None)
    keys = ("warp", "size", "fps", "frames")
    legacy_view = {k: deprecated.pop(k) for k in keys if deprecated.get(k) is not None}
    given, legacy_times = _field_bundles(
        "twoball.render", mesh, stepping, body, damping, series, deprecated
    )
    old = {**legacy_view, "time": time, "times": legacy_times}
    names = sorted(k for k, v in old.items() if v is not None)
    if names:
        warn_deprecated(
            f"twoball.render: the keyword{'s' if len(names) > 1 else ''} {', '.join(names)} "
            f"{'are' if len(names) > 1 else 'is'} deprecated; pass view=RenderOptions(...) "
            "(frames=[t] for one time)"
        )
    if legacy_times is not None:
        if "frames" in legacy_view:
            raise ParameterError("frames", "left out when times are given", legacy_view["frames"])
        legacy_view["frames"] = legacy_times
    if time is not None:
        if "frames" in legacy_view:
            raise ParameterError("time", "left out with frames", time)
        from twoball._common.errors import real_number

        legacy_view["frames"] = [
            real_number("time", time, "a time >= 0 in seconds within the modelled window")
        ]
    if legacy_view:
        if view is not None:
            raise ParameterError("view", "left out with " + ", ".join(sorted(legacy_view)), view)
        view = RenderOptions(**legacy_view)
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
        sigma=given.rules.sigma,
        recontact=given.rules.recontact,
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
    mesh: Any = None,
    stepping: Any = None,
    body: Any = None,
    damping: Any = None,
    series: Any = None,
    figure: Any = None,
    progress: Step | None = None,
    **deprecated: Any,
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
    mesh, stepping : optional
        As in :func:`export` (``waterfall`` and ``pole`` only; a mesh file too).
    body : Body, optional
        ``pole`` only: an upper body of finite mass; the panels show the cap
        average of the coupled membrane with the body's path s(t), every impact
        and separation marked.
    damping : ModalRatio or Rayleigh, optional
        The damping law, as in :func:`twoball.liftoff` (not with ``eigen``);
        ``precursor`` draws it beside the other law matched to it.
    series : Series, optional
        Filter and re-contact horizon, as in :func:`twoball.liftoff` (not with
        ``eigen``; ``waterfall`` draws u(phi) at fixed instants and takes the
        whole window as horizon).
    figure : PlotOptions, optional
        The solvers drawn, resolution, waterfall instants, eigenvalue meshes
        and degree (:class:`~twoball.PlotOptions`).
    progress : callable, optional
        Called with a short text as each stage starts (:class:`~twoball.Reporter`).
    **deprecated
        The keywords of version 0.2 (``dpi``, ``instants``, ``levels``,
        ``orders``, ``max_degree``, ``level``, ``sigma``, ...) and ``backends``
        (now ``figure.backends``), with a :class:`DeprecationWarning`.

    Every argument that the chosen ``kind`` does not use is refused
    (:class:`~twoball.ParameterError`), never ignored.  ``pole`` with both
    backends puts a panel of the difference finite elements minus closed form
    under each quantity; ``waterfall`` with both stacks that difference at the
    nodes beside the waterfall.

    Examples
    --------
    >>> import tempfile, pathlib, twoball
    >>> out = pathlib.Path(tempfile.mkdtemp()) / "pole.svg"
    >>> mesh = twoball.MeshOptions("sphere", level=1)
    >>> figure = twoball.PlotOptions(backends=["legendre"])
    >>> result = twoball.plot("pole", out, mesh=mesh, figure=figure)
    >>> result.file.name, result.rows[0][0]
    ('pole.svg', 'lift-off (legendre)')
    """
    from twoball._common.staging import check_file
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
    legacy = {k: deprecated.pop(k) for k in tuple(deprecated) if k in PLOT_OPTION_KEYS}
    legacy = {k: v for k, v in legacy.items() if v is not None}
    given, _ = _field_bundles("twoball.plot", mesh, stepping, body, damping, series, deprecated)
    if legacy:
        names = sorted(legacy)
        warn_deprecated(
            f"twoball.plot: the keyword{'s' if len(names) > 1 else ''} {', '.join(names)} "
            f"{'are' if len(names) > 1 else 'is'} deprecated; pass figure=PlotOptions(...)"
        )
        if figure is not None:
            raise ParameterError("figure", "left out with " + ", ".join(names), figure)
        figure = PlotOptions(**legacy)
    figure = PlotOptions() if figure is None else figure
    if not isinstance(figure, PlotOptions):
        raise ParameterError("figure", "a twoball.PlotOptions", type(figure).__name__)
    if kind not in PLOT_KINDS:
        raise ParameterError("kind", "one of " + ", ".join(PLOT_KINDS), kind)
    figure_format(out, "out")
    target = check_file(out)
    _not_the_mesh(out, given)
    t_end, route = _window(given)
    if given.body is not None and kind != "pole":
        raise ParameterError(
            "mass_ratio", f"left out with kind {kind} (pole only)", given.body.mass_ratio
        )
    rules = given.rules
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
        if given.stepping is not None:
            given.stepping.refuse("with kind precursor (the closed form)", "route")
        case = with_damping(_case(case), given.damping)
        window = t_end_dimensionless(case, t_end)
        say("the closed form under each damping law")
        curves = law_curves(case, rules.sigma, rules.recontact, window)
        drawn = precursor_figure(case, curves, window)
        rows += precursor_rows(case, curves)
    elif kind == "eigen":
        if given.stepping is not None:  # the window and the time options name themselves
            from twoball.modal.stepping import Stepping

            given.stepping.refuse("with kind eigen (use levels, orders)", *Stepping.VALID)
        if given.series is not None:  # the field that was changed, else the bundle
            name, value = next(iter(given.series.changed().items()), ("series", given.series))
            raise ParameterError(name, "left out with kind eigen (use levels, orders)", value)
        refused = {"case": case, "backends": figure.backends, "mesh": given.mesh}
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
        if kind == "waterfall":
            rules.refuse(
                "with kind waterfall (it draws u(phi) at fixed instants; the "
                "re-contact horizon acts on the lift-off: kind pole)",
                "recontact",
            )
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
            check_field_body(case, given.body, field, recontact=rules.recontact, route=route)
        check_frame_budget(case, instants, "instants", field)
        model = ball_model(
            case,
            field,
            backends=chosen,
            body=given.body,
            sigma=rules.sigma,
            recontact=rules.recontact,
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
PLOT_OPTION_KEYS = ("dpi", "instants", "levels", "orders", "max_degree", "backends")


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
