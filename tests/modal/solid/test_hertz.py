"""Hertz's impact formulas: the coefficient 2.87, energy balance, and the force law's impulse."""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.integrate import solve_ivp

from twoball._common.errors import ParameterError
from twoball.modal.solid.hertz import (
    HERTZ_TIME_COEFFICIENT,
    effective_modulus,
    hertz_contact_time,
    hertz_force,
    hertz_max_compression,
    hertz_peak_force,
)

# a superball-like sphere: 25 mm radius, 1000 kg/m^3, E = 5 MPa, nu = 0.45
R, RHO, E, NU = 0.025, 1000.0, 5e6, 0.45
M = 4 / 3 * math.pi * R**3 * RHO
ESTAR = E / (1 - NU**2)


def test_coefficient_is_the_published_2_87():
    assert round(HERTZ_TIME_COEFFICIENT, 2) == 2.87
    assert effective_modulus(E, NU) == pytest.approx(ESTAR, rel=1e-15)


def test_against_integrated_hertz_oscillator():
    """m x'' = -F(x) integrated from x = 0, x' = v0 until x returns to 0: t_c, x_max, F_max."""
    v0 = 2.0

    def rhs(t, s):
        return [s[1], -hertz_force(max(s[0], 0.0), R, ESTAR) / M]

    def back(t, s):
        return s[0] if t > 0 else 1.0

    back.terminal, back.direction = True, -1
    sol = solve_ivp(rhs, (0, 1.0), [0.0, v0], events=back, rtol=1e-11, atol=1e-15, max_step=1e-6)
    tc = sol.t_events[0][0]
    assert hertz_contact_time(M, R, ESTAR, v0) == pytest.approx(tc, rel=1e-6)
    assert hertz_max_compression(M, R, ESTAR, v0) == pytest.approx(np.max(sol.y[0]), rel=1e-6)
    assert hertz_peak_force(M, R, ESTAR, v0) == pytest.approx(
        hertz_force(np.max(sol.y[0]), R, ESTAR), rel=1e-6
    )
    assert sol.y[1][-1] == pytest.approx(-v0, rel=1e-6)  # no loss


def test_scalings():
    """t_c ~ v0^(-1/5), F_max ~ v0^(6/5), delta_max ~ v0^(4/5)."""
    v = np.array([0.5, 1.0, 2.0, 4.0])
    tc = [hertz_contact_time(M, R, ESTAR, s) for s in v]
    fm = [hertz_peak_force(M, R, ESTAR, s) for s in v]
    np.testing.assert_allclose(np.diff(np.log(tc)) / np.diff(np.log(v)), -0.2, atol=1e-12)
    np.testing.assert_allclose(np.diff(np.log(fm)) / np.diff(np.log(v)), 1.2, atol=1e-12)


def test_invalid():
    with pytest.raises(ParameterError):
        hertz_contact_time(M, R, ESTAR, 0.0)
    with pytest.raises(ParameterError):
        hertz_force(-1e-3, R, ESTAR)
    with pytest.raises(ParameterError):
        effective_modulus(E, 0.5)
