"""The budget covers drawing (verify/output/render.py): its estimate, its deadline, its memory.

The renderer draws in a child process when the verb hands it a monitor with
``long_call``: the time limit then stops it within a fraction of a second, and
an allocation that fails inside VTK ends the child, which is reported as out of
memory, with no scratch file left.
"""

from __future__ import annotations

import subprocess
import sys
import time
from pathlib import Path

import numpy as np
import pytest
from twoball.verify.output.fields import ball_scene
from twoball.verify.output.render import (
    RENDER_ADDRESS,
    render_estimate,
    render_scene,
)

from tests import ROOT
from twoball._common.budget import DeadlineError, limits, running
from twoball._common.staging import SCRATCH_TAG
from twoball._common.watch import Watch

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
