"""Interrupts (SIGINT, SIGTERM) and killed parents (twoball._common.signals): outputs stay whole.

Each command runs as ``python -m twoball`` in a subprocess that stops at a named
stage of :mod:`twoball._common.staging` (``TWOBALL_TEST_PAUSE``) and is signalled
there; inside VTK signals are held back and raised between frames.
"""

from __future__ import annotations

import json
import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest

from tests import ROOT
from tests._common.commands import (
    FAST,
    FILE_WRITERS,
    FOLDER_WRITERS,
    children,
    interrupt,
    no_scratch,
    running,
    snapshot,
    start,
    wait_for_pause,
)
from twoball._common.signals import Interrupted, checkpoint, held_signals
from twoball._common.staging import MARKER, foreign_entry
from twoball.verify.output.series import read_series

SIGNALS = [(signal.SIGINT, 130), (signal.SIGTERM, 143)]
POOL_SWEEP = ["sweep", "--param", "damping", "--values", "0:0.3:40", "--workers", "2"]


@pytest.mark.parametrize("stage", ["begin", "staged", "commit"])
@pytest.mark.parametrize(("signum", "status"), SIGNALS)
def test_interrupted_pvd_export_keeps_a_whole_collection(tmp_path, stage, signum, status):
    out = tmp_path / "x.pvd"
    assert start(["export", *FAST, "--frames", "2", "--out", str(out)]).wait() == 0
    old = snapshot(tmp_path)
    code, _ = interrupt(["export", *FAST, "--frames", "3", "--out", str(out)], stage, signum)
    no_scratch(tmp_path)
    now = snapshot(tmp_path)
    frames = [p for p in tmp_path.iterdir() if p.name.startswith("x_frames-")]
    assert len(frames) == 1 and foreign_entry(frames[0]) is None  # one collection, whole
    if stage == "commit":  # signals wait for the commit; the new collection stands, whole
        assert code == status and len(read_series(out)) == 4
    else:
        assert code == status and now == old


@pytest.mark.parametrize(("signum", "status"), SIGNALS)
def test_interrupted_xdmf_export_keeps_the_pair(tmp_path, signum, status):
    out = tmp_path / "x.xdmf"
    assert start(["export", *FAST, "--frames", "2", "--out", str(out)]).wait() == 0
    old = snapshot(tmp_path)
    code, _ = interrupt(["export", *FAST, "--frames", "3", "--out", str(out)], "staged", signum)
    assert code == status and snapshot(tmp_path) == old


@pytest.mark.parametrize(
    ("command", "stage", "signum", "status"),
    [
        ("verify", "staged", signal.SIGINT, 130),
        # a signal during the commit: the new folder stands, whole; the run was interrupted
        pytest.param("verify", "commit", signal.SIGTERM, 143, marks=pytest.mark.slow),
        ("reproduce", "begin", signal.SIGTERM, 143),
        ("reproduce", "commit", signal.SIGINT, 130),
    ],
)
def test_interrupted_report_folder_is_old_or_new_whole(tmp_path, command, stage, signum, status):
    out = tmp_path / "out"
    assert start([*FOLDER_WRITERS[command], str(out)]).wait() == 0
    old = snapshot(tmp_path)
    # the folder's own commit (a figure inside it commits first, at stage "commit")
    pause = "commit-folder" if stage == "commit" else stage
    code, _ = interrupt([*FOLDER_WRITERS[command], str(out)], pause, signum)
    assert code == status
    no_scratch(tmp_path)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["out"]
    assert foreign_entry(out) is None
    listed = json.loads((out / MARKER).read_text())["files"]
    assert all((out / name).is_file() for name in listed)  # complete, old or new
    if stage != "commit":
        assert snapshot(tmp_path) == old


@pytest.mark.parametrize(
    ("signum", "status"), [SIGNALS[0], pytest.param(*SIGNALS[1], marks=pytest.mark.slow)]
)
def test_interrupted_render_leaves_the_earlier_picture(tmp_path, signum, status):
    out = tmp_path / "ball.png"
    out.write_bytes(b"an earlier picture")
    code, _ = interrupt([*FILE_WRITERS["render"], str(out)], "staged", signum)
    assert code == status and out.read_bytes() == b"an earlier picture"
    no_scratch(tmp_path)


@pytest.mark.parametrize(
    ("argv", "signum", "status"),
    [
        (POOL_SWEEP, signal.SIGINT, 130),
        (POOL_SWEEP, signal.SIGTERM, 143),
        (["reproduce", "--only", "table2", "--workers", "2"], signal.SIGTERM, 143),
    ],
)
def test_interrupt_ends_pool_workers(tmp_path, argv, signum, status):
    extra = ["--plot", str(tmp_path / "s.png")] if argv[0] == "sweep" else []
    extra = extra or ["--out", str(tmp_path / "rep")]
    code, kids = interrupt([*argv, *extra], "pool", signum)
    assert code == status and len(kids) >= 2
    end = time.monotonic() + 10
    while any(running(k) for k in kids) and time.monotonic() < end:
        time.sleep(0.05)
    assert not any(running(k) for k in kids)
    assert list(tmp_path.iterdir()) == []


def test_workers_die_with_a_killed_parent(tmp_path):
    process = start(POOL_SWEEP, "pool")
    wait_for_pause(process, "pool")
    kids = children(process.pid)
    process.kill()  # SIGKILL: no finally runs; PR_SET_PDEATHSIG ends the workers
    process.wait()
    end = time.monotonic() + 10
    while any(running(k) for k in kids) and time.monotonic() < end:
        time.sleep(0.05)
    assert len(kids) >= 2 and not any(running(k) for k in kids)


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


@pytest.mark.parametrize(
    ("signum", "status", "delay"),
    [
        (signal.SIGINT, 130, 0.1),  # early: the renderer's child is starting VTK
        (signal.SIGINT, 130, 0.35),
        (signal.SIGTERM, 143, 0.65),
        *(
            pytest.param(signum, status, delay, marks=pytest.mark.slow)
            for signum, status, delays in [
                (signal.SIGINT, 130, (0.2, 0.5, 0.65)),
                (signal.SIGTERM, 143, (0.2, 0.35, 0.5)),
            ]
            for delay in delays
        ),
    ],
)
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
    assert latency < 1.0  # the drawing runs in a child: the parent acts at once


# --------------------------------------------------------------------------- the mechanism
@pytest.fixture(autouse=True)
def _python_sigint():
    """SIGINT with Python's own handler, as in a foreground run.

    A shell starts a background job (``pytest ... &``) with SIGINT ignored, and
    the mechanism rightly leaves an ignored signal alone; these tests are about
    Python's handler.
    """
    previous = signal.signal(signal.SIGINT, signal.default_int_handler)
    yield
    signal.signal(signal.SIGINT, previous)


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


def test_a_signal_during_a_commit_is_held_and_reported_when_the_run_ends():
    """The output is in place: the signal waits for the next work (resume), else the end
    of the run reports it (finish returns it; the command line exits 130 / 143)."""
    from twoball._common.signals import committed_signals, finish, raise_on_signals, resume

    with raise_on_signals():
        with committed_signals():
            os.kill(os.getpid(), signal.SIGINT)
            time.sleep(0.05)  # handled by now: recorded
        time.sleep(0.05)  # the run finishing (its summary): still held, nothing raised
        with pytest.raises(Interrupted) as raised:
            resume()  # new work starts: the held signal acts here
        assert raised.value.exit_status == 130
        with committed_signals():
            pass
        os.kill(os.getpid(), signal.SIGTERM)  # after the commit, before the run ends
        time.sleep(0.05)
        assert finish() == signal.SIGTERM  # the run ends: the held signal is its status
        resume()
        os.kill(os.getpid(), signal.SIGINT)  # after the end: ignored
        time.sleep(0.05)
    # raise_on_signals restored the handlers and starts afresh
    assert signal.getsignal(signal.SIGINT) is signal.default_int_handler


def test_a_held_signal_is_delivered_again_if_no_work_checks():
    """Work after a commit that never checks still ends by the signal (re-delivered)."""
    from twoball._common.signals import HOLD_SECONDS, committed_signals, raise_on_signals

    with raise_on_signals(), pytest.raises(Interrupted) as raised:
        with committed_signals():
            pass
        os.kill(os.getpid(), signal.SIGTERM)
        for _ in range(int(20 * HOLD_SECONDS / 0.01)):  # at most 20 holds of busy work
            time.sleep(0.01)
        pytest.fail("the held signal was not delivered again")  # pragma: no cover
    assert raised.value.exit_status == 143


@pytest.mark.parametrize("signum", [signal.SIGINT, signal.SIGTERM])
def test_a_signal_after_the_status_is_decided_changes_nothing(tmp_path, signum):
    """The export has written its file and the run has ended: a signal in the teardown
    neither kills the process (the raw signal) nor prints a line; exit 0, the new file."""
    out = tmp_path / "q.vtu"
    out.write_bytes(b"an earlier file")
    process = start(["export", *FAST, "--out", str(out)], "finished")
    wait_for_pause(process, "finished")
    process.send_signal(signum)
    _, err = process.communicate(timeout=60)
    assert process.returncode == 0, err.decode()[-2000:]
    assert "interrupted" not in err.decode() and "Traceback" not in err.decode()
    assert out.read_bytes().startswith(b"<?xml")
