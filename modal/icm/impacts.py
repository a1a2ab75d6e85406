"""The two impacts of the independent collision model (§2), eqs. (2.1)-(2.5).

The lower ball hits the floor (impact velocity, time and rebound, eq. (2.1)),
meets the falling upper ball ``dt`` later (eq. (2.2)), and the two collide with
restitution (eqs. (2.3)-(2.5)).  SI units; velocities positive upwards.
"""

from __future__ import annotations

import numpy as np

from twoball._common.errors import ParameterError
from twoball.modal.icm.inputs import (
    check_drop_height,
    check_dx,
    check_g,
    check_mu,
    check_restitution,
)
from twoball.modal.scalings import STANDARD_GRAVITY


def impact_velocity(drop_height: float, g: float = STANDARD_GRAVITY) -> float:
    """Velocity of both balls when the lower one reaches the floor (§2).

    ``v0 = -sqrt(2 g H)`` with ``H = x2 - r2``, the text preceding eq. (2.1).

    Parameters
    ----------
    drop_height : float
        Fall height ``H = x2 - r2`` of the lower ball's underside [m], > 0.
    g : float, optional
        Gravitational acceleration [m/s^2], > 0.

    Returns
    -------
    float
        ``v0`` [m/s]; negative (downwards).
    """
    drop_height = check_drop_height(drop_height)
    g = check_g(g)
    return -float(np.sqrt(2.0 * g * drop_height))


def impact_time(drop_height: float, g: float = STANDARD_GRAVITY) -> float:
    """Time ``t0 = sqrt(2 H / g)`` of the lower ball's impact on the floor [s] (§2).

    Parameters
    ----------
    drop_height : float
        Fall height ``H = x2 - r2`` [m], > 0.
    g : float, optional
        Gravitational acceleration [m/s^2], > 0.

    Returns
    -------
    float
        ``t0`` [s], measured from release.
    """
    drop_height = check_drop_height(drop_height)
    g = check_g(g)
    return float(np.sqrt(2.0 * drop_height / g))


def rebound_velocity(drop_height: float, e2: float, g: float = STANDARD_GRAVITY) -> float:
    """Rebound velocity ``u0 = -e2 v0 = e2 sqrt(2 g H)`` of the lower ball, eq. (2.1).

    Parameters
    ----------
    drop_height : float
        Fall height ``H = x2 - r2`` [m], > 0.
    e2 : float
        Restitution coefficient between the lower ball and the floor, in [0, 1].
    g : float, optional
        Gravitational acceleration [m/s^2], > 0.

    Returns
    -------
    float
        ``u0`` [m/s]; >= 0 (upwards).
    """
    e2 = check_restitution("e2", e2)
    return -e2 * impact_velocity(drop_height, g)


def max_separation(drop_height: float, e2: float) -> float:
    """Largest separation for which (2.2) holds: ``4 e2 (1 + e2) H`` [m].

    Eq. (2.2) assumes the lower ball is still in flight when it meets the
    upper one.  It lands again ``2 u0 / g`` after its rebound; the gap closes
    at the constant speed ``(1 + e2) |v0|``, so the collision happens in flight
    only for ``dx <= 2 u0 (1 + e2) |v0| / g = 4 e2 (1 + e2) H``.  The bound does
    not depend on g.  For ``e2 = 0`` only ``dx = 0`` is admissible.

    Parameters
    ----------
    drop_height : float
        Fall height ``H = x2 - r2`` [m], > 0.
    e2 : float
        Restitution coefficient with the floor, in [0, 1].

    Returns
    -------
    float
        The bound [m].
    """
    drop_height = check_drop_height(drop_height)
    e2 = check_restitution("e2", e2)
    return 4.0 * e2 * (1.0 + e2) * drop_height


def second_impact_delay(
    dx: float, drop_height: float, e2: float, g: float = STANDARD_GRAVITY
) -> float:
    """Delay ``dt = -dx / ((1 + e2) v0)`` between the two impacts [s], eq. (2.2).

    Parameters
    ----------
    dx : float
        Initial gap ``x1 - x2 - r1 - r2`` between the balls [m], in
        ``[0, max_separation(drop_height, e2)]``.
    drop_height : float
        Fall height ``H = x2 - r2`` [m], > 0.
    e2 : float
        Restitution coefficient with the floor, in [0, 1].
    g : float, optional
        Gravitational acceleration [m/s^2], > 0.

    Returns
    -------
    float
        ``dt`` [s]; the second impact happens at ``t1 = t0 + dt``.

    Raises
    ------
    ParameterError
        For any input out of range, including ``dx`` beyond
        :func:`max_separation` (the lower ball would have landed again).
    """
    dx = check_dx(dx)
    e2 = check_restitution("e2", e2)
    v0 = impact_velocity(drop_height, g)
    if dx == 0.0:
        return 0.0
    limit = max_separation(drop_height, e2)
    if dx > limit:
        raise ParameterError(
            "dx",
            f"<= 4 e2 (1 + e2) H = {limit:.6g} m (lower ball airborne at 2nd impact)",
            dx,
        )
    return impact_delay(dx, -v0, e2)


def impact_delay(gap: float, speed: float, e2: float) -> float:
    """The delay ``Delta x / ((1 + e2) |v0|)`` from the floor impact to the second, eq. (2.2).

    After the floor impact the gap closes at ``(1 + e2) |v0|`` (both fall alike,
    so gravity drops out of the relative motion).  Any consistent units: SI (m,
    m/s, s) or dimensionless (R, R c, 1/c).  The one home of the formula: the
    ICM (:func:`second_impact_delay`), the whole bounce's ICM with the solver's
    own e2 and the studies call it.

    Examples
    --------
    >>> impact_delay(0.05, 4.1, 0.8)  # 5 cm at 4.1 m/s: 6.8 ms
    0.006775067750677507
    """
    return gap / ((1.0 + e2) * speed)


def approach_velocities(gap: float, speed: float, e2: float, g: float) -> tuple[float, float]:
    """``(u1, u2)`` just before the second impact, eqs. (2.1)-(2.2), positive upwards.

    The upper body falls at ``|v0|`` and the lower one rises at ``e2 |v0|`` from
    the floor impact; gravity acts on both during :func:`impact_delay`.  Any
    consistent units (``g`` as ``gamma = g / (R c^2)`` when dimensionless).
    """
    delay = impact_delay(gap, speed, e2)
    return -speed - g * delay, e2 * speed - g * delay


def icm_velocities(
    gap: float, speed: float, e2: float, e12: float, mu: float, g: float
) -> tuple[float, float]:
    """``(v1, v2)`` of the ICM, eqs. (2.1)-(2.5): the floor impact, the delay, the collision.

    ``speed`` is ``|v0|``; units as :func:`approach_velocities`.
    """
    u1, u2 = approach_velocities(gap, speed, e2, g)
    return post_impact_velocities(u1, u2, mu, e12)


def post_impact_velocities(u1: float, u2: float, mu: float, e12: float) -> tuple[float, float]:
    """Velocities after a collinear restitution impact of two bodies, eq. (2.5).

    Solves momentum conservation (2.3) and the restitution law (2.4).

    Parameters
    ----------
    u1, u2 : float
        Velocities of the upper (1) and lower (2) body just before the impact
        [m/s], positive upwards.
    mu : float
        Mass ratio ``m1 / m2``, >= 0 (0 is the limit of a massless upper body).
    e12 : float
        Restitution coefficient between the bodies, in [0, 1].

    Returns
    -------
    v1, v2 : float
        Velocities just after the impact [m/s].
    """
    mu = check_mu(mu)
    e12 = check_restitution("e12", e12)
    u1 = float(u1)
    u2 = float(u2)
    v1 = (mu * u1 + u2 + e12 * (u2 - u1)) / (mu + 1.0)
    v2 = (mu * u1 + u2 + mu * e12 * (u1 - u2)) / (mu + 1.0)
    return v1, v2
