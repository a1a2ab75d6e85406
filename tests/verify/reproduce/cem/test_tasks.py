"""Threshold tasks of the reproduction (verify/reproduce/cem/tasks.py)."""

import pytest

from twoball.modal.parameters import preset
from twoball.verify.reproduce.cem.fig12 import fig12_base
from twoball.verify.reproduce.cem.tasks import ThresholdTask


def test_v0_threshold_paper_horizon_brackets_0_29():
    # full criteria with the paper's dt < t_l horizon reproduce 0.29 m/s within 2 %
    t = ThresholdTask(fig12_base(), "v0", "paper", 0.2, 0.4, True, True, 5, 1e-4)()
    assert t.value == pytest.approx(0.29, rel=0.02)


def test_criterion_i_alone_thresholds_are_far_below_the_paper():
    # documented discrepancy: criterion (i) literally gives much lower thresholds
    base = fig12_base()
    v0 = ThresholdTask(base, "v0", "overall", 0.05, 0.2, True, True, 5, 1e-3)().value
    c = ThresholdTask(base, "wave_speed", "overall", 1.0, 5.0, True, True, 5, 1e-3)().value
    assert v0 == pytest.approx(0.0954, rel=0.01) and v0 < 0.29 / 2
    assert c == pytest.approx(2.59, rel=0.01) and c < 13.3 / 2


def test_damping_threshold_readings():
    base = preset("basketball")
    up = ThresholdTask(base, "damping", "moving_up", 0.55, 0.7, False, False, 4, 1e-4)()
    window = ThresholdTask(base, "damping", "window", 0.40, 0.55, False, False, 4, 1e-4)()
    # closest analogue of the paper's 0.602 / 0.6066: about 4 % above
    assert up.value == pytest.approx(0.628, abs=0.003)
    # the default horizon stops lifting off near 0.47 (re-contact of the slow launch)
    assert window.value == pytest.approx(0.4697, abs=0.002)
