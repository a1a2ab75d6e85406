"""The lower ball on the floor with axisymmetric finite elements, in their own modes.

Dimensionless (R, 1/c, m2).  The membrane's radial displacement lives on the
line ``x = cos(phi)`` (Lagrange P1 to P4, vertices equally spaced in phi); the
forms are those of :mod:`twoball.fem_membrane.forms` over the whole sphere,
divided by 4 pi so that the mass unit is m2 = 4 pi rho R^2.  The floor touches
the nodes of the lower hemisphere (``x < 0``): the node of polar angle phi_i is
at height ``Z + (1 + u_i) x_i``, as for the Legendre points
(:mod:`twoball.modal.floor.system`).

The contact core is handed the finite-element equations in the basis of their
own eigenvectors: ``K V = M V diag(lambda_h)`` over the whole space (dense,
``V^T M V = I``), so M, K and C are diagonal and every step costs what a
Legendre step costs.  This is a change of coordinates, exact to rounding:

* the membrane operator, bending and gas map each Laplace-Beltrami eigenvalue
  lambda_h (:class:`~twoball.modal.stiffness.Stiffness`): ``K - s M``,
  ``(1 - 2 beta) K + beta K M^-1 K`` (:mod:`twoball.fem_membrane.shell`) and
  ``gas m m^T`` (``m = M 1``) are all diagonal in V, the last on the constant
  vector only;
* the damping law is ``C = M V diag(d_k) V^T M`` with ``d_k = 2 zeta_k
  omega_k`` of the law (the modal ratio), which for Rayleigh's law is ``alpha M
  + beta K`` exactly;
* the degree-1 content of u (the centre's offset, carried by Z) is the
  eigenvector ``x`` itself: on the line, ``x = cos(phi)`` lies in the space and
  ``K x = 2 M x`` holds exactly (integration by parts of ``(1 - x^2) x'``), so
  leaving that one eigenvector out imposes ``x^T M u = 0``.
"""

from __future__ import annotations

import math

import numpy as np
import scipy.linalg as sla
from skfem import Basis, MeshLine1, asm

from twoball._common.errors import NumericalError, ParameterError
from twoball._common.monitor import Monitor, long_call
from twoball.fem_membrane.axisym import LINE_ELEMENTS
from twoball.fem_membrane.forms import axisym_mass, axisym_stiffness
from twoball.modal.balls.description import ModalBall
from twoball.modal.balls.membrane import membrane_rows, mode_decay, mode_spectrum
from twoball.modal.damping import ModalRatio, Rayleigh
from twoball.modal.stiffness import Stiffness

__all__ = ["axisym_ball", "axisym_matrices", "cap_functional_exact"]

SPHERE = 4.0 * math.pi  # the forms integrate over the unit sphere; m2 = 4 pi rho R^2


def _vertices(elements: int) -> np.ndarray:
    """Element vertices x = cos(phi), ascending, equally spaced in phi (exact ends and equator)."""
    phi = np.linspace(0.0, math.pi, elements + 1)
    x = np.cos(phi)[::-1].copy()
    x[0], x[-1] = -1.0, 1.0
    if elements % 2 == 0:
        x[elements // 2] = 0.0
    return x


def _line_basis(elements: int, order: int) -> Basis:
    """Lagrange elements of ``order`` on the line x = cos(phi) in [-1, 1]."""
    if isinstance(elements, bool) or not isinstance(elements, int) or elements < 2:
        raise ParameterError("elements", "an integer >= 2", elements)
    if order not in LINE_ELEMENTS:
        raise ParameterError("order", "1, 2, 3 or 4", order)
    mesh = MeshLine1.init_tensor(_vertices(elements))
    return Basis(mesh, LINE_ELEMENTS[order](), intorder=2 * order + 2)


def cap_functional_exact(elements: int, order: int, theta: float) -> np.ndarray:
    """Vector f with ``f . u`` the mean of the finite-element u over ``x in [cos theta, 1]``.

    Exact for the piecewise polynomials of the line: the interval is split at the
    element vertices and each piece gets an ``order + 1``-point Gauss rule.
    """
    from numpy.polynomial.legendre import leggauss

    basis = _line_basis(elements, order)
    vertices = _vertices(elements)
    low = math.cos(theta)
    cuts = np.concatenate([[low], vertices[vertices > low]])
    xi, w = leggauss(order + 1)
    points, weights = [], []
    for a, b in zip(cuts[:-1], cuts[1:], strict=True):
        points.append(0.5 * (b - a) * xi + 0.5 * (a + b))
        weights.append(0.5 * (b - a) * w)
    x, w = np.concatenate(points), np.concatenate(weights) / (1.0 - low)
    probes = basis.probes(x[None, :])
    return np.asarray(probes.T @ w).ravel()


def axisym_matrices(elements: int, order: int) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Dense K, M (divided by 4 pi) and the node positions x = cos(phi) of every DOF.

    Vertices equally spaced in phi on [0, pi]; Lagrange elements of ``order``.
    """
    basis = _line_basis(elements, order)
    K = asm(axisym_stiffness, basis).toarray() / SPHERE
    M = asm(axisym_mass, basis).toarray() / SPHERE
    return 0.5 * (K + K.T), 0.5 * (M + M.T), basis.doflocs[0].copy()


def _dense_eigenpairs(
    K: np.ndarray, M: np.ndarray, monitor: Monitor | None = None
) -> tuple[np.ndarray, np.ndarray]:
    """``K V = M V diag(lambda)``, every pair (LAPACK through scipy, which holds the GIL).

    From :data:`~twoball.fem_membrane.slicing.DENSE_CHILD` unknowns on (seconds on a
    loaded machine: 8 s at 1200) the call is handed to the monitor as a long call
    (:func:`~twoball._common.monitor.long_call`: at the edge it runs where the
    progress line moves, an interrupt acts at once and the time limit is watched,
    with the same numbers).
    """
    from twoball.fem_membrane.slicing import DENSE_CHILD

    n = K.shape[0]
    doing = f"dense eigenpairs of the drop's {n} unknowns (LAPACK)"
    if n < DENSE_CHILD:
        if monitor is not None:
            monitor(doing)
        return sla.eigh(K, M)
    return long_call(monitor, sla.eigh, K, M, doing=doing)


def axisym_ball(
    elements: int,
    order: int,
    spectrum: Stiffness,
    law: ModalRatio | Rayleigh,
    *,
    anchored: bool = False,
    monitor: Monitor | None = None,
) -> ModalBall:
    """The finite-element ball in its eigenvectors, with the floor at its lower nodes.

    Parameters
    ----------
    elements : int
        Line elements (>= 2), equally spaced in phi.
    order : {1, 2, 3, 4}
        Lagrange order.
    spectrum : Stiffness
        Membrane operator, bending, gas: omega_k^2 from each lambda_h
        (:func:`~twoball.modal.balls.membrane.mode_spectrum`; the discrete area
        ``1^T M 1 / 4 pi`` is 1 on the line, so the gas needs no correction).
    law : ModalRatio or Rayleigh
        The damping law (dimensionless, fitted already).
    anchored : bool
        Keep the degree-1 eigenvector as a mode of the membrane about a centre
        that does not move (omega^2 from its Laplace eigenvalue 2) and no
        coordinate Z: the paper's special case, a body on its start.
    monitor : Monitor, optional
        Told of the eigenpairs (a long call at the edge).

    Returns
    -------
    ModalBall
        Coordinates: the centre's height Z, then every eigenvector but the
        degree-1 one (unit masses); floor points: the nodes with ``x < 0``,
        ascending in phi.
    """
    K, M, x = axisym_matrices(elements, order)
    laplace, V = _dense_eigenpairs(K, M, monitor)
    first = int(np.argmin(np.abs(laplace - 2.0)))
    moment = V[:, first] @ (M @ x) / math.sqrt(x @ M @ x)
    if abs(laplace[first] - 2.0) > 1e-8 or abs(abs(moment) - 1.0) > 1e-8:
        raise NumericalError(
            f"axisym_ball: the degree-1 eigenvector is not x (lambda = {laplace[first]:.3g})"
        )
    if anchored:
        return _anchored(x, laplace, V, elements, order, spectrum, law)
    keep = np.delete(np.arange(laplace.size), first)
    laplace, V = laplace[keep], V[:, keep]
    laplace[np.abs(laplace) < 1e-9] = 0.0  # the constant vector: K 1 = 0 to rounding
    if np.count_nonzero(laplace == 0.0) != 1 or laplace.min() < 0.0:
        raise NumericalError("axisym_ball: the constant mode is not isolated")
    floor = np.flatnonzero(x < 0.0)
    floor = floor[np.argsort(-x[floor])]  # ascending phi, the south pole last
    top = int(np.argmax(x))
    w2, gas2 = mode_spectrum(spectrum, laplace)
    order_x = np.argsort(x)
    sorted_x, sorted_v = x[order_x], V[order_x]

    def sampler(angles: np.ndarray) -> np.ndarray:
        """The modes at any polar angles: piecewise linear between the nodes (pictures)."""
        where = np.cos(angles)
        columns = [np.interp(where, sorted_x, col) for col in sorted_v.T]
        return np.column_stack([np.zeros(where.size), *columns])

    masses = np.ones(laplace.size)
    phi = np.arccos(np.clip(x[floor], -1.0, 1.0))
    rows, reach = membrane_rows(phi, V[floor, :], masses, w2)
    return ModalBall(
        masses=np.concatenate([[1.0], masses]),
        omega_squared=np.concatenate([[0.0], w2]),
        gas_squared=np.concatenate([[0.0], gas2]),
        decay=np.concatenate([[0.0], mode_decay(law, w2)]),
        centre=0,
        phi=phi,
        floor_rows=rows,
        top=np.concatenate([[1.0], V[top, :]]),
        label=f"axisym {elements} P{order}",
        bending=spectrum.beta > 0.0,
        laplace=np.concatenate([[2.0], laplace]),
        reach=reach,
        sampler=sampler,
        averager=lambda theta: np.concatenate(
            [[1.0], cap_functional_exact(elements, order, theta) @ V]
        ),
    )


def _anchored(
    x: np.ndarray,
    laplace: np.ndarray,
    V: np.ndarray,
    elements: int,
    order: int,
    spectrum: Stiffness,
    law: ModalRatio | Rayleigh,
) -> ModalBall:
    """Every eigenvector a mode about a held centre, no floor (the paper's special case)."""
    laplace = laplace.copy()
    laplace[np.abs(laplace) < 1e-9] = 0.0
    w2, gas2 = mode_spectrum(spectrum, laplace)
    top = int(np.argmax(x))
    return ModalBall(
        masses=np.ones(laplace.size),
        omega_squared=w2,
        gas_squared=gas2,
        decay=mode_decay(law, w2),
        centre=None,
        phi=np.zeros(0),
        floor_rows=np.zeros((0, laplace.size)),
        top=V[top, :].copy(),
        label=f"axisym {elements} P{order}",
        bending=spectrum.beta > 0.0,
        laplace=laplace,
        averager=lambda theta: cap_functional_exact(elements, order, theta) @ V,
    )
