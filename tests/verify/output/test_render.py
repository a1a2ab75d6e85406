"""Off-screen pictures and animations of the ball (verify/output/render.py).

With or without a body of finite mass; sizes, warps, colour bar, unfinished MP4s.
"""

from __future__ import annotations

import math
import subprocess
import sys
import time
from pathlib import Path

import imageio.v3 as iio
import numpy as np
import pytest

import twoball
from tests import ROOT
from twoball._common.budget import DeadlineError, limits, running
from twoball._common.errors import ParameterError
from twoball._common.staging import SCRATCH_TAG
from twoball._common.watch import Watch
from twoball.modal.parameters import preset
from twoball.verify.output.fields import (
    ball_model,
    ball_scene,
    contact_scene,
    field_mesh,
    liftoff_frame,
)
from twoball.verify.output.render import (
    AUTO_WARP_LIMIT,
    AUTO_WARP_SHARE,
    RENDER_ADDRESS,
    BallScene,
    check_size,
    check_warp,
    render_estimate,
    render_frames,
    render_scene,
    round_size,
    surface_triangles,
)

CASE = preset("basketball").derive(modes=10)
LEVEL_1 = twoball.MeshOptions("sphere", level=1)


def ball_share(image: np.ndarray) -> float:
    """Share of the pixels that are not the white background."""
    return float(np.mean(np.any(image < 245, axis=-1)))


def test_render_draws_the_body_and_its_contact(coupled, tmp_path, monkeypatch):
    monkeypatch.setenv("VTK_DEFAULT_OPENGL_WINDOW", "vtkEGLRenderWindow")
    times = np.array([0.2e-3, coupled.t_end_s])
    scene = contact_scene(coupled, times, "legendre")
    assert np.array_equal(scene.body, coupled.motion("legendre", times)["s_m"])
    assert list(scene.contact) == [True, False]
    assert "IN CONTACT" in scene.caption(0, 1.0) and "in flight" in scene.caption(1, 1.0)
    out = tmp_path / "ball.png"
    result = twoball.render(
        out, CASE, backend="legendre", solver=twoball.Superposition(LEVEL_1),
        view=twoball.RenderOptions(size=(320, 240), frames=[0.2e-3]), body=twoball.Body(0.004),
    )  # fmt: skip
    image = iio.imread(out)
    assert image.shape[:2] == (240, 320)
    assert float(np.mean(np.any(image[..., :3] < 245, axis=-1))) > 0.1  # not blank
    assert result.report.mass_ratio == 0.004
    assert list(tmp_path.iterdir()) == [out]  # no scratch files left
    gif = tmp_path / "bounce.gif"
    twoball.render(
        gif, CASE, backend="legendre", solver=twoball.Superposition(LEVEL_1),
        view=twoball.RenderOptions(size=(160, 120), frames=3), body=twoball.Body(0.004),
    )  # fmt: skip
    assert iio.imread(gif, index=None).shape[:3] == (3, 120, 160)


def test_gif_colour_bar_is_smooth_and_footer_short(coarse, tmp_path):
    from twoball.verify.output.fields import ball_scene
    from twoball.verify.output.palette import colour_map_samples
    from twoball.verify.output.render import COLOUR_MAP, render_scene, wrap_footer

    scene = ball_scene(coarse, np.linspace(0.0, coarse.t_end_s, 3), "fem")
    out = render_scene(tmp_path / "ball.gif", scene, size=(320, 240), fps=10)
    frames = iio.imread(out, index=None)[..., :3]
    # the colour bar is the only place the pure colour map is drawn, unlit: count its
    # palette colours that the GIF kept exactly (a median cut alone leaves ~12 bands)
    bar = colour_map_samples(COLOUR_MAP)
    drawn = {tuple(c) for c in frames[0].reshape(-1, 3)}
    kept = sum(tuple(c) in drawn for c in bar)
    assert kept >= 60, kept
    # the background is exact white in every frame (each frame has its own palette)
    assert all(np.all(f[0, 0] == 255) for f in frames)
    footer = wrap_footer(scene.label)
    assert all(len(line) <= 30 for line in footer.splitlines())
    assert footer.replace("\n", " ") == scene.label


def test_an_unfinished_mp4_is_an_error_not_a_file(tmp_path):
    from twoball.verify.output.render import _check_mp4, _mp4_boxes

    box = (16).to_bytes(4, "big") + b"ftyp" + b"isom" + b"\0" * 4
    whole = tmp_path / "whole.mp4"
    whole.write_bytes(box + (8).to_bytes(4, "big") + b"moov")
    assert _mp4_boxes(whole) == [b"ftyp", b"moov"]
    _check_mp4(whole)
    cut = tmp_path / "cut.mp4"  # ffmpeg could not write its trailer (index)
    cut.write_bytes(box + (4096).to_bytes(4, "big") + b"mdat" + b"\0" * 100)
    with pytest.raises(OSError, match="cut.mp4"):
        _check_mp4(cut)


def test_png_shows_the_deformed_ball(model, tmp_path):
    out = tmp_path / "ball.png"
    scene = ball_scene(model, liftoff_frame(model), "fem")
    assert render_scene(out, scene, size=(320, 240)) == out
    image = iio.imread(out)
    assert image.shape[:2] == (240, 320)
    share = ball_share(image[..., :3])
    assert 0.1 < share < 0.8, share  # the ball fills a plausible part of the picture
    # the colours vary: the sphere is shaded and coloured by u, not one flat colour
    ball = image[..., :3][np.any(image[..., :3] < 245, axis=-1)]
    assert len(np.unique(ball // 8, axis=0)) > 50
    assert ball.std(axis=0).max() > 10
    assert list(tmp_path.iterdir()) == [out]  # no scratch files left


def test_the_body_leaves_the_pole(model):
    times = np.array([0.0, model.t_end_s])
    scene = ball_scene(model, times, "fem")
    report = model.backends["fem"].report
    assert scene.t_liftoff == report.t_liftoff_s
    # before lift-off the body rests on the pole; at the end it is far above it
    assert scene.body[0] == pytest.approx(scene.u[0, model.mesh.pole])
    dt = times[1] - report.t_liftoff_s
    flight = (
        report.result.displacement * model.case.radius
        + report.v_liftoff_m_s * dt
        - 0.5 * model.case.g * dt**2
    )
    assert scene.body[1] == pytest.approx(flight)
    assert scene.body[1] > 0.02


def test_frames_differ_over_time(model):
    scene = ball_scene(model, np.linspace(0.0, 0.012, 3), "fem")
    images = list(render_frames(scene, warp=None, size=(160, 120)))
    assert len(images) == 3 and all(i.shape == (120, 160, 3) for i in images)
    assert np.abs(images[0].astype(int) - images[2].astype(int)).max() > 50


@pytest.mark.parametrize(("suffix", "frames"), [(".gif", 4), (".mp4", 5)])
def test_animation_has_the_requested_frames(model, tmp_path, suffix, frames):
    out = tmp_path / f"ball{suffix}"
    scene = ball_scene(model, np.linspace(0.0, model.t_end_s, frames), "fem")
    render_scene(out, scene, size=(150, 100), fps=10)
    if suffix == ".gif":
        stack = iio.imread(out, index=None)
        assert stack.shape[:3] == (frames, 100, 150)
    else:
        import imageio.v2 as imageio

        reader = imageio.get_reader(out, format="FFMPEG")
        try:
            assert reader.count_frames() == frames
            assert tuple(reader.get_meta_data()["size"]) == (160, 112)  # rounded up to 16
        finally:
            reader.close()


def test_auto_warp_magnifies_small_displacements():
    points = np.array([[0, 0, 0.1], [0, 0.1, 0], [0.1, 0, 0]])
    small = BallScene(points, [[0, 1, 2]], [0.0], [[1e-4, 0, 0]], [1e-4], 0.1)
    large = BallScene(points, [[0, 1, 2]], [0.0], [[0.05, 0, 0]], [0.05], 0.1)
    assert small.auto_warp() == pytest.approx(0.15 * 0.1 / 1e-4)
    assert large.auto_warp() == 1.0


def test_quadratic_triangles_are_split_in_four():
    cells = np.array([[0, 1, 2, 3, 4, 5]])
    triangles = surface_triangles(cells)
    assert triangles.shape == (4, 3)
    assert sorted(set(triangles.ravel())) == list(range(6))


@pytest.mark.parametrize("size", ["100", "0x100", "100x", "axb", "100x20000", "-5x100"])
def test_bad_size(size):
    with pytest.raises(ParameterError, match="^size must be"):
        check_size(size)


def test_sizes_and_warps():
    assert check_size("320x240") == (320, 240)
    assert round_size((321, 240)) == (336, 240)
    assert check_warp(None) is None and check_warp(0) == 0.0
    for bad in (-1.0, float("nan"), float("inf")):
        with pytest.raises(ParameterError, match="^warp must be"):
            check_warp(bad)


def test_unwritable_output_leaves_nothing(model, tmp_path):
    scene = ball_scene(model, liftoff_frame(model), "fem")
    with pytest.raises(ParameterError, match="out"):
        render_scene(tmp_path / "missing" / "ball.png", scene)
    with pytest.raises(ParameterError, match="out"):
        render_scene(tmp_path / "ball.jpg", scene)
    assert list(tmp_path.iterdir()) == []


# --- The automatic warp of an animation shows the vibration, not only the initial flattening

CASE = twoball.Case.preset("basketball")
MESH = twoball.MeshOptions("sphere", level=1)
FRAMES = 12


def test_animation_warp_makes_the_wave_visible(tmp_path: Path) -> None:
    model = ball_model(CASE, field_mesh(MESH), backends=("fem",))
    times = np.linspace(0.0, model.t_end_s, FRAMES)
    scene = ball_scene(model, times, "fem")
    radius = CASE.radius
    largest = float(np.abs(scene.u).max())
    wave = float(np.abs(scene.u[times >= math.pi / CASE.wave_speed]).max())
    warp = scene.auto_warp()
    assert warp == pytest.approx(
        min(AUTO_WARP_SHARE * radius / wave, AUTO_WARP_LIMIT * radius / largest), rel=1e-12
    )
    assert largest > 10 * wave  # the flattening dwarfs the waves ...
    assert warp > 5 * AUTO_WARP_SHARE * radius / largest  # ... and no longer sets the warp
    assert warp * wave > 0.04 * radius  # the wave drawn at >= 4 % of R (old: < 1 %)
    assert warp * largest <= AUTO_WARP_LIMIT * radius * (1 + 1e-12)  # the ball never folds
    view = twoball.RenderOptions(size="64x48", frames=FRAMES)
    result = twoball.render(tmp_path / "ball.gif", solver=twoball.Superposition(MESH), view=view)
    assert result.warp == pytest.approx(warp, rel=1e-12)


def test_a_single_late_picture_keeps_the_old_rule() -> None:
    model = ball_model(CASE, field_mesh(MESH), backends=("fem",))
    scene = ball_scene(model, np.array([0.02]), "fem")
    largest = float(np.abs(scene.u).max())
    assert scene.auto_warp() == pytest.approx(AUTO_WARP_SHARE * CASE.radius / largest)


EARLIER = b"GIF89a an earlier animation"


def scratch(folder: Path) -> list[str]:
    return [p.name for p in folder.iterdir() if SCRATCH_TAG in p.name]


def test_the_estimate_counts_what_a_gif_keeps() -> None:
    """A GIF keeps its frames (7 bytes a pixel), an MP4 one; the time grows with both."""
    gif = render_estimate(2000, (640, 480), ".gif")
    mp4 = render_estimate(2000, (640, 480), ".mp4")
    assert gif.memory - mp4.memory == pytest.approx(7 * 640 * 480 * 1999)
    assert gif.address == gif.memory + RENDER_ADDRESS
    assert gif.seconds == mp4.seconds > render_estimate(2000, (320, 240), ".gif").seconds
    # 2000 frames at 640x480: minutes (measured 430 s at a load of 5.5 on two cores)
    assert 60.0 < gif.seconds < 430.0


def test_the_deadline_stops_a_drawing_within_a_second(coarse, tmp_path) -> None:
    """300 frames (about 20 s of drawing) under a 3 s limit: stopped within 2T + 3 s of
    the start, the earlier file left as it was, no scratch."""
    out = tmp_path / "x.gif"
    out.write_bytes(EARLIER)
    scene = ball_scene(coarse, np.linspace(0.0, coarse.t_end_s, 300), "legendre")
    limit = 3.0
    with limits(max_time=f"{limit}s"), running():
        began = time.monotonic()
        with pytest.raises(DeadlineError, match=r"drawing 300 frame\(s\) into x.gif"):
            render_scene(out, scene, size=(320, 240), monitor=Watch())
        took = time.monotonic() - began
    assert took < 2 * limit + 3, took
    assert out.read_bytes() == EARLIER and scratch(tmp_path) == []


def test_a_renderer_out_of_address_space_is_out_of_memory(tmp_path) -> None:
    """The child fails inside VTK (the limit it inherits is ~300 MiB above what the parent
    maps): MemoryError in the parent, not an abort of the process; no scratch."""
    out = tmp_path / "c.gif"
    done = subprocess.run(
        [sys.executable, str(Path(__file__).with_name("render_child.py")), str(out)],
        cwd="/",
        env={"PYTHONPATH": str(ROOT), "PATH": "/usr/bin:/bin", "OPENBLAS_NUM_THREADS": "1"},
        capture_output=True,
        text=True,
        timeout=300,
    )
    assert done.returncode == 0, done.stderr[-2000:]
    assert done.stdout.startswith("MemoryError the renderer (VTK) ended by SIG"), done.stdout
    assert "address-space limit" in done.stdout
    assert not out.exists() and scratch(tmp_path) == []


def test_gif_frames_match_the_rendered_pictures(model, tmp_path):
    from twoball.verify.output.render import _write_gif

    scene = ball_scene(model, np.linspace(0.0, model.t_end_s, 4), "fem")
    pictures = np.stack(list(render_frames(scene, size=(320, 240))))
    _write_gif(tmp_path / "ball.gif", iter(pictures), 10.0)
    frames = iio.imread(tmp_path / "ball.gif", index=None)[..., :3]
    error = np.abs(frames.astype(int) - pictures.astype(int))
    drawn = np.any(pictures < 250, axis=-1)  # the ball, the bar and the text
    # one shared palette looked up through Pillow's colour cache: 2.0 levels on average,
    # 2.3 on the drawn pixels, the white background at 253 and the shading in bands
    assert error.mean() < 0.5, error.mean()
    assert error[drawn].mean() < 1.2, error[drawn].mean()
    assert np.all(frames[~drawn & (pictures.min(axis=-1) == 255)] == 255)
