"""Hertz's impact of an elastic sphere on a rigid flat: closed-form reference values.

Quasi-static Hertz contact (Hertz 1882, J. reine angew. Math. 92:156; Johnson,
*Contact Mechanics*, 1985, chapters 4 (Hertz) and 11 (impact); Landau & Lifshitz,
*Theory of Elasticity*, section 9 and its problems): a sphere of radius R pressed
by delta onto a rigid flat carries

    F = (4/3) E* sqrt(R) delta^(3/2),   E* = E / (1 - nu^2)                (H1)

(the flat is rigid, so only the sphere's compliance enters E*).  A sphere of mass m
hitting at v0 stops when its kinetic energy is stored, (1/2) m v0^2 =
(8/15) E* sqrt(R) delta_max^(5/2), so

    delta_max = (15 m v0^2 / (16 E* sqrt(R)))^(2/5),                       (H2)
    F_max = (4/3) E* sqrt(R) delta_max^(3/2),                             (H3)

and the contact (compression and restitution, symmetric without losses) lasts

    t_c = 2 (delta_max / v0) int_0^1 (1 - s^(5/2))^(-1/2) ds
        = (4/5) B(2/5, 1/2) delta_max / v0 = 2.9432 delta_max / v0          (H4)

(substitute s^(5/2) = t in the integral; B is Euler's beta function).  With (H2)
this is c (m^2 / (R E*^2 v0))^(1/5), c = (4/5) B(2/5, 1/2) (15/16)^(2/5) = 2.8683,
the "2.87" of the usual statement.  Valid when t_c is long against the sphere's
lowest period 2 pi R / (eta_{2,1} c_s) (the quasi-static regime) and delta << R.
"""

from __future__ import annotations

import math

from scipy.special import beta

from twoball._common.errors import ParameterError

__all__ = [
    "HERTZ_TIME_COEFFICIENT",
    "effective_modulus",
    "hertz_contact_time",
    "hertz_force",
    "hertz_max_compression",
    "hertz_peak_force",
]

#: (4/5) B(2/5, 1/2) (15/16)^(2/5): t_c = this (m^2 / (R E*^2 v0))^(1/5), eq. (H4).
HERTZ_TIME_COEFFICIENT = 0.8 * float(beta(0.4, 0.5)) * (15.0 / 16.0) ** 0.4


def _positive(name: str, value: float) -> float:
    value = float(value)
    if not (math.isfinite(value) and value > 0):
        raise ParameterError(name, "a finite number > 0", value)
    return value


def effective_modulus(youngs_modulus: float, poisson: float) -> float:
    """E* = E / (1 - nu^2) [Pa] of a sphere on a rigid flat, eq. (H1)."""
    e = _positive("youngs_modulus", youngs_modulus)
    if not -1.0 < poisson < 0.5:
        raise ParameterError("poisson", "in (-1, 0.5)", poisson)
    return e / (1.0 - poisson**2)


def hertz_force(compression: float, radius: float, modulus: float) -> float:
    """F = (4/3) E* sqrt(R) delta^(3/2) [N], eq. (H1); delta [m], R [m], E* [Pa]."""
    if compression < 0:
        raise ParameterError("compression", ">= 0", compression)
    return 4.0 / 3.0 * modulus * math.sqrt(radius) * compression**1.5


def hertz_max_compression(mass: float, radius: float, modulus: float, speed: float) -> float:
    """delta_max [m] of eq. (H2): m [kg], R [m], E* [Pa], impact speed v0 [m/s]."""
    m, r, e, v = (
        _positive(k, x)
        for k, x in zip(
            ("mass", "radius", "modulus", "speed"), (mass, radius, modulus, speed), strict=True
        )
    )
    return (15.0 * m * v * v / (16.0 * e * math.sqrt(r))) ** 0.4


def hertz_peak_force(mass: float, radius: float, modulus: float, speed: float) -> float:
    """F_max [N] of eq. (H3): m [kg], R [m], E* [Pa], v0 [m/s]."""
    return hertz_force(hertz_max_compression(mass, radius, modulus, speed), radius, modulus)


def hertz_contact_time(mass: float, radius: float, modulus: float, speed: float) -> float:
    """t_c [s] of eq. (H4), 2.8683 (m^2 / (R E*^2 v0))^(1/5): m [kg], R [m], E* [Pa], v0 [m/s]."""
    m, r, e, v = (
        _positive(k, x)
        for k, x in zip(
            ("mass", "radius", "modulus", "speed"), (mass, radius, modulus, speed), strict=True
        )
    )
    return HERTZ_TIME_COEFFICIENT * (m * m / (r * e * e * v)) ** 0.2
