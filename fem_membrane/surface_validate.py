"""Checks that a triangulated surface is one closed sphere, and its centre and radius.

The checks behind :func:`twoball.fem_membrane.mesh_input.load_sphere_mesh`; each
failure is a :class:`twoball._common.errors.ParameterError` naming ``mesh``
that says what is wrong and by how much (:func:`refuse`):

* nodes (:func:`clean_nodes`): three finite coordinates; coincident points
  (closer than :data:`MERGE_TOLERANCE` of the bounding-box diagonal) merged --
  STL stores every triangle's corners separately -- and unused ones dropped;
* topology (:func:`check_topology`): no repeated corner, one connected surface
  (count of components), closed (count of boundary edges, i.e. holes),
  manifold (count of edges shared by more than two triangles), of sphere
  topology (Euler characteristic V - E + F = 2), six-node triangles sharing
  their edge nodes;
* shape (:func:`check_sphere`): the nodes' mean relative deviation from the
  fitted radius at most :data:`MAX_RADIAL_DEVIATION`, every node's at most
  :data:`MAX_NODE_DEVIATION`, and near the pole (:data:`POLE_CAP`) at most
  :data:`MAX_POLE_DEVIATION`: one spike or dent hides in a mean;
* orientation (:func:`orient_outward`): no zero-area triangle; every normal
  away from the centre, or every one towards it (then all are reversed, and
  this is reported); a mix is refused with the size of the minority.

Centre and radius (:func:`sphere_fit`).  The centre is the algebraic
least-squares sphere through the nodes (``|x|^2 = 2 c.x + r^2 - |c|^2``, linear
in ``c`` and ``r^2 - |c|^2``): exact for nodes on a sphere however they are
spread.  The vertex mean is not: a mesh refined near one latitude, like
:func:`twoball.fem_membrane.mesh.ring_sphere`, or a gmsh mesh with a local size
field, has its vertex mean off the centre.  The radius is the mean node
distance from that centre.  Only nodes are measured: the vertices of a coarse
P1 sphere lie on the sphere exactly while its chords sag by ``h^2 / 8``, which
is discretisation, not a geometric error.  Lengths in the source's units.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from twoball._common.errors import ParameterError

MAX_RADIAL_DEVIATION = 1e-4
"""Largest accepted mean ``|r_i - R| / R`` over the nodes (R the fitted radius).

Far above what faithful files carry (float32 STL: 6e-8; generated or CAD-placed
nodes: 1e-12 and below) and below where the geometry would rival the
discretisation: a radial perturbation of relative size d moves eigenvalues by
about 2 d (lambda ~ 1 / R^2), hence lift-off time and velocity by about d,
against 1e-4 to 1e-3 for P2 on icosphere levels 3-4.
"""
MAX_NODE_DEVIATION = 1e-2
"""Largest accepted ``|r_i - R| / R`` of any one node.

A mean of 1e-4 over 10 242 nodes hides a node pushed out by 30 % (the lift-off
velocity then doubles: 8.31 m/s against 3.84 m/s on icosphere level 5, P1).  One
node off by d moves the lift-off by about ``15 d^2`` at the pole and far less
elsewhere (measured, icosphere P1 level 5 and P2 levels 3-4, d = 1e-2: v_l
+1.3e-3 to +1.5e-3 at the pole, +1e-4 at its neighbour, 7e-6 at the equator);
1e-2 is a hundred times the mean's limit -- a node that far off is a defect,
not noise -- and the pole has the stricter :data:`MAX_POLE_DEVIATION`.
"""
MAX_POLE_DEVIATION = 1e-3
"""Largest accepted ``|r_i - R| / R`` of a node near the pole (within :data:`POLE_CAP`).

The lift-off is decided by the pole's motion, where the wave focuses: a bump or
dent of depth d there moves v_l by ``0.02-0.05 d`` plus ``15 d^2`` (measured:
one node, d = 1e-3: +2e-5 to +4e-5; a smooth bump over 0.3 rad, 61 nodes,
d = 1e-3: +5.5e-5), so 1e-3 keeps it below 1e-4, the discretisation error of
P2 on icosphere levels 3-4.
"""
POLE_CAP = 0.3  # rad: the pole's neighbourhood (also at least its 7 nearest nodes)
POLE_NEIGHBOURS = 7
MERGE_TOLERANCE = 1e-10  # points closer than this fraction of the bounding-box diagonal merge
FLAT_AREA = 1e-14  # a triangle with area below this fraction of R^2 is degenerate
MESH_FLAG = "mesh"  # the parameter; the command line shows --mesh-file


def refuse(name: str, valid: str, found: str) -> ParameterError:
    """ParameterError naming ``mesh``: ``mesh <name> must be <valid>; found <found>``."""
    error = ParameterError(MESH_FLAG, valid, found)
    error.args = (f"{MESH_FLAG} {name} must be {valid}; found {found}",)
    return error


# --- nodes --------------------------------------------------------------------------------


def _vertices_first(points: np.ndarray, cells: np.ndarray) -> tuple[np.ndarray, np.ndarray, int]:
    """Drop unused points; number vertices (corners) first, then edge nodes."""
    corner = np.zeros(points.shape[0], dtype=bool)
    corner[cells[:, :3]] = True
    used = np.zeros(points.shape[0], dtype=bool)
    used[cells] = True
    order = np.concatenate([np.flatnonzero(corner), np.flatnonzero(used & ~corner)])
    renumber = np.full(points.shape[0], -1, dtype=np.int64)
    renumber[order] = np.arange(order.size)
    return points[order], renumber[cells], points.shape[0] - order.size


def _merge_coincident(points: np.ndarray, cells: np.ndarray) -> tuple[np.ndarray, int]:
    """Cells with coincident points (closer than MERGE_TOLERANCE) pointing to one of them."""
    from scipy.sparse import coo_matrix
    from scipy.sparse.csgraph import connected_components
    from scipy.spatial import cKDTree

    extent = np.ptp(points, axis=0)
    largest = float(extent.max())
    if not largest > 0.0:
        return cells, 0
    # beyond 1e-50..1e50 in units of a power of two (exact): no overflow at any radius
    scale = 1.0 if 1e-50 < largest < 1e50 else 2.0 ** round(math.log2(largest))
    diagonal = float(np.linalg.norm(extent / scale))
    tree = cKDTree(points / scale)
    pairs = tree.query_pairs(MERGE_TOLERANCE * diagonal, output_type="ndarray")
    if pairs.size == 0:
        return cells, 0
    n = points.shape[0]
    graph = coo_matrix((np.ones(len(pairs)), (pairs[:, 0], pairs[:, 1])), shape=(n, n))
    count, labels = connected_components(graph, directed=False)
    first = np.full(count, n, dtype=np.int64)
    np.minimum.at(first, labels, np.arange(n))
    return first[labels][cells], n - count


def clean_nodes(
    name: str, points: np.ndarray, cells: np.ndarray
) -> tuple[np.ndarray, np.ndarray, int, int]:
    """Checked nodes, vertices first, coincident points merged and unused ones dropped.

    Returns
    -------
    points, cells, unused, merged
        Nodes (P, 3), cells (T, 3 or 6), and the counts of dropped and merged points.
    """
    if points.ndim != 2 or points.shape[1] != 3:
        found = f"points of shape {points.shape}"
        raise refuse(name, "three-dimensional (points with x, y, z)", found)
    if cells.size == 0:
        raise refuse(name, "a surface of triangle or triangle6 cells", "no triangles")
    if cells.min() < 0 or cells.max() >= len(points):
        raise refuse(name, "a mesh whose cells index its points", "out-of-range node indices")
    finite = np.isfinite(points[np.unique(cells)]).all(axis=1)
    if not finite.all():
        found = f"{int(np.count_nonzero(~finite))} points with NaN or inf"
        raise refuse(name, "made of finite coordinates", found)
    points, cells, unused = _vertices_first(points, cells)
    cells, merged = _merge_coincident(points, cells)
    points, cells, _ = _vertices_first(points, cells)
    return points, cells, unused, merged


# --- topology -----------------------------------------------------------------------------


def _edge_table(triangles: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Unique undirected edges, their use counts, and per triangle the edge ids of 01, 12, 20."""
    size = int(triangles.max()) + 1
    a, b = triangles.ravel(), triangles[:, [1, 2, 0]].ravel()
    keys = np.minimum(a, b) * size + np.maximum(a, b)  # one integer per undirected edge
    unique, inverse, counts = np.unique(keys, return_inverse=True, return_counts=True)
    edges = np.column_stack([unique // size, unique % size])
    return edges, counts, inverse.reshape(-1, 3)


def check_topology(name: str, cells: np.ndarray) -> None:
    """One closed manifold surface of sphere topology with conforming edge nodes."""
    from scipy.sparse import coo_matrix
    from scipy.sparse.csgraph import connected_components

    triangles = cells[:, :3]
    vertices = int(triangles.max()) + 1
    repeated = (
        (triangles[:, 0] == triangles[:, 1])
        | (triangles[:, 1] == triangles[:, 2])
        | (triangles[:, 2] == triangles[:, 0])
    )
    if repeated.any():
        found = f"{int(repeated.sum())} of {len(triangles)} triangles with a repeated corner"
        raise refuse(name, "free of degenerate triangles", found)
    rows, cols = triangles.ravel(), triangles[:, [1, 2, 0]].ravel()
    graph = coo_matrix((np.ones(rows.size), (rows, cols)), shape=(vertices, vertices))
    components, labels = connected_components(graph, directed=False)
    if components > 1:
        sizes = np.sort(np.bincount(labels[triangles[:, 0]], minlength=components))[::-1]
        shown = ", ".join(str(s) for s in sizes[:5]) + (", ..." if components > 5 else "")
        raise refuse(
            name, "one connected surface", f"{components} separate surfaces ({shown} triangles)"
        )
    edges, counts, local = _edge_table(triangles)
    open_edges = int(np.count_nonzero(counts == 1))
    if open_edges:
        raise refuse(name, "a closed surface", f"{open_edges} boundary edges (holes)")
    shared = int(np.count_nonzero(counts > 2))
    if shared:
        found = f"{shared} non-manifold edges (shared by more than two triangles)"
        raise refuse(name, "a manifold surface", found)
    euler = vertices - len(edges) + len(triangles)
    if euler != 2:
        found = f"V - E + F = {euler} (genus {(2 - euler) / 2:g})"
        raise refuse(name, "of sphere topology (V - E + F = 2)", found)
    if cells.shape[1] == 6:
        _check_edge_nodes(name, cells, local, vertices)


def _check_edge_nodes(name: str, cells: np.ndarray, local: np.ndarray, vertices: int) -> None:
    """Six-node triangles sharing an edge share its node, and edges do not share nodes."""
    edge_ids, nodes = local.ravel(), cells[:, 3:].ravel()
    node_of_edge = np.full(edge_ids.max() + 1, -1, dtype=np.int64)
    node_of_edge[edge_ids] = nodes
    disagree = int(np.count_nonzero(node_of_edge[edge_ids] != nodes))
    reused = len(node_of_edge) - len(np.unique(node_of_edge))
    corners = int(np.count_nonzero(node_of_edge < vertices))
    if disagree:
        found = f"{disagree} edge nodes not shared by the two triangles of their edge"
        raise refuse(name, "a conforming triangle6 mesh", found)
    if reused or corners:
        found = f"{reused + corners} edge nodes that are also corners or nodes of other edges"
        raise refuse(name, "a conforming triangle6 mesh", found)


# --- shape and orientation ----------------------------------------------------------------


@dataclass(frozen=True)
class SphereFit:
    """Fitted centre and radius (source units) and relative node deviations from the radius."""

    center: np.ndarray
    radius: float
    mean_deviation: float
    max_deviation: float
    pole_deviation: float = math.nan


def sphere_fit(points: np.ndarray) -> tuple[np.ndarray, float]:
    """Algebraic least-squares sphere through ``points`` (N, 3): centre and radius.

    Solves ``|x|^2 = 2 c.x + d`` for c and ``d = r^2 - |c|^2`` in the least-squares
    sense (about the points' mean, for conditioning); exact when the points lie
    on a sphere, whatever their distribution.  Units of ``points``; radius NaN
    when the points fit no sphere (e.g. coplanar).
    """
    mean = points.mean(axis=0)
    x = points - mean
    matrix = np.column_stack([2.0 * x, np.ones(len(x))])
    solution, _, rank, _ = np.linalg.lstsq(matrix, np.einsum("ij,ij->i", x, x), rcond=None)
    if rank < 4:
        return mean, math.nan
    center = solution[:3]
    squared = solution[3] + center @ center
    return center + mean, math.sqrt(squared) if squared > 0 else math.nan


def check_sphere(name: str, points: np.ndarray, pole: np.ndarray | None = None) -> SphereFit:
    """Fit the sphere; refuse a mean, a node's or (with ``pole``) a near-pole deviation too large.

    Relative radial deviations from the fitted radius: mean at most
    :data:`MAX_RADIAL_DEVIATION`, every node at most :data:`MAX_NODE_DEVIATION`,
    every node within :data:`POLE_CAP` of the unit direction ``pole`` (in the
    points' frame, from the fitted centre; also its :data:`POLE_NEIGHBOURS`
    nearest nodes) at most :data:`MAX_POLE_DEVIATION`.  Coordinates beyond
    1e-50..1e50 in size are first scaled by a power of two (exact), so a ball of
    radius 1e-200 or 1e200 (any unit) neither underflows nor overflows in the
    squares of the fit; centre and radius come back in the file's units.
    """
    largest = float(np.abs(points).max())
    if not (math.isfinite(largest) and largest > 0.0):
        raise refuse(name, "a sphere", "nodes that fit no sphere (all at the origin)")
    scale = 1.0 if 1e-50 < largest < 1e50 else 2.0 ** round(math.log2(largest))
    center, radius = sphere_fit(points / scale)
    if not (math.isfinite(radius) and radius > 0.0):
        raise refuse(name, "a sphere", "nodes that fit no sphere (coplanar or degenerate)")
    offsets = points / scale - center
    distance = np.linalg.norm(offsets, axis=1)
    radius = float(distance.mean())
    center = center * scale
    deviation = np.abs(distance - radius) / radius
    angle = (
        np.zeros(len(points))
        if pole is None
        else np.arccos(np.clip(offsets @ np.asarray(pole, dtype=float) / distance, -1.0, 1.0))
    )
    near = angle <= max(POLE_CAP, float(np.sort(angle)[min(POLE_NEIGHBOURS, len(angle)) - 1]))
    pole_deviation = float(deviation[near].max()) if pole is not None else math.nan
    radius *= scale
    fit = SphereFit(center, radius, float(deviation.mean()), float(deviation.max()), pole_deviation)
    if fit.mean_deviation > MAX_RADIAL_DEVIATION:
        found = (
            f"mean radial deviation {fit.mean_deviation:.2e} of the fitted radius "
            f"{radius:.6g} (largest {fit.max_deviation:.2e})"
        )
        raise refuse(name, f"a sphere to {MAX_RADIAL_DEVIATION:g} (mean radial deviation)", found)
    worst = int(np.argmax(deviation))
    where = "" if pole is None else f", {angle[worst]:.3g} rad from the pole"
    if fit.max_deviation > MAX_NODE_DEVIATION:
        found = (
            f"a node off by {fit.max_deviation:.2e} of the fitted radius{where} (a spike or dent)"
        )
        raise refuse(name, f"a sphere to {MAX_NODE_DEVIATION:g} at every node", found)
    if pole is not None and pole_deviation > MAX_POLE_DEVIATION:
        at = np.flatnonzero(near)[np.argmax(deviation[near])]
        found = (
            f"a node off by {pole_deviation:.2e} of the fitted radius, {angle[at]:.3g} rad from "
            "the pole (a bump or dent where the lift-off is decided)"
        )
        valid = f"a sphere to {MAX_POLE_DEVIATION:g} within {POLE_CAP:g} rad of the pole"
        raise refuse(name, valid, found)
    return fit


def reverse(cells: np.ndarray, which: np.ndarray) -> np.ndarray:
    """Reverse the orientation of the triangles ``which`` (swap corners 1 and 2)."""
    out = cells.copy()
    swap = [0, 2, 1] if cells.shape[1] == 3 else [0, 2, 1, 5, 4, 3]  # edges 01<->20, 12 stays
    out[which] = cells[which][:, swap]
    return out


def orient_outward(
    name: str, points: np.ndarray, cells: np.ndarray, fit: SphereFit, known: bool = True
) -> tuple[np.ndarray, bool]:
    """Cells with every normal pointing away from the centre, and whether all were reversed.

    ``known=False`` (scikit-fem meshes, whose corners are sorted by default)
    orients every triangle by its geometry instead of refusing a mix.
    """
    corners = (points[cells[:, :3]] - fit.center) / fit.radius  # unit ball: no overflow
    normal = np.cross(corners[:, 1] - corners[:, 0], corners[:, 2] - corners[:, 0])
    flat = int(np.count_nonzero(0.5 * np.linalg.norm(normal, axis=1) <= FLAT_AREA))
    if flat:
        raise refuse(name, "free of degenerate triangles", f"{flat} triangles of zero area")
    inward = np.einsum("ij,ij->i", normal, corners.sum(axis=1)) < 0.0
    flipped = False
    if not known:
        cells = reverse(cells, inward)
    elif inward.all():
        cells, flipped = reverse(cells, inward), True
    elif inward.any():
        minority = min(int(inward.sum()), int((~inward).sum()))
        found = f"{minority} of {len(cells)} triangles oriented opposite to the others"
        raise refuse(name, "consistently oriented", found)
    # neighbours must traverse their shared edge in opposite senses: each directed edge once
    triangles = cells[:, :3]
    directed = triangles.ravel() * (int(triangles.max()) + 1) + triangles[:, [1, 2, 0]].ravel()
    twice = len(directed) - len(np.unique(directed))
    if twice:
        found = f"{twice} edges traversed in the same sense by both triangles (folded surface)"
        raise refuse(name, "consistently oriented", found)
    return cells, flipped
