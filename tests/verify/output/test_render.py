"""twoball render: off-screen pictures and animations of the ball (pyvista, imageio)."""

from __future__ import annotations

import os
import subprocess
import sys

import imageio.v3 as iio
import numpy as np
import pytest
from twoball.fem_membrane.options import MeshOptions
from twoball.modal.parameters import preset
from twoball.verify.output.fields import ball_model, ball_scene, field_mesh, liftoff_frame
from twoball.verify.output.render import (
    BallScene,
    check_size,
    check_warp,
    render_frames,
    render_scene,
    round_size,
    surface_triangles,
)

from twoball._common.errors import ParameterError
from twoball.cli.main import main

WHITE = 255


@pytest.fixture(scope="module")
def model():
    return ball_model(preset("basketball"), field_mesh(MeshOptions(level=2, order=1)))


def ball_share(image: np.ndarray) -> float:
    """Share of the pixels that are not the white background."""
    return float(np.mean(np.any(image < 245, axis=-1)))


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


# --------------------------------------------------------------------------- command line
def test_cli_render_png_without_display_is_quiet(tmp_path):
    """A fresh interpreter with no DISPLAY: no X attempt; stderr holds only twoball's warnings.

    Level 1 is far too coarse for the N = 30 modes, so the accuracy warnings must be there.
    """
    out = tmp_path / "ball.png"
    env = {k: v for k, v in os.environ.items() if k not in ("DISPLAY", "VTK_DEFAULT_OPENGL_WINDOW")}
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    env["PYTHONPATH"] = root + os.pathsep + env.get("PYTHONPATH", "")
    proc = subprocess.run(
        [sys.executable, "-m", "twoball", "--quiet", "render", "--level", "1"]
        + ["--size", "200x150", "--out", str(out)],  # --quiet: no progress, warnings stay
        capture_output=True,
        text=True,
        check=False,
        env=env,
        cwd=tmp_path,
    )
    assert proc.returncode == 0, proc.stderr
    lines = proc.stderr.splitlines()
    assert lines and all(line.startswith("twoball: warning: ") for line in lines), proc.stderr
    assert any("under-resolves" in line for line in lines)
    assert iio.imread(out).shape[:2] == (150, 200)


def test_cli_render_gif(tmp_path, capsys):
    out = tmp_path / "ball.gif"
    code = main(
        ["render", "--level", "1", "--backend", "legendre", "--frames", "3"]
        + ["--size", "120x90", "--warp", "2", "--out", str(out)]
    )
    assert code == 0
    assert iio.imread(out, index=None).shape[:3] == (3, 90, 120)
    assert "Rendered" in capsys.readouterr().out


@pytest.mark.parametrize(
    ("extra", "flag"),
    [
        (["--size", "12x"], "--size"),
        (["--size", "0x100"], "--size"),
        (["--warp", "-1"], "--warp"),
        (["--warp", "big"], "--warp"),
        (["--frames", "0"], "--frames"),
        (["--time", "-1"], "--time"),
        (["--time", "1.0"], "--time"),
        (["--fps", "0"], "--fps"),
        (["--backend", "x"], "--backend"),
    ],
)
def test_cli_render_bad_input(tmp_path, capsys, extra, flag):
    out = tmp_path / "ball.png"
    with pytest.raises(SystemExit) as stop:
        main(["render", "--level", "1", *extra, "--out", str(out)])
    err = capsys.readouterr().err
    assert stop.value.code == 2
    assert len(err.strip().splitlines()) == 1 and flag in err and "Traceback" not in err
    assert list(tmp_path.iterdir()) == []


@pytest.mark.parametrize("name", ["missing/ball.png", "ball.tiff"])
def test_cli_render_bad_out(tmp_path, capsys, name):
    with pytest.raises(SystemExit) as stop:
        main(["render", "--level", "1", "--out", str(tmp_path / name)])
    err = capsys.readouterr().err
    assert stop.value.code == 2 and len(err.strip().splitlines()) == 1 and "--out" in err
