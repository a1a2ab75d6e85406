"""An interrupted render ends with 130/143 and one line, never a crash, and keeps the earlier file.

``python -m twoball render --out x.gif`` is signalled a little after its scratch
entry ``.x.gif.twoball-scratch-*`` appears, while VTK is imported and draws.  A
signal turned into an exception inside VTK crashed the interpreter (SIGSEGV in
VTK's module import) or was swallowed by it (the render finished with status 0
and replaced the earlier file); now it is held back and raised between frames.
Several runs at staggered delays, both signals.
"""

from __future__ import annotations

import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest

from twoball._common.signals import Interrupted, checkpoint, held_signals

ROOT = Path(__file__).resolve().parents[2]
EARLIER = b"GIF89a an earlier animation"
RENDER = ["render", "-q", "--level", "1", "--frames", "60", "--size", "160x120"]


def scratch_entries(folder: Path) -> list[Path]:
    return [p for p in folder.iterdir() if p.name.startswith(".x.gif.twoball-scratch-")]


def interrupted_render(folder: Path, signum: int, delay: float) -> tuple[int, str, float]:
    """Render; signal it ``delay`` s after its scratch appears; status, stderr, latency."""
    env = dict(os.environ, PYTHONPATH=str(ROOT), OPENBLAS_NUM_THREADS="1")
    env.setdefault("VTK_DEFAULT_OPENGL_WINDOW", "vtkEGLRenderWindow")
    env.pop("TWOBALL_TEST_PAUSE", None)
    process = subprocess.Popen(
        [sys.executable, "-m", "twoball", *RENDER, "--out", str(folder / "x.gif")],
        cwd="/",
        env=env,
        stdout=subprocess.DEVNULL,
        stderr=subprocess.PIPE,
    )
    end = time.monotonic() + 120
    while not scratch_entries(folder) and process.poll() is None and time.monotonic() < end:
        time.sleep(0.005)
    assert process.poll() is None, "the render ended before its scratch appeared"
    time.sleep(delay)
    sent = time.monotonic()
    process.send_signal(signum)
    _, err = process.communicate(timeout=60)
    return process.returncode, err.decode(), time.monotonic() - sent


@pytest.mark.parametrize("delay", [0.2, 0.35, 0.5, 0.65])
@pytest.mark.parametrize(("signum", "status"), [(signal.SIGINT, 130), (signal.SIGTERM, 143)])
def test_interrupted_render_exits_cleanly_and_keeps_the_earlier_gif(
    tmp_path, signum, status, delay
):
    out = tmp_path / "x.gif"
    out.write_bytes(EARLIER)
    code, err, latency = interrupted_render(tmp_path, signum, delay)
    assert code == status, (code, err[-2000:])  # not -11 (SIGSEGV), not 0 (swallowed)
    assert err.strip().splitlines() == ["twoball: interrupted"], err[-2000:]
    assert out.read_bytes() == EARLIER
    assert scratch_entries(tmp_path) == []
    assert latency < 10.0  # a frame or two; generous for a loaded machine


# --------------------------------------------------------------------------- the mechanism
def test_held_signal_waits_for_the_checkpoint():
    with pytest.raises(Interrupted) as raised:
        with held_signals():
            os.kill(os.getpid(), signal.SIGTERM)
            time.sleep(0.05)  # the handler has run by now: recorded, not raised
            reached = True
            checkpoint()
            pytest.fail("the checkpoint did not raise")  # pragma: no cover
    assert reached and raised.value.exit_status == 143
    checkpoint()  # nothing pending any more


def test_held_signal_is_raised_at_the_end_of_the_block():
    with pytest.raises(Interrupted) as raised:
        with held_signals():
            os.kill(os.getpid(), signal.SIGINT)
            time.sleep(0.05)
            done = True
    assert done and raised.value.exit_status == 130


def test_held_signals_restores_the_handlers():
    before = {s: signal.getsignal(s) for s in (signal.SIGINT, signal.SIGTERM)}
    with held_signals():
        checkpoint()
    assert {s: signal.getsignal(s) for s in before} == before
