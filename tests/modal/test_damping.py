"""Damping laws (modal/damping.py): the Rayleigh fit at two frequencies."""

from __future__ import annotations

import math

import numpy as np
import pytest
from twoball.modal.damping import Rayleigh

from twoball._common.errors import ParameterError

DAMPING = 0.13


def test_fit_matches_the_ratio_at_both_frequencies():
    fit = Rayleigh.fit(DAMPING, math.sqrt(2), math.sqrt(30 * 31))
    assert fit.ratios(np.array([math.sqrt(2), math.sqrt(930)])) == pytest.approx(
        [DAMPING, DAMPING], rel=1e-14
    )
    inside = fit.ratios(np.array([3.0, 10.0, 20.0]))
    assert np.all(inside < DAMPING)  # below D between the fitting frequencies
    assert fit.ratios(np.array([60.0]))[0] > DAMPING
    with pytest.raises(ParameterError, match="rayleigh_frequencies"):
        Rayleigh.fit(DAMPING, 5.0, 2.0)
