"""Initial condition, contact angle <-> impact speed, deformation work (eqs. (3.3)-(3.10))."""

import math

import numpy as np
import pytest
from scipy.integrate import quad
from twoball.modal.initial import (
    deformation_work,
    initial_displacement,
    initial_displacement_x,
    phi_a_from_v0,
    v0_dimensionless,
    v0_from_phi_a,
)

from twoball._common.errors import ParameterError


def test_initial_displacement_is_the_truncated_sphere():
    phi_a = 2.6
    phi = np.linspace(0, math.pi, 1001)
    f = initial_displacement(phi, phi_a)
    assert np.all(f[phi <= phi_a] == 0)
    # on the cap, 1 + F = cos(phi_a)/cos(phi): the points lie on the plane z = cos(phi_a)
    cap = phi > phi_a
    z = (1 + f[cap]) * np.cos(phi[cap])
    np.testing.assert_allclose(z, math.cos(phi_a), rtol=1e-14)
    assert f[-1] == pytest.approx(-1 - math.cos(phi_a))
    np.testing.assert_allclose(initial_displacement_x(np.cos(phi), phi_a), f, atol=1e-12)


def test_v0_formula_against_eq_3_7_as_printed():
    for phi_a in (1.7, 2.2, 2.6, 3.0):
        c = math.cos(phi_a)
        printed = 0.12 * 320 * math.sqrt((-1 + 2 * c**3 + 3 * c**2) / (6 * c))
        assert v0_from_phi_a(phi_a, 0.12, 320) == pytest.approx(printed, rel=1e-13)


def test_phi_a_v0_round_trip_to_1e_12():
    phis = np.concatenate([np.linspace(math.pi / 2 + 1e-6, math.pi - 1e-6, 400), [2.6]])
    for phi_a in phis:
        v0 = v0_from_phi_a(phi_a, 0.12, 320.0)
        assert abs(phi_a_from_v0(v0, 0.12, 320.0) - phi_a) < 1e-12
        assert abs(phi_a_from_v0(-v0, 0.12, 320.0) - phi_a) < 1e-12


def test_v0_round_trip_from_speed():
    for v0 in (1e-3, 0.29, 4.1, 8.7, 100.0):
        phi_a = phi_a_from_v0(v0, 0.12, 320.0)
        assert math.pi / 2 < phi_a < math.pi
        assert v0_from_phi_a(phi_a, 0.12, 320.0) == pytest.approx(v0, rel=1e-12)


def test_v0_is_monotone_decreasing_in_phi_a():
    v = [v0_dimensionless(p) for p in np.linspace(1.6, 3.1, 200)]
    assert np.all(np.diff(v) < 0)


@pytest.mark.parametrize("v0", [0.0, math.inf, math.nan])
def test_speed_without_solution(v0):
    with pytest.raises(ParameterError, match="v0"):
        phi_a_from_v0(v0, 0.12, 320.0)


@pytest.mark.parametrize("phi_a", [1.0, math.pi / 2, math.pi, 4.0])
def test_phi_a_out_of_range(phi_a):
    with pytest.raises(ParameterError, match=r"phi_a must be in \(pi/2, pi - 1e-6\]"):
        v0_dimensionless(phi_a)


@pytest.mark.parametrize("phi_a", [1.8, 2.6, 3.0])
def test_work_equals_strain_energy_of_F(phi_a):
    # -W/(T R^2) = (1/2) int |grad F|^2 dS = pi int_{phi_a}^{pi} F'(phi)^2 sin(phi) dphi
    c = math.cos(phi_a)

    def integrand(phi):
        return (c * math.sin(phi) / math.cos(phi) ** 2) ** 2 * math.sin(phi)

    strain, _ = quad(integrand, phi_a, math.pi, epsabs=1e-14, epsrel=1e-13)
    assert -deformation_work(phi_a) == pytest.approx(math.pi * strain, rel=1e-10)
    # eq. (3.6): the kinetic energy 2 pi rho R^2 v0^2 -> 2 pi v0^2 in units of T R^2
    assert 2 * math.pi * v0_dimensionless(phi_a) ** 2 == pytest.approx(-deformation_work(phi_a))
