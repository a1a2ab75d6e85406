"""Linear complementarity problems with a symmetric positive semi-definite matrix.

Each step of the contact integrator solves

    w = D z + b,   w >= 0,   z >= 0,   w^T z = 0                      (LCP)

with D = G W^-1 G^T the Delassus matrix of the constraints in play (symmetric,
positive semi-definite; definite when their rows of G are independent), z the
impulses and w the constrained normal velocities (Acary & Brogliato 2008,
"Numerical Methods for Nonsmooth Dynamical Systems", §10.4 and ch. 12).

The solver is block principal pivoting (Júdice & Pires 1994, Comput. Oper.
Res. 21:587) warm-started from a guess of the active set, with Murty's
least-index single pivot when the number of infeasible indices stops
decreasing (Murty 1974): finite for positive definite D.  When D is singular
(more constraints than independent rows) or pivoting stalls, the LCP is solved
as the equivalent non-negative least-squares problem ``min |A z + A y|, z >= 0``
with ``D = A^T A`` and ``b = D y`` (Lawson & Hanson 1974, ch. 23), which is
exact for any positive semi-definite D with b in its range.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from scipy.optimize import nnls

from twoball._common.errors import NumericalError

_MAX_PIVOTS = 200  # block pivots before the NNLS fallback (finite for SPD D; a guard)
_SLACK = 3  # Júdice-Pires: block pivots allowed without progress before Murty's rule


@dataclass(frozen=True)
class LCPSolution:
    """Solution of the LCP ``w = D z + b``, ``0 <= z ⊥ w >= 0``.

    Attributes
    ----------
    z : ndarray
        Impulses (>= 0).
    w : ndarray
        ``D z + b`` (>= 0 up to rounding).
    pivots : int
        Block pivots used (0: the warm start was the answer).
    method : str
        ``"pivoting"`` or ``"nnls"``.
    """

    z: np.ndarray
    w: np.ndarray
    pivots: int
    method: str


def _solve_block(D: np.ndarray, b: np.ndarray, active: np.ndarray) -> np.ndarray | None:
    """z with ``(D z + b)_A = 0`` on the active set A and ``z = 0`` off it; None if singular."""
    z = np.zeros(b.size)
    idx = np.flatnonzero(active)
    if idx.size == 0:
        return z
    block = D[idx[:, None], idx]
    diag = np.diag(block)
    if diag.min() <= 0.0:
        return None
    try:
        z_a = np.linalg.solve(block, -b[idx])
    except np.linalg.LinAlgError:
        return None
    # a near-singular block (dependent constraint rows) shows as a large residual
    # or huge impulses: leave it to NNLS (2-norms of the vectors, 1-norm of the block)
    if not np.all(np.isfinite(z_a)):
        return None
    residual = block @ z_a + b[idx]
    b_a = b[idx]
    column_sum = float(np.abs(block).sum(axis=0).max())
    if math.sqrt(residual @ residual) > 1e-9 * (
        math.sqrt(b_a @ b_a) + column_sum * math.sqrt(z_a @ z_a)
    ):
        return None
    z[idx] = z_a
    return z


def _nnls_lcp(D: np.ndarray, b: np.ndarray) -> np.ndarray:
    """The LCP as non-negative least squares on ``D = A^T A`` (D positive semi-definite)."""
    values, vectors = np.linalg.eigh(D)
    scale = max(float(values.max(initial=0.0)), 1e-300)
    keep = values > 1e-13 * scale
    A = np.sqrt(values[keep])[:, None] * vectors[:, keep].T  # D ~= A^T A
    y = vectors[:, keep] @ ((vectors[:, keep].T @ b) / values[keep])  # b ~= D y
    z, _ = nnls(A, -(A @ y), maxiter=50 * max(b.size, 1))
    return z


def solve_lcp(
    D: np.ndarray,
    b: np.ndarray,
    guess: np.ndarray | None = None,
    tolerance: float = 1e-12,
) -> LCPSolution:
    """Solve ``w = D z + b``, ``0 <= z ⊥ w >= 0`` for symmetric positive semi-definite D.

    Parameters
    ----------
    D : ndarray, shape (m, m)
        Delassus matrix (impulse to velocity), dimensionless.
    b : ndarray, shape (m,)
        Free normal velocities (plus the restitution term).
    guess : ndarray of bool, shape (m,), optional
        Indices expected to carry an impulse (warm start).
    tolerance : float
        Relative feasibility tolerance (of ``max |b|`` and of ``max |D| max z``).

    Returns
    -------
    LCPSolution
    """
    m = b.size
    if m == 0:
        return LCPSolution(np.zeros(0), np.zeros(0), 0, "pivoting")
    active = np.zeros(m, dtype=bool) if guess is None else np.asarray(guess, dtype=bool).copy()
    if not active.any() and np.all(b >= 0):
        return LCPSolution(np.zeros(m), b.copy(), 0, "pivoting")
    scale_b = float(np.max(np.abs(b)))
    best = m + 1
    slack = _SLACK
    for pivots in range(_MAX_PIVOTS):
        z = _solve_block(D, b, active)
        if z is None:
            break
        w = D @ z + b
        tol = tolerance * max(scale_b, float(np.max(np.abs(D))) * float(np.max(z, initial=0.0)))
        bad_z = active & (z < -tol)
        bad_w = ~active & (w < -tol)
        infeasible = bad_z | bad_w
        count = int(infeasible.sum())
        if count == 0:
            z = np.where(active, np.maximum(z, 0.0), 0.0)
            w = D @ z + b
            return LCPSolution(z, w, pivots, "pivoting")
        if count < best:
            best, slack = count, _SLACK
            active ^= infeasible  # Júdice-Pires block exchange
        elif slack > 0:
            slack -= 1
            active ^= infeasible
        else:
            first = int(np.flatnonzero(infeasible).min())  # Murty's least-index pivot
            active[first] = not active[first]
    z = _nnls_lcp(D, b)
    w = D @ z + b
    tol = 1e-8 * max(scale_b, float(np.max(np.abs(D))) * float(np.max(z, initial=0.0)))
    if np.min(w) < -tol or abs(float(w @ z)) > tol * max(float(np.sum(z)), 1.0):
        raise NumericalError(
            f"LCP of size {m}: no complementary solution (min w = {np.min(w):.3e}, "
            f"w.z = {float(w @ z):.3e})"
        )
    return LCPSolution(z, np.maximum(w, 0.0), _MAX_PIVOTS, "nnls")


__all__ = ["LCPSolution", "solve_lcp"]
