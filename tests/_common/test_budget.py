"""Resource guards (twoball._common.budget): limits, messages, estimates against measurements.

Every absurd size is run in one child process whose address space
and CPU time are capped: had any of them started its work it would die with a
MemoryError traceback (exit 1) or by SIGXCPU; a refusal by the guard is exit 2
with its one-line message, i.e. it happened before the allocation.
"""

from __future__ import annotations

import json
import os
import subprocess
import sys
import textwrap
from pathlib import Path

import pytest
from twoball.modal.cost import check_series, series_estimate

from tests import ROOT
from twoball._common import budget
from twoball._common.budget import (
    Budget,
    BudgetError,
    Estimate,
    GiB,
    MiB,
    format_bytes,
    parse_bytes,
    parse_seconds,
)
from twoball._common.errors import ParameterError

ABSURD = [
    ["liftoff", "--modes", "20000"],
    ["liftoff", "--modes", "100000"],
    ["liftoff", "--t-end", "1e6"],
    ["liftoff", "--backend", "fem", "--level", "9"],
    ["liftoff", "--backend", "fem", "--level", "50"],
    ["liftoff", "--backend", "fem", "--scheme", "alpha", "--dt", "1e-9"],
    ["sweep", "--param", "damping", "--values", "0:0.5:1000000"],
    ["sweep", "--param", "damping", "--values", "0:0.5:10000"]
    + ["--param", "v0", "--values", "1:5:10000"],
    ["sweep", "--param", "damping", "--values", "0:0.5:64", "--workers", "100"],
    ["plot", "waterfall", "--instants", "100000", "--out", "{tmp}/w.png"],
    ["export", "--times", "{times}", "--out", "{tmp}/x.xdmf"],
]


CHILD = textwrap.dedent(
    """
    import contextlib, io, json, resource, sys
    resource.setrlimit(resource.RLIMIT_AS, (3 * 2**30, 3 * 2**30))
    resource.setrlimit(resource.RLIMIT_CPU, (60, 60))
    from twoball.cli.main import main
    out = []
    for argv in json.loads(sys.argv[1]):
        err = io.StringIO()
        with contextlib.redirect_stderr(err), contextlib.redirect_stdout(io.StringIO()):
            try:
                status = main(argv)
            except SystemExit as stop:
                status = stop.code
        out.append([status, err.getvalue()])
    print(json.dumps(out))
    """
)


def test_sizes_and_durations_parse() -> None:
    assert parse_bytes("12GiB") == 12 * GiB
    assert parse_bytes("500MB") == 500 * 10**6
    assert parse_bytes("2e9") == 2 * 10**9
    assert parse_seconds("90min") == 5400.0
    assert parse_seconds("2h") == 7200.0
    assert parse_seconds("3600") == 3600.0
    assert format_bytes(15.0 * GiB) == "15 GiB"
    for bad in ("12x", "-1GiB", "0", "nan", "GiB"):
        with pytest.raises(ParameterError, match="^max_memory must be a size > 0"):
            parse_bytes(bad)
    with pytest.raises(ParameterError, match="^max_time must be"):
        parse_seconds("soon")


def test_default_memory_is_half_the_machine(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.delenv(budget.MEMORY_ENV, raising=False)
    monkeypatch.delenv(budget.TIME_ENV, raising=False)
    pages = os.sysconf("SC_PAGE_SIZE") * os.sysconf("SC_PHYS_PAGES")
    default = Budget.default()
    assert default.max_memory == int(0.5 * pages)
    assert default.max_seconds == budget.DEFAULT_MAX_SECONDS
    monkeypatch.setenv(budget.MEMORY_ENV, "3GiB")
    monkeypatch.setenv(budget.TIME_ENV, "10min")
    assert Budget.default() == Budget(3 * GiB, 600.0)
    assert Budget.from_options("1GiB", "5s") == Budget(GiB, 5.0)  # options beat the environment


def test_refusal_message_names_option_estimate_and_limit() -> None:
    limit = Budget(int(11.7 * GiB), 300.0)
    with pytest.raises(BudgetError) as caught:
        limit.check("modes 100000", series_estimate(100000, 4 * 3.141592653589793))
    assert str(caught.value) == (
        "modes 100000 needs ~15 GiB of memory; limit 11.7 GiB (raise the memory limit, max_memory)"
    )
    assert isinstance(caught.value, ParameterError) and caught.value.name == "modes"
    with pytest.raises(
        BudgetError, match=r"^dt 1e-09 needs ~.* limit 5 min \(raise the time limit, max_time\)$"
    ):
        limit.check("dt 1e-09", Estimate(GiB, 1e6))
    assert limit.check("modes 30", Estimate(200 * MiB, 1.0)) == Estimate(200 * MiB, 1.0)


def test_limits_context_restores_the_budget() -> None:
    before = budget.current_budget()
    with budget.limits("1GiB", "1s") as inner:
        assert budget.current_budget() == inner == Budget(GiB, 1.0)
        with pytest.raises(BudgetError, match="^modes 3000 needs"):
            check_series(3000, 4 * 3.141592653589793)
    assert budget.current_budget() == before


def test_each_absurd_size_is_refused_before_any_allocation(tmp_path: Path) -> None:
    times = ",".join(f"{k * 3e-6:.6g}" for k in range(10000))
    cases = [[w.format(tmp=tmp_path, times=times) for w in argv] for argv in ABSURD]
    control = ["liftoff", "--json"]  # a normal run fits the same limits
    env = dict(os.environ, OPENBLAS_NUM_THREADS="1", MPLBACKEND="Agg")
    env.pop(budget.MEMORY_ENV, None)
    env.pop(budget.TIME_ENV, None)
    done = subprocess.run(
        [sys.executable, "-c", CHILD, json.dumps([*cases, control])],
        cwd=ROOT,
        env=env,
        capture_output=True,
        text=True,
        timeout=300,
    )
    assert done.returncode == 0, done.stderr[-2000:]
    results = json.loads(done.stdout.splitlines()[-1])
    for argv, (status, err) in zip(cases, results[:-1], strict=True):
        lines = err.strip().splitlines()
        assert status == 2, (argv, err[-500:])
        assert len(lines) == 1 and lines[0].startswith("twoball: error: "), (argv, err)
        assert "Traceback" not in err
    refused = [err for _, err in results[:-1]]
    assert "--modes 20000 needs ~" in refused[0]
    assert refused[0].rstrip().endswith("(raise the time limit, --max-time)"), refused[0]
    assert "--modes 100000 needs ~15 GiB of memory" in refused[1]
    assert "--t-end 1e+06 needs ~" in refused[2]
    assert refused[2].rstrip().endswith("(raise the memory limit, --max-memory)"), refused[2]
    assert "--level 9" in refused[3] and "--level 50" in refused[4]
    assert "--dt 1e-09 needs ~" in refused[5]
    assert "(1000000 points) needs ~" in refused[6]
    assert "(100000000 points) needs ~" in refused[7]
    assert "--workers must be an integer in [1, " in refused[8]
    assert "--instants must be an integer in [2, 2000]" in refused[9]
    assert "--times must be at most 2000 times" in refused[10]
    assert results[-1][0] == 0, results[-1][1]
