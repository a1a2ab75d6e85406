"""Initial condition, contact angle and deformation energy, eqs. (3.3)-(3.7), (3.10)."""

from __future__ import annotations

import math

import numpy as np
from numpy.typing import ArrayLike
from scipy.optimize import brentq

from .errors import ParameterError


def initial_displacement(phi: ArrayLike, phi_a: float) -> np.ndarray:
    """Dimensionless initial radial displacement F(phi), eq. (3.10).

    ``F = cos(phi_a)/cos(phi) - 1`` for phi > phi_a (the flattened cap) and 0 elsewhere:
    the sphere truncated by the floor plane at polar angle phi_a.
    """
    phi = np.asarray(phi, dtype=float)
    inside = phi > phi_a
    cos_phi = np.where(inside, np.cos(phi), 1.0)
    return np.where(inside, math.cos(phi_a) / cos_phi - 1.0, 0.0)


def initial_displacement_x(x: ArrayLike, phi_a: float) -> np.ndarray:
    """F as a function of ``x = cos(phi)``: ``cos(phi_a)/x - 1`` for x < cos(phi_a), eq. (3.10)."""
    x = np.asarray(x, dtype=float)
    xa = math.cos(phi_a)
    inside = x < xa
    return np.where(inside, xa / np.where(inside, x, 1.0) - 1.0, 0.0)


def _energy_shape(phi_a: float) -> float:
    """``(-1 + 2 cos^3 + 3 cos^2) / (6 cos)`` of eq. (3.7); positive on (pi/2, pi)."""
    c = math.cos(phi_a)
    # (-1 + 2c^3 + 3c^2) = (1 + c)^2 (2c - 1): written factored for accuracy near phi_a -> pi
    return (1.0 + c) ** 2 * (2.0 * c - 1.0) / (6.0 * c)


def _check_phi_a(phi_a: float) -> float:
    phi_a = float(phi_a)
    if not (math.pi / 2 < phi_a < math.pi):
        raise ParameterError("phi_a", "in (pi/2, pi) = (1.5708, 3.1416) rad", phi_a)
    return phi_a


def v0_dimensionless(phi_a: float) -> float:
    """Impact speed in units of R c that flattens the ball up to ``phi_a``, eq. (3.7)."""
    return math.sqrt(_energy_shape(_check_phi_a(phi_a)))


def v0_from_phi_a(phi_a: float, radius: float, wave_speed: float) -> float:
    """Impact speed ``|v0|`` [m/s] for contact angle ``phi_a`` [rad], eq. (3.7)."""
    return radius * wave_speed * v0_dimensionless(phi_a)


def max_v0_dimensionless() -> float:
    """Supremum of eq. (3.7) over (pi/2, pi), approached as phi_a -> pi/2: unbounded.

    Returned as ``inf``; kept as a function so callers state the bound by name.
    """
    return math.inf


def phi_a_from_v0(v0: float, radius: float, wave_speed: float) -> float:
    """Contact angle phi_a [rad] in (pi/2, pi) for impact speed ``|v0|`` [m/s], inverting eq. (3.7).

    The right-hand side of (3.7) decreases monotonically from +inf (phi_a -> pi/2)
    to 0 (phi_a -> pi), so every speed ``0 < |v0| < inf`` has exactly one solution; a
    zero or non-finite speed has none and raises :class:`ParameterError`.  The
    root is found with a bracketing solver to double precision.
    """
    speed = abs(float(v0))
    if not (math.isfinite(speed) and speed > 0):
        raise ParameterError("v0", "a finite nonzero speed (eq. (3.7) has no solution)", v0)
    target = math.log((speed / (radius * wave_speed)) ** 2)  # log (v0 / R c)^2

    # Solve in s = pi - phi_a: the shape of (3.7) rises monotonically from ~s^4/24
    # (s -> 0) to +inf (s -> pi/2); work with its logarithm for a uniform accuracy.
    def residual(s: float) -> float:
        return math.log(_energy_shape(math.pi - s)) - target

    hi_s = math.pi / 2 * (1 - 1e-15)
    if residual(hi_s) < 0:
        raise ParameterError("v0", "small enough for eq. (3.7) to have a solution", v0)
    lo_s = 1e-3
    while residual(lo_s) > 0:
        lo_s *= 1e-3
        if lo_s < 1e-60:
            raise ParameterError("v0", "large enough for eq. (3.7) to have a solution", v0)
    s = brentq(residual, lo_s, hi_s, xtol=1e-300, rtol=4 * np.finfo(float).eps, maxiter=500)
    return math.pi - s


def deformation_work(phi_a: float) -> float:
    """Dimensionless work of deformation ``W / (T R^2)``, eq. (3.5) (negative).

    ``W = -T R^2 pi (-1 + 2 cos^3 + 3 cos^2) / (3 cos)``; its negative equals the
    strain energy ``(1/2) int |grad_s F|^2 dS`` over the unit sphere and, by
    eq. (3.6), the kinetic energy ``2 pi rho R^2 v0^2`` before impact.
    """
    return -2.0 * math.pi * _energy_shape(_check_phi_a(phi_a))
