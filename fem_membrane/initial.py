"""The initial displacement F of eq. (3.10) in the finite-element space.

The Galerkin L2 projection ``M u0 = b`` with ``b_i = int F phi_i dS`` is the
discrete twin of the Legendre coefficient integral (3.12): the modal coefficient
of an M-orthonormal mode is ``phi_k^T M u0 = phi_k^T b = int F phi_k dS``.  F has
a kink at phi = phi_a, so the load b is integrated with a composite rule
(the reference element split ``4**s`` times for triangles, ``2**s`` times for
lines) on every element the kink may touch, and with an ordinary Gauss rule
elsewhere.  On the sphere F is evaluated at the radial projection of each
quadrature point onto the unit sphere (``cos(phi) = z / |x|``).  Nodal interpolation
is offered as an alternative.  Dimensionless.

Orders 3 and 4: the smooth rule has degree ``2 p + 4`` (10, 12), the
composite rule on cut elements the same degree on each of the ``4**s``
sub-triangles; the partial bases share the space's degree-of-freedom
numbering (``dofs=basis.dofs``: P3/P4 edge numbering is orientation-corrected,
see :func:`twoball.fem_membrane.space.oriented_dofs`).
"""

from __future__ import annotations

import math

import numpy as np
from scipy.sparse.linalg import splu
from skfem import CellBasis, LinearForm, MeshLine1, MeshTri1
from skfem.quadrature import get_quadrature
from skfem.refdom import RefLine, RefTri

from twoball.fem_membrane.space import Discretisation
from twoball.fem_membrane.validate import INITIAL_METHODS, check_choice
from twoball.modal.initial import check_phi_a, initial_displacement_x

KINK_SUBDIVISIONS = 4  # refinements of the reference element on elements cut by the kink
LOAD_EXTRA_ORDER = 4  # quadrature degree beyond 2 * order for the smooth parts of F


@LinearForm
def _load(v, w):
    return w.f * v


def composite_rule(refdom: type, subdivisions: int, degree: int) -> tuple[np.ndarray, np.ndarray]:
    """Quadrature on the reference triangle/line split uniformly ``subdivisions`` times."""
    base_points, base_weights = get_quadrature(refdom, degree)
    if refdom is RefTri:
        sub = MeshTri1.init_refdom().refined(subdivisions)
    elif refdom is RefLine:
        sub = MeshLine1.init_refdom().refined(subdivisions)
    else:
        raise NotImplementedError(refdom)
    corners = sub.p[:, sub.t]  # (dim, nodes, cells)
    origin = corners[:, 0, :]
    edges = corners[:, 1:, :] - origin[:, None, :]  # (dim, dim, cells): columns = edge vectors
    points = origin[:, :, None] + np.einsum("ikc,kq->icq", edges, base_points)
    if refdom is RefTri:
        scale = np.abs(edges[0, 0] * edges[1, 1] - edges[0, 1] * edges[1, 0])
    else:
        scale = np.abs(edges[0, 0])
    weights = scale[:, None] * base_weights[None, :]
    return points.reshape(points.shape[0], -1), weights.reshape(-1)


def kink_elements(space: Discretisation, phi_a: float, samples: int = 2) -> np.ndarray:
    """Indices of elements on which cos(phi) - cos(phi_a) may change sign.

    Sampled at the vertices of the reference element refined ``samples`` times,
    with a margin of a quarter of each element's range of cos(phi), so elements
    with the kink on their boundary are included.
    """
    basis = space.basis
    refdom = basis.mesh.refdom
    sub = (MeshTri1 if refdom is RefTri else MeshLine1).init_refdom().refined(samples)
    x = basis.mapping.F(sub.p)
    c = space.polar_cosine(x) - math.cos(phi_a)
    low, high = c.min(axis=1), c.max(axis=1)
    margin = 0.25 * (high - low)
    return np.flatnonzero((low - margin <= 0.0) & (high + margin >= 0.0))


def initial_load(
    space: Discretisation, phi_a: float, subdivisions: int = KINK_SUBDIVISIONS
) -> np.ndarray:
    """Load vector ``b_i = int F phi_i dS`` over the unit sphere, eqs. (3.10), (3.12).

    Parameters
    ----------
    space : Discretisation
        Sphere or axisymmetric space.
    phi_a : float
        Contact angle [rad] in (pi/2, pi).
    subdivisions : int
        Refinements of the reference element for the composite rule on elements
        touched by the kink.

    Returns
    -------
    ndarray, shape (dofs,)
        ``b = M u_proj`` (dimensionless).
    """
    phi_a = check_phi_a(phi_a)
    basis = space.basis
    mesh, elem, mapping = basis.mesh, basis.elem, basis.mapping
    degree = 2 * space.order + LOAD_EXTRA_ORDER
    cut = kink_elements(space, phi_a)
    smooth = np.setdiff1d(np.arange(mesh.nelements), cut)
    load = np.zeros(basis.N)
    rules = [
        (smooth, get_quadrature(mesh.refdom, degree)),
        (cut, composite_rule(mesh.refdom, subdivisions, degree)),
    ]
    for elements, rule in rules:
        if elements.size == 0:
            continue
        part = CellBasis(
            mesh, elem, mapping=mapping, quadrature=rule, elements=elements, dofs=basis.dofs
        )
        x = np.asarray(part.global_coordinates())
        f = space.measure * initial_displacement_x(space.polar_cosine(x), phi_a)
        load += _load.assemble(part, f=f)
    return load


def project_initial(space: Discretisation, phi_a: float) -> np.ndarray:
    """Galerkin L2 projection of F onto the space: solves ``M u = b`` (dimensionless)."""
    return splu(space.mass.tocsc()).solve(initial_load(space, phi_a))


def interpolate_initial(space: Discretisation, phi_a: float) -> np.ndarray:
    """Nodal interpolant of F: F at each degree of freedom's location (dimensionless)."""
    phi_a = check_phi_a(phi_a)
    return initial_displacement_x(space.polar_cosine(space.basis.doflocs), phi_a)


def initial_moments(space: Discretisation, phi_a: float, method: str = "projection") -> np.ndarray:
    """``M u0`` for the projected (``b`` itself) or the interpolated initial displacement.

    The modal coefficients are ``Phi^T M u0`` for M-orthonormal modes Phi.
    """
    method = check_choice("initial", method, INITIAL_METHODS)
    if method == "projection":
        return initial_load(space, phi_a)
    return space.mass @ interpolate_initial(space, phi_a)
