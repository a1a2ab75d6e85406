"""Triangle quality of a user's sphere mesh: its smallest angles, refused or warned.

The radial checks of :mod:`twoball.fem_membrane.surface_validate` see only where
the nodes lie, not how they are joined: a node slid along the sphere towards
its neighbour keeps every radius exact while the triangles between them
collapse.  The smallest angle of each triangle (its vertices; measured in 3-D)
tells:

* :data:`DEGENERATE_ANGLE` -- below it anywhere, the mesh is refused
  (:func:`check_angles`): a collapsed edge or a sliver.  Measured on icosphere
  level 4 (P1, 2562 nodes) with one node slid towards its neighbour: at 0.004 deg
  the rational Krylov route no longer converges ("use the full eigen route", a
  message that names the solver, not the mesh); at 0.9 deg, away from the pole,
  the lift-off velocity moves by 2e-5 only.  0.1 deg keeps a margin of 20 to
  the failure and passes any mesh a mesher would call a mesh (a UV sphere's
  pole fan of 720 segments has 0.5 deg).
* :data:`POOR_ANGLE` -- below it within :data:`~twoball.fem_membrane.
  surface_validate.POLE_CAP` of the pole, a warning (:func:`pole_quality_warnings`):
  the pole's motion decides the lift-off, and there a poor triangle moves it
  (measured, the pole's nearest neighbour slid towards the pole: 90 % of the
  edge, smallest angle 5.6 deg: v_l +0.5 % on level 4, +2.1 % on level 3; 98 %,
  1.1 deg: +0.6 % and +2.5 %).  15 deg is the usual floor of quality meshers
  (an icosphere has 54 deg, gmsh's frontal meshes 25 deg and more).

Only the vertices (the first three nodes of 3- or 6-node triangles) are used.
"""

from __future__ import annotations

import math

import numpy as np

from twoball.fem_membrane.surface_validate import POLE_CAP, refuse

__all__ = [
    "DEGENERATE_ANGLE",
    "POOR_ANGLE",
    "check_angles",
    "pole_quality_warnings",
    "smallest_angles",
]

DEGENERATE_ANGLE = math.radians(0.1)
"""Smallest accepted angle of any triangle [rad] (0.1 deg; see the module documentation)."""
POOR_ANGLE = math.radians(15.0)
"""Smallest angle [rad] below which a triangle near the pole is warned about (15 deg)."""


def smallest_angles(points: np.ndarray, cells: np.ndarray) -> np.ndarray:
    """The smallest interior angle [rad] of each triangle (its first three nodes)."""
    corners = [points[cells[:, k]] for k in range(3)]
    smallest = np.full(cells.shape[0], np.pi)
    for k in range(3):
        a, b, c = corners[k], corners[(k + 1) % 3], corners[(k + 2) % 3]
        u, v = b - a, c - a
        # atan2(|u x v|, u.v): accurate for angles near 0 (arccos of the cosine is not)
        angle = np.arctan2(np.linalg.norm(np.cross(u, v), axis=1), np.einsum("ij,ij->i", u, v))
        smallest = np.minimum(smallest, angle)
    return smallest


def _from_pole(points: np.ndarray, cells: np.ndarray, pole: np.ndarray) -> np.ndarray:
    """Polar angle [rad] of each triangle's centroid about ``pole`` (a direction)."""
    centroid = points[cells[:, :3]].mean(axis=1)
    centre = points.mean(axis=0) if points.shape[0] else np.zeros(3)
    offset = centroid - centre
    unit = np.asarray(pole, dtype=float) / np.linalg.norm(pole)
    length = np.linalg.norm(offset, axis=1)
    return np.arccos(np.clip(offset @ unit / np.where(length > 0, length, 1.0), -1.0, 1.0))


def check_angles(
    name: str, points: np.ndarray, cells: np.ndarray, pole: np.ndarray | None = None
) -> float:
    """Refuse a mesh with a triangle whose smallest angle is below :data:`DEGENERATE_ANGLE`.

    Returns the smallest angle of the mesh [rad].  ``pole`` (a direction in the
    points' frame) only places the worst triangle in the message.
    """
    angles = smallest_angles(points, cells)
    if angles.size == 0:
        return math.pi
    bad = np.flatnonzero(angles < DEGENERATE_ANGLE)
    if bad.size:
        worst = bad[np.argmin(angles[bad])]
        where = ""
        if pole is not None:
            where = f", {_from_pole(points, cells[[worst]], pole)[0]:.3g} rad from the pole"
        raise refuse(
            name,
            f"made of proper triangles (every angle at least {math.degrees(DEGENERATE_ANGLE):g}"
            " deg)",
            f"{bad.size} degenerate triangle{'s' if bad.size > 1 else ''}, the worst with an "
            f"angle of {math.degrees(angles[worst]):.2g} deg{where} (a collapsed edge or a "
            "sliver; remesh)",
        )
    return float(angles.min())


def pole_quality_warnings(points: np.ndarray, cells: np.ndarray) -> list[str]:
    """A warning if triangles near the pole (+z, unit sphere) have an angle below POOR_ANGLE."""
    near = _from_pole(points, cells, np.array([0.0, 0.0, 1.0])) <= POLE_CAP
    if not near.any():
        return []
    angles = smallest_angles(points, cells[near])
    poor = angles < POOR_ANGLE
    if not poor.any():
        return []
    count = int(poor.sum())
    return [
        f"mesh quality near the pole: {count} triangle{'s' if count > 1 else ''} within "
        f"{POLE_CAP:g} rad of the pole {'have' if count > 1 else 'has'} an angle below "
        f"{math.degrees(POOR_ANGLE):g} deg (the smallest {math.degrees(angles.min()):.2g} deg); "
        "the pole's motion decides the lift-off, and such triangles move v_l by up to a few "
        "percent: remesh the pole's neighbourhood"
    ]
