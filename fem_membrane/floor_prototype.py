"""Prototype: the ball dropped on the floor with axisymmetric finite elements + the contact core.

The membrane's radial displacement u lives on the line ``x = cos(phi)`` (P1 or
P2, scikit-fem ``MeshLine1``, vertices equally spaced in phi); the forms are
those of :mod:`twoball.fem_membrane.forms` divided by 4 pi, so the mass unit is
m2 = 4 pi rho R^2 as in :mod:`twoball.modal.floor_prototype`.

* The n = 1 content of u is the rigid translation, carried by Z: it is removed
  by the linear constraint ``c^T u = 0`` with ``c = M x`` (the first moment
  ``int u cos(phi) dS``), eliminated at the north-pole node (``u = B w``; B is
  the identity with one dense row; ``B^T M B`` then holds the dense rank-one
  term ``c c^T``, so the reduced matrices are stored densely -- fine on the line,
  a sphere mesh would need the constraint as a multiplier or a low-rank update).
* Pressurised operator: ``K - 2 M`` (omega^2 = n(n+1) - 2 on P_n) plus the gas
  ``gas m m^T`` with ``m = M 1`` (the mean of u), exactly as on the modes.
* Damping: the modal ratio D as the dense matrix ``C = M V diag(2 D omega) V^T M``
  over the finite-element eigenpairs (Z undamped), or Rayleigh ``alpha M + beta K``.
* Floor: ``z_i = Z + (1 + u_i) x_i >= 0`` at every node with x_i < 0.

Dimensionless; q = (Z, w).
"""

from __future__ import annotations

import math
import time
from dataclasses import dataclass

import numpy as np
import scipy.linalg as sla
import scipy.sparse as sp
from skfem import Basis, ElementLineP1, ElementLineP2, MeshLine1, asm
from twoball.fem_membrane.forms import axisym_mass, axisym_stiffness
from twoball.modal.floor_prototype import (
    BASKETBALL_GAMMA,
    BASKETBALL_GAS,
    BASKETBALL_V0,
    OPERATORS,
    DropResult,
    measure_drop,
    run_drop,
)
from twoball.modal.nonsmooth import ContactProblem

from twoball._common.errors import ParameterError

SPHERE = 4.0 * math.pi  # the forms integrate over the unit sphere; m2 = 4 pi rho R^2


@dataclass(frozen=True)
class AxisymFloorModel:
    """The ball on the floor, axisymmetric finite elements (dimensionless).

    Parameters
    ----------
    elements : int
        Line elements, equally spaced in phi on [0, pi].
    order : {1, 2}
        Lagrange order.
    operator, gas, damping, rayleigh, v0, gamma, restitution
        As in :class:`twoball.modal.floor_prototype.FloorModel`.
    """

    elements: int = 100
    order: int = 2
    operator: str = "pressurised"
    gas: float = BASKETBALL_GAS
    damping: float = 0.0
    rayleigh: tuple[float, float] | None = None
    v0: float = BASKETBALL_V0
    gamma: float = BASKETBALL_GAMMA
    restitution: float = 0.0

    def __post_init__(self) -> None:
        if not isinstance(self.elements, int) or self.elements < 4:
            raise ParameterError("elements", "an integer >= 4", self.elements)
        if self.order not in (1, 2):
            raise ParameterError("order", "1 or 2", self.order)
        if self.operator not in OPERATORS:
            raise ParameterError("operator", "one of " + ", ".join(OPERATORS), self.operator)
        if not 0.0 <= self.damping < 1.0:
            raise ParameterError("damping", "a number in [0, 1)", self.damping)


@dataclass(frozen=True)
class AxisymFloorSetup:
    """Problem, start and the floor nodes (ascending phi) of an :class:`AxisymFloorModel`."""

    problem: ContactProblem
    q0: np.ndarray
    v0: np.ndarray
    phi: np.ndarray
    x: np.ndarray  # x = cos(phi) of every degree of freedom of u
    reduction: sp.csr_matrix  # u = B w


def axisym_floor_setup(model: AxisymFloorModel) -> AxisymFloorSetup:
    """Assemble M, K, C, the n = 1 elimination and the floor constraints of ``model``."""
    phi_v = np.linspace(0.0, math.pi, model.elements + 1)
    x_v = np.cos(phi_v)[::-1].copy()
    x_v[0], x_v[-1] = -1.0, 1.0
    mesh = MeshLine1.init_tensor(x_v)
    element = ElementLineP1() if model.order == 1 else ElementLineP2()
    basis = Basis(mesh, element, intorder=2 * model.order + 2)
    M = asm(axisym_mass, basis).tocsr() / SPHERE
    K = asm(axisym_stiffness, basis).tocsr() / SPHERE
    x = basis.doflocs[0].copy()
    n = x.size
    ones = np.asarray(M @ np.ones(n)).ravel()  # m = M 1: the mean of u is m^T u
    if model.operator == "pressurised":
        K = K - 2.0 * M
    first = np.asarray(M @ x).ravel()  # c = M x: the P1 moment
    k = int(np.argmax(x))  # eliminate the north-pole node
    others = np.delete(np.arange(n), k)
    rows = np.concatenate([others, np.full(n - 1, k)])
    cols = np.concatenate([np.arange(n - 1), np.arange(n - 1)])
    vals = np.concatenate([np.ones(n - 1), -first[others] / first[k]])
    B = sp.csr_matrix((vals, (rows, cols)), shape=(n, n - 1))
    Mr = (B.T @ M @ B).tocsr()
    Kr = (B.T @ K @ B).tocsr()
    if model.gas:
        mb = B.T @ ones
        Kr = Kr + model.gas * sp.csr_matrix(np.outer(mb, mb))
    # the elimination adds the dense rank-one terms c c^T (and the gas m m^T): the
    # reduced matrices are dense, and a dense Cholesky factorisation beats SuperLU
    size = n  # Z + (n - 1) reduced coordinates
    Mr, Kr = Mr.toarray(), Kr.toarray()
    Mfull = np.zeros((size, size))
    Mfull[0, 0] = 1.0
    Mfull[1:, 1:] = Mr
    Kfull = np.zeros((size, size))
    Kfull[1:, 1:] = Kr
    Cfull = np.zeros((size, size))
    if model.rayleigh is not None:
        alpha, beta = model.rayleigh
        Cfull[1:, 1:] = alpha * Mr + beta * Kr
    elif model.damping > 0.0:
        w2, V = sla.eigh(Kr, Mr)
        omega = np.sqrt(np.clip(w2, 0.0, None))
        MV = Mr @ V
        Cr = (MV * (2.0 * model.damping * omega)) @ MV.T
        Cfull[1:, 1:] = 0.5 * (Cr + Cr.T)
    floor = np.flatnonzero(x < 0.0)
    floor = floor[np.argsort(-x[floor])]  # ascending phi
    phi = np.arccos(x[floor])
    Bf = B[floor]  # rows of the floor nodes (unit rows: the pole node is not on the floor)
    G = sp.hstack([sp.csr_matrix(np.ones((floor.size, 1))), sp.diags(x[floor]) @ Bf]).tocsr()
    f = np.zeros(size)
    f[0] = -model.gamma
    problem = ContactProblem.create(Mfull, Cfull, Kfull, f, G, x[floor], model.restitution)
    q0 = np.zeros(size)
    q0[0] = 1.0
    v0 = np.zeros(size)
    v0[0] = -model.v0
    return AxisymFloorSetup(problem, q0, v0, phi, x, B)


def axisym_drop(
    model: AxisymFloorModel, dt: float, *, flight: float = 1.0, keep: bool = False
) -> DropResult:
    """Drop the finite-element ball on the floor and measure the bounce (as the modal one)."""
    start = time.perf_counter()
    setup = axisym_floor_setup(model)
    tr, wall = run_drop(setup.problem, setup.q0, setup.v0, dt, flight=flight)
    gaps = tr.q @ setup.problem.constraints.T + setup.problem.offset
    total = time.perf_counter() - start
    result = measure_drop(
        tr, setup.phi, gaps, gamma=model.gamma, v0=model.v0, wall_s=total, keep=keep
    )
    return result


__all__ = ["AxisymFloorModel", "AxisymFloorSetup", "axisym_drop", "axisym_floor_setup"]
