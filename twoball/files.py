"""``twoball.export``, ``twoball.render`` and ``twoball.plot``: the fields on the sphere as files.

Each solves the case with the requested backend(s) on a sphere mesh (the one
definition of mesh options, :class:`twoball.mesh_options.MeshOptions`), writes
to ``out`` and returns a small result object with ``as_dict()``.
"""

from __future__ import annotations

import math
import os
from collections.abc import Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from twoball.mesh_options import SPHERE_KINDS, MeshOptions
from twoball.modal.errors import ParameterError
from twoball.modal.parameters import Case
from twoball.modal.report import LiftoffReport

__all__ = ["ExportResult", "PlotResult", "RenderResult", "export", "plot", "render"]

FIELD_BACKENDS: tuple[str, ...] = ("fem", "legendre")
INITIAL_METHODS: tuple[str, ...] = ("projection", "interpolation")
DEFAULT_ANIMATION_FRAMES = 60


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

    def as_dict(self) -> dict[str, Any]:
        """JSON-ready summary with the lift-off of the exported backend."""
        return {
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

    def as_dict(self) -> dict[str, Any]:
        """JSON-ready summary."""
        return {
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

    def as_dict(self) -> dict[str, Any]:
        """JSON-ready summary."""
        return {
            "warnings": self.warnings,
            "file": str(self.file),
            "kind": self.kind,
            "rows": [list(r) for r in self.rows],
            "liftoff": {name: r.as_dict() for name, r in self.reports.items()},
        }


def _check_backend(backend: str) -> str:
    if backend not in FIELD_BACKENDS:
        raise ParameterError("backend", "one of " + ", ".join(FIELD_BACKENDS), backend)
    return backend


def field_warnings(model: Any, backend: str, order: int | None, level: int | None) -> list[str]:
    """Accuracy warnings of ``backend``'s fields: its lift-off's, and the FE mesh resolution."""
    warnings = list(model.backend(backend).report.warnings)
    if backend == "fem":
        from twoball.fem_membrane.guards import mesh_warnings

        kind = "ring" if model.mesh.ring is not None else "sphere"
        order = MeshOptions.resolve(None, level=level, order=order).order
        warnings += mesh_warnings(kind, level, None, order, model.backend(backend).series.filter)
    return warnings


def check_frame_budget(
    case: Case, count: int, name: str, level: int | None, order: int | None
) -> None:
    """Refuse ``count`` frames on the mesh when their memory or time cannot fit (budget)."""
    from twoball.budget import check_frames
    from twoball.verify.output.fields import MAX_FRAMES

    if count > MAX_FRAMES:  # the same cap for frames, times and instants
        if name in ("instants", "frames"):  # a count
            low = 2 if name == "instants" else 1
            raise ParameterError(name, f"an integer in [{low}, {MAX_FRAMES}]", count)
        raise ParameterError(name, f"at most {MAX_FRAMES} {name}", f"{count} {name}")
    spec = MeshOptions.resolve(None, level=level, order=order)
    check_frames(f"{name} ({count} frames)", count, "sphere", spec.level, spec.order, case.modes)


def ball_model_of(
    case: Case,
    backends: Sequence[str],
    *,
    mesh: str | None,
    level: int | None,
    order: int | None,
    initial: str,
    sigma: str,
    recontact: str,
    t_end: float | None,
    route: str = "auto",
) -> Any:
    """Solve ``case`` with ``backends`` on the sphere mesh of the options (see ``BallModel``)."""
    from twoball.fem_membrane.krylov import ROUTES
    from twoball.verify.output.fields import ball_model

    if route not in ROUTES:
        raise ParameterError("route", "one of " + ", ".join(ROUTES), route)
    spec = MeshOptions.resolve(mesh, level=level, order=order, kinds=SPHERE_KINDS, files=False)
    if initial not in INITIAL_METHODS:
        raise ParameterError("initial", "one of " + ", ".join(INITIAL_METHODS), initial)
    return ball_model(
        case,
        spec.level,
        spec.order,
        mesh=spec.kind,
        sigma=sigma,
        recontact=recontact,
        t_end_s=t_end,
        backends=tuple(backends),
        initial=initial,
        route=route,
    )


def export(
    out: str | os.PathLike[str],
    case: Case | None = None,
    *,
    backend: str = "fem",
    format: str | None = None,
    frames: int | None = None,
    times: Sequence[float] | None = None,
    mesh: str | None = None,
    level: int | None = None,
    order: int | None = None,
    initial: str = "projection",
    sigma: str = "lanczos",
    recontact: str = "window",
    t_end: float | None = None,
    route: str = "auto",
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
    mesh, level, order
        Sphere mesh (``sphere`` or ``ring``), level (default 3), order (default 2).
        Mesh files are not taken here yet (the fields are evaluated on generated meshes).
    initial : {"projection", "interpolation"}
        FE representation of the initial displacement, eq. (3.10).
    sigma, recontact, t_end
        As in :func:`twoball.liftoff`.
    route : {"auto", "full", "krylov"}
        FE mode shapes: every eigenpair below the cutoff (``full``), the Ritz pairs
        of the rational Krylov route converged on the whole field (``krylov``), or
        Krylov from 2000 unknowns on (``auto``, default; sphere P2 level 3 has 2562).
    """
    from twoball.fem_membrane.export import series_format, write_series
    from twoball.staging import check_file
    from twoball.verify.output.fields import (
        DEFAULT_FRAMES,
        check_frames,
        check_times,
        field_series,
        frame_times,
        liftoff_frame,
        window_s,
    )

    case = Case.preset("basketball") if case is None else case
    fmt = series_format(out, format)
    target = check_file(out)
    _check_backend(backend)
    MeshOptions.resolve(mesh, level=level, order=order, kinds=SPHERE_KINDS, files=False)
    if frames is not None and times is not None:
        raise ParameterError("frames", "left out when times are given", frames)
    if times is not None:
        times = check_times(window_s(case, t_end), times)
    frames = None if frames is None else check_frames(frames)
    if fmt == "vtu" and frames is not None and frames != 1:
        raise ParameterError("frames", "1 for a single .vtu file (or give one time)", frames)
    if fmt == "vtu" and times is not None and len(times) != 1:
        raise ParameterError("times", "exactly one time for a single .vtu file", list(times))
    if times is not None:
        check_frame_budget(case, len(times), "times", level, order)
    else:
        check_frame_budget(case, frames or DEFAULT_FRAMES, "frames", level, order)
    model = ball_model_of(
        case,
        FIELD_BACKENDS,
        mesh=mesh,
        level=level,
        order=order,
        initial=initial,
        sigma=sigma,
        recontact=recontact,
        t_end=t_end,
        route=route,
    )
    if fmt == "vtu" and times is None and frames is None:
        selected = liftoff_frame(model, backend)
    elif fmt == "vtu" and frames == 1:
        selected = frame_times(model, 1, None, backend, include_liftoff=False)
    else:
        selected = frame_times(model, frames, times, backend)
    series = field_series(model, selected, backend)
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
        warnings=field_warnings(model, backend, order, level),
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
    fps: float = 20.0,
    mesh: str | None = None,
    level: int | None = None,
    order: int | None = None,
    initial: str = "projection",
    sigma: str = "lanczos",
    recontact: str = "window",
    t_end: float | None = None,
    route: str = "auto",
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
    fps : float
        Frames per second of an animation.
    mesh, level, order, initial, sigma, recontact, t_end, route
        As in :func:`export`.
    """
    import numpy as np

    from twoball.fem_membrane.render import (
        DEFAULT_SIZE,
        check_size,
        check_warp,
        image_kind,
        render_scene,
        round_size,
    )
    from twoball.staging import check_file
    from twoball.verify.output.fields import ball_scene, check_frames, check_times, liftoff_frame
    from twoball.verify.output.fields import window_s as window

    case = Case.preset("basketball") if case is None else case
    kind = image_kind(out)
    target = check_file(out)
    size = check_size(DEFAULT_SIZE if size is None else size)
    warp = check_warp(warp)
    _check_backend(backend)
    if not (isinstance(fps, (int, float)) and math.isfinite(fps) and fps > 0):
        raise ParameterError("fps", "a number > 0", fps)
    if kind == ".png" and frames is not None:
        raise ParameterError("frames", "used with .gif or .mp4 only (use time for .png)", frames)
    if kind != ".png" and time is not None:
        raise ParameterError("time", "used with .png only (use frames for animations)", time)
    frames = None if frames is None else check_frames(frames)
    MeshOptions.resolve(mesh, level=level, order=order, kinds=SPHERE_KINDS, files=False)
    times = None
    if time is not None:
        times = check_times(window(case, t_end), [time], "time")
    if kind != ".png":
        count = DEFAULT_ANIMATION_FRAMES if frames is None else frames
        check_frame_budget(case, count, "frames", level, order)
    model = ball_model_of(
        case,
        (backend,),
        mesh=mesh,
        level=level,
        order=order,
        initial=initial,
        sigma=sigma,
        recontact=recontact,
        t_end=t_end,
        route=route,
    )
    if kind == ".png":
        times = liftoff_frame(model, backend) if times is None else times
    else:
        count = DEFAULT_ANIMATION_FRAMES if frames is None else frames
        times = np.linspace(0.0, model.t_end_s, count)
    scene = ball_scene(model, times, backend)
    render_scene(target, scene, warp=warp, size=size, fps=fps)
    shown = round_size(size) if kind == ".mp4" else size
    return RenderResult(
        file=target,
        times_s=[float(t) for t in times],
        size=tuple(shown),
        warp=float(scene.auto_warp() if warp is None else warp),
        backend=backend,
        report=model.backend(backend).report,
        warnings=field_warnings(model, backend, order, level),
    )


def plot(
    kind: str,
    out: str | os.PathLike[str],
    case: Case | None = None,
    *,
    backends: Sequence[str] = FIELD_BACKENDS,
    instants: int | None = None,
    levels: Sequence[int] = (1, 2, 3),
    orders: Sequence[int] = (1, 2),
    max_degree: int | None = None,
    mesh: str | None = None,
    level: int | None = None,
    order: int | None = None,
    initial: str = "projection",
    sigma: str = "lanczos",
    recontact: str = "window",
    t_end: float | None = None,
    route: str = "auto",
) -> PlotResult:
    """PNG figures: ``waterfall`` of u(phi) (Fig. 6), ``pole`` motion, FE ``eigen`` errors.

    Parameters
    ----------
    kind : {"waterfall", "pole", "eigen"}
        The figure.
    out : path
        Output PNG.
    case : Case, optional
        The impact (default the basketball preset); not used by ``eigen``.
    backends : sequence of {"fem", "legendre"}
        Solvers drawn by ``waterfall`` and ``pole``.
    instants : int, optional
        Curves of the waterfall (default 24, as in Fig. 6), >= 2.
    levels, orders, max_degree
        ``eigen``: mesh levels, element orders and the largest degree l.
    mesh, level, order, initial, sigma, recontact, t_end, route
        As in :func:`export` (``waterfall`` and ``pole``).
    """
    from twoball.staging import check_file
    from twoball.verify.output.figures import PLOT_KINDS, save_figure
    from twoball.verify.output.figures.eigen import eigen_figure, eigen_table
    from twoball.verify.output.figures.pole import pole_figure
    from twoball.verify.output.figures.waterfall import WATERFALL_INSTANTS, waterfall_figure

    if kind not in PLOT_KINDS:
        raise ParameterError("kind", "one of " + ", ".join(PLOT_KINDS), kind)
    if not str(out).lower().endswith(".png"):
        raise ParameterError("out", "a file name ending in .png", str(out))
    target = check_file(out)
    rows: list[tuple[str, str]] = []
    reports: dict[str, LiftoffReport] = {}
    warnings: list[str] = []
    if kind == "eigen":
        for name, value in (
            ("mesh", mesh),
            ("level", level),
            ("order", order),
            ("instants", instants),
        ):
            if value is not None:
                raise ParameterError(name, "left out with kind eigen (use levels, orders)", value)
        if route != "auto":
            raise ParameterError("route", "left out with kind eigen", route)
        tables = [eigen_table(lv, od, max_degree) for od in orders for lv in levels]
        figure = eigen_figure(tables)
        rows += [(t.label, f"l <= {t.degrees[-1]}, worst {t.errors[1:].max():.2e}") for t in tables]
    else:
        instants = WATERFALL_INSTANTS if instants is None else instants
        if isinstance(instants, bool) or not isinstance(instants, int) or instants < 2:
            raise ParameterError("instants", "an integer >= 2", instants)
        check_frame_budget(
            Case.preset("basketball") if case is None else case, instants, "instants", level, order
        )
        chosen = tuple(dict.fromkeys(backends))
        if not chosen or any(b not in FIELD_BACKENDS for b in chosen):
            raise ParameterError("backends", "a list of fem, legendre", list(backends))
        model = ball_model_of(
            Case.preset("basketball") if case is None else case,
            chosen,
            mesh=mesh,
            level=level,
            order=order,
            initial=initial,
            sigma=sigma,
            recontact=recontact,
            t_end=t_end,
            route=route,
        )
        figure = waterfall_figure(model, instants) if kind == "waterfall" else pole_figure(model)
        for name, solved in model.backends.items():
            report = solved.report
            reports[name] = report
            warnings += [f"{name}: {text}" for text in field_warnings(model, name, order, level)]
            if report.result.lifted:
                text = f"{report.t_liftoff_s * 1e3:.3f} ms, {report.v_liftoff_m_s:.4f} m/s"
            else:
                text = "no lift-off"
            rows.append((f"lift-off ({name})", text))
    save_figure(figure, target)
    return PlotResult(target, kind, rows, reports, warnings)
