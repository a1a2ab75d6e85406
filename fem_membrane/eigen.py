"""Eigenpairs of the generalized problem K phi = lambda M phi, and eigenvalue tables.

The discrete spectrum approximates the Laplace-Beltrami eigenvalues ``l (l + 1)``
of the unit sphere (multiplicity ``2 l + 1``; on the axisymmetric line each
appears once, with eigenfunction ``P_l(x)``), eq. (3.11).  Dimensionless.

The pairs come from :mod:`twoball.fem_membrane.slicing`: dense LAPACK for small
problems (or most of the spectrum), spectrum slicing by shift-invert Lanczos with
inertia counts above; every result carries its largest relative residual
and its M-orthonormality error.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np
import scipy.sparse as sp

from twoball._common.errors import NumericalError, ParameterError
from twoball._common.monitor import Monitor
from twoball.fem_membrane.slicing import (
    ORTHONORMALITY,
    RESIDUAL_LIMIT,
    WINDOW,
    count_bound,
    dense_pairs,
    inertia,
    orthonormality_error,
    relative_residuals,
    shift_invert,
    sliced_pairs,
    use_dense,
)
from twoball.fem_membrane.slicing import m_orthonormal as m_orthonormalise

__all__ = [
    "Eigenpairs",
    "eigen_table",
    "eigenpairs",
    "inertia",
    "lowest_eigenpairs",
    "m_orthonormalise",
    "sphere_degree",
]


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
    max_residual : float or None
        Largest relative residual ``||K x - lambda M x|| / max(||K x||, ||M x||)``
        (see :func:`twoball.fem_membrane.slicing.relative_residuals`), None when
        not computed.
    orthonormality : float or None
        ``max |Phi^T M Phi - I|``, None when not computed.
    method : str
        ``dense``, ``slicing`` or ``ritz`` (Krylov Ritz vectors).
    """

    values: np.ndarray
    vectors: np.ndarray
    next_value: float | None = None
    max_residual: float | None = None
    orthonormality: float | None = None
    method: str = ""

    @property
    def omega(self) -> np.ndarray:
        """Undamped angular frequencies ``sqrt(max(lambda, 0))`` (dimensionless)."""
        return np.sqrt(np.clip(self.values, 0.0, None))

    def __len__(self) -> int:
        return int(self.values.size)


def _next_above(K: sp.csc_matrix, M: sp.csc_matrix, upper: float) -> float:
    """The smallest eigenvalue above ``upper`` (shift-invert Lanczos, one pair)."""
    return float(shift_invert(K, M, upper, 1, which="LA")[0].min())


def _checked(
    K: sp.spmatrix,
    M: sp.spmatrix,
    values: np.ndarray,
    vectors: np.ndarray,
    method: str,
    next_value: float | None = None,
) -> Eigenpairs:
    """Eigenpairs with their residuals and M-orthonormality measured (NaN: NumericalError)."""
    if not (np.all(np.isfinite(values)) and np.all(np.isfinite(vectors))):
        raise NumericalError("eigensolver returned NaN or inf")
    error = orthonormality_error(M, vectors)
    if error > ORTHONORMALITY:
        vectors = m_orthonormalise(vectors, M)
        error = orthonormality_error(M, vectors)
    residual = relative_residuals(K, M, values, vectors)
    if residual.size and residual.max() > RESIDUAL_LIMIT:
        raise NumericalError(
            f"eigensolver: relative residual {residual.max():.1e} above {RESIDUAL_LIMIT:g}"
        )
    return Eigenpairs(
        values,
        vectors,
        next_value,
        max_residual=float(residual.max(initial=0.0)),
        orthonormality=error,
        method=method,
    )


def eigenpairs(
    K: sp.spmatrix,
    M: sp.spmatrix,
    upper: float,
    window: int = WINDOW,
    next_value: bool = True,
    monitor: Monitor | None = None,
) -> Eigenpairs:
    """All eigenpairs with ``lambda <= upper`` of ``K phi = lambda M phi`` (eq. (3.11)).

    Parameters
    ----------
    K, M : sparse matrices
        Symmetric stiffness (positive semi-definite) and mass (positive definite).
    upper : float
        Eigenvalue cutoff, e.g. ``omega_cut**2`` of the spectral filter.
    window : int
        Target number of eigenvalues per slice (spectrum slicing).
    next_value : bool
        Also find the first eigenvalue above ``upper``.
    monitor : Monitor, optional
        Told as the pairs are computed (:class:`~twoball._common.monitor.Monitor`;
        it may stop the work by raising); a dense solve is its long call.

    Returns
    -------
    Eigenpairs
        M-orthonormal pairs, ascending; their number equals the inertia count
        below ``upper`` (else :class:`NumericalError`); residuals and
        M-orthonormality measured.
    """
    n = K.shape[0]
    K, M = sp.csc_matrix(K), sp.csc_matrix(M)
    total = inertia(K, M, upper)
    if use_dense(n, total):
        values, vectors = dense_pairs(K, M, min(total + 1, n), monitor)
        keep = values <= upper
        above = values[~keep]
        after = float(above[0]) if above.size else None
        return _checked(K, M, values[keep], vectors[:, keep], "dense", after)
    values, vectors = sliced_pairs(K, M, upper, window, monitor)
    after = _next_above(K, M, upper) if next_value and total < n else None
    return _checked(K, M, values, vectors, "slicing", after)


def lowest_eigenpairs(
    K: sp.spmatrix, M: sp.spmatrix, count: int, monitor: Monitor | None = None
) -> Eigenpairs:
    """The ``count`` smallest eigenpairs (the constant mode first), M-orthonormal.

    Any ``count`` from 1 to the number of unknowns: dense LAPACK for small
    problems or large counts, else every pair below the smallest spectral gap
    ``(l + 1)^2`` holding ``count`` of them (inertia), by spectrum slicing, of
    which the lowest ``count`` are returned.  ``monitor`` as in :func:`eigenpairs`.
    """
    n = K.shape[0]
    if isinstance(count, bool) or int(count) != count or count < 1:
        raise ParameterError("count", "an integer >= 1", count)
    if count > n:
        raise ParameterError("count", f"at most the number of unknowns ({n})", count)
    count = int(count)
    K, M = sp.csc_matrix(K), sp.csc_matrix(M)
    bound = None if use_dense(n, count) else count_bound(K, M, count)
    if bound is None or use_dense(n, inertia(K, M, bound)):
        values, vectors = dense_pairs(K, M, count, monitor)
        return _checked(K, M, values, vectors, "dense")
    values, vectors = sliced_pairs(K, M, bound, monitor=monitor)
    return _checked(K, M, values[:count], vectors[:, :count], "slicing")


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
    membrane: Any = None,
    monitor: Monitor | None = None,
) -> list[dict[str, float | int]]:
    """The lowest ``count`` nonzero eigenvalues beside the exact ``l (l + 1)`` (eq. (3.11)).

    With the pressurised ``membrane`` the eigenvalues of ``K - 2 M`` beside
    ``(l - 1)(l + 2)`` (:mod:`twoball.modal.membrane`): the Laplacian's pairs,
    certified by inertia counts, are exactly its pairs with ``lambda_h - 2``
    (the residuals are measured with ``K - 2 M`` itself).

    Parameters
    ----------
    mesh : {"sphere", "ring", "axisym"}
        Mesh kind (see :func:`twoball.fem_membrane.build.build_space`).
    level, elements : int, optional
        Sphere level or axisymmetric element count.
    order : {1, 2, 3, 4}
        Element order.
    count : int
        Number of nonzero eigenvalues listed, >= 1.
    phi_a : float
        Position of the ring / axisymmetric node at the kink (no effect on the
        exact eigenvalues).
    geometry : {"isoparametric", "exact"}
        Discrete sphere (see :func:`twoball.fem_membrane.build.build_space`).
    membrane : Membrane, optional
        The membrane operator (None: the paper's).
    monitor : Monitor, optional
        Told as the pairs are computed (:func:`lowest_eigenpairs`).

    Returns
    -------
    list of dict
        One row per eigenvalue, the constant mode first: ``index``, ``l``,
        ``value``, ``exact`` = l (l + 1) or (l - 1)(l + 2), ``relative_error``
        (absolute where the exact value is 0), ``multiplicity`` (computed
        eigenvalues in the cluster of l) and
        ``expected_multiplicity`` (2 l + 1 on the sphere, 1 on the line),
        ``residual`` = ``||K x - lambda M x|| / max(||K x||, ||M x||)`` of the
        pair and ``orthonormality`` = ``max |Phi^T M Phi - I|`` over all pairs
        computed.  Dimensionless.
    """
    from twoball.fem_membrane.build import (
        build_space,  # local: build imports the spaces, which import nothing here
    )

    if isinstance(count, bool) or int(count) != count or count < 1:
        raise ParameterError("count", "an integer >= 1", count)
    space = build_space(
        mesh, level=level, elements=elements, order=order, phi_a=phi_a, geometry=geometry
    )
    if count > space.dofs:
        raise ParameterError("count", f"at most the number of unknowns ({space.dofs})", count)
    axisymmetric = space.kind == "axisym"
    if axisymmetric:
        degrees = np.arange(count + 1)
        needed = count + 1
    else:
        last = int(math.isqrt(count))  # degree of the count-th nonzero eigenvalue
        needed = (last + 2) ** 2  # complete the last cluster and the next one
    needed = min(needed, space.dofs)
    pairs = lowest_eigenpairs(space.stiffness, space.mass, needed, monitor)
    pressurised = membrane is not None and membrane.pressurised
    values = membrane.eigenvalues(pairs.values) if pressurised else pairs.values
    listed = min(count + 1, values.size)
    residuals = relative_residuals(
        space.operator(membrane), space.mass, values[:listed], pairs.vectors[:, :listed]
    )
    counts = np.ones(values.size, dtype=int)
    if not axisymmetric:
        counts = np.bincount(sphere_degree(pairs.values), minlength=values.size)
    rows = []
    for index in range(listed):
        degree = int(degrees[index]) if axisymmetric else int(math.isqrt(index))
        if pressurised:
            exact = float(membrane.legendre(degree))
        else:
            exact = float(degree * (degree + 1))
        error = abs(values[index] - exact) / abs(exact) if exact != 0 else abs(values[index])
        rows.append(
            {
                "index": index,
                "l": degree,
                "value": float(values[index]),
                "exact": exact,
                "relative_error": float(error),
                "multiplicity": int(counts[degree]),
                "expected_multiplicity": 1 if axisymmetric else 2 * degree + 1,
                "residual": float(residuals[index]),
                "orthonormality": float(pairs.orthonormality),
            }
        )
    return rows
