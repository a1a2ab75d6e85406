"""Sphere fit of a user's mesh (fem_membrane/surface_validate.py)."""

from __future__ import annotations

from pathlib import Path

import meshio
import numpy as np
import pytest

import twoball
from tests.meshes import CENTER, RADIUS, on_ball
from twoball.cli.main import main
from twoball.fem_membrane.mesh import icosphere, ring_sphere
from twoball.fem_membrane.mesh_input import load_sphere_mesh
from twoball.fem_membrane.surface_validate import (
    MAX_NODE_DEVIATION,
    MAX_POLE_DEVIATION,
    MAX_RADIAL_DEVIATION,
    sphere_fit,
)

PHI_A = 2.6


def test_sphere_fit_is_exact_for_unevenly_spread_points():
    # a ring sphere crowds vertices near phi_a: their mean is off the centre, the fit is not
    points = on_ball(ring_sphere(2, PHI_A))
    center, radius = sphere_fit(points)
    assert np.linalg.norm(points.mean(axis=0) - CENTER) > 1e-3 * RADIUS
    assert np.allclose(center, CENTER, atol=1e-15) and radius == pytest.approx(RADIUS, rel=1e-14)


# --- A spike or dent that a mean radial deviation hides is refused, at the pole most strictly


def bumped(path: Path, level: int, scale: float, node: str = "pole") -> Path:
    """The icosphere of ``level`` (radius 0.12) with one node's radius times ``scale``."""
    mesh = icosphere(level)
    points = mesh.points.copy()
    index = int(np.argmax(points[:, 2])) if node == "pole" else int(np.argmin(points[:, 2]))
    points[index] *= scale
    meshio.write(path, meshio.Mesh(0.12 * points, [("triangle", mesh.cells)]))
    return path


@pytest.mark.parametrize("scale", [1.3, 0.7])
def test_level5_pole_spike_or_dent_is_refused(scale: float, tmp_path: Path) -> None:
    """A level-5 icosphere with its pole node moved 30 % out or in: its mean deviation ~3e-5
    passes 1e-4, yet a solve on it gives v_l 8.31 m/s against 3.84."""
    path = bumped(tmp_path / "spike.vtu", 5, scale)
    points = meshio.read(path).points
    distance = np.linalg.norm(points, axis=1)
    assert np.mean(np.abs(distance / distance.mean() - 1)) < MAX_RADIAL_DEVIATION
    with pytest.raises(twoball.ParameterError) as refused:
        twoball.liftoff(solver=twoball.Superposition(twoball.MeshOptions(file=str(path))))
    assert refused.value.name == "mesh"
    assert f"to {MAX_NODE_DEVIATION:g} at every node" in str(refused.value)
    assert "3.00e-01" in str(refused.value) and "0 rad from the pole" in str(refused.value)


def test_command_line_refuses_in_one_line(tmp_path: Path, capsys) -> None:
    path = bumped(tmp_path / "spike.vtu", 5, 1.3)
    with pytest.raises(SystemExit) as status:
        main(["liftoff", "--backend", "fem", "--mesh-file", str(path)])
    assert status.value.code == 2
    out, err = capsys.readouterr()
    assert out == "" and len(err.strip().splitlines()) == 1
    assert err.startswith("twoball: error: --mesh-file spike.vtu must be a sphere to 0.01")


def test_pole_neighbourhood_is_stricter(tmp_path: Path) -> None:
    """d = 2e-3 at the pole is refused; the same node turned away from the pole is accepted."""
    path = bumped(tmp_path / "bump.vtu", 3, 1.002)
    with pytest.raises(twoball.ParameterError) as refused:
        load_sphere_mesh(path)
    assert f"to {MAX_POLE_DEVIATION:g} within 0.3 rad of the pole" in str(refused.value)
    turned = load_sphere_mesh(path, pole=(0.0, 0.0, -1.0))
    assert turned.max_radial_deviation == pytest.approx(2e-3, rel=0.01)
    assert turned.pole_radial_deviation < 1e-5  # the others, by the fitted radius's shift


def test_accepted_defects_stay_below_the_discretisation_error(tmp_path: Path) -> None:
    """At the limits the lift-off moves < 1e-4 from the clean mesh (P2 level 3 error ~1e-4)."""
    clean = twoball.liftoff(solver=twoball.Superposition(twoball.MeshOptions("sphere", level=3)))
    for name, scale, node in (
        ("pole", 1 + 0.9 * MAX_POLE_DEVIATION, "pole"),
        ("far", 1 - 0.9 * MAX_NODE_DEVIATION, "south"),
    ):
        path = bumped(tmp_path / f"{name}.vtu", 3, scale, node)
        mesh = twoball.MeshOptions(file=str(path), order=2)
        report = twoball.liftoff(solver=twoball.Superposition(mesh))
        assert report.t_liftoff_s == pytest.approx(clean.t_liftoff_s, rel=1e-4)
        assert report.v_liftoff_m_s == pytest.approx(clean.v_liftoff_m_s, rel=1e-4)
