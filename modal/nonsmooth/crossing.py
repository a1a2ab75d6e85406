"""Where a gap first reaches zero inside a step: the cubic Hermite interpolant.

A step of the integrator from ``t`` to ``t + h`` gives each gap and its rate at
both ends; the cubic Hermite interpolant of these four numbers is accurate to
O(h^4) on a smooth motion (de Boor 1978, ch. IV), so its first root is a fourth-
order estimate of the touch time.  The integrator then refines the step length
by regula falsi on the gap it actually produces.
"""

from __future__ import annotations

import numpy as np


def hermite_gap(
    s: np.ndarray | float, h: float, g0: float, u0: float, g1: float, u1: float
) -> np.ndarray:
    """Cubic Hermite interpolant at ``s`` in [0, h] of a gap with values g0, g1 and rates u0, u1."""
    x = np.asarray(s, dtype=float) / h
    h00 = (1.0 + 2.0 * x) * (1.0 - x) ** 2
    h10 = x * (1.0 - x) ** 2
    h01 = x * x * (3.0 - 2.0 * x)
    h11 = x * x * (x - 1.0)
    return h00 * g0 + h10 * h * u0 + h01 * g1 + h11 * h * u1


def first_crossing(h: float, g0: float, u0: float, g1: float, u1: float) -> float:
    """First s in (0, h] where the Hermite gap falls from >= 0 to below 0.

    ``g1 < 0`` is required (the gap ends the step negative).  A start slightly
    below zero (within rounding of a contact just left) counts as zero.  The
    cubic's real roots are computed in closed form (``numpy.roots``), so a
    brief excursion above zero of a constraint leaving at ``g0 = 0`` is found
    however short it is.
    """
    g0 = max(g0, 0.0)
    c2 = (3.0 * (g1 - g0) / h - 2.0 * u0 - u1) / h
    c3 = (2.0 * (g0 - g1) / h + u0 + u1) / (h * h)
    if g0 == 0.0:
        # p(s) = s (u0 + c2 s + c3 s^2): the crossing is a root of the quadratic
        roots = np.roots([c3, c2, u0]) if u0 > 0.0 else np.array([0.0])
    else:
        roots = np.roots([c3, c2, u0, g0])
    real = np.real(roots[np.abs(np.imag(roots)) <= 1e-12 * h])
    inside = np.sort(real[(real > 0.0) & (real <= h)])
    for r in inside:
        if hermite_gap(min(r * (1.0 + 1e-9) + 1e-15 * h, h), h, g0, u0, g1, u1) < 0.0:
            return float(r)
    return float(inside[0]) if inside.size else h


def hermite_rate(
    s: np.ndarray | float, h: float, g0: float, u0: float, g1: float, u1: float
) -> np.ndarray:
    """Time derivative of :func:`hermite_gap` at ``s``."""
    x = np.asarray(s, dtype=float) / h
    d00 = 6.0 * x * (x - 1.0) / h
    d10 = (1.0 - x) * (1.0 - 3.0 * x)
    d01 = -d00
    d11 = x * (3.0 * x - 2.0)
    return d00 * g0 + d10 * u0 + d01 * g1 + d11 * u1


__all__ = ["first_crossing", "hermite_gap", "hermite_rate"]
