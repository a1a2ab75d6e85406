"""Triangle quality of a user's mesh: degenerate triangles refused, poor ones near the pole warned.

Independent values: the angles of triangles drawn by hand (equilateral 60 deg, a
right isosceles 45 deg, a sliver of known angle), and an icosphere whose radii stay
exact while one node slides along the sphere towards its neighbour (the radial
checks cannot see it).
"""

from __future__ import annotations

import math

import meshio
import numpy as np
import pytest

import twoball
from tests.meshes import CENTER, RADIUS, write
from twoball.cli.main import main
from twoball.fem_membrane.mesh import icosphere
from twoball.fem_membrane.mesh_input import load_sphere_mesh
from twoball.fem_membrane.quality import DEGENERATE_ANGLE, POOR_ANGLE, smallest_angles


def test_smallest_angles_of_triangles_drawn_by_hand():
    s = math.sqrt(3.0) / 2.0
    points = np.array(
        [[0, 0, 0], [1, 0, 0], [0.5, s, 0], [0, 1, 0], [2, 0, 0], [1, math.tan(1e-3), 0]]
    )
    cells = np.array([[0, 1, 2], [0, 1, 3], [0, 4, 5]])
    expected = [math.pi / 3, math.pi / 4, 1e-3]  # the sliver: 1e-3 rad at both ends
    np.testing.assert_allclose(smallest_angles(points, cells), expected, rtol=1e-12)


def _slid(level: int, fraction: float, at: str = "pole") -> tuple[np.ndarray, np.ndarray]:
    """An icosphere (P1, on the 0.12 m ball) with one node slid along the sphere by
    ``fraction`` of its edge: the pole's nearest neighbour towards the pole, or a node on
    the equator towards its neighbour."""
    mesh = icosphere(level, 1)
    points, cells = mesh.points.copy(), mesh.cells
    target = int(np.argmax(points[:, 2])) if at == "pole" else int(np.argmin(np.abs(points[:, 2])))
    ring = set(cells[(cells == target).any(axis=1)].ravel()) - {target}
    node = min(ring, key=lambda j: np.linalg.norm(points[j] - points[target]))
    angle = math.acos(float(np.clip(points[node] @ points[target], -1.0, 1.0)))
    axis = np.cross(points[node], points[target])
    axis /= np.linalg.norm(axis)
    turn, v = fraction * angle, points[node]
    points[node] = v * math.cos(turn) + np.cross(axis, v) * math.sin(turn)  # v is normal to axis
    return points * RADIUS + CENTER, cells


@pytest.mark.parametrize("at", ["pole", "equator"])
def test_a_collapsed_edge_is_refused_naming_the_mesh(at):
    """99.99 % of an edge collapsed: radii exact, smallest angle 0.005 deg -- refused by its
    angle (before: accepted, then "Krylov ... use the full eigen route" near the pole)."""
    points, cells = _slid(3, 0.9999, at)
    with pytest.raises(twoball.ParameterError) as refused:
        load_sphere_mesh(meshio.Mesh(points, [("triangle", cells)]))
    text = str(refused.value)
    assert refused.value.name == "mesh" and "degenerate triangles" in text
    assert f"every angle at least {math.degrees(DEGENERATE_ANGLE):g} deg" in text


def test_a_poor_triangle_near_the_pole_is_warned_not_elsewhere():
    """98 % collapsed (1.1 deg) at the pole: v_l moves by percents -- a warning; the same
    at the equator (0.87 deg) moves it by 2e-5 and the intact mesh is quiet."""
    case = twoball.Case.preset("basketball")
    warned = {}
    for name, (points, cells) in {
        "intact": _slid(3, 0.0),
        "pole": _slid(3, 0.98, "pole"),
        "equator": _slid(3, 0.98, "equator"),
    }.items():
        mesh = meshio.Mesh(points, [("triangle", cells)])
        loaded = load_sphere_mesh(mesh)
        report = twoball.liftoff(case, solver=twoball.Superposition(mesh))
        warned[name] = [w for w in report.warnings if w.startswith("mesh quality near the pole")]
        if name != "intact":  # 1.1 deg at the pole, 0.87 deg at the equator: kept
            assert 0.8 < loaded.smallest_angle_deg < 1.2
    assert warned["intact"] == [] and warned["equator"] == []
    [text] = warned["pole"]
    assert f"an angle below {math.degrees(POOR_ANGLE):g} deg (the smallest 1.1 deg)" in text


def test_the_command_line_refuses_a_collapsed_mesh_in_one_line(tmp_path, capsys):
    points, cells = _slid(3, 0.99999)
    path = tmp_path / "ball.msh"
    write(path, points, cells)
    with pytest.raises(SystemExit) as stop:
        main(["liftoff", "--backend", "fem", "--mesh-file", str(path)])
    [line] = capsys.readouterr().err.strip().splitlines()
    assert stop.value.code == 2 and "--mesh-file" in line and "degenerate triangle" in line
