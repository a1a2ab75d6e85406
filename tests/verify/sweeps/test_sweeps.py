"""Sweep grids and failed points (verify/sweeps/sweeps.py)."""

import math

import pytest
from twoball.modal.parameters import preset
from twoball.verify.sweeps.parallel import Runner
from twoball.verify.sweeps.sweeps import SweepGrid, make_grid, run_sweep

from tests.verify.sweeps.helpers import FailAbove, cases


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
