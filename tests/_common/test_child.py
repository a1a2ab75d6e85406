"""A long compiled call in a child process: the same bits, its errors, a parent that stays awake.

References: the same call in process (bit-identical arrays, also with another
BLAS thread count set at run time), a thread ticking every 10 ms in the parent
(its largest pause while scipy's LAPACK, which holds the GIL, runs in the
child), the child's process table entry (gone after an interrupt), and a state
of the parent's that the child does not have (a new interpreter, not a fork).
"""

from __future__ import annotations

import operator
import os
import signal
import subprocess
import sys
import threading
import time

import numpy as np
import pytest
import scipy.linalg as sl
from threadpoolctl import threadpool_limits

from tests import ROOT
from tests._common.commands import children, running
from twoball._common.child import can_spawn, in_child

pytestmark = pytest.mark.skipif(not can_spawn(), reason="needs a child interpreter, main thread")


def _problem(n: int = 1200) -> tuple[np.ndarray, np.ndarray]:
    rng = np.random.default_rng(7)
    a = rng.standard_normal((n, n))
    return a + a.T, np.eye(n) + 0.01 * np.diag(rng.random(n))


def test_same_bits_as_in_process() -> None:
    a, b = _problem(400)
    inside = sl.eigh(a, b)
    outside = in_child(sl.eigh, a, b, doing="a test eigensolve")
    for x, y in zip(inside, outside, strict=True):
        assert np.array_equal(x, y)


@pytest.mark.parametrize("threads", [1, 2])
def test_same_bits_with_the_parents_thread_count(threads: int) -> None:
    """A 600 x 600 generalized problem: LAPACK's bits depend on the BLAS thread count
    (1 and 2 threads differ by ~5e-14 here), which the child takes from the parent."""
    a, b = _problem(600)
    with threadpool_limits(limits=threads, user_api="blas"):
        inside = sl.eigh(a, b)
        outside = in_child(sl.eigh, a, b, doing="a test eigensolve")
    for x, y in zip(inside, outside, strict=True):
        assert np.array_equal(x, y)


_STATE = {"changed": False}


def _changed() -> bool:
    return _STATE["changed"]


def test_the_child_is_a_new_interpreter_not_a_fork() -> None:
    _STATE["changed"] = True  # state of this process only: a fork would carry it
    try:
        assert in_child(_changed) is False
    finally:
        _STATE["changed"] = False
    assert in_child(os.getpid) != os.getpid()


def test_errors_come_back_as_they_were_raised() -> None:
    with pytest.raises(ZeroDivisionError):
        in_child(operator.truediv, 1, 0)
    with pytest.raises(np.linalg.LinAlgError):
        in_child(sl.cholesky, -np.eye(3))


def test_a_call_that_does_not_pickle_runs_in_process() -> None:
    """The child reads the call by pickle: a lambda or a local function is computed here."""
    here = os.getpid()
    assert in_child(lambda: os.getpid()) == here
    with pytest.raises(ZeroDivisionError):
        in_child(lambda: 1 / 0)


def test_parent_keeps_ticking_while_lapack_holds_the_gil() -> None:
    a, b = _problem()
    ticks: list[float] = []
    stop = threading.Event()

    def tick() -> None:
        while not stop.is_set():
            ticks.append(time.monotonic())
            time.sleep(0.01)

    def pause_during(call) -> float:
        ticks.clear()
        stop.clear()
        thread = threading.Thread(target=tick)
        thread.start()
        start = time.monotonic()
        call()
        end = time.monotonic()
        stop.set()
        thread.join()
        stamps = [start] + [t for t in ticks if start <= t <= end] + [end]
        return max(np.diff(stamps)), end - start

    held, seconds = pause_during(lambda: sl.eigh(a, b))
    free, _ = pause_during(lambda: in_child(sl.eigh, a, b))
    assert held > 0.5 * seconds  # in process the ticking thread stops for the whole call
    assert free < 0.2, (free, held)


@pytest.mark.parametrize("delay", [0.0, 2.0])
def test_the_child_dies_with_a_killed_parent(delay: float) -> None:
    """SIGKILL runs no ``finally``: the child asked the system to end it with its parent
    (killed at once: while the child starts; after 2 s: while it computes)."""
    code = "import time\nfrom twoball._common.child import in_child\nin_child(time.sleep, 60)"
    env = dict(os.environ, PYTHONPATH=str(ROOT))
    process = subprocess.Popen([sys.executable, "-c", code], env=env)
    end = time.monotonic() + 60
    kids: list[int] = []
    while not kids and process.poll() is None and time.monotonic() < end:
        time.sleep(0.05)
        kids = children(process.pid)
    time.sleep(delay)
    process.kill()
    process.wait()
    while any(running(k) for k in kids) and time.monotonic() < end:
        time.sleep(0.05)
    assert kids and not any(running(k) for k in kids)


def test_interrupt_kills_the_child_at_once() -> None:
    a, b = _problem(1800)

    def interrupt(signum: int, frame: object) -> None:
        raise KeyboardInterrupt

    previous = signal.signal(signal.SIGALRM, interrupt)
    try:
        signal.setitimer(signal.ITIMER_REAL, 0.3)
        start = time.monotonic()
        with pytest.raises(KeyboardInterrupt):
            in_child(sl.eigh, a, b)
        assert time.monotonic() - start < 0.6
    finally:
        signal.setitimer(signal.ITIMER_REAL, 0)
        signal.signal(signal.SIGALRM, previous)
    try:  # the killed child was reaped: no zombie is left to collect
        assert os.waitpid(-1, os.WNOHANG) == (0, 0)  # other children may still run
    except ChildProcessError:
        pass
