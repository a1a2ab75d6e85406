"""Helpers of the reproduction (verify/reproduce/common.py).

Thresholds, minima, comparison tables.
"""

import numpy as np
import pytest

from twoball.modal.parameters import preset
from twoball.verify.reproduce.common import (
    Comparison,
    acceleration_minima,
    comparison_table,
    find_threshold,
    series_for,
)


def test_find_threshold_bisects_a_step():
    t = find_threshold(lambda x: x > 0.3141, 0.01, 1.0, lifts_above=True, log=True, rtol=1e-6)
    assert t.value == pytest.approx(0.3141, rel=2e-6) and len(t.transitions) == 1
    t = find_threshold(lambda x: x < 0.6, 0.0, 0.99, lifts_above=False, rtol=1e-6)
    assert t.value == pytest.approx(0.6, rel=2e-6)
    assert find_threshold(lambda x: True, 0.0, 1.0, lifts_above=True).value is None


def test_find_threshold_survives_failing_points():
    def lifts(x):
        if 0.49 < x < 0.51:
            raise ArithmeticError("boom")
        return x > 0.5

    t = find_threshold(lifts, 0.0, 1.0, lifts_above=True, scan_points=11, rtol=1e-3)
    assert t.errors and t.bracket[0] <= 0.51 and t.bracket[1] >= 0.49


def test_whole_window_minimum_is_the_initial_truncation_value():
    m = acceleration_minima(preset("basketball").derive(damping=0.6))
    assert m.overall == pytest.approx(m.initial) and m.overall < -100
    assert -14 < m.moving_up < -9.81


def test_recurrence_fallback_matches_the_quadrature():
    case = preset("basketball").derive(radius=2e-3)  # ~290 Gauss points: recurrence
    fast = series_for(case)
    from twoball.modal.legendre import legendre_series

    slow = legendre_series(case.phi_a, case.damping, "lanczos", case.modes)
    t = np.linspace(0, 12, 50)
    assert np.allclose(fast.pole(t).u_tt, slow.pole(t).u_tt, rtol=1e-9, atol=1e-12)


def test_comparison_table_has_paper_ours_difference():
    row = Comparison("x", 2.0, 2.5, "m", "§1", "why")
    text = comparison_table([row])
    assert "| x | 2 m | 2.5 m | +0.5 m (+25.0 %) | [§1] why |" in text
