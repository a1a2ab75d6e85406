"""Off-screen pictures and animations of the bouncing ball with pyvista (PNG, GIF, MP4).

The ball is drawn deformed by its radial displacement (magnified by a *warp*
factor) and coloured by the displacement in mm; the upper body, a small sphere,
sits on the pole until lift-off and then follows its free flight.  All inputs
are SI (m, s); :func:`twoball.verify.output.fields.ball_scene` builds a :class:`BallScene` from
a case.

Works without a display: before VTK is loaded, ``VTK_DEFAULT_OPENGL_WINDOW`` is
set to ``vtkEGLRenderWindow`` unless the user has chosen a window class
(otherwise VTK tries X first and prints "bad X server connection"); pyvista's
``OFF_SCREEN`` is switched on, and VTK's log and output window are kept quiet
while rendering, so no warnings reach the terminal.  GIFs are written with
imageio (pillow), MP4 files with imageio-ffmpeg (H.264, frame sizes rounded up
to multiples of 16 so that no encoder has to resize).
"""

from __future__ import annotations

import contextlib
import errno
import math
import os
from collections.abc import Callable, Iterator
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np

from twoball._common.child import ChildDied
from twoball._common.choices import DEFAULT_SIZE
from twoball._common.errors import NumericalError, ParameterError
from twoball._common.estimate import BASE_MEMORY, Estimate
from twoball._common.signals import checkpoint, held_signals
from twoball._common.staging import staged_file

IMAGE_KINDS: tuple[str, ...] = (".png", ".gif", ".mp4")
MACRO_BLOCK = 16  # MP4 (H.264, yuv420p) frame sizes must be multiples of this
AUTO_WARP_SHARE = 0.15  # auto warp: the largest displacement drawn at 15 % of R
MAX_WARP_SHARE = 1.0  # a given warp may draw the largest displacement at R at most
AUTO_WARP_LIMIT = 0.9  # the automatic warp draws the largest displacement within 90 % of R
BODY_SHARE = 0.2  # radius of the drawn upper body, as a share of R
BODY_VIEW = 1.0  # the camera frames the body's flight up to this many R above the pole
MAX_SIZE = 4096  # largest accepted image side [px]
COLOUR_MAP = "coolwarm"  # of the displacement, drawn on the ball and in the colour bar
FOOTER_CHARS = 30  # longest footer line at the default size [characters]
FLOOR_SIZE = 1.25  # radius of the drawn floor disc, in R
FLOOR_VIEW = 2.0  # the camera frames the floor down to this many R below the centre
FLOOR_MARGIN = 0.55  # free band below the floor for the footer, in R
FLOOR_COLOUR = "#b0b0b0"


@dataclass(frozen=True)
class BallScene:
    """What a picture shows, in SI units.

    Parameters
    ----------
    points : ndarray, shape (P, 3)
        Undeformed node coordinates [m] on the sphere of radius ``radius``.
    cells : ndarray, shape (T, 3) or (T, 6)
        Triangles or quadratic triangles (meshio ``triangle6`` node order).
    times : ndarray, shape (F,)
        Frame times [s] after maximal compression.
    u : ndarray, shape (F, P)
        Radial displacement [m] at the nodes.
    body : ndarray, shape (F,)
        Radial position [m] of the upper body's contact point relative to the
        undeformed pole: ``u(t, 0)`` before lift-off, the ballistic path after.
    radius : float
        Ball radius R [m].
    t_liftoff : float or None
        Lift-off time [s], if the body lifts off.
    label : str
        Short description drawn in a corner (case, backend).
    settle_time : float or None
        Time [s] after which the initial flattening has travelled round the ball
        (``pi / c``); the automatic warp is measured on the frames from then on
        (:meth:`auto_warp`).  None: on every frame.
    footer_chars : int
        Longest line of the footer (``label``) at the default size [characters].
    """

    points: np.ndarray
    cells: np.ndarray
    times: np.ndarray
    u: np.ndarray
    body: np.ndarray
    radius: float
    t_liftoff: float | None = None
    label: str = ""
    settle_time: float | None = None
    footer_chars: int = FOOTER_CHARS

    def __post_init__(self) -> None:
        times = np.atleast_1d(np.asarray(self.times, dtype=float))
        u = np.atleast_2d(np.asarray(self.u, dtype=float))
        body = np.atleast_1d(np.asarray(self.body, dtype=float))
        points = np.asarray(self.points, dtype=float)
        if u.shape != (times.size, points.shape[0]) or body.shape != times.shape:
            raise ValueError("u must have shape (F, P) and body shape (F,) for F times")
        object.__setattr__(self, "times", times)
        object.__setattr__(self, "u", u)
        object.__setattr__(self, "body", body)
        object.__setattr__(self, "points", points)
        object.__setattr__(self, "cells", np.asarray(self.cells, dtype=np.int64))

    def caption(self, k: int, warp: float) -> str:
        """Text of frame ``k``: time, lift-off, where the body is, warp (short lines)."""
        text = f"t = {self.times[k] * 1e3:6.2f} ms"
        if self.t_liftoff is not None:
            text += f"\nlift-off {self.t_liftoff * 1e3:.2f} ms\nbody "
            text += "in flight" if self.times[k] >= self.t_liftoff - 1e-12 else "on the pole"
        return text + (f"\nwarp x{warp:.3g}" if warp != 1.0 else "")

    def floor_level(self, k: int, warp: float) -> float | None:
        """Height [m] of a floor plane below the ball in frame ``k`` (None: no floor drawn)."""
        return None

    def auto_warp(self) -> float:
        """Warp factor that makes the vibration visible: the wave, not the flattening.

        The largest displacement from :attr:`settle_time` on (the initial
        flattening has then travelled round the ball) is drawn at 15 % of R
        (:data:`AUTO_WARP_SHARE`), as far as the largest displacement of all
        frames stays within 90 % of R (:data:`AUTO_WARP_LIMIT`: the ball never
        folds through its centre); never below 1.  Frames all before
        :attr:`settle_time`, or none given: the largest of all frames at 15 %.

        The basketball's animation: the 17 mm flattening at t = 0 alone would
        give x1.07, which leaves the ~1 mm waves after lift-off invisible; the
        rule gives x6.3 (the flattening drawn at 90 % of R).
        """
        if not self.u.size:
            return 1.0
        size = np.abs(self.u).max(axis=1)  # largest |u| of each frame
        largest = float(size.max())
        if largest <= 0.0:
            return 1.0
        late = size if self.settle_time is None else size[self.times >= self.settle_time]
        wave = float(late.max()) if late.size else largest
        warp = AUTO_WARP_SHARE * self.radius / (wave if wave > 0.0 else largest)
        return max(1.0, min(warp, AUTO_WARP_LIMIT * self.radius / largest))


# --------------------------------------------------------------------------- options
def check_size(size: tuple[int, int] | str, flag: str = "size") -> tuple[int, int]:
    """Image size ``(width, height)`` in pixels from a tuple or a ``WxH`` string."""
    valid = f"WIDTHxHEIGHT in pixels, each an integer in [16, {MAX_SIZE}]"
    if isinstance(size, str):
        from twoball._common.ranges import whole

        parts = size.lower().replace(" ", "").split("x")
        try:
            width, height = (whole(p) for p in parts)
        except ValueError:
            raise ParameterError(flag, valid, size) from None
    else:
        try:
            width, height = size
        except (TypeError, ValueError):
            raise ParameterError(flag, valid, size) from None
        if not all(isinstance(v, int | np.integer) for v in (width, height)):
            raise ParameterError(flag, valid, size)
    if not (16 <= width <= MAX_SIZE and 16 <= height <= MAX_SIZE):
        raise ParameterError(flag, valid, size if isinstance(size, str) else tuple(size))
    return int(width), int(height)


def round_size(size: tuple[int, int], block: int = MACRO_BLOCK) -> tuple[int, int]:
    """``size`` with each side rounded up to a multiple of ``block`` (MP4 macro blocks)."""
    return tuple(int(math.ceil(s / block) * block) for s in size)  # type: ignore[return-value]


def check_warp(warp: float | None, flag: str = "warp") -> float | None:
    """A warp factor: None (automatic) or a finite number >= 0."""
    from twoball._common.errors import real_number

    if warp is None:
        return None
    value = real_number(flag, warp, "a finite number >= 0 (or auto)")
    if value < 0.0:
        raise ParameterError(flag, "a finite number >= 0 (or auto)", warp)
    return value


def check_scene_warp(scene: BallScene, warp: float | None, flag: str = "warp") -> None:
    """Refuse a warp that draws the largest displacement beyond R (the ball folds through
    its centre and leaves the picture: ``warp=1e308`` draws no ball at all).

    Checked once the displacements are known, before anything is drawn or written.
    """
    if warp is None:
        return
    largest = float(np.abs(scene.u).max()) if scene.u.size else 0.0
    if largest > 0.0 and float(warp) * largest > MAX_WARP_SHARE * scene.radius:
        limit = MAX_WARP_SHARE * scene.radius / largest
        valid = (
            f"at most {limit:.4g} here (warp x the largest |u|, {largest * 1e3:.3g} mm, "
            f"must stay within R = {scene.radius:g} m, or the drawn ball folds through its "
            "centre), or auto"
        )
        raise ParameterError(flag, valid, warp)


def image_kind(path: str | os.PathLike[str], flag: str = "out") -> str:
    """``.png``, ``.gif`` or ``.mp4`` from the suffix of ``path``."""
    suffix = Path(path).suffix.lower()
    if suffix not in IMAGE_KINDS:
        raise ParameterError(flag, "a file name ending in .png, .gif or .mp4", str(path))
    return suffix


# --------------------------------------------------------------------------- VTK set-up
def _pyvista():
    """Import pyvista for off-screen use (EGL unless the user chose a window class)."""
    os.environ.setdefault("VTK_DEFAULT_OPENGL_WINDOW", "vtkEGLRenderWindow")
    import pyvista

    pyvista.OFF_SCREEN = True
    return pyvista


@contextlib.contextmanager
def quiet_vtk() -> Iterator[None]:
    """Keep VTK's warnings off the terminal while rendering (restored afterwards).

    VTK reports through two channels: the logger (``vtkLogger``, e.g. window
    creation messages) and the output window (``vtkOutputWindow``, e.g. warnings
    of filters).  The logger's terminal verbosity is lowered to errors and the
    output window replaced by a string buffer for the duration.
    """
    from vtkmodules.vtkCommonCore import vtkLogger, vtkOutputWindow, vtkStringOutputWindow

    previous_window = vtkOutputWindow.GetInstance()
    previous_level = vtkLogger.GetCurrentVerbosityCutoff()
    buffer = vtkStringOutputWindow()
    vtkOutputWindow.SetInstance(buffer)
    vtkLogger.SetStderrVerbosity(vtkLogger.VERBOSITY_ERROR)
    try:
        yield
    finally:
        vtkOutputWindow.SetInstance(previous_window)
        vtkLogger.SetStderrVerbosity(previous_level)


# --------------------------------------------------------------------------- geometry
def surface_triangles(cells: np.ndarray) -> np.ndarray:
    """Flat triangles for drawing: P1 cells as they are, each P2 cell split into four.

    The split uses the three edge nodes (meshio ``triangle6`` order), so every
    node of a quadratic mesh is a drawn vertex.
    """
    cells = np.asarray(cells, dtype=np.int64)
    if cells.shape[1] == 3:
        return cells
    if cells.shape[1] != 6:  # P3/P4 cells: not drawn (refused, not mis-split)
        order = {10: 3, 15: 4}.get(cells.shape[1], cells.shape[1])
        raise ParameterError("order", "1 or 2 for field files and pictures", order)
    a, b, c, ab, bc, ca = cells.T
    return np.vstack(
        [
            np.column_stack([a, ab, ca]),
            np.column_stack([ab, b, bc]),
            np.column_stack([ca, bc, c]),
            np.column_stack([ab, bc, ca]),
        ]
    )


def deformed_points(points: np.ndarray, u: np.ndarray, warp: float) -> np.ndarray:
    """``x + warp * u * n`` with the outward unit normal ``n = x / |x|`` of the sphere."""
    normal = points / np.linalg.norm(points, axis=1, keepdims=True)
    return points + (warp * u)[:, None] * normal


def color_limits(u_mm: np.ndarray) -> tuple[float, float]:
    """Symmetric colour range [mm] covering 99.5 % of the nodal values of all frames.

    A percentile, not the maximum: the flattened bottom at t = 0 is far deeper
    than the later waves and would wash out every other frame.
    """
    spread = float(np.percentile(np.abs(u_mm), 99.5)) if u_mm.size else 0.0
    spread = spread if spread > 0 else 1.0
    return -spread, spread


# --------------------------------------------------------------------------- rendering
class _Renderer:
    """One off-screen plotter reused for every frame of a scene."""

    def __init__(self, scene: BallScene, warp: float, size: tuple[int, int]) -> None:
        pv = _pyvista()
        self.scene = scene
        self.warp = warp
        radius = scene.radius
        self.body_radius = BODY_SHARE * radius
        triangles = surface_triangles(scene.cells)
        faces = np.hstack([np.full((len(triangles), 1), 3), triangles]).ravel()
        self.surface = pv.PolyData(scene.points.copy(), faces)
        self.surface.point_data["u [mm]"] = scene.u[0] * 1e3
        self.plotter = pv.Plotter(off_screen=True, window_size=list(size))
        scale = min(size[0] / DEFAULT_SIZE[0], size[1] / DEFAULT_SIZE[1])  # text follows size
        small, large = max(9, round(10 * scale)), max(10, round(12 * scale))
        self.plotter.set_background("white")
        clim = color_limits(scene.u * 1e3)
        self.actor = self.plotter.add_mesh(
            self.surface,
            scalars="u [mm]",
            cmap=COLOUR_MAP,
            n_colors=256,
            clim=clim,
            smooth_shading=True,
            copy_mesh=False,
            scalar_bar_args={
                "title": "u [mm]\n",  # the newline lifts the title clear of the top label
                "color": "black",
                "vertical": True,
                "position_x": 0.84,
                "position_y": 0.22,
                "height": 0.56,
                "width": 0.08,
                "fmt": "%.1f",
                "n_labels": 3,
                "title_font_size": max(10, round(16 * scale)),
                "label_font_size": max(9, round(14 * scale)),
                "unconstrained_font_size": True,
            },
        )
        self.drawn = self.actor.mapper.dataset  # what the mapper draws (normals added)
        body = pv.Sphere(radius=self.body_radius, theta_resolution=32, phi_resolution=32)
        self.body = self.plotter.add_mesh(body, color="gold", smooth_shading=True)
        self.floor = None
        if scene.floor_level(0, warp) is not None:
            # a disc of floor under the ball, moved to its height in each frame
            disc = pv.Disc(
                center=(0.0, 0.0, 0.0),
                inner=0.0,
                outer=FLOOR_SIZE * radius,
                normal=(0.0, 0.0, 1.0),
                c_res=96,
            )
            self.floor = self.plotter.add_mesh(disc, color=FLOOR_COLOUR, lighting=False)
        # short lines: a corner annotation shrinks its font until its longest line fits
        chars = scene.footer_chars
        footer = wrap_footer(scene.label, max(chars, round(chars * scale)))
        self.plotter.add_text(footer, position="lower_left", font_size=small, color="black")
        self.clock = self.plotter.add_text(
            "", position="upper_left", font_size=large, color="black"
        )
        self._place_camera()

    def _place_camera(self) -> None:
        radius = self.scene.radius
        # the body's flight is framed up to R above the pole: a magnified flight would
        # otherwise shrink the ball to a dot (the body then leaves at the top)
        reach = min(self.warp * float(self.scene.body.max()), BODY_VIEW * radius)
        top = radius + reach + 2.0 * self.body_radius
        bottom = -radius * (1.0 + 0.2)
        levels = [self.scene.floor_level(k, self.warp) for k in range(self.scene.times.size)]
        floors = [z for z in levels if z is not None]
        if floors:  # frame the floor too (down to FLOOR_VIEW radii), the footer below it
            lowest = max(min(floors), -FLOOR_VIEW * radius)
            bottom = min(bottom, lowest) - FLOOR_MARGIN * radius
        centre = 0.5 * (top + bottom)
        height = top - bottom
        distance = 1.25 * max(height, 2.4 * radius) / (2.0 * math.tan(math.radians(15.0)))
        direction = np.array([1.0, -2.6, 0.35])
        direction /= np.linalg.norm(direction)
        focus = np.array([0.0, 0.0, centre])
        self.plotter.camera_position = [
            tuple(focus + distance * direction),
            tuple(focus),
            (0, 0, 1),
        ]
        self.plotter.camera.view_angle = 30.0

    def frame(self, k: int) -> np.ndarray:
        """RGB image (H, W, 3) of frame ``k``."""
        scene = self.scene
        u = scene.u[k]
        points = deformed_points(scene.points, u, self.warp)
        self.surface.points = points
        self.surface.point_data["u [mm]"] = u * 1e3
        self.drawn.points = points
        self.drawn.point_data["u [mm]"] = u * 1e3
        normals = self.surface.compute_normals(
            cell_normals=False, split_vertices=False, auto_orient_normals=False
        ).point_data["Normals"]
        self.drawn.point_data["Normals"] = normals
        self.drawn.point_data.active_normals_name = "Normals"
        height = scene.radius + self.warp * float(scene.body[k]) + self.body_radius
        self.body.position = (0.0, 0.0, height)
        if self.floor is not None:
            level = scene.floor_level(k, self.warp)
            self.floor.position = (0.0, 0.0, level)
        self.clock.set_text("upper_left", scene.caption(k, self.warp))
        self.plotter.render()
        return np.asarray(self.plotter.screenshot(return_img=True))[..., :3].copy()

    def close(self) -> None:
        self.plotter.close()


def render_frames(
    scene: BallScene, warp: float | None = None, size: tuple[int, int] = DEFAULT_SIZE
) -> Iterator[np.ndarray]:
    """Yield one RGB image (H, W, 3), uint8, per frame of ``scene``.

    Parameters
    ----------
    scene : BallScene
        Geometry and motion (SI).
    warp : float or None
        Displacement magnification; None: :meth:`BallScene.auto_warp`.
    size : (int, int)
        Image width and height [px].

    From the import of VTK to the closing of its window, SIGINT and SIGTERM
    are held back (:func:`twoball._common.signals.held_signals`: an exception
    inside VTK can crash the interpreter or be swallowed by it) and raised
    between frames, before any frame is handed out.
    """
    warp = scene.auto_warp() if warp is None else check_warp(warp)
    size = check_size(size)
    # VTK is imported and runs with SIGINT/SIGTERM held back: raised between frames
    with held_signals(), quiet_vtk():
        renderer = _Renderer(scene, warp, size)
        try:
            for k in range(scene.times.size):
                checkpoint()
                image = renderer.frame(k)
                checkpoint()
                yield image
        finally:
            renderer.close()


def wrap_footer(text: str, width: int = FOOTER_CHARS) -> str:
    """``text`` broken after ``:`` and ``,`` into lines of at most ``width`` characters.

    >>> wrap_footer("finite elements: R = 0.12 m, c = 320 1/s, D = 0.13", 24)
    'finite elements:\nR = 0.12 m, c = 320 1/s,\nD = 0.13'
    """
    import re

    pieces = re.findall(r"[^,:]+[,:]?", text)
    lines: list[str] = []
    for piece in (p.strip() for p in pieces):
        if lines and not lines[-1].endswith(":") and len(lines[-1]) + 1 + len(piece) <= width:
            lines[-1] += " " + piece
        else:
            lines.append(piece)
    return "\n".join(lines)


def _write_png(target: Path, images: Iterator[np.ndarray]) -> int:
    import imageio.v3 as iio

    image = next(images)
    target.write_bytes(iio.imwrite("<bytes>", image, extension=".png"))
    return 1


def _write_gif(target: Path, images: Iterator[np.ndarray], fps: float) -> int:
    from twoball.verify.output.palette import gif_bytes

    frames = np.stack(list(images))
    # encoded in memory, then written by Python: a full disk is one OSError
    target.write_bytes(gif_bytes(frames, fps, COLOUR_MAP))
    return len(frames)


def _write_mp4(target: Path, images: Iterator[np.ndarray], fps: float) -> int:
    import imageio.v2 as imageio

    count = 0
    writer = imageio.get_writer(
        target,
        format="FFMPEG",  # type: ignore[arg-type]
        mode="I",
        fps=fps,
        codec="libx264",
        pixelformat="yuv420p",
        macro_block_size=MACRO_BLOCK,
        ffmpeg_log_level="quiet",  # its failures are reported below, in one line
    )
    try:
        for image in images:
            writer.append_data(image)
            count += 1
    finally:
        writer.close()
    _check_mp4(target)
    return count


def _mp4_boxes(path: Path) -> list[bytes]:
    """Types of the top-level boxes of an MP4 file; empty if they do not tile the file."""
    import struct

    kinds, end = [], path.stat().st_size
    with open(path, "rb") as handle:
        start = 0
        while start < end:
            header = handle.read(8)
            if len(header) < 8:
                return []
            size, kind = struct.unpack(">I4s", header)
            if size == 1:  # 64-bit size follows the type
                size = struct.unpack(">Q", handle.read(8))[0]
            elif size == 0:  # the box runs to the end of the file
                size = end - start
            if size < 8 or start + size > end:
                return []
            kinds.append(kind)
            start += size
            handle.seek(start)
    return kinds


def _check_mp4(target: Path) -> None:
    """Raise OSError unless ffmpeg finished ``target`` (it ends with the ``moov`` index).

    ffmpeg reports a failed write (a full disk) only in its log; imageio does not
    raise, so the file is checked before it is put in place.
    """
    if target.is_file() and b"moov" in _mp4_boxes(target):
        return
    stat = os.statvfs(target.parent)
    full = stat.f_bavail * stat.f_frsize < (1 << 20)
    code = errno.ENOSPC if full else errno.EIO
    raise OSError(
        code, os.strerror(code) if full else "ffmpeg did not finish the video", str(target)
    )


#: Drawing one frame [s per pixel] and its fixed part [s]: VTK off-screen at 640x480, the
#: GIF's quantisation included (measured 0.19 s a frame at a load of 5.5 on two cores,
#: 0.07 s idle; a level-1 ball: the mesh's size hardly counts).
RENDER_SECONDS_PER_PIXEL = 2.0e-7
RENDER_SECONDS_PER_FRAME = 0.01
#: Starting the renderer: its child process, VTK's import and its window [s].
RENDER_START_SECONDS = 3.0
#: Address space the renderer maps beyond the interpreter's (VTK's off-screen window and
#: its thread pools; measured 0.95-1.0 GiB of VmPeak at 5 and 60 frames of 640x480).
RENDER_ADDRESS = 1 << 30
#: Resident memory of the renderer beside the frames [bytes].
RENDER_MEMORY = 200 << 20
#: Bytes a GIF holds per pixel of every frame: the RGB frames, their stack, the indexed one.
GIF_BYTES_PER_PIXEL = 7


def render_estimate(frames: int, size: tuple[int, int], kind: str) -> Estimate:
    """Memory, address space and time of drawing ``frames`` of ``size`` into a ``kind`` file.

    A GIF keeps every frame until it is encoded (one palette for all); PNG and MP4
    keep one at a time.  The fields themselves are estimated apart
    (:func:`twoball.verify.output.fields.frames_estimate`).
    """
    pixels = float(size[0]) * float(size[1])
    kept = frames if kind == ".gif" else 1
    memory = BASE_MEMORY + RENDER_MEMORY + GIF_BYTES_PER_PIXEL * pixels * kept
    seconds = RENDER_START_SECONDS + frames * (
        RENDER_SECONDS_PER_FRAME + RENDER_SECONDS_PER_PIXEL * pixels
    )
    return Estimate(memory, seconds, address=memory + RENDER_ADDRESS)


def render_scene(
    path: str | os.PathLike[str],
    scene: BallScene,
    *,
    warp: float | None = None,
    size: tuple[int, int] | str = DEFAULT_SIZE,
    fps: float = 20.0,
    progress: Callable[[int], None] | None = None,
    monitor: Any = None,
) -> Path:
    """Render ``scene`` to a PNG (its first frame), an animated GIF or an MP4.

    Parameters
    ----------
    path : path-like
        Output file; the suffix (``.png``, ``.gif``, ``.mp4``) chooses the kind.
        Written beside, then renamed into place (no partial file on failure).
    scene : BallScene
        What to draw (SI).
    warp : float or None
        Displacement magnification; None for :meth:`BallScene.auto_warp`.
    size : (int, int) or "WxH"
        Image size [px]; rounded up to multiples of 16 for MP4.
    fps : float
        Frames per second of an animation.
    progress : callable, optional
        Called with the number of frames drawn so far, after each frame (drawn
        in process only).
    monitor : Monitor, optional
        The caller's monitor (:class:`~twoball._common.monitor.Monitor`).  One with
        ``long_call`` (the verbs' :class:`~twoball._common.watch.Watch`) draws in
        a child process: the time limit and a signal act within a fraction of a
        second whatever VTK is doing, and an allocation that fails inside VTK (a
        C++ abort under an address-space limit) ends the child, not this
        process -- it is raised here as :class:`MemoryError`.

    Returns
    -------
    Path
        ``path``.
    """
    out = Path(path).expanduser()
    kind = image_kind(out)
    size = check_size(size)
    warp = check_warp(warp)
    check_scene_warp(scene, warp)
    from twoball._common.errors import real_number

    if not real_number("fps", fps, "a finite number > 0") > 0:
        raise ParameterError("fps", "a finite number > 0", fps)
    if kind == ".mp4":
        size = round_size(size)
    with staged_file(out) as target:
        runner = getattr(monitor, "long_call", None)
        if runner is None:
            draw(str(target), scene, warp, size, fps, progress)
        else:
            doing = f"drawing {scene.times.size} frame(s) into {out.name}"
            try:
                runner(draw, str(target), scene, warp, size, fps, doing=doing)
            except ChildDied as died:
                raise renderer_died(died) from None
    return out


def draw(
    target: str,
    scene: BallScene,
    warp: float | None,
    size: tuple[int, int],
    fps: float,
    progress: Callable[[int], None] | None = None,
) -> int:
    """Draw ``scene`` into the file ``target`` (its suffix the kind); the frames written.

    In the renderer's child process (:func:`render_scene` with a monitor) the C
    libraries' own messages on standard error (the EGL loader's warnings when an
    allocation fails) are dropped: what the child has to say comes back as its
    outcome, and the command's error stays one line.
    """
    from twoball._common.child import CHILD_ENV

    if os.environ.get(CHILD_ENV):
        null = os.open(os.devnull, os.O_WRONLY)
        os.dup2(null, 2)
        os.close(null)
    path = Path(target)
    kind = path.suffix.lower()
    images = render_frames(scene, warp, size)
    if progress is not None:
        images = _counted(images, progress)
    try:
        if kind == ".png":
            return _write_png(path, images)
        if kind == ".gif":
            return _write_gif(path, images, fps)
        return _write_mp4(path, images, fps)
    finally:
        images.close()  # type: ignore[attr-defined]


def renderer_died(died: ChildDied) -> BaseException:
    """What a renderer's child that ended without an outcome means here.

    Ended by SIGABRT (a C++ ``bad_alloc``), SIGSEGV or SIGBUS (a failed ``malloc``
    used all the same) under an address-space limit, or by SIGKILL (the OOM
    killer): out of memory (:class:`MemoryError`: one line, exit status 3).
    Anything else: :class:`~twoball.NumericalError` naming the status (exit 3).
    """
    import resource
    import signal

    code = died.returncode if died.returncode is not None else 0
    number = -code
    try:
        limited = resource.getrlimit(resource.RLIMIT_AS)[0] != resource.RLIM_INFINITY
    except (OSError, ValueError):
        limited = False
    crashes = {signal.SIGABRT, signal.SIGSEGV, signal.SIGBUS}
    if number == signal.SIGKILL or (limited and number in crashes):
        name = signal.Signals(number).name
        where = " under the address-space limit (ulimit -v)" if limited else ""
        return MemoryError(f"the renderer (VTK) ended by {name}{where}")
    return NumericalError(str(died))


def _counted(images: Iterator[np.ndarray], progress: Callable[[int], None]) -> Iterator[np.ndarray]:
    """``images``, calling ``progress(k)`` after the k-th; closing it closes ``images``."""
    try:
        for k, image in enumerate(images, start=1):
            yield image
            progress(k)
    finally:
        images.close()  # type: ignore[attr-defined]


@dataclass(frozen=True)
class ContactScene(BallScene):
    """A scene with a body of finite mass (SI).

    Parameters
    ----------
    contact : ndarray of bool, shape (F,)
        True in the frames where the body is on the membrane.
    impacts : ndarray, shape (I,)
        Times [s] of the body's impacts on the membrane.
    mass_ratio : float
        ``mu = m1 / m2`` of the body.

    The other parameters are those of :class:`BallScene`; ``body`` is the
    body's height ``s(t)`` [m] and ``t_liftoff`` the final separation [s].
    """

    contact: np.ndarray = field(default_factory=lambda: np.zeros(0, dtype=bool))
    impacts: np.ndarray = field(default_factory=lambda: np.zeros(0))
    mass_ratio: float = 0.0

    def __post_init__(self) -> None:
        super().__post_init__()
        contact = np.atleast_1d(np.asarray(self.contact, dtype=bool))
        if contact.shape != self.times.shape:
            raise ValueError("contact must have one flag per frame, shape (F,)")
        object.__setattr__(self, "contact", contact)
        object.__setattr__(self, "impacts", np.atleast_1d(np.asarray(self.impacts, dtype=float)))

    def caption(self, k: int, warp: float) -> str:
        """Time; the body in contact or in flight and its impacts so far; lift-off; warp."""
        t = float(self.times[k])
        text = f"t = {t * 1e3:6.2f} ms\nmu = {self.mass_ratio:g}"
        text += "\nbody IN CONTACT" if self.contact[k] else "\nbody in flight"
        text += f"\nimpacts so far: {int(np.sum(self.impacts <= t + 1e-12))}"
        if self.t_liftoff is not None:
            text += f"\nlift-off {self.t_liftoff * 1e3:.2f} ms"
        return text + (f"\nwarp x{warp:.3g}" if warp != 1.0 else "")
