"""twoball render: pictures from the command line; bad input in one line."""

from __future__ import annotations

import os
import subprocess
import sys

import imageio.v3 as iio
import numpy as np
import pytest

from tests import ROOT
from twoball.cli.main import main


def test_render_writes_a_png_of_the_file_mesh(ball_files, tmp_path, capsys):
    out = tmp_path / "ball.png"
    code = main(["render", "--mesh-file", str(ball_files["vtu"]), "--size", "160x120"]
                + ["--out", str(out)])  # fmt: skip
    assert code == 0 and "Rendered" in capsys.readouterr().out
    image = iio.imread(out)
    assert image.shape[:2] == (120, 160)
    assert np.mean(np.any(image[..., :3] < 245, axis=-1)) > 0.05  # the ball, not a blank


def test_cli_render_png_without_display_is_quiet(tmp_path):
    """A fresh interpreter with no DISPLAY: no X attempt; stderr holds only twoball's warnings.

    Level 1 is far too coarse for the N = 30 modes, so the accuracy warnings must be there.
    """
    out = tmp_path / "ball.png"
    env = {k: v for k, v in os.environ.items() if k not in ("DISPLAY", "VTK_DEFAULT_OPENGL_WINDOW")}
    env["PYTHONPATH"] = str(ROOT) + os.pathsep + env.get("PYTHONPATH", "")
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


# --------------------------------------------------------------------------- the budget
def _twoball(argv: list[str], address_space: int | None = None) -> subprocess.CompletedProcess:
    """``python -m twoball ARGV``, optionally under an address-space limit [bytes]."""
    import resource

    def limit() -> None:
        if address_space is not None:
            resource.setrlimit(resource.RLIMIT_AS, (address_space, resource.RLIM_INFINITY))

    env = dict(os.environ, PYTHONPATH=str(ROOT), OPENBLAS_NUM_THREADS="1")
    env.pop("TWOBALL_MAX_MEMORY", None)
    env.pop("TWOBALL_MAX_TIME", None)
    return subprocess.run(
        [sys.executable, "-m", "twoball", *argv],
        cwd="/",
        env=env,
        preexec_fn=limit,
        capture_output=True,
        text=True,
        timeout=300,
    )


def test_a_long_drawing_is_refused_before_the_drop(tmp_path):
    """2000 frames of 640x480 take minutes to draw: refused under --max-time 20s before
    the drop is simulated, one line naming --max-time, no file."""
    out = tmp_path / "x.gif"
    argv = ["bounce", "--render", str(out), "--frames", "2000", "--max-time", "20s"]
    done = _twoball(argv)
    lines = done.stderr.strip().splitlines()
    assert done.returncode == 2 and len(lines) == 1, done.stderr[-2000:]
    assert lines[0].startswith("twoball: error: --frames 2000 size 640x480 needs ~")
    assert lines[0].endswith("limit 20 s (raise the time limit, --max-time)")
    assert done.stdout == "" and list(tmp_path.iterdir()) == []


@pytest.mark.parametrize("kilobytes", [1_000_000, 1_300_000])
def test_a_render_under_an_address_space_limit_ends_in_one_line(tmp_path, kilobytes):
    """Under ``ulimit -v`` the renderer's address space (VTK maps ~1 GiB) is refused up
    front (status 2), or, where the estimate lets it start, the failed allocation is one
    line of out of memory (status 3): never an abort, never a scratch file."""
    out = tmp_path / "u.gif"
    argv = ["render", "-q", "--level", "1", "--frames", "5", "--out", str(out)]
    done = _twoball(argv, kilobytes * 1024)
    lines = done.stderr.strip().splitlines()
    assert done.returncode in (2, 3) and len(lines) == 1, (done.returncode, done.stderr[-2000:])
    if done.returncode == 2:
        assert "(ulimit -v)" in lines[0] or "--max-memory" in lines[0], lines
    else:
        assert lines[0].startswith("twoball: error: out of memory ("), lines
    assert list(tmp_path.iterdir()) == []


def test_a_render_over_the_memory_limit_is_refused(tmp_path):
    """--max-memory: the frames a GIF keeps (7 bytes a pixel) count."""
    out = tmp_path / "m.gif"
    argv = ["render", "--level", "1", "--frames", "400", "--max-memory", "1GiB", "--out", str(out)]
    done = _twoball(argv)
    lines = done.stderr.strip().splitlines()
    assert done.returncode == 2 and len(lines) == 1, done.stderr[-2000:]
    assert "of memory; limit 1 GiB (raise the memory limit, --max-memory)" in lines[0]
    assert list(tmp_path.iterdir()) == []
