"""A finite-element space on the sphere or the axisymmetric line, with its matrices.

:class:`Discretisation` bundles what every later step needs: the scikit-fem
basis, stiffness K and mass M (dimensionless, measure of the whole unit sphere),
the pole functional (the finite-element function's value at the north pole),
and how to read the polar angle from global coordinates.

The pole functional is a sparse row ``pole_row`` with ``pole_row @ u = u(pole)``:
the values of the basis functions at the pole in the element that holds it.
With a node at the pole (every generated mesh) it is the unit row of that
node's degree of freedom, and :func:`pole_value` reads the entry itself, so
results are bit-identical to indexing ``u[pole]``; a mesh read from a file may
have the pole anywhere inside an element.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

import numpy as np
import scipy.sparse as sp
from skfem import CellBasis, ElementTriP1, ElementTriP2, ElementTriP3, ElementTriP4, MeshTri1, asm
from skfem.assembly import Dofs
from skfem.element import Element

from twoball._common.errors import ParameterError
from twoball.fem_membrane.forms import mass, stiffness
from twoball.fem_membrane.locate import locate_pole
from twoball.fem_membrane.mapping import RadialProjectionMapping, SurfaceMapping
from twoball.fem_membrane.mesh import SphereMesh, elevate, flatten, topology
from twoball.fem_membrane.validate import GEOMETRIES, check_choice, check_order

PoleFunctional = int | sp.spmatrix
"""A degree-of-freedom index at the pole, or a sparse row (1, dofs) evaluating u there."""

TRIANGLE_ELEMENTS = {1: ElementTriP1, 2: ElementTriP2, 3: ElementTriP3, 4: ElementTriP4}
# quadrature degree for K and M: exact on flat P1 (degree 2); on curved order-p
# triangles the integrands are rational (sqrt det G, G^-1), integrated with
# degree 2p + 2: the polynomial part u v is of degree 2p, the metric adds two
SURFACE_INTORDER = {1: 2, 2: 6, 3: 8, 4: 10}
# on the exact sphere the metric is rational for every order: degree 2p + 2 for P1 too
EXACT_INTORDER = {1: 4, 2: 6, 3: 8, 4: 10}


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
    pole_row : scipy.sparse.csr_matrix, shape (1, dofs)
        Pole functional: ``pole_row @ u`` is u at the north pole (phi = 0).  An
        integer given here is turned into the unit row of that degree of freedom.
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
    geometry : {"isoparametric", "exact"}
        Discrete surface of the sphere spaces: the Lagrange interpolant of order
        ``order`` through the nodes, or the sphere itself
        (:class:`~twoball.fem_membrane.mapping.RadialProjectionMapping`); the
        axisymmetric line is exact either way.
    """

    basis: CellBasis
    stiffness: sp.csr_matrix
    mass: sp.csr_matrix
    pole_row: sp.csr_matrix
    kind: str
    order: int
    name: str
    measure: float
    polar_cosine: Callable[[np.ndarray], np.ndarray]
    kink: float | None = None
    geometry: str = "isoparametric"

    def __post_init__(self) -> None:
        self.pole_row = pole_functional(self.pole_row, self.dofs)

    @property
    def dofs(self) -> int:
        """Number of degrees of freedom."""
        return int(self.basis.N)

    def operator(self, membrane: Any = None) -> sp.csr_matrix:
        """The membrane operator's matrix: K (the paper's), or ``K - 2 M`` (pressurised).

        ``membrane`` is a :class:`~twoball.modal.membrane.Membrane` (None: the
        paper's).  The ``-2 u^2 / R^2`` term of the pressurised membrane is the
        mass form times -2 (:mod:`twoball.fem_membrane.forms`), so its
        eigenvectors are the Laplacian's and its eigenvalues ``lambda_h - 2``:
        the same error, hence the same order ``h^(2p)``, as the membrane's.
        Dimensionless.
        """
        if membrane is None or not membrane.pressurised:
            return self.stiffness
        return (self.stiffness - membrane.shift * self.mass).tocsr()

    @property
    def pole(self) -> int:
        """The degree of freedom at the north pole; ValueError if the pole is not a node.

        Code that must work for any mesh uses :attr:`pole_row` (or
        :func:`pole_value`) instead.
        """
        index, weights = pole_weights(self.pole_row)
        if index.size != 1 or weights[0] != 1.0:
            raise ValueError(
                f"{self.name}: the pole lies inside an element, not at a degree of "
                "freedom; evaluate it with pole_row"
            )
        return int(index[0])


def pole_functional(pole: PoleFunctional, dofs: int) -> sp.csr_matrix:
    """The pole functional as a sparse row (1, dofs); an index becomes a unit row."""
    if isinstance(pole, int | np.integer):
        if not 0 <= int(pole) < dofs:
            raise ValueError(f"pole index {pole} outside 0 .. {dofs - 1}")
        return sp.csr_matrix(([1.0], ([0], [int(pole)])), shape=(1, dofs))
    row = sp.csr_matrix(pole)
    if row.shape != (1, dofs):
        raise ValueError(f"pole row must have shape (1, {dofs}), got {row.shape}")
    return row


def pole_weights(pole: PoleFunctional) -> tuple[np.ndarray, np.ndarray]:
    """Degrees of freedom and weights of the pole functional (an index has weight 1)."""
    if isinstance(pole, int | np.integer):
        return np.array([int(pole)]), np.array([1.0])
    row = sp.csr_matrix(pole)
    return row.indices.astype(np.int64), row.data.astype(float)


def pole_value(pole: PoleFunctional, values: np.ndarray) -> np.ndarray:
    """``values`` (shape (dofs, ...)) evaluated at the pole: shape ``values.shape[1:]``.

    A unit functional (a node at the pole) returns ``values[index]`` itself, so
    results are bit-identical to indexing by the pole's degree of freedom.
    """
    index, weights = pole_weights(pole)
    if index.size == 1 and weights[0] == 1.0:
        return values[index[0]]
    return np.tensordot(weights, values[index], axes=1)


def pole_vector(pole: PoleFunctional, dofs: int) -> np.ndarray:
    """The pole functional as a dense vector e with ``e @ u = u(pole)``."""
    index, weights = pole_weights(pole)
    out = np.zeros(dofs)
    np.add.at(out, index, weights)
    return out


def surface_pole_row(basis: CellBasis, mesh: SphereMesh, exact: bool = False) -> sp.csr_matrix:
    """Pole functional of a sphere basis: basis values at the pole (0, 0, 1) of ``mesh``.

    With a node at the pole it is the unit row of that node's degree of freedom
    (as for every generated mesh); otherwise the pole is located in its element
    by :func:`twoball.fem_membrane.locate.locate_pole` and the row holds the values
    of that element's basis functions there (they sum to 1).  With the exact
    geometry (``exact``) the pole is located on the flat triangles, whose radial
    projection the elements are.  Dimensionless.
    """
    node = mesh.pole_node
    if node is not None:
        element, local = np.argwhere(mesh.cells == node)[0]
        if local < basis.Nbfun:  # the node is one of the element's own nodes
            return pole_functional(int(basis.element_dofs[local, element]), basis.N)
    element, xi = locate_pole(flatten(mesh) if exact else mesh)
    point = xi[:, None]
    values = np.array([basis.elem.lbasis(point, i)[0][0] for i in range(basis.Nbfun)])
    dofs = basis.element_dofs[:, element]
    return sp.csr_matrix((values, (np.zeros(dofs.size, dtype=np.int64), dofs)), shape=(1, basis.N))


def oriented_dofs(topo: MeshTri1, elem: Element) -> Dofs:
    """scikit-fem's degree-of-freedom numbering, made conforming on unsorted triangles.

    scikit-fem numbers the ``k``-th degree of freedom of an edge the same in
    both triangles sharing it, which is right only if both traverse the edge
    in the same direction (its meshes sort each triangle's vertices for this).
    Our triangles keep their outward orientation (``sort_t=False``), so
    neighbours traverse a shared edge in opposite directions; with two or more
    nodes per edge (P3, P4) the local rows of every edge running from the
    higher to the lower vertex index are reversed here.  Global edge degree of
    freedom ``k`` is then the ``k``-th node from the edge's lower vertex, as in
    :func:`twoball.fem_membrane.mesh.elevate`.  P1 and P2 are returned unchanged.
    """
    dofs = Dofs(topo, elem)
    per_edge = int(elem.facet_dofs)
    if per_edge < 2:
        return dofs
    t = topo.t
    element_dofs = dofs.element_dofs.copy()
    first = 3 * int(elem.nodal_dofs)
    for j, (a, b) in enumerate(topo.refdom.facets):
        rows = first + j * per_edge + np.arange(per_edge)
        backward = t[a] > t[b]
        element_dofs[np.ix_(rows, np.flatnonzero(backward))] = element_dofs[
            np.ix_(rows[::-1], np.flatnonzero(backward))
        ]
    dofs.element_dofs = element_dofs
    return dofs


def surface_basis(
    mesh: SphereMesh, order: int, intorder: int | None = None, geometry: str = "isoparametric"
) -> CellBasis:
    """scikit-fem basis of Lagrange order ``order`` on ``mesh``.

    ``geometry="isoparametric"``: the mesh's own geometry, flat for an order-1
    mesh, curved for orders 2 to 4 (an order-p element on an order-p mesh is
    isoparametric); quadrature degree :data:`SURFACE_INTORDER` of the higher of
    the two orders.  ``geometry="exact"``: the unit sphere itself through
    :class:`~twoball.fem_membrane.mapping.RadialProjectionMapping` of the mesh's
    triangles, quadrature degree :data:`EXACT_INTORDER`.  Degrees of freedom are
    numbered by :func:`oriented_dofs`.
    """
    order = check_order(order)
    geometry = check_choice("geometry", geometry, GEOMETRIES)
    if geometry == "exact":
        mapping = RadialProjectionMapping(mesh.points[: mesh.vertex_count].T, mesh.triangles.T)
        intorder = EXACT_INTORDER[order] if intorder is None else intorder
    else:
        lagrange = TRIANGLE_ELEMENTS[mesh.order]()
        mapping = SurfaceMapping(mesh.points.T, mesh.cells.T, lagrange)
    if intorder is None:
        intorder = max(SURFACE_INTORDER[order], SURFACE_INTORDER[mesh.order])
    topo = topology(mesh)
    elem = TRIANGLE_ELEMENTS[order]()
    dofs = oriented_dofs(topo, elem)
    return CellBasis(topo, elem, mapping=mapping, intorder=intorder, dofs=dofs)


def dof_mesh(basis: CellBasis, name: str, ring: float | None = None) -> SphereMesh:
    """The unit-sphere mesh whose nodes are the degrees of freedom of ``basis``.

    For Lagrange elements every degree of freedom sits at a node of the element:
    the nodes are ``doflocs`` and the cells their numbering (skfem's local order:
    vertices, then edges 01, 12, 20 -- meshio's ``triangle6`` at order 2), so
    eigenvectors are values at these nodes as they are.  ``ring``: phi_a of a
    ring sphere.
    """
    return SphereMesh(basis.doflocs.T, basis.element_dofs.T, name, ring)


def dof_nodes(basis: CellBasis, mesh: SphereMesh) -> np.ndarray:
    """For each degree of freedom, the index of the mesh node at the same place.

    Valid when element and geometry have the same order (isoparametric).
    """
    nodes = np.empty(basis.N, dtype=np.int64)
    nodes[basis.element_dofs.T.ravel()] = mesh.cells.ravel()
    return nodes


def sphere_space(
    mesh: SphereMesh, order: int | None = None, geometry: str = "isoparametric"
) -> Discretisation:
    """Space on a sphere mesh: isoparametric (order 1 flat, 2 to 4 curved) or on the exact sphere.

    Parameters
    ----------
    mesh : SphereMesh
        Any order; it is flattened or elevated to ``order``.
    order : {1, 2, 3, 4}, optional
        Element (and isoparametric geometry) order (default: the mesh's).
    geometry : {"isoparametric", "exact"}
        The order-p interpolant of the sphere through the mesh's nodes, or the
        sphere itself (radial projection of the flat triangles, see
        :class:`~twoball.fem_membrane.mapping.RadialProjectionMapping`); with
        ``exact`` only the mesh's vertices are used and its nodes are rebuilt as
        the images of the reference nodes.  A ring sphere keeps its ring edges
        on the circle of latitude, which the radial projection would not:
        ``exact`` is refused there.

    Returns
    -------
    Discretisation
        K, M of eq. (3.9) on the discrete sphere (dimensionless).
    """
    order = mesh.order if order is None else check_order(order)
    geometry = check_choice("geometry", geometry, GEOMETRIES)
    exact = geometry == "exact"
    if exact and mesh.ring is not None:
        raise ParameterError(
            "geometry", "isoparametric on the ring sphere (its ring edges follow phi_a)", geometry
        )
    if exact:
        mesh = flatten(mesh)  # nodes rebuilt from the vertices: the exact images
    mesh = elevate(mesh, order) if order > 1 else flatten(mesh)
    basis = surface_basis(mesh, order, geometry=geometry)
    K = asm(stiffness, basis).tocsr()
    M = asm(mass, basis).tocsr()
    pole = surface_pole_row(basis, mesh, exact)
    kind = "sphere" if mesh.ring is None else "ring"
    kink = None if mesh.ring is None else float(np.cos(mesh.ring))
    name = f"{mesh.name}, P{order}" + (", exact geometry" if exact else "")
    return Discretisation(
        basis, K, M, pole, kind, order, name, 1.0, sphere_polar_cosine, kink, geometry
    )
