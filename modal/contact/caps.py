"""The contact patch: a polar cap, and the modes averaged over it (dimensionless).

A cap of (projected) radius a on a sphere of radius R has half-angle
``theta = arcsin(a / R)`` and area ``2 pi (1 - cos theta)`` on the unit sphere.
With ``x = cos(phi)`` the cap is ``x in [cos theta, 1]`` and ``dS = dx dalpha``, so
the cap average of an axisymmetric function is its plain average over that x
interval: one Gauss-Legendre rule in x serves the Legendre modes, the
axisymmetric finite-element line and (with an azimuthal rule) the sphere.
"""

from __future__ import annotations

import math

import numpy as np
from numpy.polynomial.legendre import leggauss, legvander

from twoball._common.errors import ParameterError


def cap_angle(contact_radius: float, radius: float) -> float:
    """Half-angle ``theta = arcsin(a / R)`` [rad] of a cap of radius a [m] on radius R [m]."""
    a = float(contact_radius)
    if not (math.isfinite(a) and 0.0 < a < radius):
        raise ParameterError("contact_radius", f"in (0, R) = (0, {radius:g}) m", contact_radius)
    return math.asin(a / radius)


def one_minus_cos(theta: float) -> float:
    """``1 - cos(theta)`` without cancellation."""
    return 2.0 * math.sin(0.5 * theta) ** 2


def cap_rule(theta: float, points: int) -> tuple[np.ndarray, np.ndarray]:
    """Gauss nodes ``x = cos(phi)`` on [cos theta, 1] and weights summing to 1 (an average)."""
    xi, w = leggauss(points)
    return 1.0 - one_minus_cos(theta) * (1.0 + xi) / 2.0, w / 2.0


def legendre_cap_averages(theta: float, modes: int) -> np.ndarray:
    """Cap averages ``b_n = <P_n>_cap``, n = 0..N (Gauss in x, exact for degree <= 2N+1).

    ``b_n -> 1`` as ``theta -> 0`` (the pole value); ``b_0 = 1`` always.
    """
    x, w = cap_rule(theta, modes // 2 + 2)
    return legvander(x, modes).T @ w


def legendre_cap_averages_closed(theta: float, modes: int) -> np.ndarray:
    """The same in closed form, ``(P_{n-1} - P_{n+1})(cos theta) / ((2n+1)(1 - cos theta))``.

    Loses ~``eps / theta^2`` to cancellation for small caps; a test-only second method.
    """
    c = math.cos(theta)
    p = legvander(np.array([c]), modes + 1)[0]
    n = np.arange(1, modes + 1)
    out = np.empty(modes + 1)
    out[0] = 1.0
    out[1:] = (p[n - 1] - p[n + 1]) / ((2 * n + 1) * one_minus_cos(theta))
    return out


def sphere_cap_points(theta: float, rings: int, spokes: int) -> tuple[np.ndarray, np.ndarray]:
    """Points (3, P) on the unit-sphere cap and weights summing to 1.

    Gauss in ``x = cos(phi)`` times the trapezoid rule in azimuth (exact for
    trigonometric polynomials of degree < spokes).
    """
    x, w = cap_rule(theta, rings)
    alpha = 2.0 * np.pi * (np.arange(spokes) + 0.5) / spokes
    r = np.sqrt(np.clip(1.0 - x * x, 0.0, None))
    pts = np.stack(
        [
            np.outer(r, np.cos(alpha)).ravel(),
            np.outer(r, np.sin(alpha)).ravel(),
            np.repeat(x, spokes),
        ]
    )
    return pts, np.repeat(w / spokes, spokes)
