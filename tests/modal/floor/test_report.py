"""modal/floor/report.py: Table 1's measured row beside the whole bounce of a pair."""

from __future__ import annotations

import pytest

from twoball.modal.balls.membrane import LegendreBall
from twoball.modal.contact.body import Body
from twoball.modal.floor.bounce import bounce_problem, simulate
from twoball.modal.floor.options import Drop
from twoball.modal.pairs import PAIRS


@pytest.fixture(scope="module")
def basketball_tennis():
    """The basketball-tennis pair touching, on a coarse ball (Table 1 row 4)."""
    return simulate(bounce_problem(pair="basketball-tennis", ball=LegendreBall(12)))


def test_a_pair_has_its_table1_row_beside_the_model(basketball_tennis):
    report = basketball_tennis
    table1 = report.comparisons()["table1"]
    row = PAIRS["basketball-tennis"].table1
    assert table1["row"] == 4 and table1["pair"] == "basketball-tennis"
    assert (table1["measured_v1_ratio"], table1["measured_v2_ratio"]) == (1.8, 0.61)
    assert (table1["icm_printed_v1_ratio"], table1["icm_printed_v2_ratio"]) == (
        row.icm_v1,
        row.icm_v2,
    )
    assert table1["model_v1_ratio"] == report.v1_ratio
    assert table1["model_v2_ratio"] == report.v2_ratio
    assert table1["model_minus_measured_v1"] == pytest.approx(report.v1_ratio - 1.8)
    assert "touching" in table1["note"] and "gap" not in table1["note"]
    data = report.as_dict()
    assert data["comparisons"]["table1"] == table1  # the JSON's comparisons
    assert data["icm_solver"] is None or "v1_ratio" in data["icm_solver"]
    assert "icm" in data["baselines"]["models"]  # the ICM and the baselines beside it


def test_the_command_lines_table_shows_it(basketball_tennis):
    from twoball.cli.bounce import whole_rows

    rows = dict(whole_rows(basketball_tennis))
    assert rows["Table 1 row 4 measured v1/|v0| / v2/|v0|"] == "1.8 / 0.61 (touching)"
    assert rows["  Table 1's ICM (printed)"] == "2.1 / 0.56"
    shown = rows["  this run (model)"]
    assert shown == f"{basketball_tennis.v1_ratio:.4f} / {basketball_tennis.v2_ratio:.4f}"
    assert "icm v1/|v0| / v2/|v0|" in rows  # the baselines stay beside


def test_a_gap_is_said_and_a_body_of_ones_own_has_no_row():
    gapped = simulate(
        bounce_problem(pair="tennis-coin", ball=LegendreBall(8), drop=Drop(gap=0.02)),
        baselines=False,
    )
    assert "this run's gap is 20 mm" in gapped.comparisons()["table1"]["note"]
    assert gapped.baselines is None  # simulate(baselines=False): none computed
    own = simulate(
        bounce_problem(ball=LegendreBall(8), body=Body(0.05, restitution=0.5)), baselines=False
    )
    assert "table1" not in own.comparisons()
    drop = simulate(bounce_problem(ball=LegendreBall(8)))
    assert "table1" not in drop.comparisons() and drop.comparisons()["table1_e2"] == [0.8, 0.9]
