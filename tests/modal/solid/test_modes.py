"""Lamb's mode shapes: elasticity satisfied (Rayleigh quotient, free surface), orthogonality,
normalisation, projections and the surface/cap/centre-of-mass measures."""

from __future__ import annotations

import numpy as np
import pytest
from scipy.integrate import quad
from scipy.special import eval_legendre, lpmv

from twoball._common.errors import ParameterError
from twoball.modal.solid.lamb import speed_ratio
from twoball.modal.solid.modes import (
    SphereMode,
    modal_coefficients,
    spheroidal_modes,
    translation_mode,
)

NU = 0.3


@pytest.fixture(scope="module")
def modes() -> list[SphereMode]:
    return spheroidal_modes(NU, range(0, 6), 4)


def _derivative(f, x, h=1e-6):
    return (f(x + h) - f(x - h)) / (2 * h)


def strain_energy_ratio(mode: SphereMode, points: int = 120) -> float:
    """(int 2W dV) / (int |u|^2 dV) with mu = rho = R = 1: eta^2 for an eigenmode.

    Strains of u = U P e_r + V dP/dtheta e_theta in spherical coordinates, derivatives
    of U, V by central differences, d^2P/dtheta^2 from Legendre's equation.
    """
    lam = speed_ratio(mode.poisson) ** 2 - 2.0
    n = mode.degree
    rho, wr = np.polynomial.legendre.leggauss(points)
    rho, wr = 0.5 * (rho + 1), 0.5 * wr
    x, wx = np.polynomial.legendre.leggauss(n + 40)
    theta = np.arccos(x)
    r, t = np.meshgrid(rho, theta, indexing="ij")
    u, v = (c[:, None] for c in mode.radial(rho))
    du = _derivative(lambda s: mode.radial(s)[0], rho)[:, None]
    dv = _derivative(lambda s: mode.radial(s)[1], rho)[:, None]
    p = eval_legendre(n, np.cos(t))
    dp = lpmv(1, n, np.cos(t))  # dP/dtheta
    ddp = -n * (n + 1) * p - np.cos(t) / np.sin(t) * dp  # Legendre's equation
    e_rr = du * p
    e_tt = (u * p + v * ddp) / r
    e_pp = (u * p + v * np.cos(t) / np.sin(t) * dp) / r
    e_rt = 0.5 * (u / r + dv - v / r) * dp
    trace = e_rr + e_tt + e_pp
    w2 = 2 * (e_rr**2 + e_tt**2 + e_pp**2 + 2 * e_rt**2) + lam * trace**2
    weight = np.outer(wr * rho**2, wx)
    return float(np.sum(weight * w2) / np.sum(weight * (u**2 * p**2 + v**2 * dp**2)))


def test_rayleigh_quotient_is_eta_squared(modes):
    """Each shape is an elastic eigenfunction: its energy quotient is its eta^2 (to 1e-8)."""
    for mode in modes:
        assert strain_energy_ratio(mode) == pytest.approx(mode.eta**2, rel=1e-8, abs=1e-10)


def test_free_surface(modes):
    """sigma_rr and sigma_r-theta vanish at r = R (from U, V by finite differences)."""
    lam = speed_ratio(NU) ** 2 - 2.0
    for mode in modes:
        if mode.is_translation:
            continue
        n = mode.degree
        u, v = (c[0] for c in mode.radial(np.array([1.0])))
        du = _derivative(lambda s, m=mode: m.radial(s)[0], np.array([1.0]))[0]
        dv = _derivative(lambda s, m=mode: m.radial(s)[1], np.array([1.0]))[0]
        # sigma_rr / P = lam (U' + 2U/r - n(n+1)V/r) + 2 U', sigma_rt / P' = U/r + V' - V/r
        srr = lam * (du + 2 * u - n * (n + 1) * v) + 2 * du
        srt = u + dv - v if n > 0 else 0.0  # dP_0/dtheta = 0: no shear traction
        scale = mode.eta * (abs(u) + abs(v)) * (1 + lam)
        assert abs(srr) < 1e-6 * scale and abs(srt) < 1e-6 * scale


def test_orthonormal_in_mass(modes):
    """Gram matrix of the modes in (1/V) int u.v dV is the identity (to 1e-10)."""

    rho, wr = np.polynomial.legendre.leggauss(140)
    rho, wr = 0.5 * (rho + 1), 0.5 * wr
    x, wx = np.polynomial.legendre.leggauss(60)
    r, t = np.meshgrid(rho, np.arccos(x), indexing="ij")
    weight = 1.5 * np.outer(wr * rho**2, wx).ravel()
    fields = np.array([np.concatenate([c.ravel() for c in m.displacement(r, t)]) for m in modes])
    gram = (fields * np.concatenate([weight, weight])) @ fields.T
    np.testing.assert_allclose(gram, np.eye(len(modes)), atol=1e-10)
    # the same through the projection routine, for two of them
    c = modal_coefficients(modes, modes[5].displacement, radial_points=140)
    np.testing.assert_allclose(c, np.eye(len(modes))[5], atol=1e-10)


def test_translation_and_centre_of_mass(modes):
    """The translation moves the centre of mass by 1; no elastic mode moves it."""
    t = translation_mode(NU)
    assert t.eta == 0 and t.degree == 1 and t.radial_order == 0
    assert t.centre_of_mass() == pytest.approx(1.0, abs=1e-14)
    assert t.cap_average(0.7) == pytest.approx(1.0, abs=1e-14)
    for mode in modes:
        if not mode.is_translation:
            assert abs(mode.centre_of_mass()) < 1e-12
    # a uniform upward displacement is the translation alone
    c = modal_coefficients(modes, lambda r, th: (np.cos(th), -np.sin(th)))
    expected = np.array([1.0 if m.is_translation else 0.0 for m in modes])
    np.testing.assert_allclose(c, expected, atol=1e-12)


def test_projection_recovers_a_combination(modes):
    rng = np.random.default_rng(3)
    true = rng.normal(size=len(modes))

    def field(r, t):
        parts = [m.displacement(r, t) for m in modes]
        return sum(c * p[0] for c, p in zip(true, parts, strict=True)), sum(
            c * p[1] for c, p in zip(true, parts, strict=True)
        )

    np.testing.assert_allclose(
        modal_coefficients(modes, field, radial_points=140), true, atol=1e-10
    )


def test_surface_vertical_and_cap_average(modes):
    """u_z from the Cartesian components of the 3-D field; the cap mean by adaptive quadrature."""
    phi = np.linspace(0, np.pi, 7)
    for mode in modes:
        ur, ut, uz = mode.surface(phi)
        # e_r = (sin, cos), e_theta = (cos, -sin) in the (x, z) meridian plane
        np.testing.assert_allclose(uz, ur * np.cos(phi) - ut * np.sin(phi), atol=1e-15)
        assert mode.cap_average(0.0) == pytest.approx(uz[0], abs=1e-14)
        for theta0 in (0.2, 1.0, np.pi):
            num, _ = quad(
                lambda p, m=mode: m.surface(np.array([p]))[2][0] * np.sin(p),
                0,
                theta0,
                epsabs=1e-13,
                epsrel=1e-12,
            )
            assert mode.cap_average(theta0) == pytest.approx(num / (1 - np.cos(theta0)), abs=1e-11)
    # the whole sphere's mean of u_z is zero for every degree but 1 (int x P_n = 0)
    for mode in modes:
        if mode.degree != 1:
            assert abs(mode.cap_average(np.pi)) < 1e-13


def test_normalisation_and_sign(modes):
    for mode in modes:
        assert mode.mean_square() == pytest.approx(1.0, abs=1e-13)
        assert mode.mean_square(400) == pytest.approx(1.0, abs=1e-12)
        u1, v1 = mode.radial(np.array([1.0]))
        assert u1[0] > 0 or (u1[0] == 0 and v1[0] > 0)
    with pytest.raises(ParameterError):
        modes[0].cap_average(-0.1)
