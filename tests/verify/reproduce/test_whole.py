"""The reproduction's whole-bounce parts: Table 1, the gap curves, the timing (coarse runs).

The parts get a task that runs the whole bounce at N = 16 and two gaps, so that
the file stays fast; the numbers at the defaults are in docs/whole_bounce.rst.
Independent values: Table 1 as printed and eq. (2.6).
"""

from __future__ import annotations

from dataclasses import replace

import pytest
from twoball.modal.icm.limits import touching_ratios
from twoball.modal.icm.table1 import TABLE1
from twoball.verify.reproduce import driver
from twoball.verify.reproduce import whole as part
from twoball.verify.reproduce.common import Context
from twoball.verify.sweeps.parallel import Runner

import twoball
from twoball._bounce import BounceTask


def coarse(item):
    case, drop, body, pair = item
    return BounceTask()((case, replace(drop, modes=16), body, pair))


@pytest.fixture()
def ctx(tmp_path, monkeypatch):
    monkeypatch.setattr(part, "GAPS", (0.0, 0.2))
    part._CURVES.clear()
    return Context(tmp_path, Runner(workers=1), tasks={"bounce": coarse})


def test_the_parts_are_registered():
    for name in ("whole_table1", "whole_gap", "whole_timing"):
        assert name in driver.PARTS


def test_table1_every_row_beside_every_model(ctx):
    sec = part.part_whole_table1(ctx)
    rows = sec.data["rows"]
    assert [r["row"] for r in rows] == [1, 2, 3, 4, 5, 6]
    for r in rows:
        printed = TABLE1[r["row"] - 1]
        assert r["measured"] == [printed.measured_v1, printed.measured_v2]
        assert r["icm_printed"] == [printed.icm_v1, printed.icm_v2]
        assert r["icm_2_6"] == pytest.approx(touching_ratios(printed.mu, printed.e2, printed.e12))
        assert set(r["baselines"]) == {
            "icm",
            "two-spring-dashpot",
            "bartz2020",
            "hertz-viscoelastic",
        }
        assert 0.5 < r["whole"][0] < 3.0 and 0.3 < r["whole"][1] < 1.0
    assert len(sec.comparisons) == 12 and "ICM v1/|u0|" in sec.tables[0]


def test_gap_curves_and_timing(ctx):
    gap = part.part_whole_gap(ctx)
    assert len(gap.figures) == 3 and all(ctx.path(f).stat().st_size > 1000 for f, _ in gap.figures)
    for name in part.GAP_PAIRS:
        far = gap.data[name][-1]
        assert far["sequence"] == "independent" and far["body_left_first"] is False
        assert far["e12_effective"] is not None
    timing = part.part_whole_timing(ctx)
    assert ctx.path(timing.figures[0][0]).stat().st_size > 1000
    near = timing.data["basketball-tissue"][0]
    assert near["t_l_s"] > 0 and near["body_left_first"] is True


def test_without_the_faces_task_the_parts_refuse(tmp_path):
    with pytest.raises(twoball.ParameterError):
        part.part_whole_table1(Context(tmp_path, Runner(workers=1)))
