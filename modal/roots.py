"""A vectorised bracketing root finder (Illinois regula falsi with bisection safeguard)."""

from __future__ import annotations

from collections.abc import Callable

import numpy as np

from twoball._common.errors import NumericalError


def bracketed_roots(
    f: Callable[[np.ndarray, np.ndarray], np.ndarray],
    lower: np.ndarray,
    upper: np.ndarray,
    xtol: float = 1e-12,
    max_iter: int = 200,
) -> np.ndarray:
    """Roots of ``f`` inside each bracket ``[lower_i, upper_i]``, all refined at once.

    ``f(x, index)`` evaluates the function of bracket ``index[j]`` at ``x[j]`` (so each
    bracket may have its own parameters); it must change sign (or vanish) on every
    bracket.  Each pass evaluates ``f``
    once on all unfinished brackets: an Illinois step (regula falsi that halves a
    stale end's value), with a bisection every fourth pass so that every bracket at
    least halves every four passes.  Stops when a bracket is narrower than ``xtol``.

    Returns
    -------
    ndarray
        For each bracket, the end with the smaller ``|f|`` once it is narrower than xtol.
    """
    a = np.array(lower, dtype=float, copy=True)
    b = np.array(upper, dtype=float, copy=True)
    if a.size == 0:
        return a
    everything = np.arange(a.size)
    fa, fb = f(a, everything), f(b, everything)
    if np.any(fa * fb > 0):
        raise NumericalError("root search: a bracket does not change sign")
    side = np.zeros(a.shape, dtype=int)  # which end was kept last: -1 a, +1 b
    active = (b - a > xtol) & (fa != 0) & (fb != 0)
    for iteration in range(max_iter):
        if not active.any():
            break
        i = np.flatnonzero(active)
        ai, bi, fai, fbi = a[i], b[i], fa[i], fb[i]
        if iteration % 4 == 3:
            x = 0.5 * (ai + bi)
        else:
            x = bi - fbi * (bi - ai) / (fbi - fai)
            bad = ~((x > ai) & (x < bi))
            x[bad] = 0.5 * (ai[bad] + bi[bad])
        fx = f(x, i)
        same_as_a = np.sign(fx) == np.sign(fai)
        # replace a (fx on a's side): b is kept; halve fb if b was kept last time too
        keep_b = same_as_a
        a[i[keep_b]], fa[i[keep_b]] = x[keep_b], fx[keep_b]
        stale_b = keep_b & (side[i] == 1)
        fb[i[stale_b]] *= 0.5
        side[i[keep_b]] = 1
        keep_a = ~same_as_a
        b[i[keep_a]], fb[i[keep_a]] = x[keep_a], fx[keep_a]
        stale_a = keep_a & (side[i] == -1)
        fa[i[stale_a]] *= 0.5
        side[i[keep_a]] = -1
        hit = fx == 0
        a[i[hit]] = b[i[hit]] = x[hit]
        active[i] = (b[i] - a[i] > xtol) & ~hit
    else:
        raise NumericalError("root search did not converge")
    # the halved values are not f any more: pick by a fresh evaluation
    fa, fb = f(a, everything), f(b, everything)
    return np.where(np.abs(fa) <= np.abs(fb), a, b)


def newton_bracketed(
    f_and_slope: Callable[[np.ndarray, np.ndarray], tuple[np.ndarray, np.ndarray]],
    lower: np.ndarray,
    upper: np.ndarray,
    xtol: float = 1e-12,
    max_iter: int = 100,
) -> np.ndarray:
    """Roots in brackets by Newton's method kept inside the bracket, all at once.

    ``f_and_slope(x, index)`` returns ``(f, f')`` of bracket ``index[j]`` at ``x[j]``.
    A Newton step that leaves the current bracket is replaced by bisection; the
    bracket shrinks around the sign change after every evaluation.  A bracket is
    done when the Newton step is below ``xtol`` (quadratic convergence makes the
    remaining error far smaller) or the bracket is narrower than ``xtol``.
    """
    a = np.array(lower, dtype=float, copy=True)
    b = np.array(upper, dtype=float, copy=True)
    if a.size == 0:
        return a
    everything = np.arange(a.size)
    fa, _ = f_and_slope(a, everything)
    fb, _ = f_and_slope(b, everything)
    if np.any(fa * fb > 0):
        raise NumericalError("root search: a bracket does not change sign")
    sign_a = np.sign(fa)
    x = np.where(fa == 0, a, np.where(fb == 0, b, 0.5 * (a + b)))
    active = (fa != 0) & (fb != 0)
    for _ in range(max_iter):
        if not active.any():
            break
        i = np.flatnonzero(active)
        fx, slope = f_and_slope(x[i], i)
        same = np.sign(fx) == sign_a[i]
        a[i[same]] = x[i[same]]
        b[i[~same]] = x[i[~same]]
        with np.errstate(divide="ignore", invalid="ignore"):
            step = fx / slope
        trial = x[i] - step
        inside = np.isfinite(trial) & (trial > a[i]) & (trial < b[i])
        # a Newton step below xtol means x is a root to quadratic accuracy; at that point x
        # may coincide with a bracket end, so do not let "outside" trigger a bisection
        done = (fx == 0) | (np.abs(step) < xtol) | (b[i] - a[i] < xtol)
        x[i] = np.where(inside, trial, np.where(done, x[i], 0.5 * (a[i] + b[i])))
        active[i[done]] = False
    else:
        raise NumericalError("root search did not converge")
    return x
