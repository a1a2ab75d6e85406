"""The linear contact problem handed to the nonsmooth integrator (dimensionless).

    M q'' + C q' + K q = f + G^T lambda,                                  (N1)
    g = G q + g0 >= 0,   lambda >= 0,   lambda . g = 0                    (N2)
    U^+ = -e U^-  at an impact of a constraint (Newton's law),            (N3)

with U = G q' the normal velocities.  M is symmetric positive definite, C and K
symmetric positive semi-definite (K may be singular: free rigid motions), f a
constant load (gravity) and e in [0, 1] a restitution coefficient per
constraint (Moreau 1988; Acary & Brogliato 2008, §3.2).

The mechanical energy is ``E = 1/2 q'^T M q' + 1/2 q^T K q - f^T q``; the
integrator books its changes into work of the damping, of the contact impulses
in a step, and of the impacts (:mod:`twoball.modal.nonsmooth.moreau_jean`).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from twoball._common.errors import ParameterError
from twoball.modal.nonsmooth.linear import MatrixLike, Operator, as_operator, as_rows


@dataclass(frozen=True, eq=False)
class ContactProblem:
    """Matrices, load and unilateral constraints of (N1)-(N3), in any consistent units.

    Build it with :meth:`create`, which checks shapes and values.

    Attributes
    ----------
    mass, damping, stiffness : Operator
        M, C, K (diagonal, dense or sparse).
    load : ndarray, shape (n,)
        Constant generalised force f.
    constraints : ndarray, shape (m, n)
        G: row i gives the gap of constraint i as ``G[i] @ q + g0[i]``.
    offset : ndarray, shape (m,)
        g0.
    restitution : ndarray, shape (m,)
        Newton's coefficient e_i in [0, 1] of each constraint.
    """

    mass: Operator
    damping: Operator
    stiffness: Operator
    load: np.ndarray
    constraints: np.ndarray
    offset: np.ndarray
    restitution: np.ndarray

    @classmethod
    def create(
        cls,
        M: MatrixLike,
        C: MatrixLike | None,
        K: MatrixLike,
        f: np.ndarray | None,
        G: MatrixLike,
        g0: np.ndarray,
        restitution: float | np.ndarray = 0.0,
    ) -> ContactProblem:
        """Check and bundle the problem (N1)-(N3).

        Parameters
        ----------
        M : array_like or sparse, shape (n,) or (n, n)
            Mass matrix (a 1-D array is its diagonal); symmetric positive definite.
        C : array_like, sparse or None
            Damping matrix (None: undamped).
        K : array_like or sparse
            Stiffness matrix.
        f : array_like, shape (n,), or None
            Constant load (None: zero).
        G : array_like or sparse, shape (m, n)
            Constraint rows.
        g0 : array_like, shape (m,)
            Constraint offsets.
        restitution : float or array_like, shape (m,)
            Newton's restitution coefficients in [0, 1].

        Raises
        ------
        ParameterError
            For wrong shapes, non-finite values, a mass that is not positive
            definite on its diagonal, or a restitution outside [0, 1].
        """
        mass = as_operator("M", M)
        n = mass.size
        damping = as_operator("C", C, n)
        stiffness = as_operator("K", K, n)
        diag = mass.diagonal if mass.kind == "diagonal" else mass.to_dense().diagonal()
        if mass.kind != "sparse" and np.any(diag <= 0):
            raise ParameterError("M", "positive definite (diagonal > 0)", float(diag.min()))
        load = np.zeros(n) if f is None else np.asarray(f, dtype=float).reshape(-1)
        if load.shape != (n,) or not np.all(np.isfinite(load)):
            raise ParameterError("f", f"a finite vector of length {n}", load.shape)
        rows = as_rows("G", G, n)
        offset = np.asarray(g0, dtype=float).reshape(-1)
        if offset.shape != (rows.shape[0],) or not np.all(np.isfinite(offset)):
            raise ParameterError("g0", f"a finite vector of length {rows.shape[0]}", offset.shape)
        e = np.broadcast_to(np.asarray(restitution, dtype=float), offset.shape).copy()
        if not np.all((e >= 0.0) & (e <= 1.0)):
            raise ParameterError("restitution", "in [0, 1] for every constraint", e.tolist())
        return cls(mass, damping, stiffness, load, rows, offset, e)

    @property
    def dofs(self) -> int:
        """Number of generalised coordinates n."""
        return self.mass.size

    @property
    def count(self) -> int:
        """Number of unilateral constraints m."""
        return int(self.offset.size)

    def gap(self, q: np.ndarray) -> np.ndarray:
        """Gaps ``G q + g0`` (N2)."""
        return self.constraints @ q + self.offset

    def normal_velocity(self, v: np.ndarray) -> np.ndarray:
        """Normal velocities ``U = G v``."""
        return self.constraints @ v

    def kinetic(self, v: np.ndarray) -> float:
        """Kinetic energy ``1/2 v^T M v``."""
        return 0.5 * self.mass.quadratic(v)

    def elastic(self, q: np.ndarray) -> float:
        """Elastic energy ``1/2 q^T K q``."""
        return 0.5 * self.stiffness.quadratic(q)

    def potential(self, q: np.ndarray) -> float:
        """Potential of the constant load ``-f^T q`` (gravity: m g times height)."""
        return -float(self.load @ q)

    def energy(self, q: np.ndarray, v: np.ndarray) -> float:
        """Mechanical energy ``E = 1/2 v^T M v + 1/2 q^T K q - f^T q``."""
        return self.kinetic(v) + self.elastic(q) + self.potential(q)


__all__ = ["ContactProblem"]
