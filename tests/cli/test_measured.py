"""--measured on sweep --plot and bounce --plot, sweep --csv (twoball/cli/measured.py)."""

from __future__ import annotations

import csv

import pytest

from tests.helpers import cli_run
from twoball.cli.main import main

ROWS = "v0_m_s,v1_m_s,t_liftoff_s\n3.0,2.5,0.0099\n4.0,3.6,\n6.5,5.0,0.0099\n"


@pytest.fixture
def measured(tmp_path):
    path = tmp_path / "drops.csv"
    path.write_text(ROWS)
    return path


def refused(capsys, *argv: str) -> str:
    with pytest.raises(SystemExit) as stop:
        main(list(argv))
    lines = capsys.readouterr().err.strip().splitlines()
    assert stop.value.code == 2 and len(lines) == 1, lines
    return lines[0]


def test_a_sweep_with_its_measured_points_and_its_table(capsys, tmp_path, measured):
    figure, table = tmp_path / "sweep.png", tmp_path / "sweep.csv"
    argv = ["sweep", "--param", "v0", "--values", "2:5:4", "--plot", str(figure)]
    code, out, err = cli_run(capsys, *argv, "--measured", str(measured), "--csv", str(table))
    assert code == 0 and figure.stat().st_size > 10_000
    assert f"table written to {table}" in out
    with open(table, newline="") as handle:
        rows = list(csv.DictReader(handle))
    assert [float(r["v0_m_s"]) for r in rows] == [2.0, 3.0, 4.0, 5.0]
    assert "t_liftoff_s" in rows[0] and "v_liftoff_m_s" in rows[0]
    assert "not drawn" not in err  # every row is on the figure


def test_rows_off_the_sweep_are_said(capsys, tmp_path, measured):
    figure = tmp_path / "damping.png"
    argv = ["sweep", "--param", "damping", "--values", "0.1:0.3:3", "--plot", str(figure)]
    code, _, err = cli_run(capsys, *argv, "--measured", str(measured), "--v0", "4")
    assert code == 0
    assert f"twoball: note: 2 row(s) of {measured} at another |v0| than 4 m/s not drawn" in err


def test_a_sweep_of_the_bounce_against_damping_with_its_table(capsys, tmp_path):
    table = tmp_path / "drops.csv"
    argv = ["sweep", "--bounce", "--param", "damping", "--values", "0.05,0.3", "--modes", "12"]
    code, out, _ = cli_run(capsys, *argv, "--csv", str(table))
    assert code == 0 and "Drops on the floor against damping" in out
    with open(table, newline="") as handle:
        rows = list(csv.DictReader(handle))
    assert [float(r["damping"]) for r in rows] == [0.05, 0.3]
    assert float(rows[1]["e2"]) < float(rows[0]["e2"])
    line = refused(capsys, *argv, "--damping", "0.2")
    assert "--damping must be left out when --param damping is swept" in line


def test_one_bounce_with_its_measured_row(capsys, tmp_path):
    figure, rows = tmp_path / "bounce.png", tmp_path / "pair.csv"
    rows.write_text("v0_m_s,gap_m,v1_m_s,v2_m_s,t_liftoff_s\n4.1,0,7.4,2.5,0.014\n")
    argv = ["bounce", "--pair", "basketball-tennis", "--modes", "12", "--plot", str(figure)]
    code, out, err = cli_run(capsys, *argv, "--measured", str(rows))
    assert code == 0 and figure.stat().st_size > 10_000
    assert "not drawn" not in err and "Table 1 row 4 measured" in out


@pytest.mark.parametrize(
    ("argv", "flag"),
    [
        (["sweep", "--param", "damping", "--values", "0.1,0.2", "--measured", "{m}"], "--measured"),
        (
            ["sweep", "--param", "damping", "--param", "v0", "--values", "0.1,0.2"]
            + ["--values", "3,4", "--plot", "{t}/x.png", "--measured", "{m}"],
            "--measured",
        ),
        (
            ["sweep", "--param", "damping", "--values", "0.1", "--plot", "{t}/x.png"]
            + ["--measured", "{t}/none.csv"],
            "--measured",
        ),  # fmt: skip
        (["sweep", "--param", "damping", "--values", "0.1", "--csv", "{t}"], "--csv"),
        (
            ["sweep", "--param", "damping", "--values", "0.1", "--plot", "{t}/x.png"]
            + ["--csv", "{t}/x.png"],
            "--csv",
        ),  # fmt: skip
        (
            [
                "sweep",
                "--param",
                "damping",
                "--values",
                "0.1",
                "--csv",
                "{m}",
                "--plot",
                "{t}/x.png",
            ]
            + ["--measured", "{m}"],
            "--csv",
        ),  # fmt: skip
        (["bounce", "--measured", "{m}"], "--measured"),
        (["bounce", "--plot", "{t}/x.png", "--measured", "{t}/bad.csv"], "--measured"),
    ],
)
def test_refusals_before_the_work(capsys, tmp_path, measured, argv, flag):
    (tmp_path / "bad.csv").write_text("v0_m_s,v1_m_s\n4.1,fast\n")
    words = [w.replace("{m}", str(measured)).replace("{t}", str(tmp_path)) for w in argv]
    line = refused(capsys, *words)
    assert line.startswith(f"twoball: error: {flag}")
    if "bad.csv" in " ".join(words):
        assert "row 1 (line 2), column v1_m_s" in line
