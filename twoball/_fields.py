"""``twoball.export`` and ``twoball.render``: the fields on the sphere as files and pictures.

Each solves the case with the requested backend(s) on a sphere mesh
(:class:`~twoball.MeshOptions`) through the one builder of the solved ball,
:func:`twoball.verify.output.fields.ball_model`, writes to ``out`` and returns
a small result object with ``as_dict()``.
"""

from __future__ import annotations

import json
import os
from collections.abc import Sequence
from dataclasses import dataclass, replace
from typing import Any

from twoball._common.budget import timed
from twoball._common.choices import DEFAULT_ANIMATION_FRAMES
from twoball._common.errors import ParameterError
from twoball._common.keywords import checked
from twoball._common.progress import Step, check_progress, silent
from twoball._common.provenance import block
from twoball._common.staging import check_path_type
from twoball.modal.parameters import Case
from twoball.verify.output.results import ExportResult, RenderResult

__all__ = ["check_render_budget", "export", "render"]

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


@checked
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
    from twoball.modal.damping import with_damping
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


@checked
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
    from twoball.modal.damping import with_damping
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
    number = 1
    if kind != ".png":
        number = len(times) if times is not None else count or DEFAULT_ANIMATION_FRAMES
        check_frame_budget(case, number, "frames", field)
    check_render_budget(number, size, kind)
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
    from twoball._common.watch import Watch

    render_scene(target, scene, warp=view.warp, size=size, fps=fps, progress=drawn, monitor=Watch())
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


def check_render_budget(frames: int, size: Any, kind: str) -> None:
    """Refuse, before any work, drawing ``frames`` of ``size`` that cannot fit the budget.

    The drawing's time (VTK, the GIF's encoding), the frames a GIF keeps and the
    renderer's address space (:func:`twoball.verify.output.render.render_estimate`).
    """
    from twoball._common.budget import check
    from twoball.verify.output.render import check_size, render_estimate

    width, height = check_size(size)
    asked = f"size {width}x{height}" if kind == ".png" else f"frames {frames} size {width}x{height}"
    check(asked, render_estimate(frames, (width, height), kind))


def mesh_block(field: Any) -> dict[str, object]:
    """``mesh_file`` for a provenance block: the user's file (path, radius, centre, pole)."""
    return {} if field.source is None else {"mesh_file": field.source}
