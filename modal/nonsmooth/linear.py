"""Matrices of the contact problem: diagonal, dense or sparse, behind one interface.

The modal backend has diagonal M, C, K (one number per mode); finite elements
have sparse ones.  :class:`Operator` wraps either so the integrator can multiply
by a matrix and factorise the combination ``W = a M + b C + c K`` of the
theta-method (Jean 1999, eq. (20); Acary 2016, eq. (33)) without knowing which.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np
import scipy.linalg as sla
import scipy.sparse as sp
import scipy.sparse.linalg as spla

from twoball._common.errors import ParameterError

MatrixLike = np.ndarray | sp.spmatrix | sp.sparray
"""A 1-D array (the diagonal), a 2-D array, or a scipy sparse matrix."""


@dataclass(frozen=True)
class Operator:
    """A square matrix stored as its diagonal, densely or sparsely.

    Parameters
    ----------
    diagonal : ndarray or None
        The diagonal when the matrix is diagonal (``kind == "diagonal"``).
    dense : ndarray or None
        The full matrix (``kind == "dense"``).
    sparse : scipy.sparse.csr_matrix or None
        The full matrix (``kind == "sparse"``).
    """

    diagonal: np.ndarray | None = None
    dense: np.ndarray | None = None
    sparse: sp.csr_matrix | None = None

    @property
    def kind(self) -> str:
        """``"diagonal"``, ``"dense"`` or ``"sparse"``."""
        if self.diagonal is not None:
            return "diagonal"
        return "dense" if self.dense is not None else "sparse"

    @property
    def size(self) -> int:
        """Number of rows (= columns)."""
        if self.diagonal is not None:
            return int(self.diagonal.size)
        return int((self.dense if self.dense is not None else self.sparse).shape[0])

    def matvec(self, x: np.ndarray) -> np.ndarray:
        """The product with a vector (or the columns of a 2-D array)."""
        if self.diagonal is not None:
            return self.diagonal * x if x.ndim == 1 else self.diagonal[:, None] * x
        if self.dense is not None:
            return self.dense @ x
        return np.asarray(self.sparse @ x)

    def quadratic(self, x: np.ndarray) -> float:
        """``x^T A x``."""
        return float(x @ self.matvec(x))

    def to_dense(self) -> np.ndarray:
        """The full matrix as a dense array (for small problems and tests)."""
        if self.diagonal is not None:
            return np.diag(self.diagonal)
        return self.dense.copy() if self.dense is not None else self.sparse.toarray()

    def is_zero(self) -> bool:
        """True when every entry is 0."""
        if self.diagonal is not None:
            return not np.any(self.diagonal)
        if self.dense is not None:
            return not np.any(self.dense)
        return self.sparse.nnz == 0 or not np.any(self.sparse.data)


def as_operator(name: str, matrix: MatrixLike | None, size: int | None = None) -> Operator:
    """Wrap ``matrix`` (None: zero) as an :class:`Operator`, refusing bad shapes and values.

    Parameters
    ----------
    name : str
        Parameter name for :class:`~twoball._common.errors.ParameterError`.
    matrix : array_like, sparse matrix or None
        1-D: the diagonal; 2-D: the full matrix; sparse: kept sparse (CSR).
    size : int, optional
        Required number of rows.
    """
    if matrix is None:
        if size is None:
            raise ParameterError(name, "a matrix (its size is not known otherwise)", None)
        return Operator(diagonal=np.zeros(size))
    if sp.issparse(matrix):
        out = sp.csr_matrix(matrix, dtype=float)
        if out.shape[0] != out.shape[1]:
            raise ParameterError(name, "a square matrix", f"shape {out.shape}")
        values = out.data
        op = Operator(sparse=out)
    else:
        array = np.asarray(matrix, dtype=float)
        if array.ndim == 1:
            op = Operator(diagonal=array.copy())
        elif array.ndim == 2 and array.shape[0] == array.shape[1]:
            op = Operator(dense=array.copy())
        else:
            raise ParameterError(name, "a 1-D diagonal or a square 2-D matrix", f"{array.shape}")
        values = array
    if not np.all(np.isfinite(values)):
        raise ParameterError(name, "finite entries", "NaN or inf")
    if size is not None and op.size != size:
        raise ParameterError(name, f"a matrix of size {size}", f"size {op.size}")
    return op


def combine(operators: Sequence[Operator], weights: Sequence[float]) -> Operator:
    """``sum_k w_k A_k`` in the simplest storage that holds it (diagonal < dense < sparse)."""
    kinds = {op.kind for op, w in zip(operators, weights, strict=True) if w != 0.0}
    if kinds <= {"diagonal"}:
        diag = sum(
            (w * op.diagonal for op, w in zip(operators, weights, strict=True) if w != 0.0),
            np.zeros(operators[0].size),
        )
        return Operator(diagonal=diag)
    if "sparse" in kinds:
        total = sp.csr_matrix((operators[0].size,) * 2)
        for op, w in zip(operators, weights, strict=True):
            if w == 0.0:
                continue
            if op.kind == "sparse":
                total = total + w * op.sparse
            elif op.kind == "diagonal":
                total = total + w * sp.diags(op.diagonal)
            else:
                total = total + w * sp.csr_matrix(op.dense)
        return Operator(sparse=sp.csr_matrix(total))
    total = np.zeros((operators[0].size,) * 2)
    for op, w in zip(operators, weights, strict=True):
        if w != 0.0:
            total += w * op.to_dense()
    return Operator(dense=total)


class Factorised:
    """A factorised symmetric positive definite :class:`Operator`: ``solve(b) = A^-1 b``.

    Diagonal: division; dense: Cholesky (LAPACK ``potrf``); sparse: SuperLU.
    """

    def __init__(self, op: Operator) -> None:
        self.kind = op.kind
        if op.kind == "diagonal":
            if np.any(op.diagonal <= 0):
                raise ParameterError("W", "positive definite (check M > 0)", "a diagonal <= 0")
            self._diag = op.diagonal
        elif op.kind == "dense":
            try:
                self._cho = sla.cho_factor(op.dense)
            except np.linalg.LinAlgError:
                raise ParameterError("W", "positive definite (check M > 0)", "not") from None
        else:
            self._lu = spla.splu(op.sparse.tocsc())

    def solve(self, b: np.ndarray) -> np.ndarray:
        """``A^-1 b`` for a vector or a 2-D array of columns."""
        if self.kind == "diagonal":
            return b / self._diag if b.ndim == 1 else b / self._diag[:, None]
        if self.kind == "dense":
            return sla.cho_solve(self._cho, b)
        return self._lu.solve(np.asarray(b, dtype=float))


def as_rows(name: str, matrix: np.ndarray | sp.spmatrix, columns: int) -> np.ndarray:
    """Constraint matrix G (rows: constraints) as a dense array with ``columns`` columns.

    G is kept dense: it has one row per contact point (tens to a few hundred) and
    every Delassus product ``G W^-1 G^T`` is dense anyway.
    """
    array = matrix.toarray() if sp.issparse(matrix) else np.asarray(matrix, dtype=float)
    if array.ndim == 1:
        array = array[None, :]
    if array.ndim != 2 or array.shape[1] != columns:
        raise ParameterError(name, f"a 2-D matrix with {columns} columns", f"{array.shape}")
    if not np.all(np.isfinite(array)):
        raise ParameterError(name, "finite entries", "NaN or inf")
    return np.ascontiguousarray(array, dtype=float)


__all__ = ["Factorised", "MatrixLike", "Operator", "as_operator", "as_rows", "combine"]
