"""Sphere meshes brought by the user: files in any meshio format, meshio or scikit-fem meshes.

:func:`load_sphere_mesh` reads a triangulated sphere of any radius and centre
(gmsh ``.msh``, ``.vtu``, ``.vtk``, ``.xdmf``, ``.stl``, ``.obj``, ``.ply``, ``.off``,
... -- whatever :func:`meshio.read` reads; the points are always read by meshio,
never by ``skfem.MeshTri.load``, which drops z), checks that it is one closed
sphere, and returns it as a :class:`twoball.fem_membrane.mesh.SphereMesh` on the
unit sphere, rotated so that the requested pole direction is +z -- the
dimensionless geometry of eq. (3.9), whose pole motion decides lift-off.

The checks (one closed, manifold, connected surface of sphere topology,
spherical to :data:`MAX_RADIAL_DEVIATION` on average, to
:data:`~twoball.fem_membrane.surface_validate.MAX_NODE_DEVIATION` at every node and
:data:`~twoball.fem_membrane.surface_validate.MAX_POLE_DEVIATION` near the pole,
consistently oriented, no triangle with an angle below
:data:`~twoball.fem_membrane.quality.DEGENERATE_ANGLE` -- poor ones near the pole
are warned about, :mod:`twoball.fem_membrane.quality`) and the
centre and radius fit are in :mod:`twoball.fem_membrane.surface_validate`; each
failure is a :class:`twoball._common.errors.ParameterError` naming ``mesh``
with what is wrong and by how much.  Cells: ``triangle`` (3-node) or
``triangle6`` (6-node), one kind only; other surface cells (quadrilaterals,
polygons) are refused; lines, vertices and volume cells are ignored (and
reported in :attr:`MeshInput.description`).

Units: ``radius`` and ``center`` are in the file's units (metres if the file is
in metres); the returned mesh is dimensionless (unit radius).
"""

from __future__ import annotations

import contextlib
import io
import math
import os
import warnings
from collections.abc import Sequence
from dataclasses import dataclass, field, replace
from pathlib import Path
from typing import Any

import numpy as np

from twoball.fem_membrane.mesh import SphereMesh, elevate, flatten
from twoball.fem_membrane.surface_validate import (
    MAX_RADIAL_DEVIATION,
    check_sphere,
    check_topology,
    clean_nodes,
    orient_outward,
    refuse,
)
from twoball.fem_membrane.validate import check_order
from twoball.fem_membrane.validate import check_pole as check_pole_direction

__all__ = ["MAX_RADIAL_DEVIATION", "MeshInput", "check_pole", "load_sphere_mesh", "rotation_to_z"]

POLE_FLAG = "pole"  # the parameter; the command line shows --pole
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
        raised to the requested order 2 to 4 (new nodes projected onto the sphere).
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
    pole_radial_deviation : float
        The largest of them within 0.3 rad of the pole (and its 7 nearest nodes).
    smallest_angle_deg : float
        The smallest angle of any triangle [deg] (below 0.1 the mesh is refused;
        :mod:`twoball.fem_membrane.quality`).
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
    pole_radial_deviation: float = 0.0
    smallest_angle_deg: float = 60.0

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
            "pole_radial_deviation": self.pole_radial_deviation,
            "smallest_angle_deg": self.smallest_angle_deg,
            "merged_points": self.merged_points,
            "unused_points": self.unused_points,
            "flipped": self.flipped,
            "pole_at_node": self.pole_at_node,
            "ignored_cells": dict(self.ignored_cells),
        }


# --- reading ----------------------------------------------------------------------------


@dataclass
class _Raw:
    """Points and triangles as read, before any check."""

    points: np.ndarray
    cells: np.ndarray
    name: str
    ignored: dict[str, int] = field(default_factory=dict)
    orientation_known: bool = True  # False for scikit-fem meshes built with sort_t=True
    order: int | None = None  # a SphereMesh of order 3 or 4 (read through its vertices)


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
        try:
            readable = path.is_file() and os.access(path, os.R_OK)
        except OSError as error:  # a name too long, a loop of links, ...
            raise refuse(str(path)[:200], "an existing mesh file", error.strerror) from None
        if not readable:
            raise refuse(str(path), "an existing mesh file", "no such file")
        return _from_meshio(_meshio_read(path), path.name)
    if isinstance(source, meshio.Mesh):
        return _from_meshio(source, "(meshio.Mesh)")
    if isinstance(source, SphereMesh):
        if source.order > 2:  # the checks read 3- and 6-node triangles: its vertices,
            flat = flatten(source)  # raised again to its order (its nodes are rebuilt)
            return _Raw(flat.points, flat.cells, source.name, order=source.order)
        return _Raw(source.points, source.cells, source.name)
    module = type(source).__module__
    if module.startswith("skfem"):
        return _from_skfem(source, f"({type(source).__name__})")
    raise refuse(
        f"({type(source).__name__})",
        "a path, a meshio.Mesh, a scikit-fem MeshTri1/MeshTri2 or a SphereMesh",
        type(source).__name__,
    )


# --- pole and frame -----------------------------------------------------------------------


def check_pole(pole: object) -> np.ndarray:
    """The pole direction as a unit vector (:func:`~twoball.fem_membrane.validate.check_pole`).

    Three finite numbers, not all zero, or the text ``"X,Y,Z"``; ``None`` means +z.
    """
    if pole is None:
        return np.array([0.0, 0.0, 1.0])
    values = np.array(check_pole_direction(pole, POLE_FLAG))
    largest = float(np.abs(values).max())
    values = values / largest  # 1e308,1e308,1e308 would overflow the length
    return values / float(np.linalg.norm(values))


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
        A file in any format meshio reads or a mesh object;
        scikit-fem meshes carry 3-D points as ``p`` of shape (3, N).  Any
        radius and centre, in any length unit.
    pole : sequence of 3 floats or "X,Y,Z", optional
        Direction from the centre to the pole, in the file's frame;
        default +z.  The mesh is rotated so that it points to +z.
    order : {1, 2, 3, 4}, optional
        Geometric (and element) order of the result; default the
        source's.  A mesh raised to 2, 3 or 4 gets its new nodes from its
        vertices (equispaced points of each flat triangle projected radially
        onto the sphere, :func:`twoball.fem_membrane.mesh.elevate`; a 6-node
        source's own edge nodes are not used above order 2); a 6-node mesh
        lowered to 1 keeps its vertices.

    Returns
    -------
    MeshInput
        The unit-sphere :class:`SphereMesh` with radius, centre (file units) and
        the check figures.

    Raises
    ------
    ParameterError
        Naming ``mesh`` (what is wrong, and by how much), ``pole`` or
        ``order``.
    """
    direction = check_pole(pole)
    if order is not None:
        order = check_order(order)
    raw = _read(source)
    name = raw.name
    points, cells, unused, merged = clean_nodes(name, raw.points, raw.cells)
    check_topology(name, cells)
    fit = check_sphere(name, points, direction)
    cells, flipped = orient_outward(name, points, cells, fit, raw.orientation_known)
    from twoball.fem_membrane.quality import check_angles  # degenerate triangles: refused

    smallest = check_angles(name, (points - fit.center) / fit.radius, cells, direction)
    source_order = 1 if cells.shape[1] == 3 else 2
    if raw.order is not None:
        source_order = raw.order
    center, radius = fit.center, fit.radius

    rotation = rotation_to_z(direction)
    unit = (points - center) / radius
    if not np.array_equal(rotation, np.eye(3)):
        unit = unit @ rotation.T
    mesh_name = f"{name} ({len(cells)} triangles)"
    mesh = SphereMesh(unit, cells, mesh_name)
    target = source_order if order is None else order
    if target != mesh.order:
        mesh = elevate(mesh, target) if target > 1 else flatten(mesh)
    result = MeshInput(
        mesh=mesh,
        radius=radius,
        center=center,
        pole=direction,
        rotation=rotation,
        source_order=source_order,
        mean_radial_deviation=fit.mean_deviation,
        max_radial_deviation=fit.max_deviation,
        pole_radial_deviation=fit.pole_deviation,
        triangles=len(cells),
        vertices=int(cells[:, :3].max()) + 1,
        merged_points=merged,
        unused_points=unused,
        flipped=flipped,
        pole_at_node=mesh.pole_node is not None,
        ignored_cells={k: v for k, v in raw.ignored.items()},
        smallest_angle_deg=math.degrees(smallest),
    )
    return replace(result, description=describe(result, name))


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
        f"(largest {result.max_radial_deviation:.1e}, near the pole "
        f"{result.pole_radial_deviation:.1e})",
        f"pole ({px:.6g}, {py:.6g}, {pz:.6g}) "
        + ("at a node" if result.pole_at_node else "inside an element"),
        f"smallest triangle angle {result.smallest_angle_deg:.3g} deg",
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


def read_mesh(path: str | Path, ring: float | None = None) -> SphereMesh:
    """Read a sphere mesh with meshio (``triangle`` or ``triangle6`` cells) onto the unit sphere.

    A thin wrapper of :func:`load_sphere_mesh`:
    the surface is checked (closed, one piece, spherical, consistently oriented),
    scaled from any radius and centre to the unit sphere with the pole on +z,
    and its nodes numbered vertices first.  ``ring`` marks a latitude made of
    mesh edges (see :func:`twoball.fem_membrane.mesh.ring_sphere`).  Points are read by meshio,
    never
    through ``skfem.MeshTri.load``, which keeps only x and y.
    """
    return replace(load_sphere_mesh(path).mesh, ring=ring)
