"""twoball reproduce: figures and report, robust output, bad input in one line."""

import json
import os

import pytest

from twoball.cli.main import main
from twoball.verify.reproduce import driver as rep


def missing_parent(p):
    return p / "missing" / "rep"


def file_as_parent(p):
    (p / "file").write_text("x")
    return p / "file" / "rep"


def file_as_out(p):
    (p / "file").write_text("x")
    return p / "file"


def foreign_directory(p):
    (p / "d").mkdir()
    (p / "d" / "mine.txt").write_text("x")
    return p / "d"


def test_cli_writes_figures_and_report(tmp_path, capsys):
    out = tmp_path / "rep"
    code = main(["reproduce", "--out", str(out), "--only", "table2,fig6,fig10,table1,icm"])
    assert code == 0
    names = {p.name for p in out.iterdir()}
    assert {"reproduction.md", "reproduction.json", "fig06_waterfall.png"} <= names
    text = (out / "reproduction.md").read_text()
    assert "| c from P = 77200 Pa, m = 0.567 kg, R = 0.12 m | 320 1/s | 320.4 1/s |" in text
    data = json.loads((out / "reproduction.json").read_text())
    assert set(data["sections"]) == {"table2", "fig6", "fig10", "table1", "icm"}
    assert [p.name for p in tmp_path.iterdir()] == ["rep"]  # no staging left behind
    # a second run replaces the earlier reproduction
    assert main(["reproduce", "--out", str(out), "--only", "table2"]) == 0
    assert {p.name for p in out.iterdir()} == {
        "reproduction.md",
        "reproduction.json",
        "provenance.json",
        ".twoball-output",
    }


@pytest.mark.parametrize("make", [missing_parent, file_as_parent, file_as_out, foreign_directory])
def test_bad_out_is_one_line_exit_2(tmp_path, capsys, make):
    out = make(tmp_path)
    before = sorted(p.name for p in tmp_path.rglob("*"))
    with pytest.raises(SystemExit) as stop:
        main(["reproduce", "--out", str(out), "--only", "table2"])
    err = capsys.readouterr().err.strip().splitlines()
    assert stop.value.code == 2 and len(err) == 1 and "--out" in err[0]
    assert sorted(p.name for p in tmp_path.rglob("*")) == before  # nothing written


@pytest.mark.skipif(not os.path.isdir("/proc"), reason="needs /proc")
def test_unwritable_parent_is_one_line_exit_2(capsys):
    with pytest.raises(SystemExit) as stop:
        main(["reproduce", "--out", "/proc/twoball-reproduction", "--only", "table2"])
    err = capsys.readouterr().err.strip().splitlines()
    assert stop.value.code == 2 and len(err) == 1 and "--out" in err[0]


@pytest.mark.parametrize(
    ("argv", "flag"),
    [
        (["--only", "fig7"], "--only"),
        (["--only", ","], "--only"),
        (["--workers", "0"], "--workers"),
    ],
)
def test_bad_reproduce_options(tmp_path, capsys, argv, flag):
    with pytest.raises(SystemExit) as stop:
        main(["reproduce", "--out", str(tmp_path / "r"), *argv])
    err = capsys.readouterr().err.strip().splitlines()
    assert stop.value.code == 2 and len(err) == 1 and flag in err[0]
    assert not (tmp_path / "r").exists()


@pytest.mark.slow
def test_full_reproduction(tmp_path):
    out = tmp_path / "all"
    assert main(["reproduce", "--out", str(out), "--workers", "2"]) == 0
    data = json.loads((out / "reproduction.json").read_text())
    assert list(data["sections"]) == list(rep.PARTS)
    figures = [f for s in data["sections"].values() for f in s["figures"]]
    assert len(figures) == 17 and all((out / f).is_file() for f in figures)
    whole = {"whole_table1.png", "whole_timing.png", "whole_gap_basketball-tennis.png"}
    kinds = {"kinds_table1.png", "kinds_gap_basketball-tissue.png"}  # the shell, each body
    assert whole | kinds <= set(figures)
    text = (out / "reproduction.md").read_text()
    numbers = ("0.602", "0.29 m/s", "13.3 1/s", "0.091 mm", "1.02", "8.7 m/s", "180 1/s")
    for number in (*numbers, "2.090 / 0.488", "1.108 / 0.877"):  # (2.6) row 4; whole row 5
        assert number in text
    fig12 = data["sections"]["fig12"]["data"]
    assert fig12["solves"] == 1200 and fig12["failed"] == 0  # time: bench_sweeps.py


# --------------------------------------------------------------------------- stopped runs
def _report(out):
    return json.loads((out / "reproduction.json").read_text()), (
        out / "reproduction.md"
    ).read_text()


def test_time_limit_keeps_the_finished_parts(tmp_path):
    """Stopped at --max-time: table2 (0.1 s) is kept, fig11 (half a minute on one core)
    is named missing; status 3, one line naming the flag, within 2T + 3 s, no scratch."""
    import time

    from tests._common.commands import messages, no_scratch, start

    out = tmp_path / "rep"
    limit = 8.0
    argv = ["reproduce", "--only", "table2,fig11", "--workers", "1", "--out", str(out)]
    began = time.monotonic()
    process = start([*argv, "--max-time", f"{limit:g}s"])
    _, err = process.communicate(timeout=120)
    took = time.monotonic() - began
    lines = messages(err.decode())
    assert process.returncode == 3, err.decode()[-2000:]
    assert took < 2 * limit + 3 + 5  # the interpreter's and numpy's start-up on top
    assert len(lines) == 1 and "--max-time" in lines[0] and "max_time" not in lines[0], lines
    assert "kept the finished parts table2" in lines[0]
    data, text = _report(out)
    assert list(data["sections"]) == ["table2"] and data["missing"] == ["fig11"]
    assert data["stopped"].startswith("stopped at the time limit 8 s")
    assert "**Incomplete: 1 part(s) missing: fig11.**" in text and "max_time" not in text
    no_scratch(tmp_path)


def test_interrupt_after_a_part_keeps_it(tmp_path):
    """SIGTERM once the first part is committed: it stays, the report names the rest
    missing and why, and the status is 143."""
    import signal

    from tests._common.commands import messages, no_scratch, start, wait_for_pause

    out = tmp_path / "rep"
    argv = ["reproduce", "--only", "table2,fig11", "--workers", "1", "--out", str(out)]
    process = start(argv, "part")
    wait_for_pause(process, "part")
    process.send_signal(signal.SIGTERM)
    _, err = process.communicate(timeout=60)
    assert process.returncode == 143, err.decode()[-2000:]
    assert messages(err.decode()) == ["twoball: interrupted"]
    data, text = _report(out)
    assert list(data["sections"]) == ["table2"] and data["missing"] == ["fig11"]
    assert data["stopped"] == "interrupted by SIGTERM"
    assert "The run was interrupted by SIGTERM." in text
    no_scratch(tmp_path)


def test_reproduce_has_no_default_deadline_and_takes_the_limits(tmp_path, capsys):
    """The whole reproduction is legitimately long: no default time limit; the flags
    are there, and a bad one is refused by its name."""
    from twoball._common.budget import Budget, current_budget, verb_default

    with verb_default(float("inf")):
        assert current_budget().max_seconds == float("inf")
    from twoball._common.budget import limits

    with limits(max_time="30s"), verb_default(float("inf")):  # a limit given stands
        assert current_budget() == Budget(current_budget().max_memory, 30.0)
    with pytest.raises(SystemExit) as stop:
        main(["reproduce", "--only", "table2", "--out", str(tmp_path / "r"), "--max-time", "x"])
    err = capsys.readouterr().err.strip().splitlines()
    assert stop.value.code == 2 and err[-1].startswith("twoball: error: --max-time must be")
