"""The closed-form modes: mass normalisation, vertical rows, cap averages, centre of mass."""

from __future__ import annotations

import numpy as np
import pytest
import scipy.integrate
from numpy.polynomial import legendre

from twoball.modal.shell.modes import legendre_table, shell_modes
from twoball.modal.shell.parameters import ShellParameters

SHELLS = [
    ShellParameters(0.3),
    ShellParameters(0.5, bending=(0.0955**2) / 12, prestress=0.054, gas=1.01),
    ShellParameters(0.05, bending=1e-4, prestress=0.005),
]


def _sphere_quadrature(points: int = 200) -> tuple[np.ndarray, np.ndarray]:
    """phi and the weights of ``int f dA / (4 pi R^2)`` (Gauss-Legendre in x = cos phi)."""
    nodes, weights = np.polynomial.legendre.leggauss(points)
    return np.arccos(nodes), 0.5 * weights


def test_legendre_table_against_numpy():
    x = np.linspace(-1, 1, 11)
    values, slopes = legendre_table(12, x)
    for n in range(13):
        basis = legendre.Legendre.basis(n)
        assert np.allclose(values[n], basis(x), atol=1e-14)
        assert np.allclose(slopes[n], basis.deriv()(x), atol=1e-12 * max(1, n * n))


@pytest.mark.parametrize("shell", SHELLS)
def test_modes_are_orthonormal_in_mass_with_modal_mass_m(shell):
    """``int (w_j w_k + v_j v_k) dA / (4 pi R^2) = delta_jk``, by quadrature of sampled fields."""
    modes = shell_modes(shell, 30)
    phi, weights = _sphere_quadrature()
    w, v = modes.radial(phi), modes.meridional(phi)
    gram = (w * weights) @ w.T + (v * weights) @ v.T
    assert np.allclose(gram, np.eye(modes.count), atol=1e-12)


@pytest.mark.parametrize("shell", SHELLS)
def test_modes_are_orthogonal_in_stiffness_with_omega_squared(shell):
    """The modal stiffnesses are Omega^2: K's energy of the sampled fields."""
    nu, bh, p = shell.poisson, shell.bending, shell.prestress
    modes = shell_modes(shell, 12)
    nodes, weights = np.polynomial.legendre.leggauss(120)
    phi = 0.5 * np.pi * (nodes + 1)
    weights = 0.25 * np.pi * weights * np.sin(phi)  # int dA / (4 pi R^2)
    x, s = np.cos(phi), np.sin(phi)
    values = np.array([legendre.Legendre.basis(n)(x) for n in modes.degree])
    first = np.array([legendre.Legendre.basis(n).deriv(1)(x) for n in modes.degree])
    second = np.array([legendre.Legendre.basis(n).deriv(2)(x) for n in modes.degree])
    dphi, dphi2 = -s * first, s**2 * second - x * first
    big_w, big_v = modes.radial_amplitude[:, None], modes.meridional_amplitude[:, None]
    w, dw, ddw = big_w * values, big_w * dphi, big_w * dphi2
    v, dv = big_v * dphi, big_v * dphi2
    ephi, etheta = dv + w, v * x / s + w
    kphi, ktheta = dv - ddw, (v - dw) * x / s

    def pair(a, b):
        return (a * weights) @ b.T

    stiffness = (
        pair(ephi, ephi)
        + pair(etheta, etheta)
        + nu * (pair(ephi, etheta) + pair(etheta, ephi))
        + bh
        * (pair(kphi, kphi) + pair(ktheta, ktheta) + nu * (pair(kphi, ktheta) + pair(ktheta, kphi)))
        + p * (pair(dw, dw) - 2 * pair(w, w))
    )
    mean = w @ weights  # the gas acts on int w dA: (g / 4 pi)(4 pi <w>)^2 / (4 pi) = g <w>^2
    stiffness += shell.gas * np.outer(mean, mean)
    scale = np.max(modes.omega**2)
    assert np.allclose(stiffness, np.diag(modes.omega**2), atol=1e-11 * scale)


def test_ordering_and_translation():
    modes = shell_modes(SHELLS[1], 5)
    assert modes.count == 11
    assert modes.degree.tolist() == [0, 1, 1, 2, 2, 3, 3, 4, 4, 5, 5]
    assert modes.branch.tolist() == [1, 1, 2, 1, 2, 1, 2, 1, 2, 1, 2]
    assert modes.translation == 1
    assert modes.omega[1] == 0.0
    assert np.all(np.diff(modes.omega[3::2]) > 0) and np.all(modes.omega[4::2] > modes.omega[3::2])


@pytest.mark.parametrize("shell", SHELLS)
def test_vertical_rows(shell):
    """u_z = w cos(phi) - v sin(phi); the translation's row is 1 everywhere (to rounding)."""
    modes = shell_modes(shell, 60)
    phi = np.linspace(0.0, np.pi, 301)
    rows = modes.vertical(phi)
    expected = modes.radial(phi) * np.cos(phi) - modes.meridional(phi) * np.sin(phi)
    assert np.allclose(rows, expected, atol=1e-11)
    assert np.max(np.abs(rows[modes.translation] - 1.0)) < 4e-16
    assert np.allclose(rows[:, 0], modes.radial_amplitude, rtol=1e-15, atol=0)  # north pole
    scalar = modes.vertical(0.7)
    assert scalar.shape == (modes.count,) and np.allclose(scalar, modes.vertical([0.7])[:, 0])


def _cap_closed_form(modes, theta: float) -> np.ndarray:
    """``[(W + 2V) int_c^1 x P_n dx - V (1 - c^2) P_n(c)] / (1 - c)``, c = cos theta.

    From ``int_c^1 (1 - x^2) P_n' dx = -(1 - c^2) P_n(c) + 2 int_c^1 x P_n dx``,
    ``(2n + 1) x P_n = (n + 1) P_{n+1} + n P_{n-1}`` and
    ``int_c^1 P_k dx = (P_{k-1}(c) - P_{k+1}(c)) / (2k + 1)``.
    """
    c = np.cos(theta)
    top = modes.max_degree + 2
    values, _ = legendre_table(top, np.array(c))
    tail = np.empty(top + 1)
    tail[0] = 1.0 - c
    tail[1:-1] = (values[:-2] - values[2:]) / (2 * np.arange(1, top) + 1)
    n = modes.degree
    first = np.where(n == 0, 0.5 * (1 - c * c), 0.0)
    mixed = ((n + 1) * tail[np.minimum(n + 1, top)] + n * tail[np.maximum(n - 1, 0)]) / (2 * n + 1)
    first = np.where(n == 0, first, mixed)
    big_w, big_v = modes.radial_amplitude, modes.meridional_amplitude
    return ((big_w + 2 * big_v) * first - big_v * (1 - c * c) * values[n]) / (1 - c)


@pytest.mark.parametrize("theta", [1e-3, 0.05, 0.3, 1.2, 2.0, 3.0])
def test_cap_average_against_the_legendre_closed_form(theta):
    modes = shell_modes(SHELLS[1], 80)
    expected = _cap_closed_form(modes, theta)
    got = modes.cap_average(theta)
    atol = 1e-12 / min(1.0, 1 - np.cos(theta)) * 1e-3 if theta < 0.01 else 1e-12
    assert np.allclose(got, expected, rtol=0, atol=max(atol, 1e-12))


def test_cap_average_against_adaptive_quadrature_and_its_limits():
    modes = shell_modes(SHELLS[2], 20)
    theta = 0.7
    for k in (0, 1, 2, 7, 20, 40):

        def integrand(phi, k=k):
            return modes.vertical(np.array([phi]))[k, 0] * np.sin(phi)

        value, _ = scipy.integrate.quad(integrand, 0.0, theta, epsabs=1e-14, epsrel=1e-13)
        assert modes.cap_average(theta)[k] == pytest.approx(value / (1 - np.cos(theta)), abs=1e-12)
    assert np.array_equal(modes.cap_average(0.0), modes.radial_amplitude)  # the pole's value
    assert np.allclose(modes.cap_average(np.pi), modes.centre_of_mass(), atol=1e-14)
    grid = modes.cap_average(np.array([0.1, 0.2]))
    assert grid.shape == (modes.count, 2)
    with pytest.raises(ValueError):
        modes.cap_average(4.0)


@pytest.mark.parametrize("shell", SHELLS)
def test_only_the_translation_moves_the_centre_of_mass(shell):
    modes = shell_modes(shell, 40)
    centre = modes.centre_of_mass()
    assert centre[modes.translation] == 1.0
    others = np.delete(centre, modes.translation)
    assert np.max(np.abs(others)) < 1e-15
    phi, weights = _sphere_quadrature()
    assert np.allclose(modes.vertical(phi) @ weights, centre, atol=1e-13)  # (1/4 pi) int u_z dA


def test_four_hundred_degrees_are_cheap_and_finite():
    modes = shell_modes(SHELLS[1], 400)
    rows = modes.vertical(np.linspace(0, np.pi, 2001))
    assert rows.shape == (801, 2001) and np.all(np.isfinite(rows))
    assert np.all(np.isfinite(modes.cap_average(np.linspace(0, np.pi, 7))))
