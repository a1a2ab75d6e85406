"""The touching limit dx -> 0 of the independent collision model, eqs. (2.6) and (2.7).

:func:`touching_limit` and :func:`light_touching_limit` return the multipliers
``k`` of ``v0`` as the equations print them; since ``v0 < 0`` the rebound
ratios ``v / |v0|`` are ``-k`` (:func:`touching_ratios`).
"""

from __future__ import annotations

from twoball.modal.icm.inputs import check_mu, check_restitution


def touching_limit(mu: float, e2: float, e12: float) -> tuple[float, float]:
    """Multipliers ``(k1, k2)`` with ``v1 -> k1 v0``, ``v2 -> k2 v0`` as dx -> 0, eq. (2.6).

    ``k1 = (mu - e2 - e12 (1 + e2)) / (mu + 1)`` and
    ``k2 = (mu - e2 + mu e12 (1 + e2)) / (mu + 1)``.  Independent of the drop
    height.  Since ``v0 < 0`` the rebound ratios are ``v / |v0| = -k``; see
    :func:`touching_ratios`.

    Parameters
    ----------
    mu : float
        Mass ratio ``m1 / m2``, >= 0.
    e2, e12 : float
        Restitution coefficients (floor, between balls), in [0, 1].

    Returns
    -------
    k1, k2 : float
        Dimensionless multipliers of ``v0``.
    """
    mu = check_mu(mu)
    e2 = check_restitution("e2", e2)
    e12 = check_restitution("e12", e12)
    k1 = (mu - e2 - e12 * (1.0 + e2)) / (mu + 1.0)
    k2 = (mu - e2 + mu * e12 * (1.0 + e2)) / (mu + 1.0)
    return k1, k2


def touching_ratios(mu: float, e2: float, e12: float) -> tuple[float, float]:
    """Rebound ratios ``(v1 / |v0|, v2 / |v0|)`` in the limit dx -> 0, eq. (2.6).

    Parameters
    ----------
    mu : float
        Mass ratio ``m1 / m2``, >= 0.
    e2, e12 : float
        Restitution coefficients (floor, between balls), in [0, 1].

    Returns
    -------
    r1, r2 : float
        ``-k1`` and ``-k2`` of :func:`touching_limit` (positive = upwards).
    """
    k1, k2 = touching_limit(mu, e2, e12)
    return -k1, -k2


def light_touching_limit(e2: float, e12: float) -> tuple[float, float]:
    """Multipliers of ``v0`` for dx -> 0 and mu -> 0, eq. (2.7).

    ``v1 -> -((1 + e2) e12 + e2) v0`` and ``v2 -> -e2 v0``.  For
    ``e2 = e12 = 1`` this is the classic ``v1 = -3 v0`` (nine times the drop
    height).

    Parameters
    ----------
    e2, e12 : float
        Restitution coefficients (floor, between balls), in [0, 1].

    Returns
    -------
    k1, k2 : float
        Dimensionless multipliers of ``v0`` (both <= 0).
    """
    e2 = check_restitution("e2", e2)
    e12 = check_restitution("e12", e12)
    return -((1.0 + e2) * e12 + e2), -e2
