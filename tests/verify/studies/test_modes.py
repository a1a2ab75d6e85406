"""The study in the number of modes N (verify/studies/modes.py)."""

import pytest

from twoball._common.errors import ParameterError
from twoball.modal.parameters import preset
from twoball.verify.studies.modes import parse_modes, run_modes_study


def test_modes_study_is_second_order_and_states_the_n30_truncation():
    study = run_modes_study(preset("basketball"), modes=(30, 60, 120, 240))
    assert study.passed
    orders = {q.spec.key: q.checked_order for q in study.quantities}
    assert set(orders) == {"t_l", "v_l", "pole_l2", "energy_end"}
    for order in orders.values():
        assert order == pytest.approx(2.0, abs=0.1)
    v_l = next(q for q in study.quantities if q.spec.key == "v_l")
    assert v_l.relative_errors[0] == pytest.approx(0.0287, abs=5e-4)  # N = 30
    assert v_l.analysis.gci is not None and v_l.analysis.gci.convergence == "monotone"
    assert any("Truncation error of N = 30" in note for note in study.notes)


def test_parse_modes():
    assert parse_modes("30,60,120,240") == (30, 60, 120, 240)
    assert parse_modes("30,45,60") == (30, 45, 60)
    assert parse_modes("1:3") == (1, 2, 3)  # the one list syntax: every integer
    assert parse_modes("30:60:3") == (30, 45, 60)
    with pytest.raises(ParameterError, match="modes_list"):
        parse_modes("30:480")  # 451 counts: not a study
