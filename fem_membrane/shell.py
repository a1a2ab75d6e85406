"""Finite elements of the ball's operator: pressure term, bending by a mixed form, gas rank one.

Dimensionless (length R, time 1/c); the closed form is in
:mod:`twoball.modal.stiffness`.  On the membrane's own C0 space (sphere or
axisymmetric line, any order) the strong operator ``-Delta_s - s + beta Delta_s
(Delta_s + 2)`` is discretised with a second field ``w = -Delta_s u``, in weak
form ``M w = K u`` (the same space for w, so no boundary terms on the closed
surface).  Eliminating w leaves the Schur complement

    ``K_b = (1 - 2 beta) K - s M + beta K M^-1 K``,

where ``-s M`` (s = 2 for the pressurised membrane, 0 for the paper's) is the
mass-like form of the ``-2 u^2 / R^2`` term of :mod:`twoball.modal.membrane`
(:meth:`twoball.fem_membrane.space.Discretisation.operator`), and the enclosed
gas adds ``(gas / 4 pi) m m^T`` with ``m = M 1``, the discrete volume
functional (``m^T u = int u dS``).  ``K_b`` is never formed:

* products ``K_b x`` take one sparse solve with M (:class:`ShellOperator`);
* shift-invert solves ``(K_b - sigma M)^-1`` use the sparse saddle-point system
  ``[[(1 - 2 beta) K - sigma M, beta K], [K, -M]]`` and Woodbury for the gas
  (:func:`shell_eigenpairs_direct`);
* generalized-alpha stepping factorises the same saddle system
  (:class:`ShellAlpha`).

Because ``K_b = M p(M^-1 K)`` with ``p(mu) = (1 - 2 beta) mu - s + beta mu^2``,
the membrane's M-orthonormal eigenvectors are exactly those of ``K_b``, with
eigenvalues ``p(mu_h)``; and ``m^T phi = 0`` for every membrane mode except the
constant one (K 1 = 0), whose eigenvalue becomes ``gas * (1^T M 1) / (4 pi) - s``.
The modal routes (full and Krylov) therefore reuse the membrane eigen solvers and
map their spectra (:func:`twoball.modal.stiffness.stiffen`); the direct
shift-invert solve above checks that identity, and the eigenvalue error is
``p'(lambda) (mu_h - lambda)``: the membrane's order ``h^(2p)``.
"""

from __future__ import annotations

import math

import numpy as np
import scipy.linalg as sl
import scipy.sparse as sp
from scipy.sparse.linalg import LinearOperator, eigsh, splu

from twoball._common.errors import NumericalError
from twoball.fem_membrane.alpha import AlphaParameters, GeneralizedAlpha
from twoball.fem_membrane.damping import ModalDamping
from twoball.fem_membrane.eigen import Eigenpairs
from twoball.fem_membrane.space import Discretisation
from twoball.fem_membrane.validate import check_dt
from twoball.modal.damping import Rayleigh
from twoball.modal.series import ModalSeries
from twoball.modal.stiffness import Stiffness, stiffen


class ShellOperator(LinearOperator):
    """``K_s = (1 - 2 beta) K - s M + beta K M^-1 K + (gas / 4 pi) m m^T`` as a LinearOperator."""

    def __init__(self, space: Discretisation, stiffness: Stiffness) -> None:
        self.K = sp.csr_matrix(space.stiffness)
        self.M = sp.csr_matrix(space.mass)
        self.beta = float(stiffness.beta)
        self.shift = float(stiffness.membrane.shift)
        self.volume = np.asarray(self.M @ np.ones(self.M.shape[0]))  # m = M 1
        self.gas = float(stiffness.gas) / (4.0 * math.pi)
        self._mass_lu = splu(sp.csc_matrix(self.M)) if self.beta > 0 else None
        super().__init__(dtype=float, shape=self.K.shape)

    @property
    def surface_ratio(self) -> float:
        """Discrete area ``1^T M 1`` over the sphere's 4 pi."""
        return float(self.volume.sum() / (4.0 * math.pi))

    def _matvec(self, x: np.ndarray) -> np.ndarray:
        x = np.asarray(x, dtype=float).reshape(-1)
        kx = self.K @ x
        out = (1.0 - 2.0 * self.beta) * kx
        if self.shift:
            out = out - self.shift * (self.M @ x)
        if self._mass_lu is not None:
            out = out + self.beta * (self.K @ self._mass_lu.solve(kx))
        if self.gas:
            out = out + self.gas * self.volume * (self.volume @ x)
        return out

    def _matmat(self, X: np.ndarray) -> np.ndarray:
        return np.column_stack([self._matvec(col) for col in np.asarray(X).T])

    def _adjoint(self) -> ShellOperator:
        return self  # symmetric

    def saddle(self, a: float, b: float, extra: sp.spmatrix | None = None) -> sp.csc_matrix:
        """Sparse ``[[(a - b s) M + b (1 - 2 beta) K + extra, b beta K], [K, -M]]``.

        Its first block row solved for x gives ``(a M + b K_b + extra)^-1`` (no gas),
        since the second row makes ``z = M^-1 K x``.
        """
        if self.shift:
            a = a - b * self.shift
        top = a * self.M + b * (1.0 - 2.0 * self.beta) * self.K
        if extra is not None:
            top = top + extra
        if self.beta == 0.0:
            return sp.csc_matrix(top)
        return sp.csc_matrix(sp.bmat([[top, b * self.beta * self.K], [self.K, -self.M]]))


class _SaddleSolve:
    """``y = (a M + b K_b + extra)^-1 r`` by one sparse LU of the saddle system."""

    def __init__(self, operator: ShellOperator, a: float, b: float, extra=None) -> None:
        self.n = operator.shape[0]
        self.lu = splu(operator.saddle(a, b, extra))

    def solve(self, rhs: np.ndarray) -> np.ndarray:
        rhs = np.asarray(rhs, dtype=float)
        if self.lu.shape[0] == self.n:
            return self.lu.solve(rhs)
        pad = np.zeros((self.lu.shape[0] - self.n,) + rhs.shape[1:])
        return self.lu.solve(np.concatenate([rhs, pad]))[: self.n]


def _woodbury(solve, basis: np.ndarray, scale: np.ndarray):
    """Solver of ``(A + U diag(scale) U^T)`` from a solver of A (Sherman-Morrison-Woodbury)."""
    correction = np.column_stack([solve(col) for col in basis.T])  # A^-1 U
    small = sl.lu_factor(np.eye(scale.size) + scale[:, None] * (basis.T @ correction))

    def apply(rhs: np.ndarray) -> np.ndarray:
        y = solve(rhs)
        return y - correction @ sl.lu_solve(small, scale * (basis.T @ y))

    return apply


def shell_eigenpairs_direct(
    space: Discretisation, stiffness: Stiffness, count: int, tol: float = 1e-12
) -> Eigenpairs:
    """The ``count`` lowest eigenpairs of ``K_s phi = lambda M phi``, solved directly.

    Shift-invert Lanczos (ARPACK) with the shift below zero; the inverse by the
    saddle-point LU and Woodbury for the gas (nothing dense but the rank-one
    correction).  An independent check of the mapped spectra of :func:`stiff_series`.
    """
    operator = ShellOperator(space, stiffness)
    sigma = -1.0
    saddle = _SaddleSolve(operator, -sigma, 1.0)
    solve = saddle.solve
    if operator.gas:
        solve = _woodbury(solve, operator.volume[:, None], np.array([operator.gas]))
    n = operator.shape[0]
    inverse = LinearOperator((n, n), matvec=solve, dtype=float)
    start = np.random.default_rng(n).standard_normal(n)
    try:
        values, vectors = eigsh(
            operator, count, operator.M, sigma=sigma, OPinv=inverse, tol=tol, v0=start
        )
    except Exception as error:  # ArpackNoConvergence and friends
        raise NumericalError(f"shell eigensolver did not converge: {error}") from error
    order = np.argsort(values)
    return Eigenpairs(values[order], vectors[:, order])


def stiff_series(series: ModalSeries, space: Discretisation, stiffness: Stiffness) -> ModalSeries:
    """A finite-element membrane series mapped to the stiffened ball (see module doc)."""
    if not stiffness.active:
        return series
    ratio = float(np.asarray(space.mass @ np.ones(space.dofs)).sum() / (4.0 * math.pi))
    return stiffen(series, stiffness, ratio)


def stiff_pairs(pairs: Eigenpairs, series: ModalSeries) -> Eigenpairs:
    """Membrane eigenvectors with the stiffened eigenvalues of ``series`` (same order)."""
    return Eigenpairs(series.omega**2, pairs.vectors, None)


class RayleighOperator:
    """``C = alpha M + beta K_s`` of a Rayleigh law on the ball's operator (``C @ v``)."""

    def __init__(self, law: Rayleigh, mass: sp.spmatrix, operator: ShellOperator) -> None:
        self.alpha, self.beta = float(law.alpha), float(law.beta)
        self.mass, self.operator = mass, operator

    def __matmul__(self, v: np.ndarray) -> np.ndarray:
        return self.alpha * (self.mass @ v) + self.beta * (self.operator @ v)


class ShellAlpha(GeneralizedAlpha):
    """Generalized-alpha stepping of ``M u'' + C u' + K_s u = 0`` (pressure, bending, gas).

    The effective matrix ``(1 - alpha_m) M + (1 - alpha_f) (gamma_N dt C + beta_N
    dt^2 K_s)`` is applied inverse through the saddle-point LU; the gas and the
    low-rank modal damping enter together by one Woodbury correction.  A Rayleigh
    law ``C = a M + b K_s`` only changes the two weights of the saddle system:
    ``((1 - alpha_m) + w_c a) M + (w_k + w_c b) K_s``.
    """

    def __init__(
        self,
        mass: sp.spmatrix,
        operator: ShellOperator,
        dt: float,
        damping: ModalDamping | Rayleigh | None = None,
        rho_inf: float = 1.0,
    ) -> None:
        self.dt = check_dt(dt)
        self.parameters = p = AlphaParameters(rho_inf)
        self.mass = sp.csr_matrix(mass)
        self.stiffness = operator
        self.damping = damping
        weight_c = (1.0 - p.alpha_f) * p.gamma * self.dt
        weight_k = (1.0 - p.alpha_f) * p.beta * self.dt**2
        weight_m = 1.0 - p.alpha_m
        if isinstance(damping, Rayleigh):
            self.damping = RayleighOperator(damping, self.mass, operator)
            weight_m = weight_m + weight_c * self.damping.alpha
            weight_k = weight_k + weight_c * self.damping.beta
        self._lu = _SaddleSolve(operator, weight_m, weight_k)
        self._mass_lu = None
        self._lowrank = None
        columns, scales = [], []
        if isinstance(damping, ModalDamping):
            columns.append(damping.basis)
            scales.append(weight_c * damping.rates)
        elif damping is not None and not isinstance(damping, Rayleigh):
            raise NumericalError("ShellAlpha takes modal or Rayleigh damping only")
        if operator.gas:
            columns.append(operator.volume[:, None])
            scales.append(np.array([weight_k * operator.gas]))
        if columns:
            basis, scale = np.hstack(columns), np.concatenate(scales)
            correction = self._lu.solve(np.asfortranarray(basis))
            small = np.eye(scale.size) + scale[:, None] * (basis.T @ correction)
            self._lowrank = (basis, scale, correction, sl.lu_factor(small))


__all__ = [
    "RayleighOperator",
    "ShellAlpha",
    "ShellOperator",
    "shell_eigenpairs_direct",
    "stiff_pairs",
    "stiff_series",
]
