"""Sphere meshes brought by the user: files in any meshio format, meshio or scikit-fem meshes.

:func:`load_sphere_mesh` reads a triangulated sphere of any radius and centre
(gmsh ``.msh``, ``.vtu``, ``.vtk``, ``.xdmf``, ``.stl``, ``.obj``, ``.ply``, ``.off``,
... -- whatever :func:`meshio.read` reads; the points are always read by meshio,
never by ``skfem.MeshTri.load``, which drops z), checks that it is one closed
sphere, and returns it as a :class:`twoball.fem_membrane.mesh.SphereMesh` on the
unit sphere, rotated so that the requested pole direction is +z -- the
dimensionless geometry of eq. (3.9), whose pole motion decides lift-off.

What is checked (each failure a :class:`twoball.modal.errors.ParameterError`
naming ``--mesh-file`` with what is wrong and by how much):

* cells: ``triangle`` (3-node) or ``triangle6`` (6-node) cells, one kind only;
  other surface cells (quadrilaterals, polygons) are refused, lines, vertices
  and volume cells are ignored (and reported in :attr:`MeshInput.description`);
* coincident points (closer than 1e-10 of the bounding-box diagonal) are
  merged first -- STL stores every triangle's corners separately;
* no degenerate triangles (a repeated corner or zero area);
* one connected surface (count of components), closed (count of boundary
  edges, i.e. holes), manifold (count of edges shared by more than two
  triangles), of sphere topology (Euler characteristic V - E + F = 2), with
  six-node triangles that agree on their shared edge nodes;
* spherical: the nodes' mean distance from the fitted centre deviates from the
  radius by at most :data:`MAX_RADIAL_DEVIATION` (relative, mean over nodes);
* consistently oriented: every triangle's normal points away from the centre,
  or every one towards it (then all are flipped, and this is reported); a mix
  is refused with the number of triangles facing the minority way.

Centre and radius.  The centre is the algebraic least-squares sphere fit
through the nodes (``|x|^2 = 2 c.x + r^2 - |c|^2``, linear in ``c`` and
``r^2 - |c|^2``), which is exact for nodes on a sphere however they are spread;
the mean of the vertices is not (a mesh refined near one latitude, like
:func:`twoball.fem_membrane.mesh.ring_sphere`, or a gmsh mesh with a local size
field, has its vertex mean off the centre).  The radius is the mean node
distance from that centre.  Only nodes are measured: the vertices of a coarse
P1 sphere lie on the sphere exactly while its chords sag by ``h^2 / 8``, which
is discretisation, not a geometric error.

Units: ``radius`` and ``center`` are in the file's units (metres if the file is
in metres); the returned mesh is dimensionless (unit radius).
"""

from __future__ import annotations

import contextlib
import io
import math
import warnings
from collections.abc import Sequence
from dataclasses import dataclass, field, replace
from pathlib import Path
from typing import Any

import numpy as np
from twoball.modal.errors import ParameterError

from .checks import check_order
from .mesh import SphereMesh, elevate, flatten

MAX_RADIAL_DEVIATION = 1e-4
"""Largest accepted mean |r_i - R| / R over the nodes (relative to the fitted radius R).

Well above what faithful files carry (float32 STL: 6e-8; gmsh places nodes on
the CAD sphere to about 1e-12) and well below where the geometry would rival
the discretisation: a radial perturbation of relative size d shifts eigenvalues
by about 2 d (lambda ~ 1 / R^2), i.e. lift-off time and velocity by about d.
"""
MERGE_TOLERANCE = 1e-10  # points closer than this fraction of the bounding-box diagonal merge
FLAT_AREA = 1e-14  # a triangle with area below this fraction of R^2 is degenerate

MESH_FLAG = "--mesh-file"
POLE_FLAG = "--pole"
TRIANGLE_TYPES = ("triangle", "triangle6")
REFUSED_SURFACE_TYPES = ("quad", "quad8", "quad9", "polygon", "triangle7", "triangle10")

MeshSource = Any  # str | Path | meshio.Mesh | skfem.MeshTri1 | skfem.MeshTri2 | SphereMesh


@dataclass(frozen=True)
class MeshInput:
    """A user's sphere mesh, checked, scaled to the unit sphere and turned to its pole.

    Attributes
    ----------
    mesh : SphereMesh
        Unit sphere (dimensionless), pole direction on +z; P1 or P2 as given, or
        elevated to the requested order (new edge nodes projected onto the sphere).
    radius : float
        Fitted radius, in the file's units.
    center : ndarray, shape (3,)
        Fitted centre, in the file's units.
    pole : ndarray, shape (3,)
        Unit pole direction in the file's frame.
    rotation : ndarray, shape (3, 3)
        ``mesh.points = (x - center) / radius @ rotation.T``; it takes ``pole`` to +z.
    source_order : int
        Geometric order in the source: 1 (3-node) or 2 (6-node triangles).
    mean_radial_deviation, max_radial_deviation : float
        Mean and largest ``|r_i - radius| / radius`` over the source's nodes.
    triangles, vertices : int
        Counts after merging coincident points.
    merged_points : int
        Coincident points merged into others.
    unused_points : int
        Points of the source not used by any triangle (dropped).
    flipped : bool
        All triangles faced inward and were reversed.
    pole_at_node : bool
        A node of the mesh lies at the pole (else the pole is inside an element).
    ignored_cells : dict
        Cell types ignored (lines, vertices, volume cells) and their counts.
    description : str
        One paragraph for reports.
    """

    mesh: SphereMesh
    radius: float
    center: np.ndarray
    pole: np.ndarray
    rotation: np.ndarray
    source_order: int
    mean_radial_deviation: float
    max_radial_deviation: float
    triangles: int
    vertices: int
    merged_points: int = 0
    unused_points: int = 0
    flipped: bool = False
    pole_at_node: bool = False
    ignored_cells: dict[str, int] = field(default_factory=dict)
    description: str = ""

    def as_dict(self) -> dict[str, Any]:
        """Plain summary (no arrays but short lists) for ``info`` dictionaries and JSON."""
        return {
            "mesh": self.mesh.name,
            "radius": self.radius,
            "center": [float(c) for c in self.center],
            "pole": [float(c) for c in self.pole],
            "source_order": self.source_order,
            "order": self.mesh.order,
            "triangles": self.triangles,
            "vertices": self.vertices,
            "mean_radial_deviation": self.mean_radial_deviation,
            "max_radial_deviation": self.max_radial_deviation,
            "merged_points": self.merged_points,
            "unused_points": self.unused_points,
            "flipped": self.flipped,
            "pole_at_node": self.pole_at_node,
            "ignored_cells": dict(self.ignored_cells),
        }


def refuse(name: str, valid: str, found: str) -> ParameterError:
    """ParameterError for ``--mesh-file``: ``--mesh-file <name> must be <valid>; found <found>``."""
    error = ParameterError(MESH_FLAG, valid, found)
    error.args = (f"{MESH_FLAG} {name} must be {valid}; found {found}",)
    return error


# --- reading ----------------------------------------------------------------------------


@dataclass
class _Raw:
    """Points and triangles as read, before any check."""

    points: np.ndarray
    cells: np.ndarray
    name: str
    ignored: dict[str, int] = field(default_factory=dict)
    orientation_known: bool = True  # False for scikit-fem meshes built with sort_t=True


def _from_meshio(data: Any, name: str) -> _Raw:
    points = np.asarray(data.points, dtype=float)
    counts: dict[str, int] = {}
    for block in data.cells:
        counts[block.type] = counts.get(block.type, 0) + len(block.data)
    refused = sorted(t for t in counts if t in REFUSED_SURFACE_TYPES)
    if refused:
        found = ", ".join(f"{counts[t]} {t}" for t in refused)
        raise refuse(name, "made of triangle or triangle6 surface cells only", found)
    kinds = [t for t in TRIANGLE_TYPES if t in counts]
    if not kinds:
        found = ", ".join(f"{n} {t}" for t, n in sorted(counts.items())) or "no cells"
        raise refuse(name, "a surface of triangle or triangle6 cells", found)
    if len(kinds) > 1:
        found = f"{counts['triangle']} triangle and {counts['triangle6']} triangle6 cells"
        raise refuse(name, "of one element order (triangle or triangle6 cells)", found)
    cells = np.vstack(
        [np.asarray(b.data, dtype=np.int64) for b in data.cells if b.type == kinds[0]]
    )
    ignored = {t: n for t, n in counts.items() if t != kinds[0]}
    return _Raw(points, cells, name, ignored)


def _from_skfem(mesh: Any, name: str) -> _Raw:
    from skfem import MeshTri1, MeshTri2

    if isinstance(mesh, MeshTri2):
        # doflocs: vertices first, then one node per facet; facets of t2f are 01, 12, 02
        cells = np.vstack([mesh.t, mesh.t2f + mesh.nvertices]).T
        points = np.asarray(mesh.doflocs, dtype=float).T
    elif isinstance(mesh, MeshTri1):
        cells = np.asarray(mesh.t, dtype=np.int64).T
        points = np.asarray(mesh.p, dtype=float).T
    else:
        raise refuse(name, "a triangle mesh (MeshTri1 or MeshTri2)", type(mesh).__name__)
    # scikit-fem sorts the vertices of each triangle by default, which scrambles orientation
    return _Raw(points, np.asarray(cells, dtype=np.int64), name, orientation_known=False)


def _meshio_read(path: Path) -> Any:
    """meshio.read, quietly: its prints and warnings become the one-line refusal.

    On a file it cannot parse meshio prints to stdout/stderr and calls
    ``sys.exit(1)``; both are caught here so the command line prints one line.
    """
    import meshio

    chatter = io.StringIO()
    try:
        with (
            contextlib.redirect_stdout(chatter),
            contextlib.redirect_stderr(chatter),
            warnings.catch_warnings(),
        ):
            warnings.simplefilter("ignore")
            return meshio.read(str(path))
    except (Exception, SystemExit) as error:  # meshio raises many kinds, or exits
        said = "" if isinstance(error, SystemExit) else str(error)
        reason = " ".join((said or chatter.getvalue()).split()) or type(error).__name__
        reason = reason.removeprefix("Error: ")
        raise refuse(path.name, "a mesh file meshio can read", reason) from None


def _read(source: MeshSource) -> _Raw:
    import meshio

    if isinstance(source, str | Path):
        path = Path(source)
        if not path.is_file():
            raise refuse(str(path), "an existing mesh file", "no such file")
        return _from_meshio(_meshio_read(path), path.name)
    if isinstance(source, meshio.Mesh):
        return _from_meshio(source, "(meshio.Mesh)")
    if isinstance(source, SphereMesh):
        return _Raw(source.points, source.cells, source.name)
    module = type(source).__module__
    if module.startswith("skfem"):
        return _from_skfem(source, f"({type(source).__name__})")
    raise refuse(
        f"({type(source).__name__})",
        "a path, a meshio.Mesh, a scikit-fem MeshTri1/MeshTri2 or a SphereMesh",
        type(source).__name__,
    )


# --- checks -------------------------------------------------------------------------------


def _vertices_first(points: np.ndarray, cells: np.ndarray) -> tuple[np.ndarray, np.ndarray, int]:
    """Drop unused points; number vertices (corners) first, then edge nodes."""
    vertices = np.unique(cells[:, :3])
    extra = np.setdiff1d(np.unique(cells), vertices)
    order = np.concatenate([vertices, extra])
    renumber = np.full(points.shape[0], -1, dtype=np.int64)
    renumber[order] = np.arange(order.size)
    return points[order], renumber[cells], points.shape[0] - order.size


def _merge_coincident(points: np.ndarray, cells: np.ndarray) -> tuple[np.ndarray, np.ndarray, int]:
    """Merge points closer than MERGE_TOLERANCE of the bounding-box diagonal."""
    from scipy.sparse import coo_matrix
    from scipy.sparse.csgraph import connected_components
    from scipy.spatial import cKDTree

    diagonal = float(np.linalg.norm(np.ptp(points, axis=0)))
    pairs = cKDTree(points).query_pairs(MERGE_TOLERANCE * diagonal, output_type="ndarray")
    if pairs.size == 0:
        return points, cells, 0
    n = points.shape[0]
    graph = coo_matrix((np.ones(len(pairs)), (pairs[:, 0], pairs[:, 1])), shape=(n, n))
    count, labels = connected_components(graph, directed=False)
    first = np.full(count, n, dtype=np.int64)
    np.minimum.at(first, labels, np.arange(n))
    return points, first[labels][cells], n - count


def _edge_table(triangles: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Unique undirected edges, their use counts, and per triangle the edge ids of 01, 12, 20."""
    local = np.sort(triangles[:, [0, 1, 1, 2, 2, 0]].reshape(-1, 3, 2), axis=2).reshape(-1, 2)
    edges, inverse, counts = np.unique(local, axis=0, return_inverse=True, return_counts=True)
    return edges, counts, inverse.reshape(-1, 3)


def _check_topology(raw: _Raw, triangles: np.ndarray, vertices: int) -> np.ndarray:
    """One closed manifold surface of sphere topology; returns the per-triangle edge ids."""
    from scipy.sparse import coo_matrix
    from scipy.sparse.csgraph import connected_components

    name = raw.name
    repeated = (
        (triangles[:, 0] == triangles[:, 1])
        | (triangles[:, 1] == triangles[:, 2])
        | (triangles[:, 2] == triangles[:, 0])
    )
    if repeated.any():
        found = f"{int(repeated.sum())} of {len(triangles)} triangles with a repeated corner"
        raise refuse(name, "free of degenerate triangles", found)
    rows = triangles[:, [0, 1, 2]].ravel()
    cols = triangles[:, [1, 2, 0]].ravel()
    graph = coo_matrix((np.ones(rows.size), (rows, cols)), shape=(vertices, vertices))
    components, labels = connected_components(graph, directed=False)
    if components > 1:
        sizes = np.sort(np.bincount(labels[triangles[:, 0]], minlength=components))[::-1]
        shown = ", ".join(str(s) for s in sizes[:5]) + (", ..." if components > 5 else "")
        found = f"{components} separate surfaces ({shown} triangles)"
        raise refuse(name, "one connected surface", found)
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
    return local


def _check_edge_nodes(raw: _Raw, cells: np.ndarray, local: np.ndarray) -> None:
    """Six-node triangles sharing an edge must share its edge node."""
    if cells.shape[1] != 6:
        return
    edge_ids = local.ravel()
    nodes = cells[:, 3:].ravel()
    first = np.full(edge_ids.max() + 1, -1, dtype=np.int64)
    first[edge_ids] = nodes
    disagree = int(np.count_nonzero(first[edge_ids] != nodes))
    if disagree:
        found = f"{disagree} edge nodes not shared by the two triangles of their edge"
        raise refuse(raw.name, "a conforming triangle6 mesh", found)
    reused = len(first) - len(np.unique(first))
    corners = int(np.count_nonzero(first <= cells[:, :3].max()))
    if reused or corners:
        found = f"{reused + corners} edge nodes that are also corners or nodes of other edges"
        raise refuse(raw.name, "a conforming triangle6 mesh", found)


def sphere_fit(points: np.ndarray) -> tuple[np.ndarray, float]:
    """Algebraic least-squares sphere through ``points`` (N, 3): centre and radius.

    Solves ``|x|^2 = 2 c.x + d`` for c and ``d = r^2 - |c|^2`` in the least-squares
    sense (about the points' mean, for conditioning); exact when the points lie
    on a sphere, whatever their distribution.  Units of ``points``.
    """
    mean = points.mean(axis=0)
    x = points - mean
    matrix = np.column_stack([2.0 * x, np.ones(len(x))])
    solution, _, rank, _ = np.linalg.lstsq(matrix, np.einsum("ij,ij->i", x, x), rcond=None)
    if rank < 4:
        return mean, float("nan")
    center = solution[:3]
    squared = solution[3] + center @ center
    return center + mean, math.sqrt(squared) if squared > 0 else float("nan")


def _orientation(points: np.ndarray, triangles: np.ndarray, center: np.ndarray) -> np.ndarray:
    """Per triangle: +1 if its normal points away from ``center``, -1 towards it, 0 if flat."""
    p = points[triangles] - center
    normal = np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0])
    return np.sign(np.einsum("ij,ij->i", normal, p.sum(axis=1)))


def _reverse(cells: np.ndarray, which: np.ndarray) -> np.ndarray:
    """Reverse the orientation of the triangles ``which`` (swap corners 1 and 2)."""
    out = cells.copy()
    swap = [0, 2, 1] if cells.shape[1] == 3 else [0, 2, 1, 5, 4, 3]  # edges 01<->20, 12 stays
    out[which] = cells[which][:, swap]
    return out


# --- pole and frame -----------------------------------------------------------------------


def check_pole(pole: object) -> np.ndarray:
    """The pole direction: three finite numbers, not all zero (``--pole X,Y,Z``); unit vector.

    A string ``"X,Y,Z"`` is accepted as well.  ``None`` means +z.
    """
    if pole is None:
        return np.array([0.0, 0.0, 1.0])
    valid = "three finite numbers X,Y,Z, not all zero"
    try:
        if isinstance(pole, str):
            values = np.array([float(part) for part in pole.split(",")])
        else:
            values = np.asarray(pole, dtype=float).ravel()
    except (TypeError, ValueError):
        raise ParameterError(POLE_FLAG, valid, pole) from None
    if values.shape != (3,) or not np.all(np.isfinite(values)):
        raise ParameterError(POLE_FLAG, valid, pole)
    length = float(np.linalg.norm(values))
    if length == 0.0:
        raise ParameterError(POLE_FLAG, valid, pole)
    return values / length


def rotation_to_z(direction: np.ndarray) -> np.ndarray:
    """The rotation (3, 3) taking the unit vector ``direction`` to +z about their common normal.

    Rodrigues' formula; the identity for +z, a half turn about x for -z.
    """
    z = np.array([0.0, 0.0, 1.0])
    axis = np.cross(direction, z)
    sine, cosine = float(np.linalg.norm(axis)), float(direction @ z)
    if sine < 1e-15:
        return np.eye(3) if cosine > 0 else np.diag([1.0, -1.0, -1.0])
    k = np.array([[0.0, -axis[2], axis[1]], [axis[2], 0.0, -axis[0]], [-axis[1], axis[0], 0.0]])
    return np.eye(3) + k + k @ k * ((1.0 - cosine) / sine**2)


# --- entry point --------------------------------------------------------------------------


def load_sphere_mesh(
    source: MeshSource,
    *,
    pole: Sequence[float] | str | None = None,
    order: int | None = None,
) -> MeshInput:
    """Read, check and normalise a sphere mesh: unit radius, centre at 0, pole on +z.

    Parameters
    ----------
    source : str, Path, meshio.Mesh, skfem.MeshTri1, skfem.MeshTri2 or SphereMesh
        A file in any format meshio reads (``--mesh-file``) or a mesh object;
        scikit-fem meshes carry 3-D points as ``p`` of shape (3, N).  Any
        radius and centre, in any length unit.
    pole : sequence of 3 floats or "X,Y,Z", optional
        Direction from the centre to the pole (``--pole``), in the file's frame;
        default +z.  The mesh is rotated so that it points to +z.
    order : {1, 2}, optional
        Geometric (and element) order of the result (``--order``); default the
        source's.  A 3-node mesh raised to 2 gets edge nodes on the sphere; a
        6-node mesh lowered to 1 keeps its vertices.

    Returns
    -------
    MeshInput
        The unit-sphere :class:`SphereMesh` with radius, centre (file units) and
        the check figures.

    Raises
    ------
    ParameterError
        Naming ``--mesh-file`` (what is wrong, and by how much), ``--pole`` or
        ``--order``.
    """
    direction = check_pole(pole)
    if order is not None:
        order = check_order(order)
    raw = _read(source)
    name = raw.name
    points, cells = raw.points, raw.cells
    if points.ndim != 2 or points.shape[1] != 3:
        found = f"points of shape {points.shape}"
        raise refuse(name, "three-dimensional (points with x, y, z)", found)
    if cells.size == 0:
        raise refuse(name, "a surface of triangle or triangle6 cells", "no triangles")
    if cells.min() < 0 or cells.max() >= len(points):
        raise refuse(name, "a mesh whose cells index its points", "out-of-range node indices")
    used = np.unique(cells)
    if not np.all(np.isfinite(points[used])):
        bad = int(np.count_nonzero(~np.isfinite(points[used]).all(axis=1)))
        raise refuse(name, "made of finite coordinates", f"{bad} points with NaN or inf")
    points, cells, unused = _vertices_first(points, cells)
    points, cells, merged = _merge_coincident(points, cells)
    points, cells, _ = _vertices_first(points, cells)
    source_order = 1 if cells.shape[1] == 3 else 2
    triangles = cells[:, :3]
    vertices = int(triangles.max()) + 1
    local = _check_topology(raw, triangles, vertices)
    _check_edge_nodes(raw, cells, local)

    center, radius = sphere_fit(points)
    if not (math.isfinite(radius) and radius > 0.0):
        raise refuse(name, "a sphere", "nodes that fit no sphere (coplanar or degenerate)")
    distance = np.linalg.norm(points - center, axis=1)
    radius = float(distance.mean())
    deviation = np.abs(distance - radius) / radius
    mean_deviation, max_deviation = float(deviation.mean()), float(deviation.max())
    if mean_deviation > MAX_RADIAL_DEVIATION:
        found = (
            f"mean radial deviation {mean_deviation:.2e} of the fitted radius {radius:.6g} "
            f"(largest {max_deviation:.2e})"
        )
        raise refuse(name, f"a sphere to {MAX_RADIAL_DEVIATION:g} (mean radial deviation)", found)

    corners = points[triangles] - center
    area = 0.5 * np.linalg.norm(
        np.cross(corners[:, 1] - corners[:, 0], corners[:, 2] - corners[:, 0]), axis=1
    )
    flat = int(np.count_nonzero(area <= FLAT_AREA * radius**2))
    if flat:
        raise refuse(name, "free of degenerate triangles", f"{flat} triangles of zero area")
    sign = _orientation(points, triangles, center)
    inward = sign < 0
    flipped = False
    if not raw.orientation_known:
        cells = _reverse(cells, inward)  # scikit-fem sorted the corners: orient each one
    elif inward.all():
        cells, flipped = _reverse(cells, inward), True
    elif inward.any():
        minority = min(int(inward.sum()), int((~inward).sum()))
        found = f"{minority} of {len(cells)} triangles oriented opposite to the others"
        raise refuse(name, "consistently oriented", found)
    _check_consistent(raw, cells[:, :3])

    rotation = rotation_to_z(direction)
    unit = (points - center) / radius
    if not np.array_equal(rotation, np.eye(3)):
        unit = unit @ rotation.T
    mesh_name = f"{name} ({len(cells)} triangles)"
    mesh = SphereMesh(unit, cells, mesh_name)
    target = source_order if order is None else order
    if target != source_order:
        mesh = elevate(mesh) if target == 2 else flatten(mesh)
    result = MeshInput(
        mesh=mesh,
        radius=radius,
        center=center,
        pole=direction,
        rotation=rotation,
        source_order=source_order,
        mean_radial_deviation=mean_deviation,
        max_radial_deviation=max_deviation,
        triangles=len(cells),
        vertices=vertices,
        merged_points=merged,
        unused_points=unused,
        flipped=flipped,
        pole_at_node=mesh.pole_node is not None,
        ignored_cells={k: v for k, v in raw.ignored.items()},
    )
    return replace(result, description=describe(result, name))


def _check_consistent(raw: _Raw, triangles: np.ndarray) -> None:
    """Each directed edge once: neighbours traverse their shared edge in opposite senses."""
    directed = triangles[:, [0, 1, 1, 2, 2, 0]].reshape(-1, 2)
    _, counts = np.unique(directed, axis=0, return_counts=True)
    twice = int(np.count_nonzero(counts > 1))
    if twice:
        found = f"{twice} edges traversed in the same sense by both triangles (folded surface)"
        raise refuse(raw.name, "consistently oriented", found)


def describe(result: MeshInput, name: str) -> str:
    """One paragraph on a loaded mesh (file units for radius and centre)."""
    cx, cy, cz = result.center
    px, py, pz = result.pole
    order = f"P{result.source_order}"
    if result.mesh.order != result.source_order:
        verb = "elevated" if result.mesh.order > result.source_order else "flattened"
        order += f" {verb} to P{result.mesh.order}"
    parts = [
        f"{name}: {result.triangles} triangles, {result.vertices} vertices, {order}",
        f"radius {result.radius:.6g} and centre ({cx:.6g}, {cy:.6g}, {cz:.6g}) in file units",
        f"mean radial deviation {result.mean_radial_deviation:.1e} "
        f"(largest {result.max_radial_deviation:.1e})",
        f"pole ({px:.6g}, {py:.6g}, {pz:.6g}) "
        + ("at a node" if result.pole_at_node else "inside an element"),
    ]
    if result.flipped:
        parts.append("triangles faced inward and were reversed")
    if result.merged_points:
        parts.append(f"{result.merged_points} coincident points merged")
    if result.unused_points:
        parts.append(f"{result.unused_points} unused points dropped")
    if result.ignored_cells:
        ignored = ", ".join(f"{n} {t}" for t, n in sorted(result.ignored_cells.items()))
        parts.append(f"ignored cells: {ignored}")
    return "; ".join(parts)
