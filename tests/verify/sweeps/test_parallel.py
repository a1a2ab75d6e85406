"""Sweeps on one process, a local process pool and Dask (verify/sweeps/parallel.py).

Same numbers.
"""

import os
import time

import pytest

from tests.verify.sweeps.helpers import FailAbove, cases
from twoball.verify.sweeps import parallel
from twoball.verify.sweeps.parallel import MIN_PARALLEL_ITEMS, Outcome, Runner, chunk_size
from twoball.verify.sweeps.sweeps import SweepSolver, run_sweep


def dicts(points):
    return [p.as_dict() for p in points]


def pid(_item):
    return os.getpid()


def slow_identity(item):
    time.sleep(0.002 * (item % 3))
    return item


def test_workers_1_is_strictly_serial():
    with Runner(workers=1) as runner:
        assert runner.mode == "serial" and runner._pool is None
        assert set(o.value for o in runner.map(pid, range(50))) == {os.getpid()}


def test_small_maps_stay_in_process():
    with Runner(workers=2) as runner:
        outs = runner.map(pid, range(MIN_PARALLEL_ITEMS - 1))
        assert {o.value for o in outs} == {os.getpid()}
        outs = runner.map(pid, range(200))
        assert os.getpid() not in {o.value for o in outs}


def test_process_pool_keeps_input_order():
    with Runner(workers=2) as runner:
        outs = runner.map(slow_identity, list(range(97)))
    assert [o.value for o in outs] == list(range(97))


def test_progress_reaches_the_total():
    seen = []
    with Runner(workers=2) as runner:
        runner.map(slow_identity, list(range(60)), seen.append)
    assert seen[-1] == 60 and seen == sorted(seen)


@pytest.mark.parametrize(("count", "workers", "size"), [(0, 2, 1), (10, 2, 1), (1200, 2, 32)])
def test_chunk_size(count, workers, size):
    assert chunk_size(count, workers) == size


def test_guarded_keeps_the_error():
    out = parallel.guarded(lambda x: 1 / x, 0)
    assert isinstance(out, Outcome) and not out.ok and out.error.startswith("ZeroDivisionError")


def test_process_pool_equals_serial_exactly():
    serial = run_sweep(cases(), SweepSolver())
    with Runner(workers=2) as runner:
        pooled = run_sweep(cases(), SweepSolver(), runner=runner)
    assert dicts(pooled) == dicts(serial)  # exact equality, every key


def test_dask_local_cluster_equals_serial_exactly():
    distributed = pytest.importorskip("distributed")
    serial = run_sweep(cases(), SweepSolver())
    with distributed.LocalCluster(
        n_workers=2, threads_per_worker=1, processes=False, dashboard_address=None
    ) as cluster:
        with Runner(scheduler=cluster.scheduler_address) as runner:
            assert runner.mode == "dask" and runner.capacity == 2
            on_dask = run_sweep(cases(), SweepSolver(), runner=runner)
            failing = run_sweep(cases(), FailAbove(6.0), runner=runner)
    assert dicts(on_dask) == dicts(serial)
    assert [p.error is not None for p in failing] == [c.v0 > 6.0 for c in cases()]


@pytest.mark.slow
def test_fig12_sweeps_on_two_workers_are_those_of_one_process():
    """The 1,200 lift-offs of Fig. 12 on the pool; their wall time: benchmarks/bench_sweeps.py."""
    from twoball.verify.reproduce.cem.fig12 import fig12_cases

    _, cs = fig12_cases()
    assert len(cs) == 1200
    with Runner(workers=2) as runner:
        points = run_sweep(cs, SweepSolver(), runner=runner)
    assert all(p.error is None for p in points)
    sample = slice(0, None, 40)  # every axis and damping ratio, in one process
    alone = dicts(run_sweep(cs[sample], SweepSolver()))
    pooled = [{**d, "index": None} for d in dicts(points[sample])]
    assert pooled == [{**d, "index": None} for d in alone]


class _Listener:
    """A local TCP port that answers each connection with ``greeting`` (b"": stays silent)."""

    def __init__(self, greeting: bytes, close: bool = False) -> None:
        import socket
        import threading

        self.server = socket.create_server(("127.0.0.1", 0))
        self.address = f"tcp://127.0.0.1:{self.server.getsockname()[1]}"
        self.greeting, self.close, self.held = greeting, close, []
        threading.Thread(target=self._serve, daemon=True).start()

    def _serve(self) -> None:
        while True:
            try:
                conn, _ = self.server.accept()
            except OSError:
                return
            if self.greeting:
                conn.sendall(self.greeting)
            if self.close:
                conn.close()
            else:
                self.held.append(conn)

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.server.close()
        for conn in self.held:
            conn.close()


@pytest.mark.parametrize(
    ("greeting", "said"),
    [(b"", "said nothing"), (b"HTTP/1.0 400 Bad request\r\n\r\n", "HTTP/1.0")],
)
def test_a_port_that_does_not_greet_as_dask_is_refused(monkeypatch, greeting, said):
    """A silent port, or a web server or proxy, is no scheduler: refused naming it, no client
    (dask's would wait for ever, or read the reply as a length of exabytes)."""
    monkeypatch.setattr(parallel, "PROBE_SECONDS", 0.3)
    with _Listener(greeting) as listener:
        with pytest.raises(parallel.ParameterError) as error:
            parallel.check_scheduler(listener.address)
    assert error.value.name == "scheduler" and said in str(error.value)


def test_a_tcp_scheduler_greets_and_is_used():
    """A dask scheduler on TCP passes the probe (it speaks first) and runs the tasks."""
    distributed = pytest.importorskip("distributed")
    with distributed.LocalCluster(
        n_workers=1,
        threads_per_worker=1,
        processes=False,
        dashboard_address=None,
        protocol="tcp://",
    ) as cluster:
        address = cluster.scheduler_address
        assert address.startswith("tcp://") and parallel.check_scheduler(address) == address
        with Runner(scheduler=address) as runner:
            assert runner.mode == "dask"
            outs = runner.map(slow_identity, range(20))
    assert [o.value for o in outs] == list(range(20))


def test_a_scheduler_that_fails_the_client_is_one_line_without_a_traceback(tmp_path):
    """It greets with a plausible length, then garbage: exit 2, one line naming --scheduler,
    and the half-built dask client is closed (no ``Client.__del__`` traceback at exit)."""
    import struct
    import subprocess
    import sys

    pytest.importorskip("distributed")
    with _Listener(struct.pack("<Q", 58) + b"x" * 58, close=True) as listener:
        argv = ["sweep", "--param", "v0", "--values", "3,4", "--scheduler", listener.address]
        run = subprocess.run(
            [sys.executable, "-m", "twoball", *argv],
            capture_output=True,
            text=True,
            cwd=tmp_path,
            timeout=120,
        )
    lines = run.stderr.strip().splitlines()
    assert run.returncode == 2 and len(lines) == 1, run.stderr
    assert "--scheduler" in lines[0] and "Traceback" not in run.stderr


@pytest.mark.parametrize("workers", [1, 2])
def test_progress_starts_with_the_map(workers):
    """``progress(0)`` before the first item ends: the progress line (its thread) starts with
    the work, after the pool has forked, not when the first point is done."""
    seen = []
    with Runner(workers=workers) as runner:
        runner.map(slow_identity, range(MIN_PARALLEL_ITEMS), progress=seen.append)
    assert seen[0] == 0 and seen[-1] == MIN_PARALLEL_ITEMS


def test_the_pool_watches_the_deadline_while_its_chunks_run():
    """Past the time limit the pool's map stops while it waits, naming the item and workers."""
    from twoball._common.budget import DeadlineError, limits, running

    with Runner(workers=2) as runner, limits(max_time="1s"), running():
        time.sleep(1.05)
        with pytest.raises(DeadlineError, match=r"while item 1 of 40 \(2 workers\)"):
            runner.map(slow_identity, range(40), min_parallel=2)
