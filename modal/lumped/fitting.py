"""Fit a contact law to an isolated contact's duration and restitution.

An isolated contact of reduced mass m hit at speed v, without gravity, has a
restitution e (rebound over impact relative speed) and a duration tau.  These
functions give the law with a prescribed (tau, e) -- the inputs every lumped
model states -- and the inverse maps for checking.

Linear spring-dashpot ``m x'' + c x' + k x = 0`` with ``w0 = sqrt(k / m)``,
``zeta = c / (2 m w0)`` and ``q = zeta / sqrt(1 - zeta^2)``:

* the contact lasts while the overlap is positive (damped oscillator):
  ``e = exp(-pi q)``, ``tau w0 = pi sqrt(1 + q^2)``;
* the contact opens when the force vanishes (Schwager & Pöschel, Granular
  Matter 9, 465 (2007)): the force ``k x + c x'`` vanishes at ``w t = pi - 2
  arctan q`` (``w = w0 / sqrt(1 + q^2)``), where ``-x' / v = exp(-zeta w0 t)``,
  so ``e = exp(-q (pi - 2 arctan q))`` and ``tau w0 = sqrt(1 + q^2) (pi - 2
  arctan q)``.  e cannot fall below ``exp(-2)`` for ``zeta < 1``.

Hertz law with a dashpot, ``m x'' = -k x^(3/2) - c x^p x'``: in the units
``L = (m v^2 / k)^(2/5)`` and ``L / v`` it reads ``s'' = -s^(3/2) - b s^p s'``
with ``b = c L^(p+1) / (m v)``, so e and the reduced duration ``T = tau v / L``
depend on b alone; they are found by integrating that equation (the contact
opens when the force vanishes).  For p = 1/4 (Tsuji et al. 1992), ``b = c /
sqrt(m k)`` does not depend on v: e is the same at every impact speed.  For
p = 1/2 (Kuwabara & Kono 1987), ``b = beta v^(1/5)`` with ``beta = (3/2) A
(k / m)^(2/5)`` and ``c = (3/2) A k`` (Brilliantov et al., Phys. Rev. E 53,
5382 (1996)).  Without damping ``T = 2 (5/4)^(2/5) (2/5) B(2/5, 1/2) = 3.2181``
(Hertz's contact time; Johnson, *Contact Mechanics*, 1985, §11.4).
"""

from __future__ import annotations

import math
from functools import lru_cache

import numpy as np
from scipy.integrate import solve_ivp
from scipy.optimize import brentq
from scipy.special import beta as beta_function

from twoball._common.errors import NumericalError, ParameterError, bounded
from twoball.modal.lumped.laws import HertzLaw, LinearLaw

#: Lowest restitution of a linear spring-dashpot that never pulls (zeta -> 1).
LINEAR_FORCE_RULE_MIN_E = math.exp(-2.0)
#: Hertz's elastic contact time in the units L / v (see the module docstring).
HERTZ_ELASTIC_TIME = 2.0 * 1.25**0.4 * 0.4 * float(beta_function(0.4, 0.5))
#: Largest reduced Hertz damping b searched when fitting.
_B_MAX = 50.0


def linear_restitution(q: float, tensile: bool) -> tuple[float, float]:
    """Restitution e and reduced duration ``tau w0`` of a linear spring-dashpot contact.

    Parameters
    ----------
    q : float
        ``zeta / sqrt(1 - zeta^2)``, >= 0 (zeta: damping ratio, < 1).
    tensile : bool
        True: the contact lasts while the overlap is positive; False: it opens
        when the force vanishes.

    Returns
    -------
    e, duration : float
        Restitution and ``tau w0`` (dimensionless).

    Examples
    --------
    >>> e, d = linear_restitution(0.0, tensile=False)
    >>> e, round(d, 12)
    (1.0, 3.14159265359)
    >>> round(linear_restitution(0.1, tensile=True)[0], 6)
    0.730403
    """
    q = bounded("q", q, 0.0, 1e12)
    angle = math.pi if tensile else math.pi - 2.0 * math.atan(q)
    return math.exp(-q * angle), math.sqrt(1.0 + q * q) * angle


def _q_from_e(e: float, tensile: bool) -> float:
    """Invert :func:`linear_restitution` for q."""
    if e == 1.0:
        return 0.0
    target = -math.log(e)
    if tensile:
        return target / math.pi
    return brentq(lambda q: q * (math.pi - 2.0 * math.atan(q)) - target, 0.0, 1e12, xtol=1e-15)


def check_linear_e(name: str, e: float, tensile: bool) -> float:
    """A restitution a linear spring-dashpot with zeta < 1 can have; else ParameterError."""
    if tensile:
        return bounded(name, e, 0.0, 1.0, low_open=True)
    low = LINEAR_FORCE_RULE_MIN_E
    valid = f"in ({low:.6f}, 1] (exp(-2): a dashpot that never pulls, zeta < 1)"
    out = bounded(name, e, 0.0, 1.0, low_open=True)
    if out <= low:
        raise ParameterError(name, valid, e)
    return out


def fit_linear(mass: float, duration: float, e: float, tensile: bool) -> LinearLaw:
    """The linear spring-dashpot with contact time ``duration`` and restitution ``e``.

    Parameters
    ----------
    mass : float
        Reduced mass of the contact [kg], > 0 (m for a ball on the floor,
        ``m1 m2 / (m1 + m2)`` between two bodies).
    duration : float
        Duration of an isolated contact [s], > 0.
    e : float
        Restitution of an isolated contact, in (0, 1] (above ``exp(-2)`` when
        ``tensile`` is False).
    tensile : bool
        Which rule ends the contact (see :func:`linear_restitution`).

    Returns
    -------
    LinearLaw
        k = m w0^2 and c = 2 m zeta w0.

    Examples
    --------
    >>> law = fit_linear(0.567, math.pi / 320.0, 1.0, tensile=False)
    >>> round(law.stiffness / 0.567, 6)  # w0^2 = c^2 of the basketball
    102400.0
    """
    mass = bounded("mass", mass, 0.0, 1e12, "kg", low_open=True)
    duration = bounded("duration", duration, 0.0, 1e6, "s", low_open=True)
    e = check_linear_e("e", e, tensile)
    q = _q_from_e(e, tensile)
    w0 = linear_restitution(q, tensile)[1] / duration
    zeta = q / math.sqrt(1.0 + q * q)
    return LinearLaw(stiffness=mass * w0 * w0, damping=2.0 * mass * zeta * w0, tensile=tensile)


@lru_cache(maxsize=256)
def hertz_restitution(b: float, exponent: float) -> tuple[float, float, float]:
    """Restitution, reduced duration and reduced peak overlap of ``s'' = -s^(3/2) - b s^p s'``.

    Integrates from ``s = 0``, ``s' = 1`` until the force ``s^(3/2) + b s^p s'``
    vanishes (the contact never pulls).

    Parameters
    ----------
    b : float
        Reduced damping, >= 0.
    exponent : float
        p, in [0, 3/2).

    Returns
    -------
    e, duration, peak : float
        ``-s'`` at the end, the duration in units ``L / v`` and the largest s.

    Examples
    --------
    >>> e, duration, peak = hertz_restitution(0.0, 0.25)
    >>> round(e, 8), round(duration / HERTZ_ELASTIC_TIME, 8), round(peak, 8)
    (1.0, 1.0, 1.09336207)
    """
    b = bounded("b", b, 0.0, 1e6)
    p = bounded("exponent", exponent, 0.0, 1.5)
    if p == 1.5 and b > 0.0:
        raise ParameterError("exponent", "below 3/2 with damping", exponent)
    if b == 0.0:
        return 1.0, HERTZ_ELASTIC_TIME, 1.25**0.4

    def rhs(_t: float, y: np.ndarray) -> list[float]:
        s = max(y[0], 0.0)
        return [y[1], -(s**1.5) - b * s**p * y[1]]

    def force_zero(_t: float, y: np.ndarray) -> float:
        s = max(y[0], 0.0)
        return s ** (1.5 - p) + b * y[1] if s > 0.0 else y[0]

    force_zero.terminal = True  # type: ignore[attr-defined]
    force_zero.direction = -1.0  # type: ignore[attr-defined]
    sol = solve_ivp(
        rhs,
        (0.0, 1e3),
        [0.0, 1.0],
        method="DOP853",
        events=force_zero,
        rtol=1e-12,
        atol=1e-14,
        max_step=0.02,
        dense_output=True,
    )
    if sol.status != 1:
        raise NumericalError(f"Hertz contact with b = {b:g} did not end: {sol.message}")
    t_end = float(sol.t_events[0][0])
    e = -float(sol.y_events[0][0][1])
    peak = float(np.max(sol.y[0]))
    return max(e, 0.0), t_end, peak


def fit_hertz(mass: float, duration: float, e: float, speed: float, exponent: float) -> HertzLaw:
    """The damped Hertz law with contact time ``duration`` and restitution ``e`` at ``speed``.

    Parameters
    ----------
    mass : float
        Reduced mass of the contact [kg], > 0.
    duration : float
        Duration of an isolated contact at ``speed`` [s], > 0.
    e : float
        Restitution at ``speed``, in (0, 1] and reachable by the law.
    speed : float
        Impact (relative) speed at which ``duration`` and ``e`` hold [m/s], > 0.
    exponent : float
        p of the dashpot term (1/4 Tsuji, 1/2 Kuwabara-Kono).

    Returns
    -------
    HertzLaw
        ``k = m (T / tau)^(5/2) v^(-1/2)`` and ``c = b m v / L^(p+1)``.

    Examples
    --------
    >>> law = fit_hertz(0.05, 0.005, 1.0, 4.0, 0.25)
    >>> round(law.stiffness * (0.005 / HERTZ_ELASTIC_TIME) ** 2.5 * 4.0**0.5 / 0.05, 12)
    1.0
    """
    mass = bounded("mass", mass, 0.0, 1e12, "kg", low_open=True)
    duration = bounded("duration", duration, 0.0, 1e6, "s", low_open=True)
    speed = bounded("speed", speed, 0.0, 1e6, "m/s", low_open=True)
    e = bounded("e", e, 0.0, 1.0, low_open=True)
    b = hertz_damping(e, exponent)
    _e, reduced_time, peak = hertz_restitution(b, exponent)
    stiffness = mass * (reduced_time / duration) ** 2.5 / math.sqrt(speed)
    length = (mass * speed * speed / stiffness) ** 0.4
    damping = b * mass * speed / length ** (exponent + 1.0)
    return HertzLaw(stiffness, damping, exponent, length_scale=peak * length)


@lru_cache(maxsize=256)
def hertz_damping(e: float, exponent: float) -> float:
    """The reduced damping b at which :func:`hertz_restitution` gives ``e``.

    Parameters
    ----------
    e : float
        Restitution in (0, 1].
    exponent : float
        p of the dashpot term.

    Returns
    -------
    float
        b >= 0.

    Examples
    --------
    >>> b = hertz_damping(0.8, 0.25)
    >>> round(hertz_restitution(b, 0.25)[0], 10)
    0.8
    """
    e = bounded("e", e, 0.0, 1.0, low_open=True)
    if e == 1.0:
        return 0.0
    low_e = hertz_restitution(_B_MAX, exponent)[0]
    if e <= low_e:
        raise ParameterError(
            "e", f"in ({low_e:.4f}, 1] for a Hertz dashpot with p = {exponent:g}", e
        )
    return brentq(
        lambda b: hertz_restitution(b, exponent)[0] - e, 0.0, _B_MAX, xtol=1e-13, rtol=1e-13
    )
