"""Eigenpairs of the generalized problem K phi = lambda M phi, and eigenvalue tables.

The discrete spectrum approximates the Laplace-Beltrami eigenvalues ``l (l + 1)``
of the unit sphere (multiplicity ``2 l + 1``; on the axisymmetric line each
appears once, with eigenfunction ``P_l(x)``), eq. (3.11).  Dimensionless.

All pairs below a cutoff are found by shift-invert Lanczos (ARPACK through
:func:`scipy.sparse.linalg.eigsh`, with a sparse LU of ``K - sigma M`` as the
inverse) on *slices* of the spectrum:

1. Sylvester's law of inertia counts the eigenvalues below any shift mu: the
   number of negative pivots of a symmetric (diagonally pivoted) factorisation of
   ``K - mu M``.  This gives the exact number of pairs wanted, in total and per
   slice, and so certifies that none is missed.
2. Slice boundaries are put at ``(l + 1)^2``, midway between the exact
   eigenvalues ``l (l + 1)`` and ``(l + 1)(l + 2)``: in a spectral gap on any
   reasonable mesh, where shift-invert Lanczos converges fastest and no cluster
   of nearly equal eigenvalues is split between two runs.  Consecutive gaps are
   merged into slices of about ``window`` eigenvalues.
3. Each slice [a, b] holding k eigenvalues is solved with the shift at its centre
   and k requested: the k eigenvalues nearest to the centre are exactly those in
   [a, b], which is checked.

The constant mode (lambda = 0, K singular) lies in the first slice, whose lower
end is slightly negative.  Small problems, and problems where most of the
spectrum is wanted, are solved densely.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
import scipy.linalg as sl
import scipy.sparse as sp
from scipy.sparse.linalg import LinearOperator, eigsh, splu
from twoball.modal.errors import NumericalError, ParameterError

FIRST_SHIFT = -1e-2  # below the constant mode lambda = 0
DENSE_LIMIT = 200  # dense eigensolver up to this many degrees of freedom
WINDOW = 40  # target number of eigenvalues per shift-invert slice
TOLERANCE = 1e-10  # ARPACK relative accuracy of the Ritz values
EXTRA = 6  # pairs requested beyond those wanted in a slice (ARPACK may skip near-ties)
MAX_DEFLATIONS = 12  # extra runs for copies of multiple eigenvalues missed by Lanczos
ORTHONORMALITY = 1e-9  # |Phi^T M Phi - I| above this triggers re-orthonormalisation


@dataclass(frozen=True)
class Eigenpairs:
    """M-orthonormal eigenpairs ``K Phi = M Phi diag(values)``, values ascending.

    Attributes
    ----------
    values : ndarray, shape (m,)
        Eigenvalues lambda (dimensionless; omega = sqrt(lambda)).
    vectors : ndarray, shape (n, m)
        Eigenvectors with ``Phi^T M Phi = I``.
    next_value : float or None
        Smallest eigenvalue above the cutoff, None when not computed.
    """

    values: np.ndarray
    vectors: np.ndarray
    next_value: float | None = None

    @property
    def omega(self) -> np.ndarray:
        """Undamped angular frequencies ``sqrt(max(lambda, 0))`` (dimensionless)."""
        return np.sqrt(np.clip(self.values, 0.0, None))

    def __len__(self) -> int:
        return int(self.values.size)


def _dense(K: sp.spmatrix, M: sp.spmatrix) -> tuple[np.ndarray, np.ndarray]:
    return sl.eigh(K.toarray(), M.toarray())


def inertia(K: sp.spmatrix, M: sp.spmatrix, shift: float) -> int:
    """Number of eigenvalues of ``K phi = lambda M phi`` below ``shift`` (Sylvester).

    Counts the negative pivots of ``P (K - shift M) P^T = L U`` computed with a
    symmetric ordering and diagonal pivots (U = D L^T), which has the inertia of
    ``K - shift M``.
    """
    matrix = sp.csc_matrix(K - shift * M)
    for attempt in range(3):
        try:
            lu = splu(
                matrix,
                permc_spec="MMD_AT_PLUS_A",
                diag_pivot_thresh=0.0,
                options={"SymmetricMode": True},
            )
        except RuntimeError:  # exactly singular: shift on an eigenvalue
            shift += 1e-9 * (1.0 + abs(shift)) * (attempt + 1)
            matrix = sp.csc_matrix(K - shift * M)
            continue
        if not np.array_equal(lu.perm_r, lu.perm_c):
            raise NumericalError("inertia: the factorisation was not symmetric")
        return int(np.count_nonzero(lu.U.diagonal() < 0.0))
    raise NumericalError(f"inertia: K - mu M is singular near mu = {shift:g}")


def _shift_invert(
    K: sp.csc_matrix,
    M: sp.csc_matrix,
    sigma: float,
    k: int,
    which: str = "LM",
    deflate: np.ndarray | None = None,
):
    """The k eigenpairs nearest to ``sigma`` (or just above it for which='LA'), ascending.

    ``deflate`` (M-orthonormal columns) removes known eigenvectors: the operator
    becomes ``P (K - sigma M)^{-1} M P`` with the M-orthogonal projector
    ``P = I - X X^T M``, whose spectrum near sigma is that of the remaining modes.
    """
    lu = splu(sp.csc_matrix(K - sigma * M))
    if deflate is None:
        solve = lu.solve
    else:
        X, MX = deflate, M @ deflate

        def solve(z: np.ndarray) -> np.ndarray:
            w = lu.solve(z - MX @ (X.T @ z))
            return w - X @ (MX.T @ w)

    operator = LinearOperator(K.shape, matvec=solve, dtype=float)
    start = np.random.default_rng(K.shape[0]).standard_normal(K.shape[0])  # reproducible
    if deflate is not None:
        start -= deflate @ (MX.T @ start)
    try:
        values, vectors = eigsh(
            K, k, M, sigma=sigma, which=which, OPinv=operator, tol=TOLERANCE, v0=start
        )
    except Exception as error:  # ArpackNoConvergence and friends
        raise NumericalError(f"eigensolver did not converge near {sigma:g}: {error}") from error
    order = np.argsort(values)
    return values[order], vectors[:, order]


def _slice(K: sp.csc_matrix, M: sp.csc_matrix, lower: float, higher: float, count: int):
    """The ``count`` eigenpairs in [lower, higher] (count known from the inertia).

    Lanczos with a single start vector can miss a copy of a multiple eigenvalue
    (exact multiplicities occur on symmetric meshes); missing pairs are then
    found by a second run with the pairs already found deflated.
    """
    sigma = 0.5 * (lower + higher)
    slack = 1e-9 * (1.0 + abs(higher))
    values, vectors = np.empty(0), np.empty((K.shape[0], 0))
    for _ in range(MAX_DEFLATIONS + 1):  # each run finds >= 1 copy of every multiple value
        missing = count - values.size
        if missing == 0:
            break
        deflate = m_orthonormalise(vectors, M) if values.size else None
        request = min(missing + EXTRA, K.shape[0] - values.size - 2)
        new_values, new_vectors = _shift_invert(K, M, sigma, request, deflate=deflate)
        inside = (new_values >= lower - slack) & (new_values <= higher + slack)
        if not np.any(inside):
            break
        values = np.concatenate([values, new_values[inside]])
        vectors = np.hstack([vectors, new_vectors[:, inside]])
    if values.size != count:
        raise NumericalError(
            f"eigensolver: slice [{lower:g}, {higher:g}] holds {count} eigenvalues "
            f"(inertia), found {values.size}"
        )
    order = np.argsort(values)
    return values[order], vectors[:, order]


def slice_bounds(upper: float, total: int, window: int = WINDOW) -> list[float]:
    """Slice boundaries in (FIRST_SHIFT, upper]: gap points ``(l + 1)^2`` merged to ~window.

    The number of eigenvalues below a gap g is estimated as ``total (g / upper)^p``
    with p fitted to the two ends (p = 1 on the sphere, 1/2 on the line); the
    estimate only sizes the slices, the counts used are exact.
    """
    exponent = math.log(max(total, 2)) / math.log(max(upper, 2.0))

    def estimate(g: float) -> float:
        return total * (max(g, 0.0) / upper) ** exponent

    bounds = [FIRST_SHIFT]
    for degree in range(int(math.sqrt(max(upper, 0.0))) + 1):
        gap = (degree + 1.0) ** 2
        if gap >= upper:
            break
        if estimate(gap) - estimate(bounds[-1]) >= window and total - estimate(gap) >= window / 2:
            bounds.append(gap)
    bounds.append(upper)
    return bounds


def m_orthonormalise(vectors: np.ndarray, M: sp.spmatrix) -> np.ndarray:
    """Return ``vectors`` with ``V^T M V = I`` (Cholesky correction if needed)."""
    gram = vectors.T @ (M @ vectors)
    if gram.size == 0 or np.abs(gram - np.eye(gram.shape[0])).max() <= ORTHONORMALITY:
        return vectors
    factor = sl.cholesky(gram, lower=False)  # gram = R^T R
    return sl.solve_triangular(factor, vectors.T, trans="T", lower=False).T


def eigenpairs(
    K: sp.spmatrix,
    M: sp.spmatrix,
    upper: float,
    window: int = WINDOW,
    next_value: bool = True,
) -> Eigenpairs:
    """All eigenpairs with ``lambda <= upper`` of ``K phi = lambda M phi`` (eq. (3.11)).

    Parameters
    ----------
    K, M : sparse matrices
        Symmetric stiffness (positive semi-definite) and mass (positive definite).
    upper : float
        Eigenvalue cutoff, e.g. ``omega_cut**2`` of the spectral filter.
    window : int
        Target number of eigenvalues per shift-invert slice.
    next_value : bool
        Also find the first eigenvalue above ``upper``.

    Returns
    -------
    Eigenpairs
        M-orthonormal pairs, ascending; their number equals the inertia count
        below ``upper`` (else :class:`NumericalError`).
    """
    n = K.shape[0]
    K, M = sp.csc_matrix(K), sp.csc_matrix(M)
    total = inertia(K, M, upper) if n > DENSE_LIMIT else n
    if total >= n // 2:  # most of the spectrum is wanted: dense is cheaper and complete
        values, vectors = _dense(K, M)
        keep = values <= upper
        above = values[~keep]
        after = float(above[0]) if above.size else None
        return Eigenpairs(values[keep], m_orthonormalise(vectors[:, keep], M), after)
    bounds = slice_bounds(upper, total, window)
    counts = [0] + [inertia(K, M, g) for g in bounds[1:-1]] + [total]
    kept_values, kept_vectors = [], []
    for lower, higher, below, up_to in zip(bounds, bounds[1:], counts, counts[1:], strict=False):
        k = up_to - below
        if k <= 0:
            continue
        values, vectors = _slice(K, M, lower, higher, k)
        kept_values.append(values)
        kept_vectors.append(vectors)
    values = np.concatenate(kept_values) if kept_values else np.empty(0)
    vectors = np.hstack(kept_vectors) if kept_vectors else np.empty((n, 0))
    if not (np.all(np.isfinite(values)) and np.all(np.isfinite(vectors))):
        raise NumericalError("eigensolver returned NaN or inf")
    after = float(_shift_invert(K, M, upper, 1, which="LA")[0][0]) if next_value else None
    return Eigenpairs(values, m_orthonormalise(vectors, M), after)


def lowest_eigenpairs(K: sp.spmatrix, M: sp.spmatrix, count: int) -> Eigenpairs:
    """The ``count`` smallest eigenpairs (the constant mode first), M-orthonormal.

    Checked by the inertia: all eigenvalues up to the largest one returned are
    present (missing copies of multiple eigenvalues are found by deflation).
    """
    n = K.shape[0]
    if isinstance(count, bool) or int(count) != count or count < 1:
        raise ParameterError("count", "an integer >= 1", count)
    if count > n:
        raise ParameterError("count", f"at most the number of unknowns ({n})", count)
    if n <= DENSE_LIMIT or count >= n - 1:
        values, vectors = _dense(K, M)
        return Eigenpairs(values[:count], m_orthonormalise(vectors[:, :count], M))
    K, M = sp.csc_matrix(K), sp.csc_matrix(M)
    values, vectors = _shift_invert(K, M, FIRST_SHIFT, int(count))
    for _ in range(MAX_DEFLATIONS):
        top = values[count - 1]
        present = inertia(K, M, top + 1e-9 * (1.0 + abs(top)))
        if present <= count:
            break
        deflate = m_orthonormalise(vectors, M)
        extra, extra_vectors = _shift_invert(K, M, FIRST_SHIFT, present - count, deflate=deflate)
        values = np.concatenate([values, extra])
        vectors = np.hstack([vectors, extra_vectors])
        complete = values.size >= present  # every eigenvalue up to ``top`` is in hand
        order = np.argsort(values)[:count]
        values, vectors = values[order], vectors[:, order]
        if complete:  # (a tie across the cut would otherwise be deflated for ever)
            break
    else:
        raise NumericalError("eigensolver: could not complete the lowest eigenpairs")
    return Eigenpairs(values, m_orthonormalise(vectors, M))


def sphere_degree(values: np.ndarray) -> np.ndarray:
    """Cluster degree l of eigenvalues: ``floor(omega)``.

    ``sqrt(l (l + 1)) ~ l + 1/2``, so this splits frequencies midway between clusters.
    """
    omega = np.sqrt(np.clip(np.asarray(values, dtype=float), 0.0, None))
    return np.clip(np.floor(omega), 0, None).astype(int)


def eigen_table(
    mesh: str = "sphere",
    level: int | None = None,
    elements: int | None = None,
    order: int = 1,
    count: int = 25,
    phi_a: float = 2.6,
    geometry: str = "isoparametric",
) -> list[dict[str, float | int]]:
    """The lowest ``count`` nonzero eigenvalues beside the exact ``l (l + 1)`` (eq. (3.11)).

    Parameters
    ----------
    mesh : {"sphere", "ring", "axisym"}
        Mesh kind (see :func:`twoball.fem_membrane.build.build_space`).
    level, elements : int, optional
        Sphere level (``--level``) or axisymmetric element count (``--elements``).
    order : {1, 2, 3, 4}
        Element order (``--order``).
    count : int
        Number of nonzero eigenvalues listed (``--count``), >= 1.
    phi_a : float
        Position of the ring / axisymmetric node at the kink (no effect on the
        exact eigenvalues).
    geometry : {"isoparametric", "exact"}
        Discrete sphere (see :func:`twoball.fem_membrane.build.build_space`).

    Returns
    -------
    list of dict
        One row per eigenvalue, the constant mode first: ``index``, ``l``,
        ``value``, ``exact`` = l (l + 1), ``relative_error`` (absolute for
        l = 0), ``multiplicity`` (computed eigenvalues in the cluster of l) and
        ``expected_multiplicity`` (2 l + 1 on the sphere, 1 on the line).
        Dimensionless.
    """
    from .build import build_space  # local: build imports the spaces, which import nothing here

    if isinstance(count, bool) or int(count) != count or count < 1:
        raise ParameterError("count", "an integer >= 1", count)
    space = build_space(
        mesh, level=level, elements=elements, order=order, phi_a=phi_a, geometry=geometry
    )
    axisymmetric = space.kind == "axisym"
    if axisymmetric:
        degrees = np.arange(count + 1)
        needed = count + 1
    else:
        last = int(math.isqrt(count))  # degree of the count-th nonzero eigenvalue
        needed = (last + 2) ** 2  # complete the last cluster and the next one
    needed = min(needed, space.dofs)
    pairs = lowest_eigenpairs(space.stiffness, space.mass, needed)
    values = pairs.values
    counts = np.ones(values.size, dtype=int)
    if not axisymmetric:
        counts = np.bincount(sphere_degree(values), minlength=values.size)
    rows = []
    for index in range(min(count + 1, values.size)):
        degree = int(degrees[index]) if axisymmetric else int(math.isqrt(index))
        exact = float(degree * (degree + 1))
        error = abs(values[index] - exact) / exact if exact > 0 else abs(values[index])
        rows.append(
            {
                "index": index,
                "l": degree,
                "value": float(values[index]),
                "exact": exact,
                "relative_error": float(error),
                "multiplicity": int(counts[degree]),
                "expected_multiplicity": 1 if axisymmetric else 2 * degree + 1,
            }
        )
    return rows
