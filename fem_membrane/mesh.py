"""Triangulations of the unit sphere: icosphere and a latitude-ring sphere, order 1 to 4.

All meshes have a vertex exactly at the north pole (0, 0, 1) -- the point whose
motion decides lift-off -- and outward-oriented triangles (counter-clockwise seen
from outside).  Every vertex and every higher-order node lies on the unit sphere,
so a P1 mesh is an inscribed polyhedron and a P2, P3 or P4 mesh an isoparametric
curved surface (nodes: the equispaced points of the flat triangle, projected
radially; see :func:`elevate`).  Lengths are dimensionless (unit R).

Two families:

``icosphere(level)``
    Icosahedron with a vertex at the pole, each triangle split into four
    ``level`` times with the new vertices projected radially onto the sphere:
    ``10 * 4**level + 2`` vertices, nested refinement.
``ring_sphere(level, phi_a)``
    Rows of vertices on circles of latitude (an octahedron subdivided row by row:
    row i from the pole holds ``4 min(i, 2n - i)`` vertices, equally spaced in
    longitude), with the row latitudes chosen so that one row lies exactly on
    ``phi = phi_a``.  The kink of the initial condition (3.10) then runs along
    mesh edges.  ``n`` is set from ``level`` so that the vertex count
    ``4 n**2 + 2`` is close to the icosphere's of the same level.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace
from pathlib import Path

import numpy as np
from skfem import MeshTri1

from twoball._common.errors import ParameterError
from twoball.fem_membrane.validate import check_level, check_order

POLE = np.array([0.0, 0.0, 1.0])
_POLE_TOLERANCE = 1e-12
NODES_PER_TRIANGLE = {p: (p + 1) * (p + 2) // 2 for p in (1, 2, 3, 4)}
ORDER_OF_NODES = {n: p for p, n in NODES_PER_TRIANGLE.items()}


@dataclass(frozen=True)
class SphereMesh:
    """A triangulation of the unit sphere (dimensionless, radius 1).

    Parameters
    ----------
    points : ndarray, shape (P, 3)
        Node coordinates; the first ``vertex_count`` rows are the triangle
        vertices, then the edge nodes (``p - 1`` per edge, numbered from the
        edge's lower vertex index), then the interior nodes (orders 3, 4).
    cells : ndarray, shape (T, (p + 1)(p + 2) / 2): 3, 6, 10 or 15 columns
        Node indices per triangle, counter-clockwise seen from outside, in the
        local order of scikit-fem's ``ElementTriP{p}``: vertices 0, 1, 2, then
        the ``p - 1`` nodes of edge 01 (from vertex 0), of edge 12 (from vertex
        1), of edge 02 (from vertex 0), then the interior nodes.  Six columns
        (order 2) are also the meshio/VTK ``triangle6`` order (edges 01, 12, 20:
        a single midpoint per edge has no direction).
    name : str
        Human-readable description, e.g. ``"icosphere level 3"``.
    ring : float or None
        Polar angle of a latitude circle made of mesh edges, if any.
    """

    points: np.ndarray
    cells: np.ndarray
    name: str = "sphere"
    ring: float | None = None

    def __post_init__(self) -> None:
        points = np.ascontiguousarray(self.points, dtype=float)
        cells = np.ascontiguousarray(self.cells, dtype=np.int64)
        if points.ndim != 2 or points.shape[1] != 3:
            raise ValueError("points must have shape (P, 3)")
        if cells.ndim != 2 or cells.shape[1] not in NODES_PER_TRIANGLE.values():
            raise ValueError("cells must have shape (T, 3), (T, 6), (T, 10) or (T, 15)")
        object.__setattr__(self, "points", points)
        object.__setattr__(self, "cells", cells)

    @property
    def order(self) -> int:
        """Geometric order p: 1 (flat triangles) to 4 (curved 15-node triangles)."""
        return ORDER_OF_NODES[self.cells.shape[1]]

    @property
    def triangles(self) -> np.ndarray:
        """Vertex indices per triangle, shape (T, 3)."""
        return self.cells[:, :3]

    @property
    def vertex_count(self) -> int:
        """Number of triangle vertices (points used as corners)."""
        return int(self.triangles.max()) + 1

    @property
    def pole(self) -> int:
        """Index of the vertex at the north pole (0, 0, 1).

        Raises ValueError when no vertex lies there (a mesh read from a file may
        have the pole inside an element: see :attr:`pole_node` and
        :func:`locate_pole`).
        """
        index = int(np.argmax(self.points[: self.vertex_count, 2]))
        if np.linalg.norm(self.points[index] - POLE) > _POLE_TOLERANCE:
            raise ValueError(
                f"{self.name}: no vertex at the north pole (0, 0, 1); "
                "the pole lies inside an element (see locate_pole)"
            )
        return index

    @property
    def pole_node(self) -> int | None:
        """Index of the node (vertex, edge or interior node) at the north pole, or None."""
        index = int(np.argmax(self.points[:, 2]))
        if np.linalg.norm(self.points[index] - POLE) > _POLE_TOLERANCE:
            return None
        return index

    def area(self) -> float:
        """Area of the flat triangles (the P1 surface); tends to 4 pi."""
        p = self.points[self.triangles]
        normal = np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0])
        return 0.5 * float(np.linalg.norm(normal, axis=1).sum())


# --- construction helpers ---------------------------------------------------------------


def _normalise(points: np.ndarray) -> np.ndarray:
    return points / np.linalg.norm(points, axis=1, keepdims=True)


def orient_outward(points: np.ndarray, triangles: np.ndarray) -> np.ndarray:
    """Reorder triangle vertices so that every normal points away from the origin."""
    p = points[triangles]
    normal = np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0])
    inward = np.einsum("ij,ij->i", normal, p.sum(axis=1)) < 0.0
    out = triangles.copy()
    out[inward] = out[inward][:, [0, 2, 1]]
    return out


def _edges(triangles: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Unique edges (sorted vertex pairs) and, per triangle, the indices of edges 01, 12, 20."""
    local = triangles[:, [0, 1, 1, 2, 2, 0]].reshape(-1, 3, 2)
    pairs = np.sort(local, axis=2).reshape(-1, 2)
    edges, inverse = np.unique(pairs, axis=0, return_inverse=True)
    return edges, inverse.reshape(-1, 3)


def icosahedron() -> tuple[np.ndarray, np.ndarray]:
    """The regular icosahedron inscribed in the unit sphere with a vertex at the north pole.

    Returns points (12, 3) and outward triangles (20, 3).
    """
    z = 1.0 / math.sqrt(5.0)  # height of the two rings of five vertices
    r = 2.0 / math.sqrt(5.0)
    k = np.arange(5)
    upper = np.column_stack(
        [r * np.cos(2 * np.pi * k / 5), r * np.sin(2 * np.pi * k / 5), z + 0 * k]
    )
    lower_angle = 2 * np.pi * k / 5 + np.pi / 5
    lower = np.column_stack([r * np.cos(lower_angle), r * np.sin(lower_angle), -z + 0 * k])
    points = np.vstack([POLE, upper, lower, -POLE])
    up, lo, south = 1 + k, 6 + k, 11
    nxt = (k + 1) % 5
    triangles = np.vstack(
        [
            np.column_stack([0 * k, up, 1 + nxt]),
            np.column_stack([up, lo, 1 + nxt]),
            np.column_stack([1 + nxt, lo, 6 + nxt]),
            np.column_stack([south + 0 * k, 6 + nxt, lo]),
        ]
    )
    return points, orient_outward(points, triangles)


def refine(points: np.ndarray, triangles: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Split each triangle into four; the new edge vertices are projected onto the sphere."""
    edges, local = _edges(triangles)
    middle = _normalise(points[edges[:, 0]] + points[edges[:, 1]])
    m = local + len(points)
    a, b, c = triangles.T
    m01, m12, m20 = m.T
    new = np.vstack(
        [
            np.column_stack([a, m01, m20]),
            np.column_stack([m01, b, m12]),
            np.column_stack([m20, m12, c]),
            np.column_stack([m01, m12, m20]),
        ]
    )
    return np.vstack([points, middle]), new


def icosphere(level: int, order: int = 1) -> SphereMesh:
    """Icosphere of refinement ``level`` (``10 * 4**level + 2`` vertices; 0 = icosahedron).

    Parameters
    ----------
    level : int
        Number of four-fold refinements, in [0, 10].
    order : {1, 2, 3, 4}
        1: flat triangles; 2, 3, 4: curved isoparametric triangles of that
        order with every node on the sphere (:func:`elevate`).

    Returns
    -------
    SphereMesh
        Dimensionless unit sphere with a vertex at the north pole.
    """
    level = check_level(level)
    order = check_order(order)
    points, triangles = icosahedron()
    for _ in range(level):
        points, triangles = refine(points, triangles)
    mesh = SphereMesh(points, triangles, f"icosphere level {level}")
    return elevate(mesh, order) if order > 1 else mesh


def ring_rows(level: int) -> int:
    """Rows per hemisphere ``n`` of the ring sphere at ``level``: ``4 n^2 ~ 10 * 4**level``."""
    return max(2, round(math.sqrt(10.0) * 2.0 ** (level - 1)))


def _row_angles(rows: int, phi_a: float) -> np.ndarray:
    """Polar angles of the 2n + 1 rows, equally spaced on each side of the ring at phi_a."""
    total = 2 * rows
    ring = min(max(round(phi_a / math.pi * total), 1), total - 1)
    i = np.arange(total + 1, dtype=float)
    north = phi_a * i / ring
    south = phi_a + (math.pi - phi_a) * (i - ring) / (total - ring)
    return np.where(i <= ring, north, south)


def ring_sphere(level: int, phi_a: float, order: int = 1) -> SphereMesh:
    """Sphere mesh with a row of vertices (and of edges) on the latitude ``phi = phi_a``.

    Rows of vertices lie on circles of latitude; row i (i = 0 .. 2n from the
    north pole) holds ``4 min(i, 2n - i)`` vertices at equal longitude steps, so
    the mesh is an octahedron refined row by row (shape-regular up to the poles,
    unlike a latitude-longitude grid).  The rows are equally spaced in polar
    angle on each side of ``phi_a``, which is itself a row: the kink of
    eq. (3.10) lies on element edges.  For ``order >= 2`` the nodes of edges on
    the ring are placed on the ring (not projected radially), so the curved
    edges stay in the plane ``z = cos(phi_a)``.

    Parameters
    ----------
    level : int
        Size parameter in [0, 10]; n = ``ring_rows(level)`` rows per hemisphere.
    phi_a : float
        Polar angle of the ring [rad], in (0, pi).
    order : {1, 2, 3, 4}
        Geometric order.

    Returns
    -------
    SphereMesh
        Dimensionless unit sphere, ``4 n^2 + 2`` vertices, ``ring = phi_a``.
    """
    level = check_level(level)
    order = check_order(order)
    if not (0.0 < float(phi_a) < math.pi):
        raise ParameterError("phi_a", "in (0, pi)", phi_a)
    rows = ring_rows(level)
    angles = _row_angles(rows, float(phi_a))
    segments = [min(i, 2 * rows - i) for i in range(2 * rows + 1)]  # per octant face
    starts = np.concatenate([[0], np.cumsum([max(4 * s, 1) for s in segments])])
    points = []
    for angle, s in zip(angles, segments, strict=True):
        count = max(4 * s, 1)
        theta = 2.0 * np.pi * np.arange(count) / count
        ring = np.column_stack(
            [math.sin(angle) * np.cos(theta), math.sin(angle) * np.sin(theta), 0 * theta]
        )
        ring[:, 2] = math.cos(angle)
        points.append(ring if s > 0 else np.array([[0.0, 0.0, math.cos(angle)]]))
    points = np.vstack(points)
    points[0] = POLE
    points[-1] = -POLE

    def index(row: int, face: int, j: np.ndarray) -> np.ndarray:
        s = segments[row]
        if s == 0:
            return np.full_like(j, starts[row])
        return starts[row] + (face * s + j) % (4 * s)

    triangles = []
    for row in range(2 * rows):
        small, large = (row, row + 1) if row < rows else (row + 1, row)
        a = segments[small]
        for face in range(4):
            j = np.arange(a + 1)
            triangles.append(
                np.column_stack(
                    [index(small, face, j), index(large, face, j), index(large, face, j + 1)]
                )
            )
            j = np.arange(a)
            triangles.append(
                np.column_stack(
                    [index(small, face, j), index(large, face, j + 1), index(small, face, j + 1)]
                )
            )
    triangles = orient_outward(points, np.vstack(triangles))
    mesh = SphereMesh(points, triangles, f"ring sphere level {level} (n={rows})", float(phi_a))
    return elevate(mesh, order) if order > 1 else mesh


def interior_weights(order: int) -> np.ndarray:
    """Barycentric weights (times ``order``) of the interior nodes, shape (n, 3).

    In the local order of scikit-fem's ``ElementTriP3`` (the centroid) and
    ``ElementTriP4`` (reference points (1/4, 1/4), (1/2, 1/4), (1/4, 1/2)); the
    columns weigh vertices 0, 1, 2.
    """
    return {
        1: np.zeros((0, 3)),
        2: np.zeros((0, 3)),
        3: np.array([[1.0, 1.0, 1.0]]),
        4: np.array([[2.0, 1.0, 1.0], [1.0, 2.0, 1.0], [1.0, 1.0, 2.0]]),
    }[order]


def _edge_nodes(mesh: SphereMesh, edges: np.ndarray, order: int) -> np.ndarray:
    """The ``order - 1`` nodes of each edge, from its lower vertex, shape (E, order - 1, 3).

    Node k (1 .. order - 1) is the point ``((order - k) a + k b) / order`` of the
    chord from a to b, projected radially onto the sphere; on the ring
    (``mesh.ring``) it is instead projected onto the circle of latitude within
    its plane, so that ring edges stay in the plane ``z = cos(ring)``.
    """
    points = mesh.points
    a, b = points[edges[:, 0]], points[edges[:, 1]]
    on_ring = np.zeros(len(edges), dtype=bool)
    if mesh.ring is not None:
        height = math.cos(mesh.ring)
        on_ring = (np.abs(a[:, 2] - height) < 1e-12) & (np.abs(b[:, 2] - height) < 1e-12)
    out = np.empty((len(edges), order - 1, 3))
    for k in range(1, order):
        chord = (order - k) * a + k * b  # order 2: a + b, as before (bit-identical)
        node = _normalise(chord)
        if on_ring.any():
            planar = chord[on_ring, :2]
            planar *= math.sin(mesh.ring) / np.linalg.norm(planar, axis=1, keepdims=True)
            node[on_ring] = np.column_stack([planar, np.full(len(planar), height)])
        out[:, k - 1] = node
    return out


def elevate(mesh: SphereMesh, order: int = 2) -> SphereMesh:
    """The curved mesh of geometric ``order`` (2, 3 or 4) on the vertices of ``mesh``.

    Only the vertices and triangles of ``mesh`` are used (nodes of a curved
    mesh are rebuilt).  The new nodes are the equispaced points of each flat
    triangle (barycentric coordinates ``i / order``), projected radially onto
    the unit sphere; edge nodes of the ring (``mesh.ring``) are put on the
    circle of latitude instead (see :func:`_edge_nodes`).  Each edge's nodes are
    stored once, from its lower vertex index, and every triangle lists them in
    its own direction (the local order of scikit-fem's ``ElementTriP{order}``),
    so neighbours traversing a shared edge in opposite directions see the same
    nodes.  Dimensionless.

    Parameters
    ----------
    mesh : SphereMesh
        Any order.
    order : {1, 2, 3, 4}
        Target order; 1 returns the flat mesh (:func:`flatten`).
    """
    order = check_order(order)
    if mesh.order == order:
        return mesh
    if order == 1:
        return flatten(mesh)
    flat = flatten(mesh)
    points, triangles = flat.points, flat.triangles
    count = len(points)
    edges, local = _edges(triangles)  # local columns: edges 01, 12, 20
    per_edge = order - 1
    edge_points = _edge_nodes(flat, edges, order).reshape(-1, 3)
    # per triangle and local edge (a, b): its nodes from a to b
    columns = [triangles]
    for j, (a, b) in enumerate(((0, 1), (1, 2), (0, 2))):
        first = count + local[:, j] * per_edge
        ks = np.arange(per_edge)
        forward = triangles[:, a] < triangles[:, b]
        index = np.where(forward[:, None], ks[None, :], per_edge - 1 - ks[None, :])
        columns.append(first[:, None] + index)
    weights = interior_weights(order)
    inner = np.zeros((0, 3))
    if len(weights):
        corners = points[triangles]  # (T, 3, 3)
        inner = _normalise(np.einsum("nv,tvk->tnk", weights, corners).reshape(-1, 3))
        start = count + len(edge_points)
        columns.append(start + np.arange(len(triangles) * len(weights)).reshape(len(triangles), -1))
    cells = np.hstack(columns)
    return replace(mesh, points=np.vstack([points, edge_points, inner]), cells=cells)


def flatten(mesh: SphereMesh) -> SphereMesh:
    """The flat (order 1) mesh on the vertices of ``mesh``."""
    if mesh.order == 1:
        return mesh
    count = mesh.vertex_count
    return replace(mesh, points=mesh.points[:count], cells=mesh.triangles)


def sphere_mesh(level: int, order: int = 1, phi_a: float | None = None) -> SphereMesh:
    """Icosphere (``phi_a`` None) or ring sphere with a ring at ``phi_a``."""
    if phi_a is None:
        return icosphere(level, order)
    return ring_sphere(level, phi_a, order)


def topology(mesh: SphereMesh) -> MeshTri1:
    """scikit-fem mesh carrying the connectivity (and the 3D vertices) of ``mesh``.

    Only its topology is used -- degrees of freedom and element numbering; the
    geometry enters through :class:`twoball.fem_membrane.mapping.SurfaceMapping`.  Built
    with ``sort_t=False`` because sorting the vertices of each triangle would
    flip the orientation of half of them.
    """
    count = mesh.vertex_count
    return MeshTri1(mesh.points[:count].T.copy(), mesh.triangles.T.copy(), sort_t=False)


# --- input/output -------------------------------------------------------------------------


def write_mesh(path: str | Path, mesh: SphereMesh) -> None:
    """Write ``mesh`` with meshio (format from the suffix, e.g. ``.vtu``, ``.msh``, ``.xdmf``).

    Orders 1 and 2 only (``triangle``, ``triangle6``); the node orders of
    10- and 15-node triangles differ between formats, so orders 3 and 4 are
    refused (write :func:`flatten` of the mesh and raise it again on reading).
    """
    if mesh.order > 2:
        raise ParameterError("order", "1 or 2 for writing a mesh file", mesh.order)
    import meshio  # file input/output only: the solvers start without it

    kind = "triangle" if mesh.order == 1 else "triangle6"
    meshio.write(str(path), meshio.Mesh(mesh.points, [(kind, mesh.cells)]))


def min_angle(mesh: SphereMesh) -> float:
    """Smallest interior angle of the flat triangles [rad] (a shape-regularity measure)."""
    p = mesh.points[mesh.triangles]
    worst = np.pi
    for k in range(3):
        u = p[:, (k + 1) % 3] - p[:, k]
        v = p[:, (k + 2) % 3] - p[:, k]
        cosine = np.einsum("ij,ij->i", u, v) / (
            np.linalg.norm(u, axis=1) * np.linalg.norm(v, axis=1)
        )
        worst = min(worst, float(np.arccos(np.clip(cosine, -1, 1)).min()))
    return worst
