"""Reference-to-surface mapping that lets scikit-fem integrate on triangles in 3D.

scikit-fem maps reference triangles to the plane only.  For a triangle on a
surface the Jacobian ``J = dx/dxi`` is 3 x 2; with the metric ``G = J^T J``

* the area element is ``sqrt(det G)`` (returned as ``detDF``), and
* the pseudo-inverse ``(J^T J)^{-1} J^T`` (returned as ``invDF``, shape 2 x 3)
  turns reference gradients into tangential gradients,

so skfem's ``grad`` becomes the surface gradient and ``dot(grad(u), grad(v))``
the Laplace-Beltrami form (the weak form of eq. (3.9) on the sphere).  The
geometry is Lagrange-interpolated from nodes: P1 (flat triangles) or P2, P3, P4
(curved, isoparametric when the element of the same order is used): the map of
order p is ``x(xi) = sum_k x_k phi_k(xi)`` over the element's geometry nodes
``x_k`` and the reference Lagrange basis ``phi_k`` of scikit-fem's
``ElementTriP{p}``, and ``J`` is the same sum over the basis gradients.

:class:`RadialProjectionMapping` is the exact sphere instead: the reference
triangle goes affinely onto the flat triangle of the element's three vertices,
``y(xi) = a + (b - a) xi_1 + (c - a) xi_2``, and then radially onto the unit
sphere, ``x = y / |y|``, with ``J = (I - x x^T) J_y / |y|`` (the derivative of
``y / |y|``).  The discrete surface is the sphere itself, so no geometric error
remains; its images of the equispaced reference nodes are the nodes of
:func:`twoball.fem_membrane.mesh.elevate`.  Dimensionless.
"""

from __future__ import annotations

import numpy as np
from skfem.element import Element
from skfem.mapping import Mapping


class SurfaceMapping(Mapping):
    """Lagrange mapping of reference triangles onto a surface in R^3.

    Parameters
    ----------
    nodes : ndarray, shape (3, P)
        Geometry node coordinates.
    element_nodes : ndarray, shape (n_local, T)
        Geometry node indices per element, in the local order of ``elem``.
    elem : skfem Element
        Lagrange element of the geometry (``ElementTriP1`` to ``ElementTriP4``).

    Notes
    -----
    Implements what :class:`skfem.CellBasis` needs: ``F``, ``DF``, ``detDF`` and
    ``invDF`` at reference points ``X`` of shape (2, Q).  Boundary maps are not
    implemented (a closed surface has no boundary).
    """

    def __init__(self, nodes: np.ndarray, element_nodes: np.ndarray, elem: Element) -> None:
        self.nodes = np.asarray(nodes, dtype=float)
        self.element_nodes = np.asarray(element_nodes, dtype=np.int64)
        self.elem = elem
        self.dim = 2
        if self.nodes.shape[0] != 3:
            raise ValueError("nodes must have shape (3, P)")
        if self.element_nodes.shape[0] != elem.doflocs.shape[0]:
            raise ValueError("element_nodes must have one row per local node of elem")
        self._cache: dict[tuple, np.ndarray] = {}

    def _select(self, tind: np.ndarray | None) -> np.ndarray:
        return self.element_nodes if tind is None else self.element_nodes[:, tind]

    @staticmethod
    def _check_points(X: np.ndarray) -> np.ndarray:
        X = np.asarray(X, dtype=float)
        if X.ndim != 2:
            raise NotImplementedError("SurfaceMapping needs reference points of shape (2, Q)")
        return X

    def F(self, X: np.ndarray, tind: np.ndarray | None = None) -> np.ndarray:
        """Surface points x(xi), shape (3, T, Q)."""
        X = self._check_points(X)
        elements = self._select(tind)
        out = np.zeros((3, elements.shape[1], X.shape[1]))
        for k in range(elements.shape[0]):
            phi, _ = self.elem.lbasis(X, k)
            out += self.nodes[:, elements[k]][:, :, None] * phi[None, None, :]
        return out

    def DF(self, X: np.ndarray, tind: np.ndarray | None = None) -> np.ndarray:
        """Jacobian ``J[i, j] = dx_i / dxi_j``, shape (3, 2, T, Q) (cached)."""
        X = self._check_points(X)
        key = (X.tobytes(), X.shape, None if tind is None else np.asarray(tind).tobytes())
        if key not in self._cache:
            elements = self._select(tind)
            out = np.zeros((3, 2, elements.shape[1], X.shape[1]))
            for k in range(elements.shape[0]):
                _, dphi = self.elem.lbasis(X, k)
                out += self.nodes[:, elements[k]][:, None, :, None] * dphi[None, :, None, :]
            self._cache = {key: out}  # keep only the latest quadrature
        return self._cache[key]

    def metric(self, X: np.ndarray, tind: np.ndarray | None = None) -> np.ndarray:
        """First fundamental form ``G = J^T J``, shape (2, 2, T, Q)."""
        J = self.DF(X, tind)
        return np.einsum("kitq,kjtq->ijtq", J, J)

    def detDF(self, X: np.ndarray, tind: np.ndarray | None = None) -> np.ndarray:
        """Area element ``sqrt(det(J^T J))``, shape (T, Q)."""
        G = self.metric(X, tind)
        det = G[0, 0] * G[1, 1] - G[0, 1] * G[1, 0]
        if np.any(det <= 0.0):
            raise ValueError("degenerate surface element (zero area)")
        return np.sqrt(det)

    def invDF(self, X: np.ndarray, tind: np.ndarray | None = None) -> np.ndarray:
        """Pseudo-inverse ``(J^T J)^{-1} J^T``, shape (2, 3, T, Q).

        skfem forms ``grad_j = sum_i invDF[i, j] dphi_i``, the tangential gradient.
        """
        J = self.DF(X, tind)
        G = self.metric(X, tind)
        det = G[0, 0] * G[1, 1] - G[0, 1] * G[1, 0]
        inverse = np.array([[G[1, 1], -G[0, 1]], [-G[1, 0], G[0, 0]]]) / det
        return np.einsum("ijtq,kjtq->iktq", inverse, J)

    def normals(self, X, tind, find, t2f):  # noqa: D102 - closed surfaces have no facets
        raise NotImplementedError("SurfaceMapping: a closed surface has no boundary facets")


class RadialProjectionMapping(SurfaceMapping):
    """Exact map of reference triangles onto the unit sphere: flat triangle, then ``y / |y|``.

    Parameters
    ----------
    vertices : ndarray, shape (3, V)
        Triangle vertices (on the unit sphere; only their directions matter).
    triangles : ndarray, shape (3, T)
        Vertex indices per element, counter-clockwise seen from outside.

    Notes
    -----
    ``x(xi) = y(xi) / |y(xi)|`` with ``y`` the affine map onto the flat triangle
    of the three vertices, and ``J = (I - x x^T) J_y / |y|``, where the columns
    of ``J_y`` are the edge vectors ``b - a`` and ``c - a``.  Every point of the
    element lies on the unit sphere, so the area element and the tangential
    gradients are those of the sphere itself (the geometric error of
    isoparametric elements is absent).  Used with any element order.
    """

    def __init__(self, vertices: np.ndarray, triangles: np.ndarray) -> None:
        from skfem import ElementTriP1

        super().__init__(vertices, triangles, ElementTriP1())

    def _flat(self, X: np.ndarray, tind: np.ndarray | None) -> tuple[np.ndarray, np.ndarray]:
        """Flat points y (3, T, Q) and edge vectors J_y (3, 2, T)."""
        elements = self._select(tind)
        a, b, c = (self.nodes[:, elements[k]] for k in range(3))
        edges = np.stack([b - a, c - a], axis=1)  # (3, 2, T)
        y = a[:, :, None] + np.einsum("ijt,jq->itq", edges, X)
        return y, edges

    def F(self, X: np.ndarray, tind: np.ndarray | None = None) -> np.ndarray:
        """Points on the unit sphere ``x(xi) = y / |y|``, shape (3, T, Q)."""
        y, _ = self._flat(self._check_points(X), tind)
        return y / np.linalg.norm(y, axis=0)[None]

    def DF(self, X: np.ndarray, tind: np.ndarray | None = None) -> np.ndarray:
        """Jacobian ``(I - x x^T) J_y / |y|``, shape (3, 2, T, Q) (cached)."""
        X = self._check_points(X)
        key = (X.tobytes(), X.shape, None if tind is None else np.asarray(tind).tobytes())
        if key not in self._cache:
            y, edges = self._flat(X, tind)
            norm = np.linalg.norm(y, axis=0)  # (T, Q)
            x = y / norm[None]
            along = np.einsum("itq,ijt->jtq", x, edges)  # x . (J_y)_j
            out = (edges[:, :, :, None] - x[:, None] * along[None]) / norm[None, None]
            self._cache = {key: out}
        return self._cache[key]
