"""The closed-form CEM solution as a Legendre series, eqs. (3.11)-(3.16).

With x = cos(phi) the initial condition (3.10) is ``F = cos(phi_a)/x - 1`` on
``x in [-1, cos(phi_a)]`` and 0 above, so the coefficients (3.12) are integrals of
a smooth function over that interval.  They are computed by Gauss-Legendre
quadrature sized to the distance of the integrand's pole (x = 0) from the
interval, which gives machine precision for every phi_a in (pi/2, pi).
"""

from __future__ import annotations

import math
from functools import lru_cache

import numpy as np
from numpy.polynomial.legendre import legvander
from numpy.typing import ArrayLike

from twoball._common.errors import NumericalError, ParameterError
from twoball._common.monitor import Monitor
from twoball.modal.filters import FilterKind, SpectralFilter, legendre_frequency
from twoball.modal.initial import check_phi_a
from twoball.modal.series import ModalSeries
from twoball.modal.stiffness import Stiffness

MAX_QUADRATURE = 20000


_DENSE_JACOBI_MAX = 256  # up to this many points numpy's dense eigvalsh is as fast as scipy's


@lru_cache(maxsize=64)
def _gauss_legendre(points: int, eigensolver: str = "auto") -> tuple[np.ndarray, np.ndarray]:
    """Gauss-Legendre nodes and weights to double precision.

    Golub-Welsch nodes from the symmetric tridiagonal Jacobi matrix, one Newton
    step on P_m to polish them, and weights ``2 / ((1 - x^2) P_m'(x)^2)``.

    ``eigensolver`` picks how the Jacobi matrix's eigenvalues are found: ``dense``
    (numpy's ``eigvalsh`` on the full matrix, O(m^3) but no scipy import: the
    N = 30 rules of the command line need about 50 points), ``tridiagonal``
    (``scipy.linalg.eigvalsh_tridiagonal``, O(m^2), for the thousands of points a
    contact angle near pi/2 needs) or ``auto`` (dense up to 256 points).
    """
    k = np.arange(1, points)
    off_diagonal = k / np.sqrt(4.0 * k * k - 1.0)
    if eigensolver == "auto":
        eigensolver = "dense" if points <= _DENSE_JACOBI_MAX else "tridiagonal"
    if eigensolver == "dense":
        x = np.linalg.eigvalsh(np.diag(off_diagonal, -1))  # reads the lower triangle only
    elif eigensolver == "tridiagonal":
        from scipy.linalg import eigvalsh_tridiagonal

        x = eigvalsh_tridiagonal(np.zeros(points), off_diagonal)
    else:
        raise ValueError("eigensolver must be 'auto', 'dense' or 'tridiagonal'")
    p, dp = _legendre_and_derivative(points, x)
    x = x - p / dp
    _, dp = _legendre_and_derivative(points, x)
    w = 2.0 / ((1.0 - x * x) * dp * dp)
    # symmetrise: the rule is exactly symmetric about 0
    x = 0.5 * (x - x[::-1])
    w = 0.5 * (w + w[::-1])
    return x, w


def _legendre_and_derivative(n: int, x: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """P_n(x) and P_n'(x) by Bonnet's recurrence (|x| < 1)."""
    previous, current = np.ones_like(x), x.copy()
    for k in range(1, n):
        previous, current = current, ((2 * k + 1) * x * current - k * previous) / (k + 1)
    return current, n * (x * current - previous) / (x * x - 1.0)


def _check_modes(modes: int) -> int:
    if isinstance(modes, bool) or int(modes) != modes or modes < 0:
        raise ParameterError("modes", "an integer >= 1", modes)
    return int(modes)


def quadrature_points(modes: int, phi_a: float) -> int:
    """Gauss points that integrate ``P_n(x) / x`` on [-1, cos phi_a] to double precision.

    The factor 1/x is analytic in a Bernstein ellipse of parameter rho around the
    interval (its pole x = 0 lies outside); Gauss converges like rho^(-2m), so
    ``m = N + 24 / ln(rho) + 8`` points suffice for all n <= N.
    """
    xa = math.cos(phi_a)
    half = (1.0 + xa) / 2.0
    xi = 1.0 + (-xa) / half  # pole position in the interval's reference coordinate
    rho = xi + math.sqrt(xi * xi - 1.0)
    return min(MAX_QUADRATURE, modes + math.ceil(24.0 / math.log(rho)) + 8)


def legendre_coefficients(phi_a: float, modes: int) -> np.ndarray:
    """Coefficients a_0 .. a_N of F in Legendre polynomials, eq. (3.12) (dimensionless).

    ``a_n = (2n + 1)/2 * int_{-1}^{cos phi_a} (cos phi_a / x - 1) P_n(x) dx``, by
    Gauss-Legendre quadrature on exactly the interval where F is nonzero.
    """
    phi_a = check_phi_a(phi_a)
    modes = _check_modes(modes)
    length = 2.0 * math.sin((math.pi - phi_a) / 2.0) ** 2  # 1 + cos(phi_a), no cancellation
    nodes, weights = _gauss_legendre(quadrature_points(modes, phi_a))
    x = (nodes + 1.0) * (length / 2.0) - 1.0
    w = weights * (length / 2.0)
    # F = cos(phi_a)/x - 1 = (cos(phi_a) - x)/x, with cos(phi_a) - x = length (1 - node)/2
    integrand = (length * (1.0 - nodes) / 2.0) / x
    integrals = np.einsum("mn,m->n", legvander(x, modes), w * integrand)
    n = np.arange(modes + 1)
    coefficients = (2 * n + 1) / 2.0 * integrals
    if not np.all(np.isfinite(coefficients)):
        raise NumericalError("Legendre coefficients are not finite")
    return coefficients


def mean_displacement(phi_a: float) -> float:
    """a_0 in closed form, eq. (3.13): ``(cos phi_a (log(-cos phi_a) - 1) - 1) / 2``."""
    xa = math.cos(check_phi_a(phi_a))
    return 0.5 * (xa * (math.log(-xa) - 1.0) - 1.0)


def legendre_coefficients_recurrence(phi_a: float, modes: int) -> np.ndarray:
    """a_0 .. a_N from an exact three-term recurrence (a second, independent method).

    With ``I_n = int P_n / x`` and ``J_n = int P_n`` over [-1, cos phi_a], Bonnet's
    recursion gives ``I_{n+1} = ((2n + 1) J_n - n I_{n-1}) / (n + 1)`` with
    ``I_0 = log(-cos phi_a)``, ``I_1 = 1 + cos phi_a`` and
    ``J_n = (P_{n+1} - P_{n-1})(cos phi_a) / (2n + 1)``; then ``a_n = (2n+1)/2
    (cos(phi_a) I_n - J_n)``.  Used by the tests to check eq. (3.12).
    """
    xa = math.cos(check_phi_a(phi_a))
    modes = _check_modes(modes)
    p = legvander(np.array([xa]), modes + 1)[0]  # P_0 .. P_{N+1} at xa
    n = np.arange(modes + 1)
    j = np.empty(modes + 1)
    j[0] = xa + 1.0
    j[1:] = (p[2 : modes + 2] - p[0:modes]) / (2 * n[1:] + 1)
    i = np.empty(modes + 1)
    i[0] = math.log(-xa)
    if modes >= 1:
        i[1] = xa + 1.0
    for k in range(1, modes):
        i[k + 1] = ((2 * k + 1) * j[k] - k * i[k - 1]) / (k + 1)
    return (2 * n + 1) / 2.0 * (xa * i - j)


def legendre_series(
    phi_a: float,
    damping: float,
    filter: SpectralFilter | FilterKind = "lanczos",
    modes: int | None = None,
    stiffness: Stiffness | None = None,
    *,
    monitor: Monitor | None = None,
) -> ModalSeries:
    """The damped, filtered Legendre series of eq. (3.16) as a :class:`ModalSeries`.

    Parameters
    ----------
    phi_a : float
        Contact angle [rad] in (pi/2, pi).
    damping : float
        Modal damping ratio D in [0, 1).
    filter : SpectralFilter or {"lanczos", "printed", "none"}
        Spectral filter; a string needs ``modes``.
    modes : int, optional
        Truncation N (taken from ``filter`` when a SpectralFilter is given).
    stiffness : Stiffness, optional
        Bending and gas (:mod:`twoball.modal.stiffness`): ``omega_n^2 = n (n+1)
        (1 + beta (n (n+1) - 2))``, ``omega_0^2 = gas``; the filter still weighs
        mode n by ``sqrt(n (n+1))``.  None or inactive: the paper's membrane.
    monitor : Monitor, optional
        Told as the series is evaluated (:attr:`ModalSeries.monitor`).

    Returns
    -------
    ModalSeries
        Modes n = 0..N: ``omega_n = sqrt(n (n+1))``, coefficients a_n, pole values
        ``P_n(1) = 1``, norms ``int P_n^2 dS = 4 pi / (2n + 1)`` (dimensionless).
    """
    if isinstance(filter, str):
        filter = SpectralFilter(filter, 30 if modes is None else modes)
    elif modes is not None and modes != filter.modes:
        raise ValueError("modes disagrees with filter.modes")
    n = np.arange(filter.modes + 1)
    stiff = stiffness is not None and stiffness.active
    return ModalSeries(
        omega=stiffness.legendre_omega(n) if stiff else legendre_frequency(n),
        coefficients=legendre_coefficients(phi_a, filter.modes),
        pole_values=np.ones(n.size),
        damping=damping,
        filter=filter,
        mode_norms=4.0 * np.pi / (2 * n + 1),
        filter_omega=legendre_frequency(n) if stiff else None,
        monitor=monitor,
    )


def legendre_shapes(phi: ArrayLike, modes: int) -> np.ndarray:
    """Mode shapes ``P_n(cos phi)``, shape (N + 1, P), for :meth:`ModalSeries.field`."""
    phi = np.asarray(phi, dtype=float).reshape(-1)
    return legvander(np.cos(phi), modes).T


def displacement(
    series: ModalSeries, t: ArrayLike, phi: ArrayLike, derivative: int = 0
) -> np.ndarray:
    """u (or u_t, u_tt) of a Legendre series at times ``t`` and polar angles ``phi``.

    Dimensionless; shape ``t.shape + (len(phi),)``; eq. (3.16).
    """
    return series.field(t, legendre_shapes(phi, series.filter.modes), derivative)
