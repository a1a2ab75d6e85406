"""verify/sweeps/table.py: a sweep's table as CSV (SweepResult.to_csv, BounceSweep.to_csv)."""

from __future__ import annotations

import csv

import pytest

import twoball
from twoball.verify.sweeps.table import BOUNCE_COLUMNS, LIFTOFF_COLUMNS


def read(path) -> list[dict[str, str]]:
    with open(path, newline="", encoding="utf-8") as handle:
        return list(csv.DictReader(handle))


def test_a_liftoff_sweep_as_csv_round_trips_its_numbers(tmp_path):
    result = twoball.sweep({"damping": [0.1, 0.13, 0.99]})
    path = result.to_csv(tmp_path / "sweep.csv")
    rows = read(path)
    header = list(rows[0])
    assert header[0] == "damping" and header[1:] == [c for c in LIFTOFF_COLUMNS if c != "damping"]
    assert all(name.endswith(("_s", "_m", "_rad", "_1_s")) or name in (
        "damping", "modes", "phi_a_source", "lifted", "ratio", "warnings", "error"
    ) for name in header)  # fmt: skip
    assert len(rows) == 3
    for row, point in zip(rows, result.points, strict=True):
        assert float(row["damping"]) == point.case.damping
        assert float(row["v0_m_s"]) == point.case.v0
        if point.report.lifted:
            assert row["lifted"] == "true"
            assert float(row["t_liftoff_s"]) == point.report.t_liftoff_s  # repr: exact
            assert float(row["v_liftoff_m_s"]) == point.report.v_liftoff_m_s
        else:
            assert row["lifted"] == "false" and row["t_liftoff_s"] == ""  # blank: no value


def test_a_grid_puts_both_parameters_first(tmp_path):
    result = twoball.sweep({"v0": [3.0, 4.0], "wave_speed": [300.0, 320.0]})
    rows = read(result.to_csv(tmp_path / "grid.csv"))
    assert list(rows[0])[:2] == ["v0_m_s", "wave_speed_1_s"] and len(rows) == 4
    assert [float(r["wave_speed_1_s"]) for r in rows] == [300.0, 320.0, 300.0, 320.0]


def test_a_sweep_of_the_whole_bounce_as_csv(tmp_path):
    solver = twoball.MoreauJean(twoball.LegendreBall(8))
    result = twoball.sweep(
        {"gap": [0.0, 0.05]}, drop=twoball.Drop(), solver=solver, pair="tennis-coin"
    )
    rows = read(result.to_csv(tmp_path / "gap.csv"))
    header = list(rows[0])
    assert header[0] == "gap_m" and set(BOUNCE_COLUMNS) <= set(header)
    assert {"v1_m_s", "v2_ratio", "t_liftoff_s", "e12_effective"} <= set(header)
    for row, report in zip(rows, result.reports, strict=True):
        data = report.as_dict()
        assert float(row["v1_m_s"]) == data["v1_m_s"]
        assert float(row["v2_m_s"]) == data["v2_m_s"]  # the ball at its last release
        assert row["body_left_first"] in ("true", "false")
        assert float(row["mass_ratio"]) == pytest.approx(0.062)


def test_a_failed_point_keeps_its_row_with_the_error(tmp_path, monkeypatch):
    from tests.verify.sweeps.helpers import FailAbove

    monkeypatch.setattr("twoball.verify.sweeps.sweeps.SweepSolver", lambda *a, **k: FailAbove(3.0))
    result = twoball.sweep({"v0": [2.0, 4.0]}, workers=1)
    rows = read(result.to_csv(tmp_path / "v0.csv"))
    assert [bool(r["error"]) for r in rows] == [False, True]
    assert "refusing v0 = 4" in rows[1]["error"] and rows[1]["t_liftoff_s"] == ""
    assert float(rows[1]["v0_m_s"]) == 4.0  # the point's case stays


def test_the_path_is_checked(tmp_path, read_only_folder):
    result = twoball.sweep({"damping": [0.13]})
    with pytest.raises(twoball.ParameterError, match="path"):
        result.to_csv(tmp_path)  # a folder
    with pytest.raises(twoball.ParameterError, match="path"):
        result.to_csv(f"{read_only_folder}/x.csv")
