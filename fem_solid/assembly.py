"""Fast assembly of 3-D isotropic elasticity for a vector Lagrange basis.

scikit-fem's generic ``asm`` evaluates the form of :func:`twoball.fem_solid.forms.elasticity`
once per pair of the 30 vector basis functions of a P2 tetrahedron (900 array
expressions).  For an isotropic material the element matrix factors through the
scalar gradient products

    G_ab^ij = int d_i phi_a d_j phi_b dx                                   (F1)

as K_(a i),(b j) = lambda G_ab^ij + mu G_ab^ji + mu delta_ij sum_k G_ab^kk, the same
bilinear form C(eps(u)) : eps(v) with u = phi_b e_j, v = phi_a e_i; the mass is
M_(a i),(b j) = rho delta_ij int phi_a phi_b.  One einsum per element batch gives G.
The global numbering is scikit-fem's ``ElementVector``: scalar dof s, component c ->
3 s + c (checked against ``asm`` in the tests).
"""

from __future__ import annotations

import numpy as np
from scipy.sparse import coo_matrix, csr_matrix
from skfem import Basis, ElementTetP1, ElementTetP2, ElementVector
from skfem.mesh import MeshTet1, MeshTet2

__all__ = ["elasticity_matrices"]


def elasticity_matrices(
    mesh: MeshTet1 | MeshTet2,
    lam: float,
    mu: float,
    density: float = 1.0,
    intorder: int = 4,
    chunk_size: int = 8000,
) -> tuple[csr_matrix, csr_matrix, Basis]:
    """Stiffness and mass of 3-D elasticity on a tetrahedral mesh, eq. (F1).

    P2 on a quadratic mesh (``MeshTet2``, isoparametric), P1 on a linear one
    (``MeshTet1``, straight facets).

    Parameters
    ----------
    mesh : MeshTet1 or MeshTet2
        Linear or quadratic (isoparametric) tetrahedral mesh; it sets the element order.
    lam, mu : float
        Lame parameters (consistent units).
    density : float, optional
        rho.
    intorder : int, optional
        Quadrature order (4 integrates P2 x P2 products exactly on straight elements).
    chunk_size : int, optional
        Elements per batch.

    Returns
    -------
    K, M : csr_matrix
        In the numbering of ``vector_basis``.
    vector_basis : Basis
        ``Basis(mesh, ElementVector(ElementTetP2()))`` (or P1) of that numbering.
    """
    element = ElementTetP2() if isinstance(mesh, MeshTet2) else ElementTetP1()
    scalar = Basis(mesh, element, intorder=intorder)
    nloc = len(scalar.basis)
    size = 3 * scalar.N
    eye = np.eye(3)
    k = csr_matrix((size, size))
    m = csr_matrix((size, size))
    # batches of elements bound the memory of the 900 local entries per element
    for chunk in np.array_split(np.arange(mesh.nelements), 1 + mesh.nelements // chunk_size):
        grads = np.array([scalar.basis[a][0].grad[:, chunk] for a in range(nloc)])  # (a,i,e,q)
        values = np.array([np.asarray(scalar.basis[a][0])[chunk] for a in range(nloc)])  # (a, e, q)
        dx = scalar.dx[chunk]  # (e, q)
        g = np.einsum("aieq,bjeq,eq->eabij", grads, grads, dx, optimize=True)
        lap = np.einsum("eabkk->eab", g)
        k_local = (
            lam * g + mu * g.transpose(0, 1, 2, 4, 3) + mu * lap[..., None, None] * eye
        ).transpose(0, 1, 3, 2, 4)  # (e, a, i, b, j)
        m_scalar = density * np.einsum("aeq,beq,eq->eab", values, values, dx, optimize=True)
        m_local = np.broadcast_to(
            m_scalar[:, :, None, :, None] * eye[None, None, :, None, :], k_local.shape
        )
        dofs = scalar.element_dofs[:, chunk].T  # (e, a)
        vdofs = (3 * dofs[:, :, None] + np.arange(3)[None, None, :]).reshape(len(chunk), -1)
        vdofs = vdofs.astype(np.int32)
        rows = np.repeat(vdofs, 3 * nloc, axis=1).ravel()
        cols = np.tile(vdofs, (1, 3 * nloc)).ravel()
        k = k + coo_matrix((k_local.ravel(), (rows, cols)), shape=(size, size)).tocsr()
        m = m + coo_matrix((m_local.ravel(), (rows, cols)), shape=(size, size)).tocsr()
    return k.tocsr(), m.tocsr(), Basis(mesh, ElementVector(element), intorder=intorder)
