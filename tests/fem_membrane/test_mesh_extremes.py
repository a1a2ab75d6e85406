"""A sphere mesh of any size and a pole direction of any length give the answer of the unit ones.

References: the same icosphere written at radius 0.12 m (the lift-off must not
depend on the length unit) and the pole direction (1, 1, 1) (a direction, not a
length: (1e308, 1e308, 1e308) is the same direction, not -z after an overflow).
"""

from __future__ import annotations

import warnings
from pathlib import Path

import meshio
import numpy as np
import pytest
from twoball.fem_membrane.mesh import icosphere
from twoball.fem_membrane.mesh_input import check_pole, load_sphere_mesh

import twoball

CENTRE = np.array([0.3, -0.2, 0.1])  # in radii


def write_ball(path: Path, radius: float) -> Path:
    mesh = icosphere(2, 1)
    points = (mesh.points + CENTRE) * radius
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        meshio.write(str(path), meshio.Mesh(points, [("triangle", mesh.cells)]))
    return path


@pytest.mark.parametrize("radius", [1e200, 1e-200, 1e150, 1e-150])
def test_any_radius_gives_the_lift_off_of_the_ordinary_ball(tmp_path: Path, radius: float) -> None:
    reference = twoball.liftoff(backend="fem", mesh=write_ball(tmp_path / "ref.vtu", 0.12))
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # no overflow or underflow on the way
        report = twoball.liftoff(backend="fem", mesh=write_ball(tmp_path / "big.vtu", radius))
    assert report.t_liftoff_s == pytest.approx(reference.t_liftoff_s, rel=1e-12)
    assert report.v_liftoff_m_s == pytest.approx(reference.v_liftoff_m_s, rel=1e-10)
    loaded = load_sphere_mesh(tmp_path / "big.vtu")
    assert loaded.radius == pytest.approx(radius, rel=1e-14)
    assert np.allclose(loaded.center, CENTRE * radius, rtol=1e-12, atol=1e-14 * radius)


@pytest.mark.parametrize("scale", [1e308, 1e-308, 1e200])
def test_pole_is_a_direction_at_any_length(tmp_path: Path, scale: float) -> None:
    unit = np.ones(3) / np.sqrt(3.0)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        assert np.allclose(check_pole((scale, scale, scale)), unit, rtol=0, atol=1e-15)
        assert np.allclose(check_pole(f"{scale},{scale},{scale}"), unit, rtol=0, atol=1e-15)
    path = write_ball(tmp_path / "ball.vtu", 0.12)
    reference = twoball.liftoff(backend="fem", mesh=twoball.MeshOptions(file=path, pole=(1, 1, 1)))
    report = twoball.liftoff(
        backend="fem", mesh=twoball.MeshOptions(file=path, pole=(scale, scale, scale))
    )
    assert report.t_liftoff_s == reference.t_liftoff_s
    assert report.v_liftoff_m_s == reference.v_liftoff_m_s
