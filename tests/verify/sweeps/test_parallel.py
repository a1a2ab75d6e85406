"""Sweeps on one process, a local process pool and Dask (verify/sweeps/parallel.py).

Same numbers.
"""

import os
import time

import pytest
from twoball.verify.sweeps import parallel
from twoball.verify.sweeps.parallel import MIN_PARALLEL_ITEMS, Outcome, Runner, chunk_size
from twoball.verify.sweeps.sweeps import SweepSolver, run_sweep

from tests.verify.sweeps.helpers import FailAbove, cases


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
