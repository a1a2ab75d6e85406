"""Meshes of the elastic ball: the (r, z) half disc and half annulus, and the 3-D ball.

All of them are quadratic (isoparametric P2 geometry): every node on a curved
boundary lies on its circle or sphere to rounding (:func:`circle_error`).
Lengths are in units of the outer radius R (the outer boundary is the unit
circle or sphere).  In (r, z) the axis of symmetry is r = 0 and the north pole
is (0, 1).
"""

from __future__ import annotations

import math
from dataclasses import replace

import numpy as np
from skfem import MeshTet1, MeshTet2, MeshTri1, MeshTri2

from twoball._common.errors import ParameterError

__all__ = [
    "ball",
    "ball_gmsh",
    "circle_error",
    "half_annulus",
    "half_disc",
    "half_disc_gmsh",
    "linear",
]

_AXIS_TOL = 1e-12


def _project_arc(mesh: MeshTri1) -> MeshTri1:
    """Vertices on the curved boundary (boundary nodes off the axis) moved onto the unit circle."""
    p = mesh.p.copy()
    nodes = mesh.boundary_nodes()
    nodes = nodes[p[0, nodes] > _AXIS_TOL]
    p[:, nodes] /= np.linalg.norm(p[:, nodes], axis=0)
    return replace(mesh, doflocs=p)


def half_disc(level: int) -> MeshTri2:
    """The meridian half disc {r >= 0, r^2 + z^2 <= 1} of the solid ball, P2 geometry.

    Four triangles around the centre, refined ``level`` times (each halves h,
    h ~ 0.77 * 2^-level); after each refinement the new vertices on the arc are
    moved onto the circle, and in the quadratic mesh so are the arc's mid-edge nodes.

    Parameters
    ----------
    level : int
        Uniform refinements, >= 0.
    """
    if level < 0 or int(level) != level:
        raise ParameterError("level", "an integer >= 0", level)
    angles = np.linspace(0.0, math.pi, 5)  # from the south pole (0, -1) to the north
    arc = np.vstack([np.sin(angles), -np.cos(angles)])
    arc[0, [0, -1]] = 0.0
    p = np.hstack([np.zeros((2, 1)), arc])
    t = np.array([[0, i, i + 1] for i in range(1, 5)]).T
    mesh = MeshTri1(p, t)
    for _ in range(int(level)):
        mesh = _project_arc(mesh.refined())
    return _quadratic_on_circle(MeshTri2.from_mesh(mesh), outer=1.0)


def _quadratic_on_circle(mesh: MeshTri2, outer: float, inner: float | None = None) -> MeshTri2:
    """Mid-edge nodes of curved boundary facets moved radially onto their circle."""
    facets = mesh.boundary_facets()
    dofs = mesh.dofs.get_facet_dofs(facets).flatten()
    x = mesh.doflocs.copy()
    on_arc = x[0, dofs] > _AXIS_TOL
    dofs = dofs[on_arc]
    radius = np.linalg.norm(x[:, dofs], axis=0)
    target = np.full_like(radius, outer)
    if inner is not None:
        target[np.abs(radius - inner) < np.abs(radius - outer)] = inner
    x[:, dofs] *= target / radius
    return replace(mesh, doflocs=x)


def half_annulus(inner: float, radial: int, angular: int) -> MeshTri2:
    """The meridian half annulus {r >= 0, inner <= sqrt(r^2 + z^2) <= 1} of a hollow ball.

    A tensor grid in (s, alpha), s the radius and alpha the polar angle from the
    south pole, each cell cut in two; the quadratic mesh is built in (s, alpha)
    and every node is then mapped by (r, z) = (s sin alpha, -s cos alpha), so all
    edges, not only the boundary, follow the polar map (isoparametric P2).

    Parameters
    ----------
    inner : float
        Inner radius (R - h) / R, in (0, 1).
    radial, angular : int
        Cells across the wall and along the half circle.
    """
    if not 0.0 < inner < 1.0:
        raise ParameterError("inner", "in (0, 1)", inner)
    for name, value in (("radial", radial), ("angular", angular)):
        if value < 1 or int(value) != value:
            raise ParameterError(name, "an integer >= 1", value)
    flat = MeshTri1.init_tensor(
        np.linspace(inner, 1.0, radial + 1), np.linspace(0, math.pi, angular + 1)
    )
    quad = MeshTri2.from_mesh(flat)
    s, alpha = quad.doflocs
    x = np.ascontiguousarray(np.vstack([s * np.sin(alpha), -s * np.cos(alpha)]))
    x[0, np.isclose(alpha, 0.0) | np.isclose(alpha, math.pi)] = 0.0
    return replace(quad, doflocs=x)


def circle_error(mesh: MeshTri2 | MeshTet2, radii: tuple[float, ...] = (1.0,)) -> float:
    """Largest distance of a curved-boundary node from the nearest of ``radii`` (units of R)."""
    dofs = mesh.dofs.get_facet_dofs(mesh.boundary_facets()).flatten()
    x = mesh.doflocs[:, dofs]
    if mesh.dim() == 2:
        x = x[:, x[0] > _AXIS_TOL]
    radius = np.linalg.norm(x, axis=0)
    return float(np.min(np.abs(radius[:, None] - np.asarray(radii)[None, :]), axis=1).max())


def linear(mesh: MeshTet2) -> MeshTet1:
    """The P1 mesh of a quadratic ball's vertices (straight facets, vertices on the sphere)."""
    return MeshTet1(np.ascontiguousarray(mesh.p[:, : mesh.nvertices]), mesh.t)


def ball(level: int) -> MeshTet2:
    """The unit ball in P2 tetrahedra: scikit-fem's octahedron refined ``level`` times.

    ``MeshTet2.init_ball``: vertices on the sphere after each refinement, then the
    mid-edge nodes of the boundary facets moved onto it (h ~ 2^-level).
    """
    if level < 0 or int(level) != level:
        raise ParameterError("level", "an integer >= 0", level)
    return MeshTet2.init_ball(int(level))


def _size_field(gmsh, size: float, surface: float) -> None:
    """Size ``surface`` on the unit sphere or circle, growing linearly to ``size`` at depth 0.3."""
    if surface < size:
        field = gmsh.model.mesh.field
        dist = field.add("MathEval")
        depth = "(1 - sqrt(x^2 + y^2 + z^2))"
        field.setString(dist, "F", f"{surface} + ({size} - {surface}) * {depth} / 0.3")
        const = field.add("MathEval")
        field.setString(const, "F", f"{size}")
        cap = field.add("Min")
        field.setNumbers(cap, "FieldsList", [dist, const])
        field.setAsBackgroundMesh(cap)
        gmsh.option.setNumber("Mesh.MeshSizeFromPoints", 0)
        gmsh.option.setNumber("Mesh.MeshSizeExtendFromBoundary", 0)
        gmsh.option.setNumber("Mesh.MeshSizeFromCurvature", 0)
    else:
        gmsh.option.setNumber("Mesh.MeshSizeMin", size)
        gmsh.option.setNumber("Mesh.MeshSizeMax", size)


def half_disc_gmsh(size: float, surface_size: float | None = None) -> MeshTri2:
    """The meridian half disc meshed by gmsh, graded to ``surface_size`` at the arc.

    Modes of high degree and low radial order are confined near the surface
    (their depth ~ R / n), so a finer arc carries them at the cost of few elements.
    The arc's vertices and mid-edge nodes are on the unit circle (P2 geometry).

    Parameters
    ----------
    size : float
        Element size inside (units of R), in (0, 1].
    surface_size : float, optional
        Element size along the arc (default ``size``).
    """
    import gmsh

    if not 0.0 < size <= 1.0:
        raise ParameterError("size", "in (0, 1]", size)
    surface = size if surface_size is None else surface_size
    if not 0.0 < surface <= size:
        raise ParameterError("surface_size", f"in (0, size = {size}]", surface_size)
    initialized = gmsh.isInitialized()
    if not initialized:
        gmsh.initialize(interruptible=False)
    try:
        gmsh.option.setNumber("General.Terminal", 0)
        gmsh.model.add("half_disc")
        geo = gmsh.model.geo
        south, centre, east, north = (
            geo.addPoint(0, -1, 0),
            geo.addPoint(0, 0, 0),
            geo.addPoint(1, 0, 0),
            geo.addPoint(0, 1, 0),
        )
        lower, upper = geo.addCircleArc(south, centre, east), geo.addCircleArc(east, centre, north)
        axis = geo.addLine(north, south)
        geo.addPlaneSurface([geo.addCurveLoop([lower, upper, axis])])
        geo.synchronize()
        _size_field(gmsh, size, surface)
        gmsh.option.setNumber("Mesh.Optimize", 1)
        gmsh.model.mesh.generate(2)
        tags, coords, _ = gmsh.model.mesh.getNodes()
        types, _, nodes = gmsh.model.mesh.getElements(2)
        tri = nodes[list(types).index(2)].reshape(-1, 3).astype(np.int64)
        gmsh.model.remove()
    finally:
        if not initialized:
            gmsh.finalize()
    index = np.zeros(int(tags.max()) + 1, dtype=np.int64)
    index[tags.astype(np.int64)] = np.arange(len(tags))
    p = coords.reshape(-1, 3).T[:2]
    used = np.unique(index[tri])
    renumber = np.full(len(tags), -1)
    renumber[used] = np.arange(len(used))
    x = np.ascontiguousarray(p[:, used])
    x[0, np.abs(x[0]) < 1e-12] = 0.0
    linear = _project_arc(MeshTri1(x, np.ascontiguousarray(renumber[index[tri]].T)))
    return _quadratic_on_circle(MeshTri2.from_mesh(linear), outer=1.0)


def ball_gmsh(size: float, surface_size: float | None = None) -> MeshTet2:
    """The unit ball meshed by gmsh with element size ``size`` (``surface_size`` on the sphere).

    gmsh's linear tetrahedra become a quadratic mesh whose boundary mid-edge nodes
    are moved onto the sphere (as ``MeshTet2.init_ball`` does).  A finer
    ``surface_size`` grades the mesh towards the surface, where the low modes of
    high degree live.

    Parameters
    ----------
    size : float
        Target element size inside (units of R), in (0, 1].
    surface_size : float, optional
        Target size on the sphere (default ``size``).
    """
    import gmsh

    if not 0.0 < size <= 1.0:
        raise ParameterError("size", "in (0, 1]", size)
    surface = size if surface_size is None else surface_size
    if not 0.0 < surface <= size:
        raise ParameterError("surface_size", f"in (0, size = {size}]", surface_size)
    initialized = gmsh.isInitialized()
    if not initialized:
        gmsh.initialize(interruptible=False)
    try:
        gmsh.option.setNumber("General.Terminal", 0)
        gmsh.model.add("ball")
        gmsh.model.occ.addSphere(0, 0, 0, 1.0)
        gmsh.model.occ.synchronize()
        _size_field(gmsh, size, surface)
        gmsh.option.setNumber("Mesh.Optimize", 1)
        gmsh.model.mesh.generate(3)
        tags, coords, _ = gmsh.model.mesh.getNodes()
        types, _, nodes = gmsh.model.mesh.getElements(3)
        tet = nodes[list(types).index(4)].reshape(-1, 4)
        gmsh.model.remove()
    finally:
        if not initialized:
            gmsh.finalize()
    index = np.zeros(int(tags.max()) + 1, dtype=np.int64)
    index[tags.astype(np.int64)] = np.arange(len(tags))
    p = coords.reshape(-1, 3).T
    used = np.unique(index[tet.astype(np.int64)])
    renumber = np.full(len(tags), -1)
    renumber[used] = np.arange(len(used))
    t = renumber[index[tet.astype(np.int64)]].T
    linear = MeshTet1(p[:, used], t)
    b = linear.boundary_nodes()
    x = linear.p.copy()
    x[:, b] /= np.linalg.norm(x[:, b], axis=0)
    quad = MeshTet2.from_mesh(replace(linear, doflocs=x))
    dofs = quad.dofs.get_facet_dofs(quad.boundary_facets()).flatten()
    y = quad.doflocs.copy()
    y[:, dofs] /= np.linalg.norm(y[:, dofs], axis=0)
    return replace(quad, doflocs=y)
