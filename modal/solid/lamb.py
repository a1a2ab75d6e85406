"""Lamb's frequency equation for the spheroidal modes of a free elastic sphere, and its roots.

The displacement of a spheroidal mode of degree n (axisymmetric, m = 0) is derived
from two potentials (Lamb 1882, Proc. Lond. Math. Soc. 13:189; the same
construction underlies Sato & Usami 1962, Geophys. Mag. 31:15, and the
characteristic function of Takeuchi & Saito 1972, Methods Comput. Phys. 11):

    u = grad(phi) + curl curl(r psi e_r),
    phi = A j_n(h r) P_n(cos theta),   psi = B j_n(k r) P_n(cos theta),

h = omega / c_p, k = omega / c_s, with j_n the spherical Bessel function.  On the
free surface r = R the tractions sigma_rr and sigma_r-theta vanish.  With the
dimensionless frequencies x = h R, y = k R = eta (eta = omega R / c_s is the
quantity reported everywhere) and the recurrence j_n'(z) = (n/z) j_n - j_{n+1},
the tractions times R^2 / mu are ``M(eta) @ (A, B)`` with (derived here from the
potentials; the same matrix up to column factors as Sato & Usami 1962, eq. 2.2)

    M11 = [2n(n-1) - y^2] j_n(x) + 4x j_{n+1}(x)
    M12 = 2n(n+1) [(n-1) j_n(y) - y j_{n+1}(y)]
    M21 = 2 [(n-1) j_n(x) - x j_{n+1}(x)]
    M22 = [2(n^2-1) - y^2] j_n(y) + 2y j_{n+1}(y)          (eq. L1)

and the frequency equation is det M = 0.  For n = 0 the shear potential carries
no displacement (dP_0/d theta = 0, and its radial part is n(n+1) = 0) and the
second row is void, so the equation is M11 = 0 alone, which is Lamb's
tan(x)/x = 4 / (4 - y^2) (eq. L2); the determinant would add the spurious
roots of M22.

Conditioning.  j_n(x) spans hundreds of decades for large n (j_n(x) ~ x^n /
(2n+1)!! when x << n) and has zeros when x > n.  Each column is therefore divided
by the envelope ``s_n(z) = sqrt(j_n(z)^2 + j_{n+1}(z)^2)``, which is smooth and
never zero (j_n and j_{n+1} have no common zero: the three-term recurrence would
make every j_m vanish there).  The scaled Bessel pair (j_n, j_{n+1}) / s_n lies on
the unit circle, so the scaled matrix has entries of the size of their
polynomial factors and no poles; each row is then divided by its Euclidean norm.
The *Lamb function*

    F_n(eta) = det(M_scaled) / (|row 1| |row 2|)                (eq. L3)

is the signed sine of the angle between the two (scaled) rows: it lies in
[-1, 1], is smooth in eta, and vanishes exactly at Lamb's roots.  For n = 0 it
is M11 divided by the norm of its two terms.  |F_n| is the relative residual
used by the tests (1e-12 at the roots).  Below the first zero of j_n (z < n + 1)
the ratio j_{n+1}/j_n comes from a backward recurrence (the continued fraction
of Gauss), so nothing underflows even for n in the hundreds.

Root finding: F_n is sampled on a uniform grid in eta (step ``step``, by default
0.02, well below the least spacing of consecutive roots seen for n <= 40,
k <= 10); each sign change is refined with Brent's method to ``xtol``.  F_n has
no poles, so every sign change is a root.  A double root (a touch without sign
change) is looked for at every local minimum of |F_n| on the grid: if a bounded
minimisation of |F_n| reaches below ``1e-10`` the pair of roots is reported.

Torsional modes (u = curl(r chi e_r), purely azimuthal displacement u_phi for
m = 0) do not enter: they have no radial or meridional component, so they are a
separate family with their own equation; everything here is spheroidal.

The rigid translation (n = 1, omega = 0) is not searched for: at eta = 0 every
entry of M vanishes, and the scan starts at ``eta_start`` > 0.  It is added by
:mod:`twoball.modal.solid.modes` as the mode of radial order 0.
"""

from __future__ import annotations

import math

import numpy as np
from scipy.optimize import brentq, minimize_scalar
from scipy.special import spherical_jn

from twoball._common.errors import NumericalError, ParameterError

__all__ = [
    "boundary_matrix",
    "lamb_function",
    "lamb_roots",
    "scaled_bessel_pair",
    "speed_ratio",
]


def speed_ratio(poisson: float) -> float:
    """c_p / c_s of an isotropic solid, sqrt(2(1 - nu) / (1 - 2 nu)) (dimensionless).

    Parameters
    ----------
    poisson : float
        Poisson's ratio nu, in (-1, 1/2).
    """
    nu = float(poisson)
    if not -1.0 < nu < 0.5:
        raise ParameterError("poisson", "in (-1, 0.5)", poisson)
    return math.sqrt(2.0 * (1.0 - nu) / (1.0 - 2.0 * nu))


def _ratio_backward(n: int, z: np.ndarray, depth: int) -> np.ndarray:
    """j_{n+1}(z) / j_n(z) by backward recurrence r_{m-1} = z / (2m + 1 - z r_m)."""
    r = np.zeros_like(z)
    for m in range(n + depth, n, -1):
        r = z / (2 * m + 1 - z * r)
    return r


def scaled_bessel_pair(n: int, z: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """(j_n(z), j_{n+1}(z)) / s_n(z) with s_n = sqrt(j_n^2 + j_{n+1}^2) (dimensionless).

    Below z = n + 1 (under the first zero of j_n, where j_n > 0) the pair comes
    from the ratio j_{n+1}/j_n by backward recurrence, so it never underflows;
    above, from scipy's spherical_jn (no underflow there: |j_n| ~ 1/z).

    Parameters
    ----------
    n : int
        Degree, n >= 0.
    z : array_like
        Positive arguments.
    """
    z = np.atleast_1d(np.asarray(z, dtype=float))
    a = np.empty_like(z)
    b = np.empty_like(z)
    low = z < n + 1.0
    if low.any():
        zl = z[low]
        depth = int(40 + 2 * np.max(zl))
        t = _ratio_backward(n, zl, depth)
        scale = 1.0 / np.sqrt(1.0 + t * t)
        a[low], b[low] = scale, t * scale
    high = ~low
    if high.any():
        zh = z[high]
        jn, jn1 = spherical_jn(n, zh), spherical_jn(n + 1, zh)
        s = np.hypot(jn, jn1)
        a[high], b[high] = jn / s, jn1 / s
    return a, b


def boundary_matrix(n: int, eta: np.ndarray, poisson: float) -> np.ndarray:
    """The column-scaled traction matrix of eq. (L1), shape ``eta.shape + (2, 2)``.

    Column 1 (the dilatational potential, amplitude A) is divided by s_n(x) and
    column 2 (the shear potential, amplitude B) by s_n(y), with x = eta c_s/c_p
    and y = eta; rows are sigma_rr R^2/mu and sigma_r-theta R^2/mu.

    Parameters
    ----------
    n : int
        Degree, n >= 0.
    eta : array_like
        Dimensionless frequencies omega R / c_s (> 0).
    poisson : float
        Poisson's ratio.
    """
    eta = np.atleast_1d(np.asarray(eta, dtype=float))
    y = eta
    x = eta / speed_ratio(poisson)
    jx, jx1 = scaled_bessel_pair(n, x)
    jy, jy1 = scaled_bessel_pair(n, y)
    m = np.empty(eta.shape + (2, 2))
    m[..., 0, 0] = (2 * n * (n - 1) - y * y) * jx + 4 * x * jx1
    m[..., 0, 1] = 2 * n * (n + 1) * ((n - 1) * jy - y * jy1)
    m[..., 1, 0] = 2 * ((n - 1) * jx - x * jx1)
    m[..., 1, 1] = (2 * (n * n - 1) - y * y) * jy + 2 * y * jy1
    return m


def lamb_function(n: int, eta: np.ndarray, poisson: float) -> np.ndarray:
    """Lamb's frequency function F_n(eta) of eq. (L3), in [-1, 1] (dimensionless).

    Zero exactly at the spheroidal eigenfrequencies eta = omega R / c_s of degree
    n.  For n = 0, the breathing equation M11 = 0 (eq. L2) normalised by the norm
    of its two terms.

    Parameters
    ----------
    n : int
        Degree, n >= 0.
    eta : array_like
        Dimensionless frequencies omega R / c_s (> 0).
    poisson : float
        Poisson's ratio.
    """
    if n < 0 or int(n) != n:
        raise ParameterError("degree", "an integer >= 0", n)
    eta = np.atleast_1d(np.asarray(eta, dtype=float))
    if n == 0:
        y = eta
        x = eta / speed_ratio(poisson)
        jx, jx1 = scaled_bessel_pair(0, x)
        t1, t2 = -y * y * jx, 4 * x * jx1
        return (t1 + t2) / np.hypot(t1, t2)
    m = boundary_matrix(n, eta, poisson)
    det = m[..., 0, 0] * m[..., 1, 1] - m[..., 0, 1] * m[..., 1, 0]
    r1 = np.hypot(m[..., 0, 0], m[..., 0, 1])
    r2 = np.hypot(m[..., 1, 0], m[..., 1, 1])
    return det / (r1 * r2)


def _scalar(n: int, poisson: float):
    return lambda e: float(lamb_function(n, np.array([e]), poisson)[0])


def lamb_roots(
    n: int,
    poisson: float,
    count: int,
    *,
    step: float = 0.02,
    xtol: float = 1e-14,
    eta_start: float = 1e-3,
    eta_max: float | None = None,
) -> np.ndarray:
    """The first ``count`` roots eta = omega R / c_s of Lamb's equation F_n = 0.

    Omits the rigid translation (n = 1, eta = 0); see the module docstring for
    the grid-and-Brent method.

    Parameters
    ----------
    n : int
        Degree, n >= 0.
    poisson : float
        Poisson's ratio, in (-1, 0.5).
    count : int
        How many roots (radial orders k = 1 .. count).
    step : float, optional
        Grid step in eta.
    xtol : float, optional
        Absolute tolerance of Brent's method in eta.
    eta_start : float, optional
        Lower end of the scan.
    eta_max : float, optional
        Upper end of the scan; by default it grows until ``count`` roots are found.

    Returns
    -------
    ndarray
        Increasing roots, shape ``(count,)``.
    """
    if count < 1:
        raise ParameterError("count", ">= 1", count)
    f = _scalar(n, poisson)
    roots: list[float] = []
    lo = eta_start
    window = max(8.0, 2.0 * n + 8.0)
    limit = eta_max if eta_max is not None else math.inf
    while len(roots) < count and lo < limit:
        hi = min(lo + window, limit)
        grid = np.arange(lo, hi + 0.5 * step, step)
        grid[-1] = hi
        values = lamb_function(n, grid, poisson)
        found: list[float] = []
        for i in np.flatnonzero(np.sign(values[:-1]) * np.sign(values[1:]) <= 0):
            a, b = grid[i], grid[i + 1]
            if values[i] == 0.0:
                found.append(a)
            elif values[i + 1] != 0.0:
                found.append(brentq(f, a, b, xtol=xtol, rtol=4 * np.finfo(float).eps))
        # touches without a sign change: a local minimum of |F| between grid points
        mag = np.abs(values)
        for i in np.flatnonzero((mag[1:-1] < mag[:-2]) & (mag[1:-1] < mag[2:])) + 1:
            if np.sign(values[i - 1]) != np.sign(values[i]) or np.sign(values[i]) != np.sign(
                values[i + 1]
            ):
                continue
            sign = np.sign(values[i])
            best = minimize_scalar(
                lambda e, s=sign: s * f(e),
                bounds=(grid[i - 1], grid[i + 1]),
                method="bounded",
                options={"xatol": 1e-13},
            )
            if sign * f(best.x) < 1e-10:
                if sign * f(best.x) < 0:  # two simple roots close together
                    found.append(brentq(f, grid[i - 1], best.x, xtol=xtol))
                    found.append(brentq(f, best.x, grid[i + 1], xtol=xtol))
                else:
                    found.extend([best.x, best.x])
        # a root exactly on the seam between two windows is seen by both
        found = [r for r in found if r > eta_start and not (roots and abs(r - roots[-1]) == 0.0)]
        roots.extend(sorted(found))
        lo = hi
    if len(roots) < count:
        raise NumericalError(f"Lamb's equation n = {n}: only {len(roots)} roots below {limit}")
    return np.array(roots[:count])
