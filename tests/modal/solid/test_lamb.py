"""Lamb's frequency equation: the published roots, the residual, and a second formulation.

The second formulation is Sato & Usami's unscaled 2x2 matrix with cylindrical
Bessel functions J_{n+1/2} (and Lamb's tan(x)/x = 4/(4 - y^2) for n = 0), evaluated
with mpmath at 30 digits; its roots are found by mpmath's secant search started
from the published or computed root, and its sign changes on a grid ten times
finer than the solver's count the roots (completeness).
"""

from __future__ import annotations

import math

import mpmath
import numpy as np
import pytest
from scipy.special import jv

from twoball._common.errors import ParameterError
from twoball.modal.solid.lamb import (
    boundary_matrix,
    lamb_function,
    lamb_roots,
    scaled_bessel_pair,
    speed_ratio,
)

#: Reference roots eta = omega R / c_s, (nu, n, k) -> eta, as quoted to 4-5 digits in the
#: project's physics-source notes (an independent solution of Lamb's equation).
REFERENCE = {
    (0.25, 2, 1): 2.6399,
    (0.25, 2, 2): 4.8653,
    (0.25, 3, 1): 3.9163,
    (0.25, 0, 1): 4.4400,
    (1 / 3, 2, 1): 2.6501,
    (1 / 3, 3, 1): 3.9502,
    (1 / 3, 0, 1): 5.4874,
    (0.45, 2, 1): 2.6615,
    (0.45, 3, 1): 3.9882,
    (0.45, 0, 1): 10.005,
}

mpmath.mp.dps = 30


def sato_usami(n: int, eta, nu: float):
    """Unscaled determinant of Sato & Usami (1962, eq. 2.2) at 30 digits; Lamb's eq. for n = 0."""
    ratio = mpmath.sqrt(2 * (1 - mpmath.mpf(nu)) / (1 - 2 * mpmath.mpf(nu)))
    y = mpmath.mpf(eta)
    x = y / ratio
    if n == 0:
        return mpmath.sin(x) * (4 - y**2) - 4 * x * mpmath.cos(x)
    j = mpmath.besselj
    a = (mpmath.mpf(1) / 2 - n * (n - 1) / y**2) * j(n + 0.5, x) - 2 * x / y**2 * j(n + 1.5, x)
    b = -2 * n * (n + 1) * ((n - 1) / y**2 * j(n + 0.5, x) - x / y**2 * j(n + 1.5, x))
    c = (n - 1) / y**2 * j(n + 0.5, y) - j(n + 1.5, y) / y
    d = 2 / y * j(n + 1.5, y) + (2 * (n * n - 1) / y**2 - 1) * j(n + 0.5, y)
    return a * d - b * c


def sato_usami_float(n: int, eta: np.ndarray, nu: float) -> np.ndarray:
    """The same determinant in double precision (scipy's jv), for counting sign changes."""
    y = eta
    x = eta / math.sqrt(2 * (1 - nu) / (1 - 2 * nu))
    if n == 0:
        return np.sin(x) * (4 - y**2) - 4 * x * np.cos(x)
    a = (0.5 - n * (n - 1) / y**2) * jv(n + 0.5, x) - 2 * x / y**2 * jv(n + 1.5, x)
    b = -2 * n * (n + 1) * ((n - 1) / y**2 * jv(n + 0.5, x) - x / y**2 * jv(n + 1.5, x))
    c = (n - 1) / y**2 * jv(n + 0.5, y) - jv(n + 1.5, y) / y
    d = 2 / y * jv(n + 1.5, y) + (2 * (n * n - 1) / y**2 - 1) * jv(n + 0.5, y)
    return a * d - b * c


def independent_root(n: int, guess: float, nu: float) -> float:
    return float(mpmath.findroot(lambda e: sato_usami(n, e, nu), mpmath.mpf(guess), tol=1e-40))


@pytest.mark.parametrize(("nu", "n", "k"), sorted(REFERENCE))
def test_published_roots(nu, n, k):
    """The roots agree with the reference values to their 4-5 digits, and to 1e-6 with
    the independent 30-digit roots started from the reference value."""
    eta = lamb_roots(n, nu, k)[k - 1]
    published = REFERENCE[(nu, n, k)]
    assert abs(eta - published) <= 0.6 * 10.0 ** -(len(repr(published).split(".")[1]))
    assert abs(eta - independent_root(n, published, nu)) < 1e-6


def test_lamb_1882_value():
    """Lamb's own n = 2 value for nu = 1/3 (his incompressibility-free case): eta / pi = 0.842."""
    eta = lamb_roots(2, 1 / 3, 1)[0]
    assert abs(eta / math.pi - 0.842) / 0.842 < 3e-3


@pytest.mark.parametrize("nu", [0.25, 1 / 3])
def test_residual_n0_to_10_k1_to_5(nu):
    """|F_n| <= 1e-12 at every root n = 0..10, k = 1..5 (F_n of eq. L3 is in [-1, 1])."""
    for n in range(11):
        roots = lamb_roots(n, nu, 5)
        assert np.all(np.diff(roots) > 0)
        assert np.max(np.abs(lamb_function(n, roots, nu))) < 1e-12
        # and not zero everywhere: F_n is O(1) half-way between consecutive roots
        middle = 0.5 * (roots[1:] + roots[:-1])
        assert np.min(np.abs(lamb_function(n, middle, nu))) > 1e-3


@pytest.mark.parametrize(
    ("nu", "degrees", "count"),
    [(0.25, range(0, 11, 2), 5), (1 / 3, range(1, 11, 3), 5), (-0.5, [0, 1, 4], 3)],
)
def test_roots_against_second_formulation(nu, degrees, count):
    """Every root is a root of the 30-digit unscaled formulation to 1e-10."""
    for n in degrees:
        for eta in lamb_roots(n, nu, count):
            assert abs(eta - independent_root(n, eta, nu)) < 1e-10


@pytest.mark.parametrize(
    ("nu", "n", "k"), [(0.0, 4, 6), (0.1, 7, 3), (0.3, 12, 2), (0.4, 1, 5), (0.49, 5, 4)]
)
def test_unlisted_poisson_degree_order(nu, n, k):
    """Unlisted (nu, n, k): the k-th root equals the k-th sign change of the unscaled
    determinant on a grid 10x finer than the solver's, refined at 30 digits."""
    roots = lamb_roots(n, nu, k)
    grid = np.arange(0.05, roots[-1] + 1.0, 0.002)
    values = sato_usami_float(n, grid, nu)
    changes = np.flatnonzero(np.sign(values[:-1]) != np.sign(values[1:]))
    reference = [independent_root(n, 0.5 * (grid[i] + grid[i + 1]), nu) for i in changes]
    assert len(reference) >= k
    np.testing.assert_allclose(roots, reference[:k], rtol=0, atol=1e-10)


def test_n0_is_lamb_breathing_equation():
    """n = 0: the roots are those of tan(x)/x = 4/(4 - y^2) only (M22's roots are not modes)."""
    nu = 0.25
    roots = lamb_roots(0, nu, 4)
    x = roots / speed_ratio(nu)
    np.testing.assert_allclose(np.tan(x) / x, 4 / (4 - roots**2), rtol=1e-9)
    # the full determinant would also vanish where M22 = 0 (a void shear row)
    m22 = boundary_matrix(0, np.linspace(1, 20, 2000), nu)[:, 1, 1]
    assert np.any(np.sign(m22[1:]) != np.sign(m22[:-1]))


def test_scaled_bessel_pair_large_degree():
    """No underflow where j_n itself does (n = 300, z = 10): the pair is on the unit circle
    and its ratio is j_{n+1}/j_n ~ z / (2n + 3)."""
    a, b = scaled_bessel_pair(300, np.array([10.0, 400.0]))
    np.testing.assert_allclose(a * a + b * b, 1.0, rtol=1e-14)
    assert abs(b[0] / a[0] - 10.0 / 603.0) < 1e-3 * 10.0 / 603.0
    # below and above the switch z = n + 1 the pair agrees with scipy where both are finite
    a2, b2 = scaled_bessel_pair(5, np.array([5.99, 6.01]))
    from scipy.special import spherical_jn

    for z, ai, bi in zip((5.99, 6.01), a2, b2, strict=True):
        j5, j6 = spherical_jn(5, z), spherical_jn(6, z)
        np.testing.assert_allclose([ai, bi], np.array([j5, j6]) / math.hypot(j5, j6), rtol=1e-13)


def test_large_degree_roots():
    """n = 30 and n = 100: residual at rounding; the first root approaches the Rayleigh wave
    (eta ~ (n + 1/2) c_R / c_s, c_R / c_s = 0.9194 for nu = 1/4) from above."""
    for n in (30, 100):
        roots = lamb_roots(n, 0.25, 3)
        assert np.max(np.abs(lamb_function(n, roots, 0.25))) < 1e-12
        rayleigh = (n + 0.5) * 0.919402
        assert 0 < roots[0] / rayleigh - 1 < 0.1
    assert (
        lamb_roots(100, 0.25, 1)[0] / (100.5 * 0.919402) - 1
        < lamb_roots(30, 0.25, 1)[0] / (30.5 * 0.919402) - 1
    )


def test_invalid_input():
    with pytest.raises(ParameterError):
        speed_ratio(0.5)
    with pytest.raises(ParameterError):
        lamb_function(-1, 1.0, 0.25)
    with pytest.raises(ParameterError):
        lamb_roots(2, 0.25, 0)


@pytest.mark.slow
@pytest.mark.parametrize("nu", [-0.9, -0.3, 0.0, 0.2, 0.3, 0.4, 0.45, 0.49])
def test_completeness_many_degrees(nu):
    """n = 0..40, first 10 roots: same as the sign changes of the unscaled determinant on a
    grid of step 0.001 (double-root pairs closer than that would show as a missing root)."""
    for n in range(41):
        roots = lamb_roots(n, nu, 10)
        grid = np.arange(0.05, roots[-1] + 0.5, 0.001)
        values = sato_usami_float(n, grid, nu)
        finite = np.isfinite(values) & (values != 0)
        assert finite.all(), (nu, n)
        changes = np.flatnonzero(np.sign(values[:-1]) != np.sign(values[1:]))
        assert len(changes) >= 10
        np.testing.assert_allclose(roots, grid[changes[:10]], atol=0.0011)
