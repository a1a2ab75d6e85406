"""Resource guards (twoball._common.budget): limits, messages, estimates against measurements.

Every absurd size is run in one child process whose address space
and CPU time are capped: had any of them started its work it would die with a
MemoryError traceback (exit 1) or by SIGXCPU; a refusal by the guard is exit 2
with its one-line message, i.e. it happened before the allocation.
"""

from __future__ import annotations

import json
import math
import os
import subprocess
import sys
import textwrap
import time
from pathlib import Path

import numpy as np
import pytest

import twoball
from tests import ROOT
from twoball._common import budget
from twoball._common.budget import (
    DEFAULT_MAX_SECONDS,
    ESTIMATE_SLACK,
    Budget,
    BudgetError,
    DeadlineError,
    Estimate,
    GiB,
    MiB,
    check,
    check_deadline,
    format_bytes,
    limits,
    parse_bytes,
    parse_seconds,
    running,
    verb_default,
)
from twoball._common.errors import ParameterError
from twoball._common.watch import Watch
from twoball._costs import check_series
from twoball.modal.cost import series_estimate
from twoball.modal.filters import SpectralFilter

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
    # its converged reference sums 80000 modes in blocks: ~3 GiB of exponentials
    assert "--modes 20000 needs ~" in refused[0]
    assert refused[0].rstrip().endswith("(raise the memory limit, --max-memory)"), refused[0]
    assert "--modes 100000 needs ~15 GiB of memory" in refused[1]
    assert "--t-end 1e+06 needs ~" in refused[2]
    assert refused[2].rstrip().endswith("(raise the memory limit, --max-memory)"), refused[2]
    assert "--level 9" in refused[3]  # within the range: the budget refuses it
    assert "--level must be an integer in [0, 10], got 50" in refused[4]  # beyond any budget
    assert "--dt 1e-09 needs ~" in refused[5]
    assert "(1000000 points) needs ~" in refused[6]
    assert "(100000000 points) needs ~" in refused[7]
    assert "--workers must be an integer in [1, " in refused[8]
    assert "--instants must be an integer in [2, 2000]" in refused[9]
    assert "--times must be at most 2000 times" in refused[10]
    assert results[-1][0] == 0, results[-1][1]


# --- The time limit is also a deadline: every long loop stops past it with one clear error

FILTER = SpectralFilter("lanczos", 30)


def past_the_deadline(call):
    """``call()`` on a clock whose one-second limit has already passed."""
    with limits(max_time="1s"), running():
        time.sleep(1.05)
        with pytest.raises(DeadlineError) as caught:
            call()
    return str(caught.value)


def test_no_clock_no_deadline() -> None:
    with limits(max_time="1s"):
        time.sleep(1.05)
        check_deadline("nothing")  # outside a verb nothing is timed


def test_body_contact_steps(monkeypatch) -> None:
    """The body's stepped contact meets the deadline in its step loop (its estimate let through)."""
    from twoball._common.budget import Budget

    monkeypatch.setattr(Budget, "check", lambda self, option, estimate: estimate)
    text = past_the_deadline(lambda: twoball.liftoff(body=twoball.Body(0.1)))
    assert "while the body on the ball: step 0, 0 % of the window" in text
    assert text.startswith("stopped at the time limit 1 s after") and "max_time" in text


def test_series_evaluation_chunks() -> None:
    from twoball.modal.legendre import legendre_series

    series = legendre_series(2.6, 0.13, SpectralFilter("lanczos", 60), monitor=Watch())
    times = np.linspace(0.0, 12.0, 10_000)
    series.pole(times[:100])  # one chunk: no check
    assert "while the modal series at sample 4096 of 10000" in past_the_deadline(
        lambda: series.pole(times)
    )


def test_generalized_alpha_steps() -> None:
    from twoball.fem_membrane.alpha import GeneralizedAlpha
    from twoball.fem_membrane.axisym import axisym_space

    space = axisym_space(50, 2.6, 1)
    stepper = GeneralizedAlpha(space.mass, space.stiffness, 1e-3)
    u0 = np.zeros(space.dofs)
    text = past_the_deadline(lambda: stepper.run(u0, u0, 1.0, space.pole_row, Watch()))
    assert "while generalized-alpha step 0 of 1000" in text


def test_krylov_iterations() -> None:
    from twoball.fem_membrane.build import build_space
    from twoball.fem_membrane.initial import initial_moments
    from twoball.fem_membrane.krylov import krylov_modal_series

    space = build_space("sphere", level=2, order=1, phi_a=2.6)
    moments = initial_moments(space, 2.6)
    text = past_the_deadline(
        lambda: krylov_modal_series(space, moments, 0.13, FILTER, monitor=Watch())
    )
    assert "while the rational Krylov iteration (basis 0 of at most" in text


def test_eigenpair_slices_and_sweep_points() -> None:
    from twoball.fem_membrane.build import build_space
    from twoball.fem_membrane.slicing import sliced_pairs

    space = build_space("sphere", level=2, order=2, phi_a=2.6)
    text = past_the_deadline(
        lambda: sliced_pairs(space.stiffness, space.mass, 200.0, monitor=Watch())
    )
    assert "while eigenpairs of 642 unknowns: counting them" in text
    text = past_the_deadline(lambda: twoball.sweep({"damping": [0.1, 0.2]}))
    assert "while item 1 of 2" in text


def test_dense_eigenpairs_in_a_child_stop_at_the_deadline() -> None:
    from twoball.fem_membrane.build import build_space
    from twoball.fem_membrane.slicing import dense_pairs

    space = build_space("sphere", level=3, order=1, phi_a=2.6)  # 642 unknowns: in a child
    with limits(max_time="1s"), running():
        time.sleep(0.9)
        start = time.monotonic()
        with pytest.raises(DeadlineError, match="dense eigenpairs of 642 unknowns"):
            for _ in range(20):  # ~0.1 s each: the deadline falls inside one of them
                dense_pairs(space.stiffness, space.mass, monitor=Watch())
        assert time.monotonic() - start < 1.5


def test_the_drops_eigenpairs_and_steps(monkeypatch) -> None:
    """The drop, the whole bounce and the finite elements' dense eigenpairs stop at the
    deadline; from 500 unknowns the eigenpairs run in a child (its check comes first)."""
    from twoball._common.budget import Budget
    from twoball.fem_membrane.floor import axisym_ball
    from twoball.modal.damping import ModalRatio
    from twoball.modal.stiffness import Stiffness

    monkeypatch.setattr(Budget, "check", lambda self, option, estimate: estimate)
    quick = twoball.MoreauJean(twoball.LegendreBall(16))
    assert "while the drop: step 0, 0 % of the window" in past_the_deadline(
        lambda: twoball.bounce(solver=quick)
    )
    assert "while the whole bounce: step 0," in past_the_deadline(
        lambda: twoball.bounce(solver=quick, body=twoball.Body(0.1))
    )
    text = past_the_deadline(
        lambda: axisym_ball(300, 2, Stiffness(), ModalRatio(0.1), monitor=Watch())
    )
    assert "while dense eigenpairs of the drop's 601 unknowns (LAPACK)" in text


def _legendre(modes: int) -> twoball.MoreauJean:
    return twoball.MoreauJean(twoball.LegendreBall(modes))


def _fem(mesh: twoball.MeshOptions) -> twoball.MoreauJean:
    return twoball.MoreauJean(twoball.FEBall(mesh))


@pytest.mark.parametrize(
    "call",
    [
        {"solver": _legendre(64)},
        {"solver": _legendre(64), "drop": twoball.Drop(drop_height=300.0)},  # 77 m/s: rattles
        {"solver": _legendre(64), "body": twoball.Body(0.1)},
        {"solver": _fem(twoball.MeshOptions("axisym", elements=32, order=3))},
        {"solver": _fem(twoball.MeshOptions("axisym", elements=24, order=4)),
         "pair": "tennis-coin"},
    ],
)  # fmt: skip
def test_the_drops_cost_model_counts_its_steps(call) -> None:
    """The estimate's steps (span, localised touches) against the steps taken: 0.5-2.5x
    (measured 1.1-2.2x); its seconds per step are calibrated in modal/floor/cost.py."""
    from twoball.modal.floor.cost import drop_steps, expected_span

    report = twoball.bounce(**call)
    case, model = report.case, report.model
    v0 = case.v0 / case.scalings.velocity
    span = expected_span("body" in call or "pair" in call, 0.0, v0)
    steps = drop_steps(model["floor_points"], span, model["dt_s"] * case.wave_speed, v0)
    assert 0.5 <= steps / report.result.steps <= 2.5, (steps, report.result.steps)


@pytest.mark.parametrize("speed", [300.0, 4100.0])
def test_the_drops_rattle_stops_growing_beyond_its_calibration(speed) -> None:
    """Beyond 140 m/s (the basketball; a unit slip's 4100 m/s meant mm/s) the ball leaves
    sooner and rattles less: the estimate stays an upper bound within 10x (measured 7.3x
    and 8.4x at N = 64), not the v0^2 growth that refused a 1 s run as 7 min."""
    from twoball.modal.floor.cost import drop_steps, expected_span

    report = twoball.bounce(twoball.Case(v0=speed), solver=_legendre(64))
    case, model = report.case, report.model
    v0 = case.v0 / case.scalings.velocity
    span = expected_span(False, 0.0, v0)
    steps = drop_steps(model["floor_points"], span, model["dt_s"] * case.wave_speed, v0)
    assert 1.0 <= steps / report.result.steps <= 10.0, (steps, report.result.steps)


def test_the_drop_on_the_command_line_stops_at_the_deadline(tmp_path, monkeypatch, capsys):
    """With its estimate let through, a 140 m/s drop (thousands of steps) meets the deadline
    in its step loop: one line, exit 3."""
    import contextlib

    from twoball._common.budget import Budget
    from twoball.cli.main import main

    monkeypatch.setattr(Budget, "check", lambda self, option, estimate: estimate)
    monkeypatch.chdir(tmp_path)
    with pytest.raises(SystemExit) as stop, contextlib.suppress(KeyboardInterrupt):
        main(["--quiet", "bounce", "--max-time", "1s", "--drop-height", "1000"])
    [line] = capsys.readouterr().err.splitlines()
    assert stop.value.code == 3
    assert line.startswith("twoball: error: stopped at the time limit 1 s after 1")
    assert ", while the drop: step " in line and line.endswith("(raise the time limit, --max-time)")


def run_cli(argv: list[str], cwd: Path, **kwargs) -> tuple[subprocess.CompletedProcess, float]:
    env = dict(os.environ, OPENBLAS_NUM_THREADS="1", MPLBACKEND="Agg", PYTHONPATH=str(ROOT))
    for name in ("TWOBALL_MAX_MEMORY", "TWOBALL_MAX_TIME"):
        env.pop(name, None)
    start = time.monotonic()
    done = subprocess.run(
        [sys.executable, "-m", "twoball", *argv],
        cwd=cwd,
        env=env,
        capture_output=True,
        text=True,
        timeout=600,
        **kwargs,
    )
    return done, time.monotonic() - start


def test_command_line_stops_at_the_deadline_with_one_line(tmp_path, monkeypatch, capsys):
    """With every estimate let through, only the deadline stops ``verify`` (about a minute)."""
    import contextlib

    from twoball._common.budget import Budget
    from twoball.cli.main import main

    monkeypatch.setattr(Budget, "check", lambda self, option, estimate: estimate)
    monkeypatch.chdir(tmp_path)
    start = time.monotonic()
    with contextlib.suppress(SystemExit):
        main(["--quiet", "verify", "--max-time", "1s", "--out", "r"])
    seconds = time.monotonic() - start
    err = capsys.readouterr().err
    [line] = err.splitlines()
    assert line.startswith("twoball: error: stopped at the time limit 1 s after 1")
    assert ", while " in line and line.endswith("(raise the time limit, --max-time)")
    assert seconds < 1 + 3.0  # the last pass of a loop, clean-up
    assert not (tmp_path / "r").exists() and list(tmp_path.iterdir()) == []


def _address_space(limit: int):
    def apply() -> None:
        import resource

        resource.setrlimit(resource.RLIMIT_AS, (limit, limit))

    return apply


def test_address_space_limit_refuses_before_work_or_ends_in_one_line(tmp_path: Path) -> None:
    """``ulimit -v 10000000``: level 5 order 4 reserved 9.5 GB (SuperLU) and died in a traceback."""
    argv = ["liftoff", "--backend", "fem", "--level", "5", "--order", "4"]
    done, seconds = run_cli(argv, tmp_path, preexec_fn=_address_space(10_000_000 * 1024))
    assert done.returncode == 2 and seconds < 5, done.stderr
    assert done.stderr.startswith("twoball: error: --level 5 --order 4 needs ~")
    # a memory limit of its own does not lift the address-space limit: with --max-memory
    # 9GiB the run mapped 9.5 GB and died in a SuperLU allocation after 39 s; now its
    # address space (84 kB per P4 DOF, measured 73) is refused at once
    done, _ = run_cli(
        [*argv, "--max-memory", "9GiB"], tmp_path, preexec_fn=_address_space(10_000_000 * 1024)
    )
    assert done.returncode == 2, done.stderr
    [line] = done.stderr.splitlines()
    assert line.startswith("twoball: error: --level 5 --order 4 needs ~13.5 GiB of address space")
    assert "left under the address-space limit (ulimit -v)" in line
    # level 6, P2 has the same memory estimate (3.22 GiB) but maps 6.6 GB (it runs): the
    # address estimates against the measured VmPeak [GiB]
    from twoball.fem_membrane.cost import fem_dofs, fem_estimate

    for level, order, mapped in ((6, 2, 6.58), (5, 4, 11.82), (5, 3, 5.24), (4, 4, 3.25)):
        estimate = fem_estimate(fem_dofs("sphere", level, None, order), 30, "krylov", 2, order)
        assert mapped < estimate.address / 2**30 < 1.3 * mapped, (level, order, estimate)


def test_an_allocation_the_estimates_missed_is_one_line_exit_3(capsys) -> None:
    """A MemoryError (or SuperLU's failed malloc) that got past the estimates: one line."""
    from twoball.cli.guard import guarded

    def short_of_memory() -> int:
        raise MemoryError("Unable to allocate 7.45 GiB for an array")

    def superlu() -> int:
        raise RuntimeError("SUPERLU_MALLOC fails for buf in intMalloc()")

    for command in (short_of_memory, superlu):
        assert guarded(command) == 3
        [line] = capsys.readouterr().err.splitlines()
        assert line.startswith("twoball: error: out of memory (")


def test_budget_refusals_name_this_subcommands_flags_and_its_defaults() -> None:
    """A name becomes its flag where the subcommand has the option, marked as the default
    when the user did not give it; the words of a value in parentheses stay words."""
    import argparse

    from twoball.cli.flags import budget_flags

    bounce = argparse.Namespace(modes=100, dt=None, t_end=None, _given_once={"modes": 100})
    assert budget_flags("modes 100 dt 1.5625e-05 t_end 0.0981748", bounce) == (
        "--modes 100 --dt 1.5625e-05 (the default) --t-end 0.0981748 (the default)"
    )
    render = argparse.Namespace(frames=None, _given_once={})
    assert budget_flags("frames (60 frames)", render) == "--frames (60 frames) (the default)"
    given = argparse.Namespace(frames=60, _given_once={"frames": 60})
    assert budget_flags("frames (60 frames)", given) == "--frames (60 frames)"
    # an option this subcommand does not have stays a name
    assert budget_flags("t_end 0.02", argparse.Namespace(_given_once={})) == "t_end 0.02"
    assert budget_flags("modes 30") == "--modes 30"  # no command line: the flag
    sweep = argparse.Namespace(values=["0:0.5:1000000"], _given_once={})  # given in turns
    assert budget_flags("values (1000000 points)", sweep) == "--values (1000000 points)"


def _started_ago(seconds: float) -> None:
    """Put the running clock's start ``seconds`` in the past (and re-read the limit)."""
    budget._clock.update(start=time.monotonic() - seconds, read=None)


def test_off_is_no_limit() -> None:
    assert budget.parse_seconds("off") == math.inf == budget.parse_seconds(" None ")
    assert budget.format_seconds(math.inf) == "off"
    assert Budget.from_options(None, "off").max_seconds == math.inf
    with pytest.raises(budget.ParameterError, match="or off"):
        budget.parse_seconds("soon")


def test_the_default_follows_and_a_given_limit_does_not(monkeypatch) -> None:
    monkeypatch.delenv(budget.TIME_ENV, raising=False)
    assert Budget.from_options(None, None).follows
    assert not Budget.from_options(None, "5min").follows
    monkeypatch.setenv(budget.TIME_ENV, "5min")
    assert not Budget.from_options(None, None).follows  # the environment gives one too


def test_the_default_deadline_follows_an_accepted_estimate(monkeypatch) -> None:
    """Left at the default, a run the estimates accepted (4 min) is not stopped at 5 min
    (a loaded machine), only past ESTIMATE_SLACK times its estimate."""
    monkeypatch.delenv(budget.TIME_ENV, raising=False)
    with limits(), running():
        check("work", Estimate(MiB, 240.0))
        _started_ago(DEFAULT_MAX_SECONDS + 60)
        check_deadline("the work")  # 6 min: within 10 x 4 min
        _started_ago(ESTIMATE_SLACK * 240.0 + 5)
        with pytest.raises(DeadlineError, match="the default time limit 40 min"):
            check_deadline("the work")


def test_without_an_estimate_the_default_deadline_is_five_minutes(monkeypatch) -> None:
    monkeypatch.delenv(budget.TIME_ENV, raising=False)
    with limits(), running():
        _started_ago(DEFAULT_MAX_SECONDS - 5)
        check_deadline("the work")
        _started_ago(DEFAULT_MAX_SECONDS + 1)
        with pytest.raises(DeadlineError, match="the default time limit 5 min"):
            check_deadline("the work")


def test_a_given_limit_is_the_deadline_whatever_the_estimates() -> None:
    with limits(max_time="5min"), running():
        check("work", Estimate(MiB, 240.0))
        _started_ago(DEFAULT_MAX_SECONDS + 1)
        with pytest.raises(DeadlineError, match=r"at the time limit 5 min .*max_time\)"):
            check_deadline("the work")


def test_a_verb_without_a_default_deadline(monkeypatch) -> None:
    """reproduce: no default deadline (inf) and nothing refused for time; a limit given
    (the option or the environment) stands."""
    monkeypatch.delenv(budget.TIME_ENV, raising=False)
    with limits(), running(), verb_default(math.inf):
        check("work", Estimate(MiB, 86400.0))  # a day: not refused
        _started_ago(86400.0 * 20)
        check_deadline("the work")
    monkeypatch.setenv(budget.TIME_ENV, "20s")
    with limits(), running(), verb_default(math.inf):
        with pytest.raises(budget.BudgetError, match="limit 20 s"):
            check("work", Estimate(MiB, 60.0))
