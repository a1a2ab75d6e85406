"""The ball's meshes: curved nodes on their circles and spheres, volumes converging."""

from __future__ import annotations

import math

import numpy as np
import pytest
from skfem import Basis, ElementTetP2, ElementTriP2, Functional

from twoball._common.errors import ParameterError
from twoball.fem_solid.mesh import ball, ball_gmsh, circle_error, half_annulus, half_disc


@Functional
def swept_volume(w):
    return 2.0 * math.pi * w.x[0]


@Functional
def volume(w):
    return 1.0 + 0.0 * w.x[0]


def test_half_disc_nodes_on_circle_and_volume_order():
    """Arc nodes (vertices and mid-edge) on the unit circle; the swept volume -> 4 pi / 3 at
    the isoparametric P2 rate (observed order in [3.5, 5] on levels 1-4)."""
    errors = []
    for level in range(1, 5):
        mesh = half_disc(level)
        assert circle_error(mesh) < 1e-15
        assert mesh.p[0].min() >= 0.0
        v = swept_volume.assemble(Basis(mesh, ElementTriP2(), intorder=6))
        errors.append(abs(v - 4 * math.pi / 3))
    orders = np.log2(np.array(errors[:-1]) / np.array(errors[1:]))
    assert np.all((orders > 3.5) & (orders < 5.0)), orders


def test_half_annulus_on_both_circles():
    mesh = half_annulus(0.6, 3, 24)
    assert circle_error(mesh, (0.6, 1.0)) < 1e-15
    v = swept_volume.assemble(Basis(mesh, ElementTriP2(), intorder=6))
    assert v == pytest.approx(4 * math.pi / 3 * (1 - 0.6**3), rel=1e-6)


def test_balls_on_sphere():
    for mesh in (ball(2), ball_gmsh(0.5)):
        assert circle_error(mesh) < 1e-15
        v = volume.assemble(Basis(mesh, ElementTetP2(), intorder=4))
        assert v == pytest.approx(4 * math.pi / 3, rel=2e-3)


def test_graded_gmsh_ball_is_finer_at_the_surface():
    mesh = ball_gmsh(0.5, 0.2)
    edges = mesh.p[:, mesh.edges]
    length = np.linalg.norm(edges[:, 0] - edges[:, 1], axis=0)
    depth = 1.0 - np.linalg.norm(0.5 * (edges[:, 0] + edges[:, 1]), axis=0)
    assert length[depth < 0.05].mean() < 0.7 * length[depth > 0.4].mean()


def test_invalid():
    with pytest.raises(ParameterError):
        half_disc(-1)
    with pytest.raises(ParameterError):
        half_annulus(1.0, 2, 8)
    with pytest.raises(ParameterError):
        ball_gmsh(0.3, 0.5)


def test_gmsh_half_disc_on_circle_and_graded():
    from twoball.fem_solid.mesh import half_disc_gmsh

    mesh = half_disc_gmsh(0.3, 0.1)
    assert circle_error(mesh) < 1e-15 and mesh.p[0].min() == 0.0
    v = swept_volume.assemble(Basis(mesh, ElementTriP2(), intorder=6))
    assert v == pytest.approx(4 * math.pi / 3, rel=1e-6)
