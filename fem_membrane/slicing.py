"""Eigenpairs of ``K x = lambda M x`` by dense LAPACK or by spectrum slicing.

K is symmetric positive semi-definite (the stiffness of eq. (3.9)), M symmetric
positive definite (the mass).  Two methods, chosen by size:

Dense (up to :data:`DENSE_DOFS` unknowns when over 150 pairs are wanted, or most of the spectrum)
    LAPACK ``sygvx`` (:func:`scipy.linalg.eigh`, ``subset_by_index``) for the
    lowest pairs, ``sygvd`` for all of them.  Measured (one thread): 2.4 s CPU for
    the lowest 900 of 2562 unknowns (sphere P2 level 3); the cost grows as n^3,
    so at 10k unknowns it would take minutes.

Spectrum slicing (above)
    1. Sylvester's law of inertia: the number of eigenvalues below mu equals the
       number of negative pivots of a symmetric factorisation of ``K - mu M``
       (:func:`inertia`).  This counts the pairs wanted in total and in each slice,
       and so certifies that none is missed.
    2. Slice boundaries in spectral gaps: on the unit sphere the eigenvalues
       cluster near ``l (l + 1)``, so the points ``(l + 1)^2`` lie between
       clusters (on the axisymmetric line too).  Consecutive gaps are merged into
       slices of about ``window`` eigenvalues; no cluster is split.
    3. Each slice [a, b] holding k eigenvalues is solved by shift-invert Lanczos
       (ARPACK) with the shift at its centre and k (+6) requested, the k nearest
       being those in [a, b] (checked).  ONE sparse LU per slice, with a
       symmetric minimum-degree ordering (:func:`factorise`: half the fill of the
       default column ordering, so every Lanczos solve costs half), serves every
       run of the slice, including the deflated reruns that find copies of
       multiple eigenvalues a single start vector missed.

Measured alternatives that lost (sphere P2, one thread, CPU seconds for the 817 /
961 pairs below 961 at levels 3 / 4): block shift-invert Krylov with BLAS-3
Gram-Schmidt and inertia-certified adaptive slice ends took 7.3 / 41 s against
ARPACK slicing's 4.2 / 25 s (it needs about 4 basis vectors per converged pair,
and its Gram-Schmidt grows with the square of the slice's basis); slices of 100
or 200 pairs instead of 40 did not help ARPACK (27-28 s at level 4).  ARPACK's
tolerance 1e-8 instead of 1e-10 saved 6 % at level 4 (17.0 against 18.1 s) with
the same relative residuals of the pairs, 3e-11 at most.

Everything here is dimensionless and returns plain arrays; :mod:`twoball.fem_membrane.eigen` wraps
them into :class:`twoball.fem_membrane.eigen.Eigenpairs`.
"""

from __future__ import annotations

import math

import numpy as np
import scipy.linalg as sl
import scipy.sparse as sp
from scipy.sparse.linalg import LinearOperator, eigsh, splu

from twoball._common.errors import NumericalError
from twoball._common.monitor import Monitor, long_call

DENSE_DOFS = 3000  # dense LAPACK up to this many unknowns when over DENSE_COUNT pairs are wanted
DENSE_COUNT = 150
DENSE_ALWAYS = 200  # dense LAPACK for any count up to this many unknowns
#: From this many unknowns the dense solve is handed to the monitor as a long call
#: (:func:`twoball._common.monitor.long_call`; at the edge a child process): scipy's
#: LAPACK holds the GIL (~0.1 s at 500 unknowns, 5 s at 2562), which would freeze the
#: progress line and hold back Ctrl-C; the numbers are the same bits.
DENSE_CHILD = 500
DENSE_FRACTION = 0.4  # ... or when more than this fraction of the spectrum is wanted
FIRST_SHIFT = -1e-2  # below the constant mode lambda = 0
WINDOW = 40  # target number of eigenvalues per slice
ARPACK_TOLERANCE = 1e-8  # ARPACK accuracy of the Ritz values of (K - sigma M)^-1 M
RESIDUAL_LIMIT = 1e-6  # a returned pair with a larger relative residual: NumericalError
#: ARPACK's Lanczos basis per slice, as a multiple of the pairs asked for: 1.35 k
#: instead of scipy's 2 k + 1 cuts the orthogonalisation work; all 961 pairs of
#: sphere P2 level 4 in 15.5 s CPU instead of 18.2 s (same residuals, 3e-11).
NCV_FACTOR = 1.35
EXTRA = 6  # pairs requested beyond those wanted in a slice (ARPACK may skip near-ties)
MAX_DEFLATIONS = 12  # extra runs for copies of multiple eigenvalues missed by Lanczos
ORTHONORMALITY = 1e-9  # |Phi^T M Phi - I| above this triggers re-orthonormalisation
PIVOT_THRESHOLD = 0.1  # SuperLU keeps the diagonal pivot unless 10x smaller than the column


def factorise(matrix: sp.spmatrix):
    """Sparse LU of a symmetric matrix: symmetric minimum-degree ordering, diagonal pivots.

    Half the fill of the default column ordering on sphere meshes (measured at
    sphere P2 level 4: 0.87M against 2.0M nonzeros), so each solve is twice as
    fast.  It only generates Krylov subspaces; Rayleigh-Ritz uses K and M.
    """
    return splu(
        sp.csc_matrix(matrix),
        permc_spec="MMD_AT_PLUS_A",
        diag_pivot_thresh=PIVOT_THRESHOLD,
        options={"SymmetricMode": True},
    )


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


def relative_residuals(
    K: sp.spmatrix, M: sp.spmatrix, values: np.ndarray, vectors: np.ndarray
) -> np.ndarray:
    """``||K x - lambda M x|| / max(||K x||, ||M x||)`` per pair (2-norms).

    Equal to ``||K x - lambda M x|| / ||K x||`` for lambda >= 1 (where
    ``||K x|| ~ lambda ||M x||``) and still defined for the constant mode
    (lambda = 0, K x = 0).
    """
    KX, MX = K @ vectors, M @ vectors
    return _residuals(KX, MX, values)


def _residuals(KX: np.ndarray, MX: np.ndarray, values: np.ndarray) -> np.ndarray:
    scale = np.maximum(np.linalg.norm(KX, axis=0), np.linalg.norm(MX, axis=0))
    residual = np.linalg.norm(KX - MX * values, axis=0)
    return residual / np.maximum(scale, np.finfo(float).tiny)


def orthonormality_error(M: sp.spmatrix, vectors: np.ndarray) -> float:
    """``max |X^T M X - I|`` (0 for no vectors)."""
    if vectors.shape[1] == 0:
        return 0.0
    gram = vectors.T @ (M @ vectors)
    return float(np.abs(gram - np.eye(gram.shape[0])).max())


def dense_pairs(
    K: sp.spmatrix, M: sp.spmatrix, count: int | None = None, monitor: Monitor | None = None
) -> tuple[np.ndarray, np.ndarray]:
    """The lowest ``count`` pairs (default all), ascending, M-orthonormal, by dense LAPACK.

    Solved as ``M x = nu (K + M) x`` with ``nu = 1 / (lambda + 1)`` (K + M is
    positive definite, K is singular): the lowest lambda are the largest nu,
    which LAPACK finds to an error of about eps times the largest nu, so lambda
    keeps a relative accuracy of about eps (lambda + 1) -- the direct ``K x =
    lambda M x`` would lose eps lambda_max / lambda, measured 1e-11 on
    axisymmetric P4 (lambda_max ~ 1e8).  ``sygvx`` (``subset_by_index``) for part
    of the spectrum, ``sygvd`` for more than half.

    From :data:`DENSE_CHILD` unknowns on the LAPACK call is handed to ``monitor``
    as a long call (:func:`~twoball._common.monitor.long_call`: at the edge it runs
    where the progress line moves, an interrupt acts at once and the time limit is
    watched, with the same numbers); without a monitor it runs here.
    """
    n = K.shape[0]
    count = n if count is None else int(min(max(count, 1), n))
    if n >= DENSE_CHILD:  # LAPACK through scipy holds the GIL: a child keeps us responsive
        doing = f"dense eigenpairs of {n} unknowns (LAPACK)"
        nu, vectors = long_call(monitor, _dense_lapack, K, M, count, doing=doing)
    else:
        nu, vectors = _dense_lapack(K, M, count)
    nu, vectors = nu[::-1], vectors[:, ::-1]  # ascending lambda
    if np.any(nu <= 0.0):
        raise NumericalError("dense eigensolver: K + M is not positive definite")
    return 1.0 / nu - 1.0, vectors / np.sqrt(nu)  # x^T (K + M) x = 1 -> x^T M x = 1


def _dense_lapack(K: sp.spmatrix, M: sp.spmatrix, count: int) -> tuple[np.ndarray, np.ndarray]:
    """The largest ``count`` pairs of ``M x = nu (K + M) x``, nu ascending (LAPACK sygvd/sygvx)."""
    n = K.shape[0]
    Md = sp.csr_matrix(M).toarray()
    Ad = sp.csr_matrix(K).toarray() + Md
    if count > n // 2:
        nu, vectors = sl.eigh(Md, Ad, driver="gvd")
        return nu[n - count :], vectors[:, n - count :]
    return sl.eigh(Md, Ad, subset_by_index=[n - count, n - 1], driver="gvx")


def slice_bounds(upper: float, total: int, window: int = WINDOW) -> list[float]:
    """Slice boundaries in (FIRST_SHIFT, upper]: gap points ``(l + 1)^2`` merged to ~window.

    The number of eigenvalues below a gap g is estimated as ``total (g / upper)^p``
    with p fitted to the two ends (p = 1 on the sphere, 1/2 on the line); the
    estimate only sizes the slices, the counts used are exact (inertia).
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


def shift_invert(
    K: sp.csc_matrix,
    M: sp.csc_matrix,
    sigma: float,
    k: int,
    which: str = "LM",
    deflate: np.ndarray | None = None,
    factor=None,
) -> tuple[np.ndarray, np.ndarray]:
    """The k eigenpairs nearest to ``sigma`` (or just above it for which='LA'), ascending.

    ARPACK (:func:`scipy.sparse.linalg.eigsh`) with the inverse from ``factor``
    (default :func:`factorise` of ``K - sigma M``).  ``deflate`` (M-orthonormal
    columns) removes known eigenvectors: the operator becomes
    ``P (K - sigma M)^{-1} M P`` with ``P = I - X X^T M``.
    """
    lu = factorise(K - sigma * M) if factor is None else factor
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
            K,
            k,
            M,
            sigma=sigma,
            which=which,
            OPinv=operator,
            tol=ARPACK_TOLERANCE,
            v0=start,
            ncv=min(K.shape[0] - 1, max(int(NCV_FACTOR * k) + 1, k + 20)),
        )
    except Exception as error:  # ArpackNoConvergence and friends
        raise NumericalError(f"eigensolver did not converge near {sigma:g}: {error}") from error
    order = np.argsort(values)
    return values[order], vectors[:, order]


def slice_pairs(
    K: sp.csc_matrix, M: sp.csc_matrix, lower: float, higher: float, count: int
) -> tuple[np.ndarray, np.ndarray]:
    """The ``count`` eigenpairs in [lower, higher] (count known from the inertia).

    One factorisation at the slice centre serves every ARPACK run of the slice.
    Lanczos with a single start vector can miss a copy of a multiple eigenvalue
    (exact multiplicities occur on symmetric meshes); missing pairs are then found
    by another run with the pairs already found deflated.
    """
    sigma = 0.5 * (lower + higher)
    slack = 1e-9 * (1.0 + abs(higher))
    factor = factorise(K - sigma * M)
    values, vectors = np.empty(0), np.empty((K.shape[0], 0))
    for _ in range(MAX_DEFLATIONS + 1):  # each run finds >= 1 copy of every multiple value
        missing = count - values.size
        if missing == 0:
            break
        deflate = m_orthonormal(vectors, M) if values.size else None
        request = min(missing + EXTRA, K.shape[0] - values.size - 2)
        new_values, new_vectors = shift_invert(K, M, sigma, request, deflate=deflate, factor=factor)
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


def m_orthonormal(vectors: np.ndarray, M: sp.spmatrix) -> np.ndarray:
    """Return ``vectors`` with ``V^T M V = I`` (Cholesky correction if needed)."""
    gram = vectors.T @ (M @ vectors)
    if gram.size == 0 or np.abs(gram - np.eye(gram.shape[0])).max() <= ORTHONORMALITY:
        return vectors
    factor = sl.cholesky(gram, lower=False)  # gram = R^T R
    return sl.solve_triangular(factor, vectors.T, trans="T", lower=False).T


def sliced_pairs(
    K: sp.spmatrix,
    M: sp.spmatrix,
    upper: float,
    window: int = WINDOW,
    monitor: Monitor | None = None,
) -> tuple[np.ndarray, np.ndarray]:
    """All pairs with ``lambda <= upper`` by spectrum slicing, ascending.

    Their number equals the inertia count below ``upper``, slice by slice (else
    NumericalError).  ``monitor`` (:class:`~twoball._common.monitor.Monitor`) is
    told before the count and every slice; it may stop the work by raising.
    """
    n = K.shape[0]
    K, M = sp.csc_matrix(K), sp.csc_matrix(M)
    if monitor is not None:
        monitor(f"eigenpairs of {n} unknowns: counting them (inertia)")
    total = inertia(K, M, upper)
    bounds = slice_bounds(upper, total, window)
    counts = [0] + [inertia(K, M, g) for g in bounds[1:-1]] + [total]
    values: list[np.ndarray] = []
    vectors: list[np.ndarray] = []
    pieces = len(bounds) - 1
    for k, (lower, higher, below, up_to) in enumerate(
        zip(bounds, bounds[1:], counts, counts[1:], strict=False), start=1
    ):
        if monitor is not None:
            monitor(f"eigenpairs of {n} unknowns: slice {k} of {pieces} (pairs {up_to} of {total})")
        if up_to > below:
            found, shapes = slice_pairs(K, M, lower, higher, up_to - below)
            values.append(found)
            vectors.append(shapes)
    if not values:
        return np.empty(0), np.empty((n, 0))
    return np.concatenate(values), np.hstack(vectors)


def count_bound(K: sp.spmatrix, M: sp.spmatrix, count: int) -> float | None:
    """A gap point ``(l + 1)^2`` with at least ``count`` eigenvalues below it, the smallest.

    Found by doubling and bisection over l with :func:`inertia`; None when even
    ``lambda = 1e12`` has fewer below it (then the dense path is the only one).
    """
    low, high = 0, 1
    while inertia(K, M, float(high + 1) ** 2) < count:
        low, high = high, 2 * high
        if high > 1e6:
            return None
    while high - low > 1:
        middle = (low + high) // 2
        if inertia(K, M, float(middle + 1) ** 2) >= count:
            high = middle
        else:
            low = middle
    if low == 0 and inertia(K, M, 1.0) >= count:
        high = 0
    return float(high + 1) ** 2


def use_dense(n: int, wanted: int) -> bool:
    """Dense LAPACK for tiny problems, many pairs of small ones, or most of the spectrum.

    Measured (one thread, sphere P2 level 3, 2562 unknowns): dense 2.4 s CPU for
    any count, slicing 4.2 s for 817 pairs but a fraction of a second for 50.
    """
    if n <= DENSE_ALWAYS or wanted > DENSE_FRACTION * n:
        return True
    return n <= DENSE_DOFS and wanted > DENSE_COUNT
