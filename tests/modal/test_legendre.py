"""Legendre coefficients and the series against independent values (eqs. (3.11)-(3.16))."""

import math

import mpmath
import numpy as np
import pytest
from scipy.linalg import eigvalsh_tridiagonal
from scipy.special import eval_legendre

from twoball.modal.filters import SpectralFilter
from twoball.modal.initial import (
    deformation_work,
    initial_displacement,
)
from twoball.modal.legendre import (
    _DENSE_JACOBI_MAX,
    _gauss_legendre,
    displacement,
    legendre_coefficients,
    legendre_coefficients_recurrence,
    legendre_series,
    mean_displacement,
)


@pytest.mark.parametrize("phi_a", [1.6, 2.0, 2.6, 3.0])
def test_coefficients_against_high_precision_quadrature(phi_a):
    a = legendre_coefficients(phi_a, 60)
    mpmath.mp.dps = 30
    xa = mpmath.cos(phi_a)
    for n in (0, 1, 2, 7, 30, 60):
        exact = (
            (2 * n + 1)
            / mpmath.mpf(2)
            * mpmath.quad(lambda x, n=n: (xa / x - 1) * mpmath.legendre(n, x), [-1, xa])
        )
        # machine precision of the integral, times the (2n + 1)/2 prefactor of eq. (3.12)
        assert abs(a[n] - float(exact)) < 2e-15 * (2 * n + 1)


@pytest.mark.parametrize("phi_a", [1.6, 2.0, 2.6, 2.9])
def test_a0_by_quadrature_equals_closed_form_3_13(phi_a):
    assert abs(legendre_coefficients(phi_a, 5)[0] - mean_displacement(phi_a)) < 1e-13


def test_coefficients_against_recurrence():
    a = legendre_coefficients(2.6, 400)
    b = legendre_coefficients_recurrence(2.6, 400)
    np.testing.assert_allclose(a, b, rtol=0, atol=1e-13)


def test_partial_sums_reproduce_F_away_from_the_kink():
    phi_a = 2.6
    phi = np.concatenate([np.linspace(0.0, phi_a - 0.3, 40), np.linspace(phi_a + 0.2, math.pi, 20)])
    exact = initial_displacement(phi, phi_a)
    errors = []
    for modes in (30, 60, 120, 240, 480):
        series = legendre_series(phi_a, 0.0, SpectralFilter("none", modes))
        errors.append(np.abs(displacement(series, 0.0, phi) - exact).max())
    assert all(e2 < e1 for e1, e2 in zip(errors, errors[1:], strict=False))
    assert errors[-1] < 0.1 * errors[0]
    assert errors[-1] < 1e-4


def test_series_matches_eq_3_14_written_out():
    phi_a, damping, modes = 2.6, 0.13, 12
    series = legendre_series(phi_a, damping, SpectralFilter("none", modes))
    a = legendre_coefficients(phi_a, modes)
    t = np.array([0.0, 0.7, 3.1])
    phi = np.array([0.0, 1.0, 2.9])
    n = np.arange(modes + 1)
    w = np.sqrt(n * (n + 1.0))
    wd = w * math.sqrt(1 - damping**2)
    b = a * damping / math.sqrt(1 - damping**2)  # eq. (3.15)
    expected = np.zeros((t.size, phi.size))
    for k in range(modes + 1):
        time_part = (a[k] * np.cos(wd[k] * t) + b[k] * np.sin(wd[k] * t)) * np.exp(
            -damping * w[k] * t
        )
        expected += np.outer(time_part, eval_legendre(k, np.cos(phi)))
    np.testing.assert_allclose(displacement(series, t, phi), expected, atol=1e-14)
    # pole state vs the field and finite differences of the closed form
    state = series.pole(t)
    np.testing.assert_allclose(state.u, expected[:, 0], atol=1e-14)
    h = 1e-5
    fd_v = (series.pole(t + h).u - series.pole(t - h).u) / (2 * h)
    fd_a = (series.pole(t + h).u_t - series.pole(t - h).u_t) / (2 * h)
    np.testing.assert_allclose(state.u_t, fd_v, atol=1e-8)
    np.testing.assert_allclose(state.u_tt, fd_a, atol=1e-8)
    assert abs(state.u_t[0]) < 1e-16  # released from rest


def test_field_satisfies_the_wave_equation_mode_by_mode():
    # u_tt + 2 D omega u_t + omega^2 u = 0 for each modal coordinate
    series = legendre_series(2.6, 0.2, SpectralFilter("lanczos", 20))
    t = np.linspace(0, 5, 7)
    q = series.modal_coordinates(t, 0)
    qt = series.modal_coordinates(t, 1)
    qtt = series.modal_coordinates(t, 2)
    w = series.omega
    np.testing.assert_allclose(qtt + 2 * 0.2 * w * qt + w**2 * q, 0, atol=1e-12)


def test_undamped_series_conserves_modal_energy():
    series = legendre_series(2.6, 0.0, SpectralFilter("lanczos", 30))
    energy = series.energy(np.linspace(0, 4 * math.pi, 50))
    np.testing.assert_allclose(energy, energy[0], rtol=1e-12)
    damped = legendre_series(2.6, 0.13, SpectralFilter("lanczos", 30)).energy([0.0, 1.0, 2.0])
    assert damped[0] == pytest.approx(energy[0]) and damped[2] < damped[1] < damped[0]


def test_modal_energy_tends_to_the_work_of_eq_3_5():
    target = -deformation_work(2.6)
    gaps = []
    for modes in (100, 400, 1600):
        e0 = legendre_series(2.6, 0.0, SpectralFilter("none", modes)).energy(0.0)
        gaps.append(target - float(e0))
    assert all(g > 0 for g in gaps)  # truncation only removes energy
    assert gaps[1] < 0.6 * gaps[0] and gaps[2] < 0.6 * gaps[1]
    assert gaps[-1] / target < 0.01


@pytest.mark.parametrize("points", [2, 9, 46, 101, _DENSE_JACOBI_MAX, _DENSE_JACOBI_MAX + 1])
def test_gauss_rule_dense_and_tridiagonal_eigensolvers_agree(points):
    x_dense, w_dense = _gauss_legendre(points, "dense")
    x_tri, w_tri = _gauss_legendre(points, "tridiagonal")
    np.testing.assert_allclose(x_dense, x_tri, rtol=0, atol=4e-16)
    np.testing.assert_allclose(w_dense, w_tri, rtol=4e-15, atol=0)
    # the nodes against numpy's independent rule (companion matrix + one Newton step);
    # its weights are less accurate near the ends (1e-11 relative), so check ours by
    # exactness instead: sum w P_k(x) = int P_k = 2 delta_k0 for every k < 2 m
    np.testing.assert_allclose(x_dense, np.polynomial.legendre.leggauss(points)[0], atol=1e-15)
    moments = np.polynomial.legendre.legvander(x_dense, 2 * points - 1).T @ w_dense
    np.testing.assert_allclose(moments, np.eye(2 * points)[0] * 2.0, rtol=0, atol=2e-14)


def test_gauss_rule_auto_switches_at_the_documented_size():
    for points in (_DENSE_JACOBI_MAX, _DENSE_JACOBI_MAX + 1):
        solver = "dense" if points <= _DENSE_JACOBI_MAX else "tridiagonal"
        (x_auto, w_auto), (x, w) = _gauss_legendre(points), _gauss_legendre(points, solver)
        assert np.array_equal(x_auto, x) and np.array_equal(w_auto, w)
    with pytest.raises(ValueError, match="eigensolver"):
        _gauss_legendre(10, "qr")


def test_gauss_rule_nodes_are_the_jacobi_eigenvalues():
    # Golub-Welsch: the nodes are the eigenvalues of the Jacobi matrix of P_n (a third check)
    k = np.arange(1, 60)
    x = eigvalsh_tridiagonal(np.zeros(60), k / np.sqrt(4.0 * k * k - 1.0))
    np.testing.assert_allclose(_gauss_legendre(60, "dense")[0], x, rtol=0, atol=2e-15)
