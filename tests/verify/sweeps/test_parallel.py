"""Sweeps on one process, a local process pool and Dask: same numbers, same order, errors kept."""

import json
import math
import os
import time

import numpy as np
import pytest
from twoball.modal.parameters import Case, preset
from twoball.verify.sweeps import parallel
from twoball.verify.sweeps.parallel import MIN_PARALLEL_ITEMS, Outcome, Runner, chunk_size
from twoball.verify.sweeps.sweeps import SweepGrid, SweepSolver, make_grid, run_sweep, sweep_cases

from twoball._common.errors import NumericalError
from twoball.cli.main import main


def cases(count=40):
    return sweep_cases(preset("basketball"), "v0", np.linspace(1.0, 12.0, count))


def dicts(points):
    return [p.as_dict() for p in points]


class FailAbove:
    """Picklable solver that raises a NumericalError for v0 above a limit."""

    def __init__(self, limit):
        self.limit = limit
        self.solve = SweepSolver()

    def __call__(self, case: Case):
        if case.v0 > self.limit:
            raise NumericalError(f"refusing v0 = {case.v0:g}")
        return self.solve(case)


def pid(_item):
    return os.getpid()


def slow_identity(item):
    time.sleep(0.002 * (item % 3))
    return item


# --- the runner -------------------------------------------------------------------


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


# --- sweeps: identical numbers whichever way they run ---------------------------------


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


def test_a_failed_point_is_a_row_with_its_parameters():
    for workers in (1, 2):
        with Runner(workers=workers) as runner:
            points = run_sweep(cases(), FailAbove(6.0), runner=runner)
        good = [p for p in points if p.error is None]
        bad = [p for p in points if p.error is not None]
        assert len(good) + len(bad) == 40 and bad and good
        for p in bad:
            row = p.as_dict()
            assert row["error"].startswith("NumericalError: refusing v0")
            assert row["v0_m_s"] == p.case.v0 > 6.0 and row["lifted"] is None
            assert math.isnan(p.ratio)
        assert all(p.as_dict()["error"] is None for p in good)


def test_sweep_cli_reports_failed_points(capsys, monkeypatch):
    monkeypatch.setattr("twoball.verify.sweeps.sweeps.SweepSolver", lambda *a: FailAbove(3.0))
    assert main(["sweep", "--param", "v0", "--values", "2:4:3", "--json", "--workers", "1"]) == 0
    rows = json.loads(capsys.readouterr().out)["results"]
    assert [r["error"] is not None for r in rows] == [False, False, True]
    assert all(r["phi_a_source"] == "eq. (3.7)" for r in rows)  # failed points too
    assert main(["sweep", "--param", "v0", "--values", "2:4:3", "--workers", "1"]) == 0
    assert "NumericalError" in capsys.readouterr().out


def test_sweep_cli_workers_give_the_same_json(capsys):
    argv = ["sweep", "--param", "damping", "--values", "0:0.4:24", "--json"]
    main([*argv, "--workers", "1"])
    serial = json.loads(capsys.readouterr().out)
    main([*argv, "--workers", "2"])
    parallel = json.loads(capsys.readouterr().out)
    assert parallel["results"] == serial["results"]  # the provenance names the workers
    assert parallel["provenance"]["call"]["arguments"]["workers"] == 2


# --- 2-D grids ----------------------------------------------------------------------


def test_grid_shape_and_order():
    grid = make_grid(["damping", "v0"], ["0:0.3:3", "2:8:4"])
    assert isinstance(grid, SweepGrid) and grid.shape == (3, 4)
    cs = grid.cases(preset("basketball"))
    assert len(cs) == 12 and grid.indices()[:5] == [(0, 0), (0, 1), (0, 2), (0, 3), (1, 0)]
    assert [c.damping for c in cs[:4]] == [0.0] * 4
    assert [c.v0 for c in cs[:4]] == pytest.approx([2, 4, 6, 8])
    assert len({c.phi_a for c in cs[:4]}) == 4  # phi_a from eq. (3.7) per v0


def test_grid_cli_json_and_heat_map(capsys, tmp_path):
    png = tmp_path / "grid.png"
    argv = ["sweep", "--param", "damping", "--values", "0.05:0.3:3"]
    argv += ["--param", "v0", "--values", "2:6:2", "--json", "--plot", str(png)]
    assert main(argv) == 0
    rows = json.loads(capsys.readouterr().out)["results"]
    assert [r["index"] for r in rows] == [[i, j] for i in range(3) for j in range(2)]
    assert png.stat().st_size > 10_000 and png.read_bytes()[:4] == b"\x89PNG"
    assert not [p for p in tmp_path.iterdir() if p.name.startswith(".")]


# --- bad input: one line, exit status 2 --------------------------------------------------


@pytest.mark.parametrize(
    ("argv", "flag"),
    [
        (["--param", "v0", "--values", "1:2"], "--values"),
        (["--param", "v0", "--values", "1:x:3"], "--values"),
        (["--param", "v0", "--param", "damping", "--values", "1:2:3"], "--values"),
        (["--param", "v0", "--values", "1:2:3", "--values", "0:1:2"], "--values"),
        (["--param", "v0", "--param", "v0", "--values", "1:2:3", "--values", "1:2:3"], "--param"),
        (["--param", "v0", "--values", "1:2:3", "--workers", "0"], "--workers"),
        (["--param", "v0", "--values", "1:2:3", "--workers", "two"], "--workers"),
        (["--param", "v0", "--values", "1:2:3", "--plot", "/nonexistent/dir/a.png"], "--plot"),
        (["--param", "v0", "--values", "1:2:3", "--plot", "/tmp/a.xyz"], "--plot"),
    ],
)
def test_bad_sweep_input_is_one_line_exit_2(capsys, argv, flag):
    with pytest.raises(SystemExit) as stop:
        main(["sweep", *argv])
    err = capsys.readouterr().err.strip().splitlines()
    assert stop.value.code == 2 and len(err) == 1 and flag in err[0]


def test_unreachable_scheduler_is_one_line_exit_2(capsys, monkeypatch):
    pytest.importorskip("distributed")
    monkeypatch.setattr(parallel, "CONNECT_TIMEOUT", "0.5s")
    with pytest.raises(SystemExit) as stop:
        main(["sweep", "--param", "v0", "--values", "1:2:3", "--scheduler", "tcp://127.0.0.1:9"])
    err = capsys.readouterr().err.strip().splitlines()
    assert stop.value.code == 2 and len(err) == 1 and "--scheduler" in err[0]


@pytest.mark.slow
def test_fig12_sweeps_finish_in_30_s_on_two_workers():
    from twoball.verify.reproduce.cem.fig12 import FIG12_AXES, FIG12_DAMPING, fig12_base

    base = fig12_base()
    cs = [
        base.derive(damping=d, **{field: float(x)})
        for field, values, _ in FIG12_AXES.values()
        for d in FIG12_DAMPING
        for x in values
    ]
    assert len(cs) == 1200
    start = time.perf_counter()
    with Runner(workers=2) as runner:
        points = run_sweep(cs, SweepSolver(), runner=runner)
    assert time.perf_counter() - start < 30.0
    assert all(p.error is None for p in points)
