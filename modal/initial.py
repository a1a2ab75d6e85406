"""Initial condition, contact angle and deformation energy, eqs. (3.3)-(3.7), (3.10)."""

from __future__ import annotations

import math
from typing import Any

import numpy as np
from numpy.typing import ArrayLike

from twoball._common.errors import ParameterError, real_number
from twoball.modal.roots import bracketed_roots

_EPS = float(np.finfo(float).eps)
_S_MIN = 1e-6  # smallest pi - phi_a resolved: (3.7) is ~ s^4 / 8 there
_LOG_S_MIN = math.log(_S_MIN)
#: Valid contact angles: 1 + cos(phi_a) must keep digits (pi - phi_a >= 1e-6), eq. (3.7).
PHI_A_RANGE = "in (pi/2, pi - 1e-6] = (1.5708, 3.1415917) rad"


def initial_displacement(phi: ArrayLike, phi_a: float) -> np.ndarray:
    """Dimensionless initial radial displacement F(phi), eq. (3.10).

    ``F = cos(phi_a)/cos(phi) - 1`` for phi > phi_a (the flattened cap) and 0 elsewhere:
    the sphere truncated by the floor plane at polar angle phi_a.
    """
    phi_a = check_phi_a(phi_a)
    phi = np.asarray(phi, dtype=float)
    inside = phi > phi_a
    cos_phi = np.where(inside, np.cos(phi), 1.0)
    return np.where(inside, math.cos(phi_a) / cos_phi - 1.0, 0.0)


def initial_displacement_x(x: ArrayLike, phi_a: float) -> np.ndarray:
    """F as a function of ``x = cos(phi)``: ``cos(phi_a)/x - 1`` for x < cos(phi_a), eq. (3.10)."""
    x = np.asarray(x, dtype=float)
    xa = math.cos(check_phi_a(phi_a))
    inside = x < xa
    return np.where(inside, xa / np.where(inside, x, 1.0) - 1.0, 0.0)


def _energy_shape(phi_a: float) -> float:
    """``(-1 + 2 cos^3 + 3 cos^2) / (6 cos)`` of eq. (3.7); positive on (pi/2, pi)."""
    c = math.cos(phi_a)
    # (-1 + 2c^3 + 3c^2) = (1 + c)^2 (2c - 1): written factored for accuracy near phi_a -> pi
    return (1.0 + c) ** 2 * (2.0 * c - 1.0) / (6.0 * c)


def check_phi_a(phi_a: object) -> float:
    """Contact angle phi_a [rad] in :data:`PHI_A_RANGE`, as a float, eq. (3.3).

    Closer to pi than 1e-6 rad, ``1 + cos(phi_a)`` in eq. (3.7) and the pole
    position of the quadrature of eq. (3.12) are mostly round-off (at pi - 1e-9
    it is exactly 0 in double precision).
    """
    value = real_number("phi_a", phi_a, PHI_A_RANGE)
    if not (math.pi / 2 < value and math.pi - value >= _S_MIN * (1.0 - 1e-9)):
        raise ParameterError("phi_a", PHI_A_RANGE, phi_a)
    return value


def _scale(radius: float, wave_speed: float) -> tuple[float, float]:
    """R and c checked (as :class:`~twoball.modal.parameters.Case` does)."""
    from twoball.modal.scalings import check_radius, check_wave_speed

    return check_radius(radius), check_wave_speed(wave_speed)


def v0_dimensionless(phi_a: float) -> float:
    """Impact speed in units of R c that flattens the ball up to ``phi_a``, eq. (3.7)."""
    return math.sqrt(_energy_shape(check_phi_a(phi_a)))


def v0_from_phi_a(phi_a: float, radius: float, wave_speed: float) -> float:
    """Impact speed ``|v0|`` [m/s] for contact angle ``phi_a`` [rad], eq. (3.7)."""
    radius, wave_speed = _scale(radius, wave_speed)
    return radius * wave_speed * v0_dimensionless(phi_a)


def max_v0_dimensionless() -> float:
    """Supremum of eq. (3.7) over (pi/2, pi), approached as phi_a -> pi/2: unbounded.

    Returned as ``inf``; kept as a function so callers state the bound by name.
    """
    return math.inf


def gas_energy_shape(phi_a: float, gas: float) -> float:
    """Gas term added to the shape of eq. (3.7): ``omega_0^2 a_0^2`` (dimensionless).

    The enclosed gas stores ``(1/2) omega_0^2 int a_0^2 dOmega = 2 pi omega_0^2
    a_0^2`` (unit T R^2) when the mean displacement is a_0 of eq. (3.13); with the
    kinetic energy ``2 pi v0^2`` of eq. (3.6) this adds ``omega_0^2 a_0^2`` to
    ``v0^2``.  (Bending adds nothing finite: F has a crease at phi_a.)
    """
    c = math.cos(check_phi_a(phi_a))
    a0 = 0.5 * (c * (math.log(-c) - 1.0) - 1.0)
    return gas * a0 * a0


def phi_a_from_v0(
    v0: float, radius: float, wave_speed: float, gas: float = 0.0, membrane: Any = None
) -> float:
    """Contact angle phi_a [rad] in (pi/2, pi) for impact speed ``|v0|`` [m/s], inverting eq. (3.7).

    The right-hand side of (3.7) decreases monotonically from +inf (phi_a -> pi/2)
    to 0 (phi_a -> pi), so every speed ``0 < |v0| < inf`` has exactly one solution; a
    zero or non-finite speed has none and raises :class:`ParameterError`, and so does
    a speed so slow that ``pi - phi_a < 1e-6`` (``|v0| < 3.5e-13 R c``), where
    ``1 + cos(phi_a)`` in (3.7) is mostly round-off.  The root is found to double
    precision by a bracketing solver (:func:`~twoball.modal.roots.bracketed_roots`,
    regula falsi with bisection) on the logarithm of (3.7) as a function of
    ``log(pi - phi_a)``, where it is nearly a straight line.

    ``gas`` (``omega_0^2`` of :mod:`twoball.modal.stiffness`, default 0) adds the
    energy of the compressed gas to the balance (3.6) (:func:`gas_energy_shape`);
    ``membrane`` (a :class:`~twoball.modal.membrane.Membrane`, default the
    paper's) the energy of its ``-2 u^2 / R^2`` term when pressurised
    (:meth:`~twoball.modal.membrane.Membrane.energy_shape`).
    """
    from twoball.modal.scalings import check_v0

    speed = check_v0(v0)
    radius, wave_speed = _scale(radius, wave_speed)
    # |v0| <= 1e6 m/s and R c >= 1e-12 m/s (checked): the square stays below 1e36
    squared = (speed / (radius * wave_speed)) ** 2
    target = math.log(squared) if squared > 0 else -math.inf  # log (v0 / R c)^2

    # Solve in y = log(pi - phi_a): with s = pi - phi_a the shape of (3.7) rises
    # monotonically from ~s^4/8 (s -> 0) to +inf (s -> pi/2); its logarithm is
    # ~ 4 y - log 8 for small s, so a bracket in y is refined quickly and uniformly.
    pressurised = membrane is not None and membrane.pressurised

    def shape(phi_a: float) -> float:
        if pressurised:
            extra = gas_energy_shape(phi_a, gas) + membrane.energy_shape(phi_a)
            return _energy_shape(phi_a) + extra
        if gas > 0.0:
            return _energy_shape(phi_a) + gas_energy_shape(phi_a, gas)
        return _energy_shape(phi_a)

    def residual(y: float) -> float:
        return math.log(shape(math.pi - math.exp(y))) - target

    upper = math.log(math.pi / 2 * (1 - 1e-15))
    if residual(upper) < 0:
        raise ParameterError(
            "v0",
            f"small enough for eq. (3.7) to have a solution at R = {radius:g} m, "
            f"c = {wave_speed:g} 1/s",
            v0,
        )
    if residual(_LOG_S_MIN) > 0:
        # 1 + cos(phi_a) ~ s^2 / 2 is lost to round-off as s -> 0 (log(0) below s ~ 1e-8)
        slowest = radius * wave_speed * math.sqrt(shape(math.pi - math.exp(_LOG_S_MIN)))
        raise ParameterError(
            "v0",
            f"at least {slowest:.3g} m/s at R = {radius:g} m, c = {wave_speed:g} 1/s (slower "
            "impacts put phi_a within 1e-6 rad of pi, where eq. (3.7) loses double precision)",
            v0,
        )
    lower = upper - 1.0
    while residual(lower) > 0:
        upper, lower = lower, max(lower - 1.0, _LOG_S_MIN)
    # A bracketing solver, not Newton: for phi_a near pi the residual is a staircase at
    # the level of round-off in 1 + cos(phi_a).  Bracket width 4 ulp of y: 4 eps relative
    # in s, i.e. about one ulp in phi_a.
    y = bracketed_roots(
        lambda y, index: np.array([residual(float(value)) for value in y]),
        np.array([lower]),
        np.array([upper]),
        xtol=4.0 * _EPS * max(1.0, -lower),
    )
    return math.pi - math.exp(float(y[0]))


def deformation_work(phi_a: float) -> float:
    """Dimensionless work of deformation ``W / (T R^2)``, eq. (3.5) (negative).

    ``W = -T R^2 pi (-1 + 2 cos^3 + 3 cos^2) / (3 cos)``; its negative equals the
    strain energy ``(1/2) int |grad_s F|^2 dS`` over the unit sphere and, by
    eq. (3.6), the kinetic energy ``2 pi rho R^2 v0^2`` before impact.
    """
    return -2.0 * math.pi * _energy_shape(check_phi_a(phi_a))
