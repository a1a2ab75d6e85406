"""Rational block Krylov route to the filtered pole motion on large meshes.

The pole motion of eqs. (3.14)-(3.16) on M-orthonormal eigenpairs,

    u_pole(t) = sum_k sigma(omega_k) q_k(t) phi_k[pole] (phi_k^T b),

is a bilinear form ``e_pole^T f_t(K, M) b`` of the pole functional and the load
``b = M u0`` (the projected initial displacement).  Only the modes in which both
``M^{-1} b`` and ``M^{-1} e_pole`` have components matter; for the axisymmetric F
on a sphere mesh that is about one (zonal) mode per degree l, plus the few modes of
the pole's symmetry class that mesh anisotropy mixes in.  Instead of every
eigenpair below the cutoff (:func:`twoball.fem_membrane.eigen.eigenpairs`), this module
finds just those by a rational block Krylov method:

1. Shifts ``sigma_1 < ... < sigma_s`` are put in spectral gaps ``(l + 1)^2``
   (midway between ``l (l + 1)`` and ``(l + 1)(l + 2)``) spread over
   ``[0, lambda_cut]``, the first one slightly negative (K is singular), and each
   ``K - sigma_j M`` is factorised once by :func:`scipy.sparse.linalg.splu`.
2. The block start is ``(K - sigma_1 M)^{-1} [b, e_pole]`` -- the operator
   ``(K - sigma M)^{-1} M`` applied to ``[M^{-1} b, M^{-1} e_pole]``, so no mass
   solve is needed and the pole functional's high frequencies are damped at once.
3. Each step applies the next shift's operator ``(K - sigma_j M)^{-1} M`` (cycling
   through the shifts) to the newest block, M-orthogonalises it against the whole
   basis twice (classical block Gram-Schmidt, full reorthogonalisation) and
   M-orthonormalises it, dropping directions that are numerically dependent.
4. Rayleigh-Ritz: ``V^T K V s = theta V^T M V s`` on the basis V gives Ritz pairs
   ``(theta_k, y_k = V s_k)``; the series uses ``omega = sqrt(theta)``,
   ``coefficients = y_k^T b`` and ``pole_values = y_k[pole]`` -- the same
   :class:`twoball.modal.series.ModalSeries` the full route builds, so the filter and
   :func:`twoball.modal.liftoff.find_liftoff` apply unchanged.

Stopping rule (``tol`` defaults to 1e-10): the filtered pole displacement u and
acceleration u_tt of the Ritz series, sampled 16 times per period of omega_cut on
[0, t_end], change by at most ``tol`` relative to their own maximum (each
separately) over one full cycle of shifts, on two consecutive cycles.  The Ritz
pairs and the criterion are evaluated after whole cycles (one block from every
shift), every ``max(1, basis // 100)`` cycles, against the previous evaluation
(the Rayleigh-Ritz eigenproblem of the growing basis dominates the cost when
done on every step; the wider spacing only makes the comparison stricter).
The basis grows by at most two columns per step, so a cycle adds 2 len(shifts)
directions; a stagnating step cannot satisfy the rule alone.  With
``field_times`` the whole field must settle too
(:mod:`twoball.fem_membrane.ritz_field`).  This is a difference-of-iterates
estimate, not a bound: measured against the full route the u_tt error was up to about 10 ``tol``
(2e-10 on sphere P1 level 4 with 4 shifts) and u, t_l, v_l agreed to 1e-11 or
better.  If the rule is not met within ``max_basis`` vectors, NumericalError.

Shifts: 3 by default (-1, 15^2, 31^2 for N = 30).  Measured on sphere meshes of
2.5k-41k dofs, 2-4 shifts need about half the basis of a single shift at -1
(about 130-220 vectors against 400+); beyond 3, the extra factorisations cost
more than they save.  Dense work runs with one OpenBLAS thread (many thin
products and small eigenproblems, which threads slow down on a loaded machine).

Why not per-pair residuals: the projection ``Y diag(f(theta)) Y^T`` is a
Gauss-type quadrature of the bilinear form, exact for the rational functions the
basis spans; it converges long before every Ritz pair does.  On sphere meshes
the pole's symmetry class holds near-degenerate partners of each zonal mode (e.g.
m = 0, 5, 10, ... on the icosphere), and their Ritz pairs may keep relative
residuals of 1e-2 while the pole trajectory agrees with the full route to 1e-11.
The relative residuals ``||K y - theta M y||_{M^{-1}} / (1 + theta)`` of the
weighted Ritz pairs (``|sigma_k q_k(0) phi_k[pole]| (1 + theta_k)`` at least
``tol`` times the largest) are therefore reported (one extra factorisation, of
M), not used to stop; the well-separated ones match eigenvalues of the full
route to round-off (tested).

Everything is dimensionless.
"""

from __future__ import annotations

import math
import time as clock
from dataclasses import dataclass, field
from typing import Any

import numpy as np
import scipy.sparse as sp
from threadpoolctl import threadpool_limits

from twoball._common.choices import ROUTES
from twoball._common.errors import NumericalError, ParameterError
from twoball._common.monitor import Monitor
from twoball.fem_membrane.eigen import Eigenpairs
from twoball.fem_membrane.ritz_field import FieldChange
from twoball.fem_membrane.slicing import factorise
from twoball.fem_membrane.space import Discretisation, PoleFunctional, pole_value, pole_vector
from twoball.modal.filters import SpectralFilter
from twoball.modal.liftoff import DEFAULT_T_END
from twoball.modal.series import ModalSeries, check_law

TOLERANCE = 1e-10  # relative change of the filtered pole trajectory (u and u_tt)
SHIFT_COUNT = 3  # default number of shifts (factorisations of K - sigma M)
FIRST_SHIFT = -1.0  # below the constant mode lambda = 0 (K is singular)
AUTO_THRESHOLD = 2000  # --route auto: Krylov from this many degrees of freedom on
MAX_BASIS = 1200  # give up beyond this many basis vectors
FIRST_COLUMNS = 128  # basis columns reserved at first (doubled when full)
DEPENDENT = 1e-10  # drop a new direction whose norm falls below this fraction
SAMPLES_PER_PERIOD = 16  # trajectory samples per period of omega_cut
CHECK_SPACING = 100  # criteria every max(1, basis // 100) cycles of shifts
PASSES = 2  # consecutive cycles on which the trajectory criterion must hold


@dataclass
class KrylovInfo:
    """What the Krylov route did (dimensionless).

    Attributes
    ----------
    converged : bool
        The trajectory criterion was met.
    iterations : int
        Block steps (applications of a shifted inverse to a block).
    factorizations : int
        Sparse LU factorisations: one per shift, plus one of M for the residual norms.
    basis_size : int
        Columns of the M-orthonormal Krylov basis.
    shifts : tuple of float
        The shifts sigma_j.
    trajectory_change : float
        Relative change of the pole trajectory over the last shift cycle.
    residuals : ndarray
        Relative M^{-1} residuals of the weighted Ritz pairs below the cutoff
        (empty when not computed).
    residual_values : ndarray
        Their Ritz values theta.
    max_residual : float
        Largest of ``residuals``.
    modes : int
        Ritz pairs with eigenvalue <= lambda_cut (the series' length).
    weighted : int
        How many of them carry non-negligible pole weight.
    history : list of dict
        Per Ritz step: ``basis``, ``change``.
    seconds : dict
        ``factorize``, ``iterate``, ``residuals``.
    """

    converged: bool
    iterations: int
    factorizations: int
    basis_size: int
    shifts: tuple[float, ...]
    trajectory_change: float
    residuals: np.ndarray
    residual_values: np.ndarray
    max_residual: float
    modes: int
    weighted: int
    history: list[dict[str, float]] = field(default_factory=list)
    seconds: dict[str, float] = field(default_factory=dict)
    pairs: Eigenpairs | None = None

    def as_dict(self) -> dict[str, Any]:
        """Plain summary for ``info`` dictionaries and reports (no arrays)."""
        return {
            "converged": self.converged,
            "iterations": self.iterations,
            "factorizations": self.factorizations,
            "basis_size": self.basis_size,
            "shifts": list(self.shifts),
            "trajectory_change": self.trajectory_change,
            "max_residual": self.max_residual,
            "modes": self.modes,
            "weighted": self.weighted,
            "seconds": dict(self.seconds),
        }


def choose_route(route: str, dofs: int, threshold: int = AUTO_THRESHOLD) -> str:
    """Resolve the ``route``: ``full`` or ``krylov`` as given; ``auto`` by problem size.

    ``auto`` takes the Krylov route from ``threshold`` degrees of freedom on (sphere
    P1 level 4 = 2562 dofs is already 1.6x faster, level 5 about 5x) and the full
    eigen route below, where it costs under a second and also yields every pair.
    """
    if route not in ROUTES:
        raise ParameterError("route", "one of full, krylov, auto", route)
    if route != "auto":
        return route
    return "krylov" if dofs >= threshold else "full"


def default_shifts(upper: float, count: int = SHIFT_COUNT) -> np.ndarray:
    """``count`` shifts over [0, upper]: FIRST_SHIFT, then gap points ``(l + 1)^2``.

    The gap points are spread evenly in frequency, ``l + 1 ~ j sqrt(upper) / (count - 1)``,
    the last one at the gap nearest to ``upper`` (the filter cutoff is itself such a
    gap).  Dimensionless.
    """
    if isinstance(count, bool) or int(count) != count or count < 1:
        raise ParameterError("shifts", "an integer >= 1", count)
    top = math.sqrt(max(upper, 1.0))
    shifts = [FIRST_SHIFT]
    for j in range(1, int(count)):
        gap = max(1, round(j * top / (count - 1)))
        shifts.append(float(gap) ** 2)
    return np.unique(np.array(shifts))


def _widened(array: np.ndarray, columns: int, used: int, rows: int | None = None) -> np.ndarray:
    """``array`` in a larger column-major buffer of ``columns`` columns (first ``used`` kept).

    ``rows`` also grows a square matrix (the projected stiffness); new entries are zero.
    """
    if rows is None:
        out = np.empty((array.shape[0], columns), order="F")
        out[:, :used] = array[:, :used]
        return out
    out = np.zeros((rows, columns))
    out[:used, :used] = array[:used, :used]
    return out


def _m_orthonormalise(
    block: np.ndarray, basis: np.ndarray, mass_basis: np.ndarray, M: sp.csc_matrix
) -> tuple[np.ndarray, np.ndarray]:
    """Block M-Gram-Schmidt of ``block`` against ``basis`` (twice), then within itself.

    Returns the new M-orthonormal columns and M times them; directions whose
    M-norm falls below DEPENDENT of the original are dropped.
    """
    mass_block = M @ block
    before = np.sqrt(np.maximum(np.einsum("ij,ij->j", block, mass_block), 0.0))
    for _ in range(2):
        if basis.shape[1]:
            block = block - basis @ (mass_basis.T @ block)
            mass_block = M @ block
        gram = block.T @ mass_block
        gram = 0.5 * (gram + gram.T)
        values, vectors = np.linalg.eigh(gram)
        keep = values > (DEPENDENT * before.max()) ** 2
        if not np.any(keep):
            return block[:, :0], mass_block[:, :0]
        transform = vectors[:, keep] / np.sqrt(values[keep])
        block = block @ transform
        mass_block = mass_block @ transform
        before = np.ones(block.shape[1])
    return block, mass_block


def _series(
    values: np.ndarray,
    coefficients: np.ndarray,
    pole_values: np.ndarray,
    damping: Any,
    filter: SpectralFilter,
    monitor: Monitor | None = None,
) -> ModalSeries:
    keep = values <= filter.omega_cut**2
    return ModalSeries(
        omega=np.sqrt(np.clip(values[keep], 0.0, None)),
        coefficients=coefficients[keep],
        pole_values=pole_values[keep],
        damping=damping,
        filter=filter,
        mode_norms=np.ones(int(np.count_nonzero(keep))),
        monitor=monitor,
    )


def _trajectory(series: ModalSeries, grid: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    state = series.pole(grid)
    return state.u, state.u_tt


def _serial_blas() -> threadpool_limits:
    """One BLAS thread while inside (restored afterwards).

    The dense work of the Krylov loop is many thin products and small eigenproblems,
    which BLAS threads slow down by orders of magnitude on a loaded machine.
    """
    return threadpool_limits(limits=1, user_api="blas")


def _unpack(
    problem: Discretisation | tuple[sp.spmatrix, sp.spmatrix, PoleFunctional],
) -> tuple[sp.csc_matrix, sp.csc_matrix, PoleFunctional]:
    if isinstance(problem, Discretisation):
        return sp.csc_matrix(problem.stiffness), sp.csc_matrix(problem.mass), problem.pole_row
    K, M, pole = problem
    return sp.csc_matrix(K), sp.csc_matrix(M), pole


def krylov_modal_series(
    problem: Discretisation | tuple[sp.spmatrix, sp.spmatrix, int],
    moments: np.ndarray,
    damping: Any,
    filter: SpectralFilter,
    *,
    tol: float = TOLERANCE,
    residuals: bool = True,
    shifts: int | np.ndarray | None = None,
    t_end: float = DEFAULT_T_END,
    max_basis: int = MAX_BASIS,
    vectors: bool = False,
    field_times: np.ndarray | None = None,
    monitor: Monitor | None = None,
) -> tuple[ModalSeries, KrylovInfo]:
    """The filtered finite-element modal series of eq. (3.16) from Ritz pairs.

    Equivalent, to the stated tolerance at the pole, to
    :func:`twoball.fem_membrane.modal.modal_series` on all eigenpairs below the cutoff
    (eqs. (3.14)-(3.16)), at the cost of one sparse LU per shift.  See the module
    docstring for the method and the stopping rule.  Dimensionless.

    Parameters
    ----------
    problem : Discretisation or (K, M, pole)
        The space (its stiffness, mass and pole functional) or the matrices themselves
        (the pole as a degree of freedom or a sparse row).
    moments : ndarray, shape (dofs,)
        ``b = M u0``; for the Galerkin projection the load ``b_i = int F phi_i dS``.
    damping : float or Rayleigh
        Modal damping ratio D in [0, 1), or a Rayleigh law in units of c
        (:class:`twoball.modal.series.ModalSeries`).
    filter : SpectralFilter
        Weights by frequency; its ``omega_cut**2`` is the eigenvalue cutoff.
    tol : float
        Relative tolerance of the pole trajectory (u and u_tt), the stopping rule.
    residuals : bool
        Compute the M^{-1} residuals of the weighted Ritz pairs (diagnostics).
    shifts : int or array_like, optional
        Number of shifts (default 3, from :func:`default_shifts`) or the shifts.
    t_end : float
        End of the time window on which the trajectory is compared.
    max_basis : int
        Largest Krylov basis before giving up (NumericalError).
    vectors : bool
        Also return the Ritz vectors below the cutoff as ``info.pairs``
        (:class:`Eigenpairs`, M-orthonormal) -- e.g. for the filtered initial
        displacement and modal damping of direct time stepping, or the field on
        every node (files, pictures).
    field_times : ndarray, optional
        Also require the whole field (u, u_t, u_tt in the M-norm) to settle at
        these instants (:mod:`twoball.fem_membrane.ritz_field`), as needed when
        the Ritz vectors serve as mode shapes.
    monitor : Monitor, optional
        Told at every iteration and as the series are evaluated
        (:class:`~twoball._common.monitor.Monitor`; it may stop the work by
        raising); the series returned keeps it (:attr:`ModalSeries.monitor`).

    Returns
    -------
    series : ModalSeries
        Ritz pairs with ``theta <= omega_cut**2``: ``omega = sqrt(theta)``,
        ``coefficients = Y^T b``, ``pole_values = Y[pole]``, ``mode_norms = 1``.
    info : KrylovInfo
        Iterations, factorisations, basis size, residuals, timings.
    """
    with _serial_blas():
        return _krylov(
            problem,
            moments,
            damping,
            filter,
            tol,
            residuals,
            shifts,
            t_end,
            max_basis,
            vectors,
            field_times,
            monitor,
        )


def _krylov(
    problem: Discretisation | tuple[sp.spmatrix, sp.spmatrix, int],
    moments: np.ndarray,
    damping: Any,
    filter: SpectralFilter,
    tol: float,
    residuals: bool,
    shifts: int | np.ndarray | None,
    t_end: float,
    max_basis: int,
    vectors: bool,
    field_times: np.ndarray | None = None,
    monitor: Monitor | None = None,
) -> tuple[ModalSeries, KrylovInfo]:
    damping = check_law(damping)
    if not (math.isfinite(tol) and 0.0 < tol < 1.0):
        raise ParameterError("tol", "in (0, 1)", tol)
    K, M, pole = _unpack(problem)
    n = K.shape[0]
    b = np.asarray(moments, dtype=float)
    if b.shape != (n,):
        raise ValueError("moments must have one entry per degree of freedom")
    upper = filter.omega_cut**2
    if shifts is None or isinstance(shifts, int | np.integer):
        sigma = default_shifts(upper, SHIFT_COUNT if shifts is None else int(shifts))
    else:
        sigma = np.asarray(shifts, dtype=float).ravel()
    seconds: dict[str, float] = {}
    start = clock.perf_counter()
    factors = [factorise(sp.csc_matrix(K - s * M)) for s in sigma]
    seconds["factorize"] = clock.perf_counter() - start

    start = clock.perf_counter()
    limit = min(max_basis, n)
    # column-major, grown by doubling: the memory reserved stays within twice the
    # columns in use (reserving all max_basis columns at once took 4.4 GB of address
    # space on a 163842-DOF mesh that used a fraction of it)
    capacity = min(limit, FIRST_COLUMNS)
    basis, mass_basis, stiff_basis = (np.empty((n, capacity), order="F") for _ in range(3))
    projected = np.zeros((capacity, capacity))  # V^T K V, grown block by block
    loads = np.empty(capacity)  # V^T b
    size = 0
    block = factors[0].solve(np.column_stack([b, pole_vector(pole, n)]))
    grid = np.linspace(
        0.0, t_end, math.ceil(t_end * filter.omega_cut * SAMPLES_PER_PERIOD / (2 * math.pi)) + 1
    )
    trajectories: list[tuple[np.ndarray, np.ndarray]] = []
    whole = None if field_times is None else FieldChange(field_times, 1)
    passes, iterations, change = 0, 0, math.inf
    history: list[dict[str, float]] = []
    converged_trajectory = False
    theta = np.empty(0)
    small = np.empty((0, 0))
    while True:
        if monitor is not None:
            monitor(f"the rational Krylov iteration (basis {size} of at most {limit})")
        new, mass_new = _m_orthonormalise(block, basis[:, :size], mass_basis[:, :size], M)
        width = min(new.shape[1], limit - size)
        if width == 0:  # invariant subspace: the projection is exact
            converged_trajectory = size > 0
            theta, small = np.linalg.eigh(projected[:size, :size])
            break
        end = size + width
        if end > capacity:
            capacity = min(limit, max(2 * capacity, end))
            basis, mass_basis, stiff_basis = (
                _widened(a, capacity, size) for a in (basis, mass_basis, stiff_basis)
            )
            projected = _widened(projected, capacity, size, rows=capacity)
            loads = np.concatenate([loads[:size], np.empty(capacity - size)])
        basis[:, size:end] = new[:, :width]
        mass_basis[:, size:end] = mass_new[:, :width]
        stiff_basis[:, size:end] = K @ new[:, :width]
        column = basis[:, :end].T @ stiff_basis[:, size:end]
        projected[:end, size:end] = column
        projected[size:end, :end] = column.T
        projected[size:end, size:end] = 0.5 * (column[size:] + column[size:].T)
        loads[size:end] = new[:, :width].T @ b
        size = end
        lag = len(factors)  # one full cycle of shifts
        if (iterations + 1) % (lag * max(1, size // CHECK_SPACING)) and size < limit:
            iterations += 1  # Ritz pairs and the criteria once per cycle of shifts
            shift = factors[iterations % len(factors)]
            block = shift.solve(np.asfortranarray(mass_basis[:, size - width : size]))
            continue
        # Rayleigh-Ritz on the M-orthonormal basis (V^T M V = I to round-off)
        theta, small = np.linalg.eigh(projected[:size, :size])
        at_pole = pole_value(pole, basis[:, :size])
        series = _series(theta, small.T @ loads[:size], at_pole @ small, damping, filter, monitor)
        current = _trajectory(series, grid)
        trajectories.append(current)
        if len(trajectories) > 1:  # against the previous cycle
            change = max(
                float(np.abs(c - p).max() / max(np.abs(c).max(), np.finfo(float).tiny))
                for c, p in zip(current, trajectories[0], strict=True)
            )
            del trajectories[0]
        if whole is not None:  # the field on every node, in the M-norm
            change = max(change, whole.update(series, small[:, theta <= upper]))
        passes = passes + 1 if change <= tol else 0
        history.append({"basis": float(size), "change": change})
        if passes >= PASSES:
            converged_trajectory = True
            break
        if size >= limit:
            break
        iterations += 1
        shift = factors[iterations % len(factors)]
        block = shift.solve(np.asfortranarray(mass_basis[:, size - width : size]))
    seconds["iterate"] = clock.perf_counter() - start

    start = clock.perf_counter()
    V = basis[:, :size]
    coefficients = small.T @ loads[:size]
    pole_values = pole_value(pole, basis[:, :size]) @ small
    below = theta <= upper
    weights = filter(np.sqrt(np.clip(theta, 0.0, None))) * coefficients * pole_values
    scale = np.abs(weights) * (1.0 + np.abs(theta))
    weighted = below & (scale >= tol * scale[below].max(initial=0.0)) & (scale > 0)
    chosen = np.flatnonzero(weighted)
    norms = np.empty(0)
    if residuals:
        residual = (stiff_basis[:, :size] @ small[:, chosen]) - (
            mass_basis[:, :size] @ small[:, chosen]
        ) * theta[chosen]
        dual = np.einsum("ij,ij->j", residual, factorise(M).solve(residual))
        norms = np.sqrt(np.maximum(dual, 0.0)) / (1.0 + np.abs(theta[chosen]))
        seconds["residuals"] = clock.perf_counter() - start
    series = _series(theta, coefficients, pole_values, damping, filter, monitor)
    if not (np.all(np.isfinite(theta)) and np.all(np.isfinite(coefficients))):
        raise NumericalError("Krylov route: Ritz values or coefficients are not finite")
    if not converged_trajectory:
        raise NumericalError(
            f"Krylov route: pole trajectory not converged to {tol:g} with {size} basis "
            f"vectors (last change {change:.2e}); use the full eigen route"
        )
    pairs = None
    if vectors:
        pairs = Eigenpairs(theta[below], V @ small[:, below])
    info = KrylovInfo(
        converged=converged_trajectory,
        iterations=iterations,
        factorizations=len(factors) + int(residuals),
        basis_size=size,
        shifts=tuple(float(s) for s in sigma),
        trajectory_change=change,
        residuals=norms,
        residual_values=theta[chosen] if residuals else np.empty(0),
        max_residual=float(norms.max(initial=0.0)),
        modes=int(np.count_nonzero(below)),
        weighted=int(chosen.size),
        history=history,
        seconds=seconds,
        pairs=pairs,
    )
    return series, info
