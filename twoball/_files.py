"""``twoball.export``, ``twoball.render`` and ``twoball.plot``: the fields on the sphere as files.

Each solves the case with the requested backend(s) on a sphere mesh (the one
definition of mesh options, :class:`twoball.fem_membrane.options.MeshOptions`), writes
to ``out`` and returns a small result object with ``as_dict()``.
"""

from __future__ import annotations

import json
import os
from collections.abc import Sequence
from dataclasses import dataclass, field, replace
from pathlib import Path
from typing import Any

from twoball._common.errors import ParameterError
from twoball._common.progress import Step, silent
from twoball._common.provenance import block
from twoball._common.staging import check_path_type
from twoball.modal.parameters import Case
from twoball.modal.report import LiftoffReport
from twoball.verify.output.fields import (
    FIELD_BACKENDS,
    FieldMesh,
    check_backend,
    check_fps,
    check_frame_budget,
    check_initial,
    eigen_sizes,
    field_mesh,
    field_warnings,
)

__all__ = ["ExportResult", "PlotResult", "RenderResult", "export", "plot", "render"]

DEFAULT_ANIMATION_FRAMES = 60
DEFAULT_FPS = 20.0


def export(
    out: str | os.PathLike[str],
    case: Case | None = None,
    *,
    backend: str = "fem",
    format: str | None = None,
    frames: int | None = None,
    times: Sequence[float] | None = None,
    mesh: Any = None,
    level: int | None = None,
    order: int | None = None,
    pole: Sequence[float] | str | None = None,
    geometry: str | None = None,
    initial: str | None = None,
    sigma: str = "lanczos",
    recontact: str = "window",
    t_end: float | None = None,
    progress: Step | None = None,
    route: str = "auto",
    mass_ratio: float | None = None,
    contact_radius: float | None = None,
    restitution: float | None = None,
    energy: str | None = None,
) -> ExportResult:
    """Write u, u_t, u_tt (SI) of both backends on the sphere mesh over time.

    Parameters
    ----------
    out : path
        Main output file: ``.xdmf`` (with ``.h5``), ``.pvd`` (with ``.vtu`` per frame) or ``.vtu``.
    case : Case, optional
        The impact (default the basketball preset).
    backend : {"fem", "legendre"}
        Which solver's u, u_t, u_tt and lift-off are the main fields.
    format : {"xdmf", "pvd", "vtu"}, optional
        Default from the suffix of ``out``.
    frames : int, optional
        Frames evenly spaced over [0, t_end] (default 25, plus the lift-off).
    times : sequence of float, optional
        Frame times [s] instead of ``frames``.
    mesh : {"sphere", "ring"}, path, meshio.Mesh or scikit-fem mesh, optional
        Sphere mesh kind (default ``sphere``), or the user's sphere: a file any
        format meshio reads, of any radius, centre and length unit, 3- or
        6-node triangles, checked as by :func:`twoball.liftoff` (a broken or
        non-spherical mesh raises :class:`ParameterError` naming ``mesh``).
        The fields are in SI in the case's frame: nodes at R times the unit
        sphere, the pole on +z; the file's radius, centre, pole and path are in
        the file's metadata (field data ``mesh_file_*``, text ``mesh_file``)
        and provenance (``mesh_file``).
    level, order
        Level of a generated sphere (default 3; not with a file) and element
        order 1 or 2 (default 2; a file: its own, a 6-node file is order 2).
    pole : (x, y, z) or "X,Y,Z", optional
        Pole direction in the file's frame (default +z); a mesh file only.
    geometry : {"isoparametric", "exact"}, optional
        Discrete sphere of the finite elements (default isoparametric); ``exact``
        on the icosphere and files only.
    initial : {"projection", "interpolation"}, optional
        FE representation of the initial displacement, eq. (3.10) (default projection).
    sigma, recontact, t_end
        As in :func:`twoball.liftoff`.
    progress : callable, optional
        Called with a short text as each stage starts (:class:`twoball._common.progress.Reporter`).
    route : {"auto", "full", "krylov"}
        FE mode shapes: every eigenpair below the cutoff (``full``), the Ritz pairs
        of the rational Krylov route converged on the whole field (``krylov``), or
        Krylov from 2000 unknowns on (``auto``, default; sphere P2 level 3 has 2562).
    mass_ratio, contact_radius, restitution, energy : optional
        An upper body of finite mass (docs/contact.rst; ``mass_ratio`` in (0, 100],
        ``contact_radius`` [m]): the fields are the membrane coupled to it (full
        eigen route), each frame gets field data ``s_m`` [m], ``s_t_m_s`` [m/s] and
        ``contact`` (1/0), and the text ``contact_events`` lists every event (JSON, SI).

    Every file carries the case and :mod:`twoball._common.provenance` (VTU string field
    data ``provenance`` and ``case``, XDMF grid attributes); field names end in
    their unit (``u_m``, ``u_t_m_s``, ``u_tt_m_s2``, ...).
    """
    arguments = dict(locals())  # the call, for the provenance
    check_path_type(out)
    from twoball._common.staging import check_file
    from twoball.verify.output.contact_fields import contact_options, contact_series, model_of
    from twoball.verify.output.fields import (
        DEFAULT_FRAMES,
        check_frames,
        check_times,
        field_series,
        frame_times,
        liftoff_frame,
        window_s,
    )
    from twoball.verify.output.series import series_format, write_series

    case = Case.preset("basketball") if case is None else case
    fmt = series_format(out, format)
    target = check_file(out)
    check_backend(backend)
    field = field_mesh(mesh, level, order, pole, geometry, cells=True, load=False)
    contact = contact_options(
        case, mass_ratio, contact_radius, restitution, energy, recontact=recontact, route=route
    )
    if frames is not None and times is not None:
        raise ParameterError("frames", "left out when times are given", frames)
    if times is not None:
        times = check_times(window_s(case, t_end), times)
    frames = None if frames is None else check_frames(frames)
    if fmt == "vtu" and frames is not None and frames != 1:
        raise ParameterError("frames", "1 for a single .vtu file (or give one time)", frames)
    if fmt == "vtu" and times is not None and len(times) != 1:
        raise ParameterError("times", "exactly one time for a single .vtu file", list(times))
    field = field_mesh(mesh, level, order, pole, geometry, cells=True)  # reads a file
    if times is not None:
        check_frame_budget(case, len(times), "times", field)
    else:
        check_frame_budget(case, frames or DEFAULT_FRAMES, "frames", field)
    say = progress or silent
    model = model_of(
        case,
        FIELD_BACKENDS,
        contact,
        field,
        initial=initial,
        sigma=sigma,
        recontact=recontact,
        t_end=t_end,
        progress=progress,
        route=route,
    )
    if fmt == "vtu" and times is None and frames is None:
        selected = liftoff_frame(model, backend)
    elif fmt == "vtu" and frames == 1:
        selected = frame_times(model, 1, None, backend, include_liftoff=False)
    else:
        selected = frame_times(model, frames, times, backend)
    say(f"fields at {len(selected)} frames")
    series = field_series(model, selected, backend)
    series = series if contact is None else contact_series(series, model, backend)
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


def render(
    out: str | os.PathLike[str],
    case: Case | None = None,
    *,
    backend: str = "fem",
    time: float | None = None,
    frames: int | None = None,
    warp: float | None = None,
    size: tuple[int, int] | str | None = None,
    fps: float | None = None,
    mesh: Any = None,
    level: int | None = None,
    order: int | None = None,
    pole: Sequence[float] | str | None = None,
    geometry: str | None = None,
    initial: str | None = None,
    sigma: str = "lanczos",
    recontact: str = "window",
    t_end: float | None = None,
    progress: Step | None = None,
    route: str = "auto",
    mass_ratio: float | None = None,
    contact_radius: float | None = None,
    restitution: float | None = None,
    energy: str | None = None,
) -> RenderResult:
    """Off-screen picture (``.png``) or animation (``.gif``, ``.mp4``) of the bouncing ball.

    Parameters
    ----------
    out : path
        ``FILE.png`` (one instant: ``time`` [s], default the lift-off), ``.gif`` or ``.mp4``.
    case : Case, optional
        The impact (default the basketball preset).
    backend : {"fem", "legendre"}
        Which solver's displacement is drawn.
    time : float, optional
        Instant [s] of a PNG.
    frames : int, optional
        Frames of an animation over [0, t_end] (default 60).
    warp : float, optional
        Displacement magnification (default automatic: largest displacement at 15 % of R).
    size : (int, int) or "WxH", optional
        Image size in pixels (MP4: rounded up to multiples of 16).
    fps : float, optional
        Frames per second of an animation, in [0.001, 1000] (default 20); not with ``.png``.
    mesh, level, order, pole, geometry, initial, sigma, recontact, t_end, progress, route
        As in :func:`export` (``initial`` needs ``backend="fem"``).
    mass_ratio, contact_radius, restitution, energy : optional
        An upper body of finite mass: drawn at its height s(t) over the coupled
        membrane, the caption saying when it is in contact (as in :func:`export`).
    """
    arguments = dict(locals())  # the call, for the provenance
    check_path_type(out)
    import numpy as np

    from twoball._common.staging import check_file
    from twoball.verify.output.contact_fields import contact_options, contact_scene, model_of
    from twoball.verify.output.fields import ball_scene, check_frames, check_times, liftoff_frame
    from twoball.verify.output.fields import window_s as window
    from twoball.verify.output.render import (
        DEFAULT_SIZE,
        check_size,
        check_warp,
        image_kind,
        render_scene,
        round_size,
    )

    case = Case.preset("basketball") if case is None else case
    kind = image_kind(out)
    target = check_file(out)
    size = check_size(DEFAULT_SIZE if size is None else size)
    warp = check_warp(warp)
    check_backend(backend)
    if kind == ".png" and fps is not None:
        raise ParameterError("fps", "used with .gif or .mp4 only", fps)
    fps = DEFAULT_FPS if fps is None else check_fps(fps)
    check_initial(initial, (backend,))
    if kind == ".png" and frames is not None:
        raise ParameterError("frames", "used with .gif or .mp4 only (use time for .png)", frames)
    if kind != ".png" and time is not None:
        raise ParameterError("time", "used with .png only (use frames for animations)", time)
    frames = None if frames is None else check_frames(frames)
    field = field_mesh(mesh, level, order, pole, geometry, cells=True, load=False)
    contact = contact_options(
        case, mass_ratio, contact_radius, restitution, energy, recontact=recontact, route=route
    )
    times = None
    if time is not None:
        from twoball._common.errors import real_number

        valid = "a time >= 0 in seconds within the modelled window"
        times = check_times(window(case, t_end), [real_number("time", time, valid)], "time")
    field = field_mesh(mesh, level, order, pole, geometry, cells=True)  # reads a file
    if kind != ".png":
        count = DEFAULT_ANIMATION_FRAMES if frames is None else frames
        check_frame_budget(case, count, "frames", field)
    say = progress or silent
    model = model_of(
        case,
        (backend,),
        contact,
        field,
        initial=initial,
        sigma=sigma,
        recontact=recontact,
        t_end=t_end,
        progress=progress,
        route=route,
    )
    if kind == ".png":
        times = liftoff_frame(model, backend) if times is None else times
    else:
        count = DEFAULT_ANIMATION_FRAMES if frames is None else frames
        times = np.linspace(0.0, model.t_end_s, count)
    scene = (ball_scene if contact is None else contact_scene)(model, times, backend)
    say(f"drawing {len(times)} frame(s) into {target}")
    drawn = None if len(times) < 2 else lambda k: say(f"frame {k}/{len(times)} into {target}")
    render_scene(target, scene, warp=warp, size=size, fps=fps, progress=drawn)
    shown = round_size(size) if kind == ".mp4" else size
    return RenderResult(
        file=target,
        times_s=[float(t) for t in times],
        size=tuple(shown),
        warp=float(scene.auto_warp() if warp is None else warp),
        backend=backend,
        report=model.backend(backend).report,
        warnings=field_warnings(model, backend, field),
        provenance=block(case, "twoball.render", arguments) | mesh_block(field),
    )


def plot(
    kind: str,
    out: str | os.PathLike[str],
    case: Case | None = None,
    *,
    backends: Sequence[str] | None = None,
    instants: int | None = None,
    levels: Sequence[int] | None = None,
    orders: Sequence[int] | None = None,
    max_degree: int | None = None,
    mesh: Any = None,
    level: int | None = None,
    order: int | None = None,
    pole: Sequence[float] | str | None = None,
    geometry: str | None = None,
    initial: str | None = None,
    sigma: str | None = None,
    recontact: str | None = None,
    t_end: float | None = None,
    progress: Step | None = None,
    route: str = "auto",
    dpi: float | None = None,
    mass_ratio: float | None = None,
    contact_radius: float | None = None,
    restitution: float | None = None,
    energy: str | None = None,
) -> PlotResult:
    """Figures: ``waterfall`` of u(phi) (Fig. 6), ``pole`` motion, FE ``eigen`` errors.

    Parameters
    ----------
    kind : {"waterfall", "pole", "eigen"}
        The figure.
    out : path
        Output file; its suffix chooses the format: any format matplotlib
        writes (``.pdf``, ``.svg``, ``.eps``, ``.png``, ...).
    case : Case, optional
        The impact (default the basketball preset); refused by ``eigen``.
    backends : sequence of {"fem", "legendre"}, optional
        Solvers drawn by ``waterfall`` and ``pole`` (default both).
    instants : int, optional
        Curves of the waterfall (default 24, as in Fig. 6), >= 2; ``waterfall`` only.
    levels, orders, max_degree
        ``eigen`` only: mesh levels (default 1, 2, 3), element orders (default 1,
        2) and the largest degree l.
    mesh, level, order, pole, geometry, initial, sigma, recontact, t_end
        As in :func:`export` (``waterfall`` and ``pole`` only; defaults as there;
        a mesh file too).
    progress, route
        As in :func:`export` (``route`` not with ``eigen``).
    dpi : float, optional
        Resolution of raster formats (PNG, ...) [dots per inch], 50 to 1200;
        default 300.
    mass_ratio, contact_radius, restitution, energy : optional
        ``pole`` only: an upper body of finite mass; the panels show the cap
        average of the coupled membrane with the body's path s(t), every impact
        and separation marked (as in :func:`export`).

    Every argument that the chosen ``kind`` does not use is refused
    (:class:`ParameterError`), never ignored.  ``pole`` with both backends
    puts a panel of the difference finite elements minus closed form under
    each quantity; ``waterfall`` with both stacks that difference at the nodes
    beside the waterfall.
    """
    arguments = dict(locals())  # the call, for the provenance
    check_path_type(out)
    from twoball._common.staging import check_file
    from twoball.verify.output.contact_fields import model_of, plot_contact
    from twoball.verify.output.figures import PLOT_KINDS, check_dpi, figure_format, save_figure
    from twoball.verify.output.figures.contact_pole import contact_pole_figure
    from twoball.verify.output.figures.eigen import eigen_figure, eigen_table
    from twoball.verify.output.figures.pole import pole_figure
    from twoball.verify.output.figures.waterfall import WATERFALL_INSTANTS, waterfall_figure

    if kind not in PLOT_KINDS:
        raise ParameterError("kind", "one of " + ", ".join(PLOT_KINDS), kind)
    figure_format(out, "out")
    dpi = check_dpi(dpi, "dpi")
    target = check_file(out)
    contact = plot_contact(
        kind, case, mass_ratio, contact_radius, restitution, energy,
        recontact=recontact, route=route,
    )  # fmt: skip
    rows: list[tuple[str, str]] = []
    reports: dict[str, LiftoffReport] = {}
    warnings: list[str] = []
    if kind == "eigen":
        for name, value in (
            ("case", case),
            ("backends", backends),
            ("instants", instants),
            ("mesh", mesh),
            ("pole", pole),
            ("geometry", geometry),
            ("level", level),
            ("order", order),
            ("initial", initial),
            ("sigma", sigma),
            ("recontact", recontact),
            ("t_end", t_end),
        ):
            if value is not None:
                shown = type(value).__name__ if name == "case" else value
                shown = os.fspath(shown) if isinstance(shown, os.PathLike) else shown
                raise ParameterError(name, "left out with kind eigen (use levels, orders)", shown)
        if route != "auto":
            raise ParameterError("route", "left out with kind eigen", route)
        levels, orders = eigen_sizes(levels, orders, max_degree)
        say = progress or silent
        tables = []
        for od in orders:
            for lv in levels:
                say(f"eigenvalues of sphere L{lv} P{od}")
                tables.append(eigen_table(lv, od, max_degree))
        figure = eigen_figure(tables)
        rows += [(t.label, f"l <= {t.degrees[-1]}, worst {t.errors[1:].max():.2e}") for t in tables]
    else:
        for name, value in (("levels", levels), ("orders", orders), ("max_degree", max_degree)):
            if value is not None:
                raise ParameterError(name, f"left out with kind {kind} (eigen only)", value)
        if kind == "pole" and instants is not None:
            raise ParameterError("instants", "left out with kind pole (waterfall only)", instants)
        sigma = "lanczos" if sigma is None else sigma
        recontact = "window" if recontact is None else recontact
        backends = FIELD_BACKENDS if backends is None else backends
        instants = WATERFALL_INSTANTS if instants is None else instants
        if isinstance(instants, bool) or not isinstance(instants, int) or instants < 2:
            raise ParameterError("instants", "an integer >= 2", instants)
        chosen = tuple(dict.fromkeys(backends))
        if not chosen or any(b not in FIELD_BACKENDS for b in chosen):
            raise ParameterError("backends", "a list of fem, legendre", list(backends))
        field = field_mesh(mesh, level, order, pole, geometry)  # reads a file
        check_frame_budget(
            Case.preset("basketball") if case is None else case, instants, "instants", field
        )
        model = model_of(
            Case.preset("basketball") if case is None else case,
            chosen,
            contact,
            field,
            initial=initial,
            sigma=sigma,
            recontact=recontact,
            t_end=t_end,
            progress=progress,
            route=route,
        )
        if contact is not None:
            figure = contact_pole_figure(model)
        elif kind == "waterfall":
            figure = waterfall_figure(model, instants)
        else:
            figure = pole_figure(model)
        for name, solved in model.backends.items():
            report = solved.report
            reports[name] = report
            warnings += [f"{name}: {text}" for text in field_warnings(model, name, field)]
            if report.result.lifted:
                text = f"{report.t_liftoff_s * 1e3:.3f} ms, {report.v_liftoff_m_s:.4f} m/s"
            else:
                text = "no lift-off"
            rows.append((f"lift-off ({name})", text))
    (progress or silent)(f"writing {target}")
    save_figure(figure, target, "out", dpi, "dpi")
    used = None if kind == "eigen" else Case.preset("basketball") if case is None else case
    provenance = block(used, "twoball.plot", arguments)
    if kind != "eigen":
        provenance |= mesh_block(field)
    return PlotResult(target, kind, rows, reports, warnings, provenance)


def mesh_block(field: FieldMesh) -> dict[str, object]:
    """``mesh_file`` for a provenance block: the user's file (path, radius, centre, pole)."""
    return {} if field.source is None else {"mesh_file": field.source}


@dataclass(frozen=True)
class ExportResult:
    """Files written by :func:`export` and what they hold (SI)."""

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

    def as_dict(self) -> dict[str, Any]:
        """JSON-ready summary with the lift-off of the exported backend."""
        return {
            "provenance": self.provenance,
            "warnings": self.warnings,
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
    """The picture or animation written by :func:`render`."""

    file: Path
    times_s: list[float]
    size: tuple[int, int]
    warp: float
    backend: str
    report: LiftoffReport
    warnings: list[str] = field(default_factory=list)
    provenance: dict[str, Any] | None = None

    def as_dict(self) -> dict[str, Any]:
        """JSON-ready summary."""
        return {
            "provenance": self.provenance,
            "warnings": self.warnings,
            "file": str(self.file),
            "times_s": self.times_s,
            "size": list(self.size),
            "warp": self.warp,
            "backend": self.backend,
            "liftoff": self.report.as_dict(),
        }


@dataclass(frozen=True)
class PlotResult:
    """The PNG written by :func:`plot`, with one line per curve family."""

    file: Path
    kind: str
    rows: list[tuple[str, str]] = field(default_factory=list)
    reports: dict[str, LiftoffReport] = field(default_factory=dict)
    warnings: list[str] = field(default_factory=list)
    provenance: dict[str, Any] | None = None

    def as_dict(self) -> dict[str, Any]:
        """JSON-ready summary."""
        return {
            "provenance": self.provenance,
            "warnings": self.warnings,
            "file": str(self.file),
            "kind": self.kind,
            "rows": [list(r) for r in self.rows],
            "liftoff": {name: r.as_dict() for name, r in self.reports.items()},
        }
