"""Axisymmetric reduction: eq. (3.9) on the line x = cos(phi) in [-1, 1].

For u = u(phi) the Laplace-Beltrami weak form becomes ``int (1 - x^2) u' v' dx``
and the mass ``int u v dx`` (scikit-fem example 16 solves this eigenproblem;
its eigenfunctions are the Legendre polynomials P_n with eigenvalues n (n + 1),
eq. (3.11)).  Both forms carry the factor 2 pi of the azimuth, so K and M are the
whole-sphere matrices restricted to axisymmetric functions: the mass of the
constant is 4 pi and modal energies agree with the sphere backend.  The pole
displacement does not depend on this normalisation (a factor s in M scales the
M-orthonormal modes by 1/sqrt(s) and their coefficients by sqrt(s)).

The pole phi = 0 is x = 1.  Nodes are equally spaced in phi on each side of
phi_a (so elements shrink in x towards the poles, where the Legendre modes vary
fastest in x), with a node exactly at ``x = cos(phi_a)``, the kink of F.
"""

from __future__ import annotations

import math

import numpy as np
from skfem import CellBasis, ElementLineP1, ElementLineP2, MeshLine1, asm
from skfem.element import ElementH1
from skfem.refdom import RefLine

from twoball.fem_membrane.forms import AZIMUTH, axisym_mass, axisym_stiffness
from twoball.fem_membrane.space import Discretisation, line_polar_cosine
from twoball.fem_membrane.validate import check_elements, check_order
from twoball.modal.initial import check_phi_a


class ElementLineLagrange(ElementH1):
    """Lagrange line element of order p with equispaced nodes (scikit-fem style).

    Local nodes: the two vertices 0 and 1 of the reference line, then the
    interior nodes ``k / p`` (k = 1 .. p - 1) in increasing order.  scikit-fem's
    own ``ElementLinePp`` is hierarchical (integrated Legendre polynomials)
    and has no node locations, so nodal interpolation and ``doflocs`` need
    this one for p = 3, 4.  On a line each element owns its interior nodes,
    so no orientation question arises.
    """

    nodal_dofs = 1
    refdom = RefLine

    def __init__(self, p: int) -> None:
        self.p = int(p)
        self.interior_dofs = self.p - 1
        self.maxdeg = self.p
        self.dofnames = ["u"] * self.p
        nodes = np.concatenate([[0.0, 1.0], np.arange(1, self.p) / self.p])
        self.doflocs = nodes[:, None]
        self._nodes = nodes

    def lbasis(self, X: np.ndarray, i: int) -> tuple[np.ndarray, np.ndarray]:
        """Value and derivative of the i-th Lagrange polynomial at reference points X.

        ``X`` is ``(1, Q)`` in assembly and ``(1, N, 1)`` when scikit-fem probes
        points (``Basis.probes``, as the cap average does); any shape after the
        first axis is kept, as scikit-fem's own elements do.
        """
        if not 0 <= i < self.p + 1:
            self._index_error()
        x = np.asarray(X[0])
        others = np.delete(self._nodes, i)
        scale = np.prod(self._nodes[i] - others)
        factors = x[None, ...] - others.reshape((-1,) + (1,) * x.ndim)  # (p, *x.shape)
        phi = np.prod(factors, axis=0) / scale
        dphi = np.zeros_like(x)
        for k in range(others.size):
            dphi = dphi + np.prod(np.delete(factors, k, axis=0), axis=0)
        return phi, np.array([dphi / scale])


LINE_ELEMENTS = {
    1: ElementLineP1,
    2: ElementLineP2,
    3: lambda: ElementLineLagrange(3),
    4: lambda: ElementLineLagrange(4),
}


def axisym_nodes(elements: int, phi_a: float) -> np.ndarray:
    """Vertices x = cos(phi), ascending from -1 to 1, with one at cos(phi_a).

    ``E_a = round(E phi_a / pi)`` (clamped to 1 .. E - 1) elements of equal
    polar-angle length cover [0, phi_a], the others [phi_a, pi].
    """
    elements = check_elements(elements)
    phi_a = check_phi_a(phi_a)
    north = min(max(round(elements * phi_a / math.pi), 1), elements - 1)
    phi = np.concatenate(
        [np.linspace(0.0, phi_a, north + 1), np.linspace(phi_a, math.pi, elements - north + 1)[1:]]
    )
    x = np.cos(phi)
    x[0], x[north], x[-1] = 1.0, math.cos(phi_a), -1.0
    return x[::-1].copy()


def axisym_mesh(elements: int, phi_a: float) -> MeshLine1:
    """scikit-fem line mesh on [-1, 1] with ``elements`` elements and a vertex at cos(phi_a)."""
    return MeshLine1.init_tensor(axisym_nodes(elements, phi_a))


def axisym_space(elements: int, phi_a: float, order: int = 2) -> Discretisation:
    """Axisymmetric P1 to P4 space of eq. (3.9) with whole-sphere K and M (dimensionless).

    The line is straight (no geometric error); the forms' weight ``1 - x^2``
    is a polynomial, so Gauss quadrature of degree ``2 p + 2`` integrates K and
    M exactly.

    Parameters
    ----------
    elements : int
        Number of line elements E >= 2.
    phi_a : float
        Contact angle [rad] in (pi/2, pi); a vertex is put at x = cos(phi_a).
    order : {1, 2, 3, 4}
        Polynomial order; P3, P4: :class:`ElementLineLagrange`.

    Returns
    -------
    Discretisation
        Pole degree of freedom at x = 1; ``measure`` 2 pi.
    """
    order = check_order(order)
    mesh = axisym_mesh(elements, phi_a)
    basis = CellBasis(mesh, LINE_ELEMENTS[order](), intorder=2 * order + 2)
    K = asm(axisym_stiffness, basis).tocsr()
    M = asm(axisym_mass, basis).tocsr()
    pole = int(basis.nodal_dofs[0, int(np.argmax(mesh.p[0]))])
    name = f"axisymmetric line, {elements} elements, P{order}"
    return Discretisation(
        basis, K, M, pole, "axisym", order, name, AZIMUTH, line_polar_cosine, math.cos(phi_a)
    )
