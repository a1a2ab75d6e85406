"""The time-step study (verify/studies/time_step.py): order 2 of generalized-alpha."""

import pytest
from twoball.modal.parameters import preset
from twoball.verify.studies.time_step import run_dt_study

from tests.helpers import by_key


def test_dt_study_is_second_order_for_generalized_alpha():
    study = run_dt_study(preset("basketball"), mesh="axisym", order=2, levels=(1, 2, 3))
    assert study.passed
    q = by_key(study)
    for key in ("t_l", "v_l", "pole_l2", "pole_samples"):
        assert q[key].checked_order == pytest.approx(2.0, abs=0.15)
    assert q["t_l_hermite"].spec.band is None  # reported, not checked
