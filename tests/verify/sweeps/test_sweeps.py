"""Sweep grids and failed points (verify/sweeps/sweeps.py)."""

import json
import math

import numpy as np
import pytest

import twoball
from tests.verify.sweeps.helpers import FailAbove, cases
from twoball.cli.main import main
from twoball.modal.initial import phi_a_from_v0
from twoball.modal.parameters import preset
from twoball.verify.output.figures.sweep import sweep_figure
from twoball.verify.sweeps.parallel import Runner
from twoball.verify.sweeps.sweeps import SweepGrid, make_grid, run_sweep


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


def test_grid_shape_and_order():
    grid = make_grid(["damping", "v0"], ["0:0.3:3", "2:8:4"])
    assert isinstance(grid, SweepGrid) and grid.shape == (3, 4)
    cs = grid.cases(preset("basketball"))
    assert len(cs) == 12 and grid.indices()[:5] == [(0, 0), (0, 1), (0, 2), (0, 3), (1, 0)]
    assert [c.damping for c in cs[:4]] == [0.0] * 4
    assert [c.v0 for c in cs[:4]] == pytest.approx([2, 4, 6, 8])
    assert len({c.phi_a for c in cs[:4]}) == 4  # phi_a from eq. (3.7) per v0


# --- One phi_a rule per sweep: no dip at a preset's own |v0|, and the JSON and figure say which


def test_v0_sweep_has_no_dip_at_the_presets_speed() -> None:
    speeds = [3.9, 4.0, 4.1, 4.2, 4.3]
    result = twoball.sweep({"v0": speeds})
    ratios = np.array([p.ratio for p in result.points])
    bends = np.abs(np.diff(ratios, 2))  # measured-phi_a point: 0.0316 + 0.0376 before
    assert bends.max() < 1e-3
    point = result.points[2].case
    assert point.phi_a == pytest.approx(phi_a_from_v0(4.1, 0.12, 320.0), rel=1e-12)
    alone = twoball.liftoff(twoball.Case.preset("basketball", phi_a="eq. (3.7)"))
    assert result.points[2].ratio == alone.ratio
    assert result.phi_a_rule.startswith("eq. (3.7) at every point")


def test_other_sweeps_keep_the_base_angle() -> None:
    result = twoball.sweep({"damping": [0.1, 0.13]})
    assert {p.case.phi_a for p in result.points} == {2.6}
    assert result.phi_a_rule == "2.6 rad at every point (measured (basketball))"


def test_json_and_figure_say_the_rule(capsys) -> None:
    assert main(["sweep", "--param", "v0", "--values", "4,4.1", "--json"]) == 0
    data = json.loads(capsys.readouterr().out)
    assert set(data) == {"results", "provenance"}  # the one shape of every JSON output
    assert all(p["phi_a_rule"].startswith("eq. (3.7) at every point") for p in data["results"])
    result = twoball.sweep({"wave_speed": [300.0, 320.0]})
    grid = SweepGrid(result.parameters, tuple(result.values))
    figure = sweep_figure(grid, result.points)
    assert "eq. (3.7) at every point" in figure._suptitle.get_text()


def test_mass_ratio_sweep_with_both_energies_has_one_rule() -> None:
    body = twoball.Body(0.0, energy="both")
    result = twoball.sweep({"mass_ratio": [0.0, 1e-6]}, body=body)
    first, second = (p.report for p in result.points)
    assert first.membrane.phi_a == pytest.approx(second.membrane.phi_a, abs=1e-6)
