"""The reproduction's whole-bounce parts: Table 1, the gap curves, the timing (coarse runs).

The parts' task (:class:`~twoball.verify.sweeps.bounce.BounceTask`) runs the whole
bounce at N = 16 here, and two gaps, so that the file stays fast; the numbers at
the defaults are in docs/whole_bounce.rst.
Independent values: Table 1 as printed and eq. (2.6).
"""

from __future__ import annotations

import pytest

import twoball
from twoball.modal.icm.limits import touching_ratios
from twoball.modal.icm.table1 import TABLE1
from twoball.verify.reproduce import driver
from twoball.verify.reproduce import whole as part
from twoball.verify.reproduce.common import Context
from twoball.verify.sweeps import bounce as sweeps
from twoball.verify.sweeps.parallel import Runner

COARSE = twoball.MoreauJean(twoball.LegendreBall(16))
TASK = sweeps.BounceTask


def coarse(monitor=None) -> TASK:
    """The parts' task on N = 16 Legendre modes (the parts build it with their monitor)."""
    return TASK(solver=COARSE, monitor=monitor)


@pytest.fixture()
def told() -> list[str]:
    """What the runs told the context's monitor."""
    return []


@pytest.fixture()
def ctx(tmp_path, monkeypatch, told):
    monkeypatch.setattr(part, "GAPS", (0.0, 0.2))
    monkeypatch.setattr(sweeps, "BounceTask", coarse)
    part._CURVES.clear()
    return Context(tmp_path, Runner(workers=1), monitor=told.append)


def test_the_parts_are_registered():
    for name in ("whole_table1", "whole_gap", "whole_timing"):
        assert name in driver.PARTS


def test_table1_every_row_beside_every_model(ctx, told):
    sec = part.part_whole_table1(ctx)
    assert any(text.startswith("the whole bounce: step") for text in told)  # the runs told it
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
    for column in ("v1: TSD / Bartz / Hertz", "v2: TSD / Bartz / Hertz", "v2 at the floor release"):
        assert column in sec.tables[0], column
    assert "e2 in the run" not in sec.tables[0]
    for r in rows:  # the baselines' v2 beside their v1
        for name in ("two-spring-dashpot", "bartz2020", "hertz-viscoelastic"):
            assert 0.3 < r["baselines"][name][1] < 1.0, (r["pair"], name)
        assert r["whole_v2_floor_release"] == pytest.approx(r["whole"][1], rel=1e-12)
    assert [f for f, _ in sec.figures] == ["whole_table1.png"]
    assert ctx.path("whole_table1.png").stat().st_size > 1000


def test_the_preamble_names_the_model_of_the_parts_that_ran():
    whole = driver.models_line(["whole_table1", "whole_gap"])
    assert "N = 192" in whole and "Moreau-Jean" in whole and "Lanczos" not in whole
    cem = driver.models_line(["fig6"])
    assert "Lanczos filter, N = 30" in cem and "N = 192" not in cem


@pytest.mark.slow
def test_gap_curves_and_timing(ctx):
    gap = part.part_whole_gap(ctx)
    assert len(gap.figures) == 3 and all(ctx.path(f).stat().st_size > 1000 for f, _ in gap.figures)
    for name in part.GAP_PAIRS:
        far = gap.data[name][-1]
        assert far["sequence"] == "independent" and far["body_left_first"] is False
        assert far["e12_effective"] is not None
    timing = part.part_whole_timing(ctx)
    assert ctx.path(timing.figures[0][0]).stat().st_size > 1000
    # eq. (2.2) with each pair's own e2 (Table 1: 0.80 and 0.90), the measured window only
    # over the small gaps
    figure = part.timing_figure(part._curves(ctx))
    wide = figure.axes[0]
    icm = {ln.get_label(): ln for ln in wide.get_lines() if ln.get_label().startswith("ICM")}
    assert sorted(icm) == [
        "ICM, eq. (2.2), $e_2$ = 0.8 (tennis)",
        "ICM, eq. (2.2), $e_2$ = 0.9 (tissue, table-tennis)",
    ]
    for e2, line in zip((0.8, 0.9), sorted(icm.items()), strict=True):
        gap, t_ms = line[1].get_xdata()[-1] * 1e-3, line[1].get_ydata()[-1] * 1e-3
        # eq. (2.2) with gravity as the ICM baseline has it: above gap / ((1 + e2) |v0|)
        assert t_ms == pytest.approx(gap / ((1.0 + e2) * 4.1), rel=0.05)
    (band,) = wide.collections
    xs = band.get_paths()[0].vertices[:, 0]
    assert xs.min() == 0.0 and xs.max() == pytest.approx(part.MEASURED_TL_GAP * 1e3)
    near = timing.data["basketball-tissue"][0]
    assert near["t_l_s"] > 0 and near["body_left_first"] is True
