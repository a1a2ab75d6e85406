"""A long compiled call in a forked child: the same bits, its errors, and a parent that stays awake.

References: the same call in process (bit-identical arrays), a thread ticking
every 10 ms in the parent (its largest pause while scipy's LAPACK, which holds
the GIL, runs in the child), and the child's process table entry (gone after an
interrupt).
"""

from __future__ import annotations

import os
import signal
import threading
import time

import numpy as np
import pytest
import scipy.linalg as sl

from twoball._common.child import can_fork, in_child

pytestmark = pytest.mark.skipif(not can_fork(), reason="needs fork, in the main thread")


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


def test_errors_come_back_as_they_were_raised() -> None:
    with pytest.raises(ZeroDivisionError):
        in_child(lambda: 1 / 0)
    with pytest.raises(np.linalg.LinAlgError):
        in_child(sl.cholesky, -np.eye(3))


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
