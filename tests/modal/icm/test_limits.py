"""Touching limits of the independent collision model (modal/icm/limits.py), eqs. (2.6)-(2.7)."""

from __future__ import annotations

import pytest

from twoball.modal.icm import (
    light_touching_limit,
    touching_limit,
    touching_ratios,
)


def test_touching_limit_hand_values():
    # mu = 0.25, e2 = 0.5, e12 = 0.6:
    # k1 = (0.25 - 0.5 - 0.9) / 1.25 = -0.92, k2 = (0.25 - 0.5 + 0.225) / 1.25 = -0.02.
    k1, k2 = touching_limit(0.25, 0.5, 0.6)
    assert k1 == pytest.approx(-0.92, rel=1e-14)
    assert k2 == pytest.approx(-0.02, rel=1e-12)
    assert touching_ratios(0.25, 0.5, 0.6) == pytest.approx((0.92, 0.02), rel=1e-12)
    # Table 1 row 1 by hand: (0.062 - 0.83 - 0.46 * 1.83) / 1.062 = -1.6098 / 1.062.
    k1, _ = touching_limit(0.062, 0.83, 0.46)
    assert k1 == pytest.approx(-1.6098 / 1.062, rel=1e-14)


def test_light_touching_limit_hand_values():
    assert light_touching_limit(0.5, 0.6) == pytest.approx((-1.4, -0.5), rel=1e-14)
    assert light_touching_limit(0.0, 0.0) == (0.0, -0.0)
