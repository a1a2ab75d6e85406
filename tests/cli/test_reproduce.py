"""twoball reproduce: figures and report, robust output, bad input in one line."""

import json
import os

import pytest
from twoball.verify.reproduce import driver as rep

from twoball.cli.main import main


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
