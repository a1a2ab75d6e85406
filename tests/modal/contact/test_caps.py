"""Cap averages of the Legendre modes (modal/contact/caps.py), eq. (C3) of docs/contact.rst."""

from __future__ import annotations

import numpy as np
import pytest

from twoball.modal.contact.caps import (
    legendre_cap_averages,
    legendre_cap_averages_closed,
)


@pytest.mark.parametrize("theta", [0.3, 0.1, 1e-2])
def test_cap_averages_match_closed_form(theta):
    gauss = legendre_cap_averages(theta, 40)
    closed = legendre_cap_averages_closed(theta, 40)
    # the closed form loses ~eps/theta^2 to cancellation
    assert np.max(np.abs(gauss - closed)) < 50 * np.finfo(float).eps / theta**2
    assert gauss[0] == pytest.approx(1.0, abs=1e-15)


def test_cap_average_tends_to_pole_value():
    theta = 1e-4
    b = legendre_cap_averages(theta, 30)
    n = np.arange(31)
    # <P_n>_cap = 1 - n(n+1) theta^2 / 8 + O(theta^4)
    assert np.max(np.abs(b - (1 - n * (n + 1) * theta**2 / 8))) < 1e-12
