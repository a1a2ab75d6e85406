"""verify/output/figures/measured.py: the user's rows on the model's figures, and the notes."""

from __future__ import annotations

import numpy as np
import pytest

import twoball
from twoball.verify.fit.data import Measurements
from twoball.verify.output.figures.measured import (
    MEASURED_COLOUR,
    bounce_overlay,
    bounce_sweep_overlay,
    draw_overlay,
    overlay_for,
    sweep_overlay,
)


def measured_artists(figure) -> int:
    """Lines and markers drawn in the measured colour, over every panel."""
    from matplotlib.colors import to_hex

    count = 0
    for ax in figure.axes:
        for line in ax.get_lines():
            if to_hex(line.get_color()) == MEASURED_COLOUR.lower():
                count += 1
    return count


@pytest.fixture(scope="module")
def v0_sweep():
    return twoball.sweep({"v0": [2.0, 3.0, 4.0, 5.0]})


def test_a_v0_sweep_places_each_row_at_its_speed(v0_sweep):
    data = Measurements.from_columns(
        {"v0_m_s": [3.0, 4.0, None], "v1_m_s": [2.4, 3.2, 3.0], "t_liftoff_s": [0.0099, None, 0.01]}
    )
    plan = overlay_for(v0_sweep, data)
    ratio, time = plan.layers
    assert ratio.panel == ("v_l",) and time.panel == ("t_l",)
    assert ratio.x[:2].tolist() == [3.0, 4.0]
    assert ratio.y[:2] == pytest.approx([2.4 / 3.0, 3.2 / 4.0])  # v1 / |v0|
    assert np.isnan(ratio.y[2])  # no v0_m_s: not placed
    assert time.y[0] == pytest.approx(9.9)  # ms
    assert plan.notes == ("1 row(s) of rows without v0_m_s not drawn (a v0 sweep places a row "
                          "at its |v0|)",)  # fmt: skip
    from twoball.verify.output.figures.sweep import sweep_figure
    from twoball.verify.sweeps.sweeps import SweepGrid

    figure = sweep_figure(SweepGrid(("v0",), tuple(v0_sweep.values)), v0_sweep.points)
    draw_overlay(figure, plan)
    assert measured_artists(figure) >= 2
    assert all(ax.get_legend() is not None for ax in figure.axes[:2])


def test_any_other_parameter_draws_lines_at_the_sweeps_speed():
    data = Measurements.from_columns({"v0_m_s": [4.1, 3.0], "v1_m_s": [3.7, 2.5]})
    plan = sweep_overlay(data, "damping", 4.1)
    assert plan.layers[0].x is None and plan.layers[0].y[0] == pytest.approx(3.7 / 4.1)
    assert np.isnan(plan.layers[0].y[1])
    assert plan.notes == ("1 row(s) of rows at another |v0| than 4.1 m/s not drawn",)


def test_columns_a_figure_does_not_show_are_said():
    data = Measurements.from_columns({"v2_m_s": [2.0], "phi_a_rad": [2.6]})
    notes = sweep_overlay(data, "damping", 4.1).notes
    assert notes[0].startswith("v2_m_s, phi_a_rad of rows not drawn: the lift-off sweep shows")
    assert notes[-1] == "nothing of rows drawn"


def test_the_whole_bounces_sweep_takes_v1_v2_and_the_time_at_their_gap():
    data = Measurements.from_columns(
        {
            "gap_m": [0.0, 0.05],
            "v1_m_s": [7.4, 6.0],
            "v2_m_s": [2.5, 2.4],
            "t_liftoff_s": [0.012, 0.02],
        }
    )
    plan = bounce_sweep_overlay(data, "gap", 4.1, body=True)
    assert [layer.panel for layer in plan.layers] == [("v_1/|v_0|",), ("v_2/|v_0|",), ("time",)]
    assert plan.layers[0].x.tolist() == [0.0, 50.0]  # mm, as the figure
    assert plan.layers[1].y == pytest.approx([2.5 / 4.1, 2.4 / 4.1])
    drops = bounce_sweep_overlay(data, "v0", None, body=False)
    assert drops.notes[-1] == "nothing of rows drawn"  # no v0_m_s, no phi_a_rad


def test_one_drop_takes_the_rows_at_its_speed_and_gap():
    data = Measurements.from_columns(
        {"v0_m_s": [4.1, 4.1, 3.0], "gap_m": [0.0, 0.02, 0.0], "v1_m_s": [7.0, 6.0, 5.0]}
    )
    plan = bounce_overlay(data, 4.1, 0.0, body=True)
    v1 = plan.layers[0]
    assert v1.panel == ("velocity",) and v1.x is None
    assert v1.y[0] == 7.0 and np.isnan(v1.y[1:]).all()
    assert "1 row(s) of rows at another |v0| than 4.1 m/s not drawn" in plan.notes
    assert "1 row(s) of rows at another gap than 0 mm not drawn" in plan.notes


def test_a_drop_figure_takes_the_measured_contact_angle(tmp_path):
    solver = twoball.MoreauJean(twoball.LegendreBall(12))
    report = twoball.bounce(solver=solver)
    path = report.plot(tmp_path / "drop.png", measured={"v0_m_s": [4.1], "phi_a_rad": [2.6]})
    assert path.stat().st_size > 10_000
    plan = overlay_for(report, Measurements.from_columns({"phi_a_rad": [2.6], "v1_m_s": [1.0]}))
    assert plan.notes[0].startswith("v1_m_s of rows not drawn: the drop's figure shows phi_a_rad")
