"""Spheroidal mode shapes of Lamb's sphere, their normalisation and projections.

A mode of degree n, radial order k (axisymmetric, m = 0) has the displacement

    u(r, theta) = U(rho) P_n(cos theta) e_r + V(rho) dP_n/dtheta e_theta,   rho = r / R,

with, from the potentials of :mod:`twoball.modal.solid.lamb` (x = eta c_s/c_p,
y = eta, amplitudes A, B from the null vector of eq. L1):

    U(rho) = A [n j_n(x rho) - x rho j_{n+1}(x rho)] / rho + B n(n+1) j_n(y rho) / rho
    V(rho) = A j_n(x rho) / rho + B [(n+1) j_n(y rho) - y rho j_{n+1}(y rho)] / rho   (eq. M1)

(the gradient of phi and curl curl(r psi e_r), R = 1).  dP_n/dtheta = P_n^1(cos theta)
with the Condon-Shortley phase of scipy's ``lpmv``.

Normalisation (eq. M2): unit modal mass in units of the ball's mass,
``int rho_m u.u dV = M``, i.e. the volume mean of |u|^2 is 1:

    (3 / (2n + 1)) int_0^1 rho^2 [U^2 + n(n+1) V^2] d rho = 1,

using int P_n^2 d(cos) = 2/(2n+1) and int (dP_n/dtheta)^2 d(cos) = 2n(n+1)/(2n+1).
Modes of different (n, k) are orthogonal in this inner product, so a field u_0
has the coefficients c = (1/V) int u_0 . u_nk dV (eq. M3) and u_0 = sum c u_nk;
a coefficient carries the unit of u_0.  The sign is fixed by U(1) > 0 (the
north pole moves outwards), or V(1) > 0 where U(1) = 0.

The rigid translation along z is the mode n = 1, k = 0, eta = 0 with U = V = 1
(e_z = cos theta e_r - sin theta e_theta); its modal coordinate is the
displacement of the centre of mass.  Every other mode leaves the centre of mass
at rest (they are mass-orthogonal to the translation; :meth:`SphereMode.centre_of_mass`
computes it rather than assuming it).
"""

from __future__ import annotations

from collections.abc import Callable, Iterable
from dataclasses import dataclass

import numpy as np
from scipy.special import eval_legendre, lpmv, spherical_jn

from twoball._common.errors import ParameterError
from twoball.modal.solid.lamb import boundary_matrix, lamb_roots, scaled_bessel_pair, speed_ratio

__all__ = ["SphereMode", "modal_coefficients", "spheroidal_modes", "translation_mode"]

_RHO_MIN = 1e-8  # eq. (M1) at rho -> 0 is evaluated here (relative error ~1e-16)


def _legendre_nodes(count: int, a: float, b: float) -> tuple[np.ndarray, np.ndarray]:
    """Gauss-Legendre nodes and weights on [a, b]."""
    x, w = np.polynomial.legendre.leggauss(count)
    return 0.5 * (b - a) * x + 0.5 * (b + a), 0.5 * (b - a) * w


@dataclass(frozen=True)
class SphereMode:
    """One axisymmetric spheroidal mode of a free elastic sphere (dimensionless, R = 1).

    Attributes
    ----------
    degree : int
        n, the Legendre degree.
    radial_order : int
        k >= 1 for elastic modes (the k-th root of Lamb's equation); 0 for the
        translation (n = 1, eta = 0).
    eta : float
        omega R / c_s.
    poisson : float
        Poisson's ratio.
    amplitude_p, amplitude_s : float
        A and B of eq. (M1), already normalised by eq. (M2).
    """

    degree: int
    radial_order: int
    eta: float
    poisson: float
    amplitude_p: float
    amplitude_s: float

    @property
    def is_translation(self) -> bool:
        """True for the rigid translation (eta = 0)."""
        return self.radial_order == 0

    def radial(self, rho: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """U(rho), V(rho) of eq. (M1) at rho = r / R in [0, 1] (dimensionless)."""
        rho = np.maximum(np.asarray(rho, dtype=float), _RHO_MIN)
        if self.is_translation:
            return np.ones_like(rho), np.ones_like(rho)
        n = self.degree
        x = self.eta / speed_ratio(self.poisson)
        y = self.eta
        a, b = self.amplitude_p, self.amplitude_s
        jx, jx1 = spherical_jn(n, x * rho), spherical_jn(n + 1, x * rho)
        jy, jy1 = spherical_jn(n, y * rho), spherical_jn(n + 1, y * rho)
        u = a * (n * jx - x * rho * jx1) / rho + b * n * (n + 1) * jy / rho
        v = a * jx / rho + b * ((n + 1) * jy - y * rho * jy1) / rho
        if n == 0:  # V multiplies dP_0/dtheta = 0: no tangential field
            v = np.zeros_like(u)
        return u, v

    def displacement(self, rho: np.ndarray, theta: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """(u_r, u_theta) at (rho, theta), polar angle theta from the north pole (dimensionless)."""
        u, v = self.radial(rho)
        c = np.cos(theta)
        return u * eval_legendre(self.degree, c), v * lpmv(1, self.degree, c)

    def surface(self, phi: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """Surface displacement at polar angles phi: (u_r, u_theta, u_z).

        u_z = u_r cos(phi) - u_theta sin(phi) is the vertical (polar-axis)
        component, positive upwards (dimensionless, per unit modal coordinate).
        """
        phi = np.asarray(phi, dtype=float)
        ur, ut = self.displacement(np.ones_like(phi), phi)
        return ur, ut, ur * np.cos(phi) - ut * np.sin(phi)

    def cap_average(self, theta0: float) -> float:
        """Area mean of u_z over the polar cap phi <= theta0 of the surface (dimensionless).

        (1 / (1 - cos theta0)) int_{cos theta0}^1 [U(1) x P_n(x) - V(1) sqrt(1-x^2)
        P_n^1(x)] dx: the integrand is a polynomial of degree n + 1, so Gauss-Legendre
        with n + 4 points in x = cos(phi) is exact.  theta0 = 0 gives the pole value.
        """
        if not 0.0 <= theta0 <= np.pi:
            raise ParameterError("theta0", "in [0, pi]", theta0)
        if theta0 == 0.0:
            return float(self.surface(np.array([0.0]))[2][0])
        x, w = _legendre_nodes(self.degree + 4, np.cos(theta0), 1.0)
        uz = self.surface(np.arccos(x))[2]
        return float(w @ uz / (1.0 - np.cos(theta0)))

    def centre_of_mass(self, points: int | None = None) -> float:
        """Vertical displacement of the centre of mass, (1/V) int u_z dV (dimensionless).

        Quadrature: Gauss-Legendre in rho (``points``) and exact in cos(theta).
        1 for the translation; rounding-level for every elastic mode.
        """
        rho, wr = _legendre_nodes(points or _radial_points(self), 0.0, 1.0)
        x, wx = _legendre_nodes(self.degree + 4, -1.0, 1.0)
        u, v = self.radial(rho)
        n = self.degree
        i1 = wx @ (x * eval_legendre(n, x))
        i2 = wx @ (-np.sqrt(1.0 - x * x) * lpmv(1, n, x))
        return float(1.5 * (wr * rho**2) @ (u * i1 + v * i2))

    def mean_square(self, points: int | None = None) -> float:
        """Volume mean of |u|^2, eq. (M2) (1 for a normalised mode)."""
        rho, w = _legendre_nodes(points or _radial_points(self), 0.0, 1.0)
        u, v = self.radial(rho)
        n = self.degree
        return float(3.0 / (2 * n + 1) * (w * rho**2) @ (u * u + n * (n + 1) * v * v))


def _radial_points(mode: SphereMode) -> int:
    """Gauss points in rho for the products of two mode shapes (oscillation ~ eta)."""
    return int(48 + mode.degree + 2 * np.ceil(mode.eta))


def translation_mode(poisson: float) -> SphereMode:
    """The rigid translation along the polar axis: n = 1, k = 0, eta = 0, U = V = 1."""
    speed_ratio(poisson)  # validates
    return SphereMode(1, 0, 0.0, float(poisson), 1.0, 0.0)


def _mode(n: int, k: int, eta: float, poisson: float) -> SphereMode:
    """The normalised mode of degree n at the root eta (radial order k)."""
    if n == 0:
        a, b = 1.0, 0.0
    else:
        m = boundary_matrix(n, np.array([eta]), poisson)[0]
        # the null vector of the row with the larger norm (both are parallel at a root)
        row = m[0] if np.hypot(*m[0]) >= np.hypot(*m[1]) else m[1]
        a, b = row[1], -row[0]
    # back from the scaled columns: A = a / s_n(x), B = b / s_n(y)
    x, y = eta / speed_ratio(poisson), eta
    sx = np.hypot(spherical_jn(n, x), spherical_jn(n + 1, x))
    sy = np.hypot(spherical_jn(n, y), spherical_jn(n + 1, y))
    if sx == 0.0 or sy == 0.0:  # underflow: only for n in the hundreds at these roots
        jx, _ = scaled_bessel_pair(n, np.array([x]))
        raise ParameterError("degree", "small enough that j_n(x) does not underflow", (n, jx))
    raw = SphereMode(n, k, float(eta), float(poisson), a / sx, b / sy)
    scale = 1.0 / np.sqrt(raw.mean_square())
    u1, v1 = raw.radial(np.array([1.0]))
    sign = np.sign(u1[0]) if abs(u1[0]) > 1e-12 * abs(v1[0]) else np.sign(v1[0])
    scale *= sign
    return SphereMode(n, k, float(eta), float(poisson), a / sx * scale, b / sy * scale)


def spheroidal_modes(
    poisson: float, degrees: Iterable[int], count: int, *, translation: bool = True
) -> list[SphereMode]:
    """The first ``count`` elastic modes of each degree, normalised by eq. (M2).

    Parameters
    ----------
    poisson : float
        Poisson's ratio, in (-1, 0.5).
    degrees : iterable of int
        Degrees n >= 0.
    count : int
        Radial orders k = 1 .. count for each degree.
    translation : bool, optional
        Add the rigid translation (n = 1, k = 0) when degree 1 is asked.

    Returns
    -------
    list of SphereMode
        By degree, then radial order.
    """
    modes: list[SphereMode] = []
    for n in degrees:
        if translation and n == 1:
            modes.append(translation_mode(poisson))
        roots = lamb_roots(int(n), poisson, count)
        modes.extend(_mode(int(n), k, eta, poisson) for k, eta in enumerate(roots, start=1))
    return modes


def modal_coefficients(
    modes: list[SphereMode],
    field: Callable[[np.ndarray, np.ndarray], tuple[np.ndarray, np.ndarray]],
    *,
    radial_points: int = 96,
    angular_points: int = 96,
) -> np.ndarray:
    """Coefficients of an axisymmetric field in the modes, eq. (M3).

    c_j = (1/V) int u_0 . u_j dV by Gauss-Legendre quadrature in rho on [0, 1] and
    in cos(theta) on [-1, 1] (tensor product).

    Parameters
    ----------
    modes : list of SphereMode
        Normalised modes (eq. M2).
    field : callable
        ``field(rho, theta) -> (u_r, u_theta)`` on arrays of equal shape; any unit,
        which the coefficients carry.
    radial_points, angular_points : int, optional
        Quadrature points in rho and cos(theta).

    Returns
    -------
    ndarray
        One coefficient per mode.
    """
    rho, wr = _legendre_nodes(radial_points, 0.0, 1.0)
    x, wx = _legendre_nodes(angular_points, -1.0, 1.0)
    rr, xx = np.meshgrid(rho, x, indexing="ij")
    theta = np.arccos(xx)
    ur0, ut0 = field(rr, theta)
    weight = 1.5 * np.outer(wr * rho**2, wx)  # (3 / 4 pi) * 2 pi * rho^2 d rho d cos
    out = np.empty(len(modes))
    for j, mode in enumerate(modes):
        ur, ut = mode.displacement(rr, theta)
        out[j] = np.sum(weight * (ur0 * ur + ut0 * ut))
    return out
