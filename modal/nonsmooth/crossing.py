"""Where a gap first reaches zero inside a step: cubic Hermite interpolation and secant.

A step of the integrator from ``t`` to ``t + h`` gives each gap and its rate at
both ends; the cubic Hermite interpolant of these four numbers is accurate to
O(h^4) on a smooth motion (de Boor 1978, ch. IV), so its first root is a fourth-
order estimate of the touch time.  The integrator then refines the step length
by the secant method on the gap it actually produces.
"""

from __future__ import annotations

import numpy as np
from scipy.optimize import brentq

_SAMPLES = 16  # sub-intervals searched for the first sign change of the interpolant


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
    below zero (within rounding of a contact just left) counts as zero.
    Returns ``h`` if no sign change is resolved on the sample grid.
    """
    g0 = max(g0, 0.0)
    grid = np.linspace(0.0, h, _SAMPLES + 1)
    values = hermite_gap(grid, h, g0, u0, g1, u1)
    below = np.flatnonzero(values[1:] < 0.0) + 1
    for k in below:
        if values[k - 1] >= 0.0:
            lo, hi = grid[k - 1], grid[k]
            if values[k - 1] == 0.0:
                return float(lo) if lo > 0.0 else float(hi) * 1e-3
            return float(
                brentq(lambda s: float(hermite_gap(s, h, g0, u0, g1, u1)), lo, hi, xtol=1e-15 * h)
            )
    return h


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
