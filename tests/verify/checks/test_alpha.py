"""The generalized-alpha checks of verify (verify/checks/alpha.py): the energy decay band."""

import math

import numpy as np
import pytest

from twoball.verify.checks.alpha import decay_band


def test_energy_decay_band_is_exact_for_one_mode():
    low, high = decay_band(0.13)
    assert low == pytest.approx(1 / 1.13) and high == pytest.approx(1 / 0.87)
    d, t = 0.13, np.linspace(0.0, 20.0, 20001)
    wd = math.sqrt(1 - d * d)
    q = np.exp(-d * t) * (np.cos(wd * t) + d / wd * np.sin(wd * t))
    qt = -np.exp(-d * t) * np.sin(wd * t) / wd
    factor = (qt**2 + q**2) * np.exp(2 * d * t)  # E(t) e^{2 D t} / E(0) with E(0) = 1/2
    assert factor.min() == pytest.approx(low, rel=1e-6)
    assert factor.max() == pytest.approx(high, rel=1e-6)
