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


def first_crossings(
    h: float, g0: np.ndarray, u0: np.ndarray, g1: np.ndarray, u1: np.ndarray
) -> np.ndarray:
    """:func:`first_crossing` of several gaps over one step, at once (same numbers).

    The cubics' companion matrices are stacked and their eigenvalues found in
    one LAPACK call per size (what :func:`numpy.roots` does for each alone, so
    the roots are the same to the last bit); a gap whose cubic has a vanishing
    leading coefficient or is not finite takes :func:`first_crossing`.

    Parameters
    ----------
    h : float
        Step length (dimensionless time), > 0.
    g0, u0, g1, u1 : ndarray, shape (k,)
        Each gap and its rate at the step's start and end (``g1 < 0``).

    Returns
    -------
    ndarray, shape (k,)
        The first crossing of each gap in (0, h].
    """
    g0 = np.maximum(np.asarray(g0, dtype=float), 0.0)
    u0, g1, u1 = (np.asarray(x, dtype=float) for x in (u0, g1, u1))
    c2 = (3.0 * (g1 - g0) / h - 2.0 * u0 - u1) / h
    c3 = (2.0 * (g0 - g1) / h + u0 + u1) / (h * h)
    out = np.full(g0.size, np.nan)
    start = g0 == 0.0
    finite = np.isfinite(c2) & np.isfinite(c3) & np.isfinite(u0) & np.isfinite(g0)
    regular = finite & (c3 != 0.0)
    out[start & (u0 <= 0.0) & finite] = h  # the root 0 alone: no crossing inside
    roots = np.full((g0.size, 3), np.nan + 0j)
    quadratic = regular & start & (u0 > 0.0)
    cubic = regular & ~start
    for mask, size in ((quadratic, 2), (cubic, 3)):
        k = np.flatnonzero(mask)
        if not k.size:
            continue
        companion = np.zeros((k.size, size, size))
        for i in range(1, size):
            companion[:, i, i - 1] = 1.0
        companion[:, 0, 0] = -c2[k] / c3[k]
        companion[:, 0, 1] = -u0[k] / c3[k]
        if size == 3:
            companion[:, 0, 2] = -g0[k] / c3[k]
        roots[k, :size] = np.linalg.eigvals(companion)
    solved = quadratic | cubic
    real = np.where(np.abs(roots.imag) <= 1e-12 * h, roots.real, np.nan)
    inside = (real > 0.0) & (real <= h)
    probe = np.minimum(np.where(inside, real, 0.0) * (1.0 + 1e-9) + 1e-15 * h, h)
    below = hermite_gap(probe, h, g0[:, None], u0[:, None], g1[:, None], u1[:, None]) < 0.0
    passing = np.where(inside & below, real, np.inf).min(axis=1)
    smallest = np.where(inside, real, np.inf).min(axis=1)
    chosen = np.where(np.isfinite(passing), passing, np.where(np.isfinite(smallest), smallest, h))
    out[solved] = chosen[solved]
    for i in np.flatnonzero(np.isnan(out)):  # the rare cases numpy.roots handles alone
        out[i] = first_crossing(h, g0[i], u0[i], g1[i], u1[i])
    return out


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


__all__ = ["first_crossing", "first_crossings", "hermite_gap", "hermite_rate"]
