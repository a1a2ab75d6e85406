"""A finite-element space on the sphere or the axisymmetric line, with its matrices.

:class:`Discretisation` bundles what every later step needs: the scikit-fem
basis, stiffness K and mass M (dimensionless, measure of the whole unit sphere),
the degree of freedom at the north pole, and how to read the polar angle from
global coordinates.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

import numpy as np
import scipy.sparse as sp
from skfem import CellBasis, ElementTriP1, ElementTriP2, asm

from .checks import check_order
from .forms import mass, stiffness
from .mapping import SurfaceMapping
from .mesh import SphereMesh, elevate, flatten, topology

TRIANGLE_ELEMENTS = {1: ElementTriP1, 2: ElementTriP2}
# quadrature degree for K and M: exact on flat P1; curved P2 integrands are rational
SURFACE_INTORDER = {1: 2, 2: 6}


def sphere_polar_cosine(x: np.ndarray) -> np.ndarray:
    """cos(phi) of the radial projection of points ``x`` (shape (3, ...)) onto the sphere."""
    return x[2] / np.sqrt(x[0] ** 2 + x[1] ** 2 + x[2] ** 2)


def line_polar_cosine(x: np.ndarray) -> np.ndarray:
    """cos(phi) on the axisymmetric line, where the coordinate is x = cos(phi) itself."""
    return x[0]


@dataclass
class Discretisation:
    """Finite-element space and matrices of eq. (3.9) (dimensionless).

    Attributes
    ----------
    basis : skfem.CellBasis
        The basis (with the surface mapping on the sphere).
    stiffness, mass : scipy.sparse.csr_matrix
        K and M over the whole unit sphere (axisymmetric forms include 2 pi).
    pole : int
        Degree of freedom at the north pole (phi = 0).
    kind : str
        ``"sphere"``, ``"ring"`` or ``"axisym"``.
    order : int
        Polynomial order of the elements (and of the geometry on the sphere).
    name : str
        Description of the mesh.
    measure : float
        Factor turning the basis' ``dx`` into the sphere's ``dS``: 1 on the
        sphere, 2 pi on the axisymmetric line.
    polar_cosine : callable
        Global coordinates (shape (dim, ...)) to cos(phi).
    kink : float or None
        ``cos(phi_a)`` if the mesh has nodes (or a ring of edges) there.
    """

    basis: CellBasis
    stiffness: sp.csr_matrix
    mass: sp.csr_matrix
    pole: int
    kind: str
    order: int
    name: str
    measure: float
    polar_cosine: Callable[[np.ndarray], np.ndarray]
    kink: float | None = None

    @property
    def dofs(self) -> int:
        """Number of degrees of freedom."""
        return int(self.basis.N)


def surface_basis(mesh: SphereMesh, order: int, intorder: int | None = None) -> CellBasis:
    """scikit-fem basis of Lagrange order ``order`` on ``mesh`` with its own geometry.

    The geometry is the mesh's: flat for an order-1 mesh, curved for order 2; a
    P2 element on a P2 mesh is isoparametric.
    """
    order = check_order(order)
    geometry = TRIANGLE_ELEMENTS[mesh.order]()
    mapping = SurfaceMapping(mesh.points.T, mesh.cells.T, geometry)
    if intorder is None:
        intorder = max(SURFACE_INTORDER[order], SURFACE_INTORDER[mesh.order])
    return CellBasis(topology(mesh), TRIANGLE_ELEMENTS[order](), mapping=mapping, intorder=intorder)


def dof_nodes(basis: CellBasis, mesh: SphereMesh) -> np.ndarray:
    """For each degree of freedom, the index of the mesh node at the same place.

    Valid when element and geometry have the same order (isoparametric).
    """
    nodes = np.empty(basis.N, dtype=np.int64)
    nodes[basis.element_dofs.T.ravel()] = mesh.cells.ravel()
    return nodes


def sphere_space(mesh: SphereMesh, order: int | None = None) -> Discretisation:
    """Isoparametric space on a sphere mesh: order 1 flat, order 2 curved.

    Parameters
    ----------
    mesh : SphereMesh
        Any order; it is flattened or elevated to ``order``.
    order : {1, 2}, optional
        Element and geometry order (default: the mesh's).

    Returns
    -------
    Discretisation
        K, M of eq. (3.9) on the discrete sphere (dimensionless).
    """
    order = mesh.order if order is None else check_order(order)
    mesh = elevate(mesh) if order == 2 else flatten(mesh)
    basis = surface_basis(mesh, order)
    K = asm(stiffness, basis).tocsr()
    M = asm(mass, basis).tocsr()
    pole = int(basis.nodal_dofs[0, mesh.pole])
    kind = "sphere" if mesh.ring is None else "ring"
    kink = None if mesh.ring is None else float(np.cos(mesh.ring))
    return Discretisation(
        basis, K, M, pole, kind, order, f"{mesh.name}, P{order}", 1.0, sphere_polar_cosine, kink
    )
