"""Initial condition, contact angle <-> impact speed, deformation work (eqs. (3.3)-(3.10))."""

import math

import mpmath
import numpy as np
import pytest
from scipy.integrate import quad
from scipy.optimize import brentq

from twoball._common.errors import ParameterError
from twoball.modal.initial import (
    _energy_shape,
    deformation_work,
    initial_displacement,
    initial_displacement_x,
    phi_a_from_v0,
    v0_dimensionless,
    v0_from_phi_a,
)

V0 = np.geomspace(1e-10, 1e4, 241)


def brentq_phi_a(v0: float) -> float:
    """phi_a of eq. (3.7) by scipy's Brent solver in s = pi - phi_a (the former method)."""
    target = math.log((v0 / (0.12 * 320.0)) ** 2)

    def residual(s: float) -> float:
        return math.log(_energy_shape(math.pi - s)) - target

    eps = np.finfo(float).eps
    s = brentq(residual, 1e-6, math.pi / 2 * (1 - 1e-15), xtol=1e-300, rtol=4 * eps, maxiter=500)
    return math.pi - s


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


def test_phi_a_from_v0_matches_brent_within_round_off():
    ours = np.array([phi_a_from_v0(v, 0.12, 320.0) for v in V0])
    brent = np.array([brentq_phi_a(v) for v in V0])
    # both find the sign change of the same floating-point residual: a few ulp apart
    assert (np.abs(ours - brent) / np.spacing(brent)).max() <= 4
    # and the speed comes back where it is well conditioned: away from phi_a -> pi,
    # where 1 + cos phi_a cancels, and from phi_a -> pi/2, where v0 ~ (-cos phi_a)^-1/2
    resolved = (ours < 3.0) & (V0 <= 100.0)
    back = np.array([v0_from_phi_a(p, 0.12, 320.0) for p in ours[resolved]])
    np.testing.assert_allclose(back, V0[resolved], rtol=1e-13)


def test_phi_a_from_v0_against_eq_3_7_in_high_precision():
    mpmath.mp.dps = 40
    for v0 in V0[165::8]:  # phi_a from 2.96 down to pi/2 + 3e-6
        log_t = 2 * mpmath.log(mpmath.mpf(v0) / (mpmath.mpf("0.12") * 320))

        def residual(y, log_t=log_t):  # log of (3.7) minus log (v0 / R c)^2, y = log(pi - phi_a)
            c = -mpmath.cos(mpmath.exp(y))
            return mpmath.log((1 + c) ** 2 * (2 * c - 1) / (6 * c)) - log_t

        bracket = (mpmath.log(1e-7), mpmath.log(mpmath.pi / 2) - mpmath.mpf(10) ** -30)
        exact = float(mpmath.pi - mpmath.exp(mpmath.findroot(residual, bracket, "illinois")))
        # (3.7) in double precision has round-off amplified by 1 / (1 + cos phi_a) <= 100 here
        assert abs(phi_a_from_v0(v0, 0.12, 320.0) - exact) <= 4 * np.spacing(exact)


@pytest.mark.parametrize("v0", [1e-12, 1e-30, 1e-300])
def test_phi_a_from_v0_refuses_speeds_it_cannot_resolve(v0):
    with pytest.raises(ParameterError, match=r"^v0 must be at least .* m/s"):
        phi_a_from_v0(v0, 0.12, 320.0)
