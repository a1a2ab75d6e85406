"""Sphere meshes (fem_membrane/mesh.py).

Counts, pole vertex, orientation, curved nodes, the ring.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from twoball._common.errors import ParameterError
from twoball.fem_membrane.axisym import axisym_space
from twoball.fem_membrane.mesh import (
    _edges,
    icosphere,
    min_angle,
    ring_rows,
    ring_sphere,
    topology,
)

PHI_A = 2.6


def outward(mesh) -> np.ndarray:
    p = mesh.points[mesh.triangles]
    normal = np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0])
    return np.einsum("ij,ij->i", normal, p.sum(axis=1)) > 0


def euler_characteristic(mesh) -> int:
    t = mesh.triangles
    edges = np.unique(np.sort(t[:, [0, 1, 1, 2, 2, 0]].reshape(-1, 2), axis=1), axis=0)
    return mesh.vertex_count - len(edges) + len(t)


def test_mesh_builders_reject():
    with pytest.raises(ParameterError, match=r"level must be an integer in \[0, 10\], got -1"):
        icosphere(-1)
    with pytest.raises(ParameterError, match="order must be 1, 2, 3 or 4"):
        icosphere(1, order=5)
    with pytest.raises(ParameterError, match="phi_a"):
        ring_sphere(1, 4.0)
    with pytest.raises(ParameterError, match="elements must be an integer >= 2"):
        axisym_space(1, PHI_A)


@pytest.mark.parametrize("order", [3, 4])
@pytest.mark.parametrize("kind", ["sphere", "ring"])
def test_nodes_lie_on_the_sphere_once_each(order, kind):
    mesh = icosphere(1, order) if kind == "sphere" else ring_sphere(1, PHI_A, order)
    flat = icosphere(1) if kind == "sphere" else ring_sphere(1, PHI_A)
    edges, _ = _edges(flat.triangles)
    interior = {3: 1, 4: 3}[order]
    assert mesh.cells.shape[1] == (order + 1) * (order + 2) // 2
    assert len(mesh.points) == len(flat.points) + (order - 1) * len(edges) + interior * len(
        flat.cells
    )
    assert np.abs(np.linalg.norm(mesh.points, axis=1) - 1.0).max() < 1e-15
    # no node twice (a torn numbering would duplicate edge nodes)
    assert len(np.unique(np.round(mesh.points, 12), axis=0)) == len(mesh.points)
    assert np.array_equal(np.unique(mesh.cells), np.arange(len(mesh.points)))
    if kind == "ring":  # nodes of ring edges stay on the ring
        height = math.cos(PHI_A)
        on_ring = np.abs(flat.points[:, 2] - height) < 1e-12
        ring_edges = np.flatnonzero(on_ring[edges].all(axis=1))
        start = len(flat.points)
        nodes = start + (order - 1) * ring_edges[:, None] + np.arange(order - 1)
        assert np.abs(mesh.points[nodes.ravel(), 2] - height).max() < 1e-15


@pytest.mark.parametrize("level", [0, 1, 2, 3])
def test_icosphere_counts_pole_orientation(level):
    mesh = icosphere(level)
    assert mesh.vertex_count == 10 * 4**level + 2
    assert len(mesh.triangles) == 20 * 4**level
    assert np.array_equal(mesh.points[mesh.pole], [0.0, 0.0, 1.0])
    assert np.allclose(np.linalg.norm(mesh.points, axis=1), 1.0, atol=1e-15)
    assert outward(mesh).all()
    assert euler_characteristic(mesh) == 2
    assert min_angle(mesh) > math.radians(50)  # shape regular under refinement


def test_icosahedron_is_regular():
    mesh = icosphere(0)
    p = mesh.points[mesh.triangles]
    lengths = np.linalg.norm(p - np.roll(p, 1, axis=1), axis=2)
    assert np.allclose(lengths, lengths[0, 0], rtol=1e-14)


@pytest.mark.parametrize("mesh", [icosphere(2, order=2), ring_sphere(2, PHI_A, order=2)])
def test_curved_mesh_nodes_on_sphere(mesh):
    assert mesh.order == 2 and mesh.cells.shape[1] == 6
    assert np.allclose(np.linalg.norm(mesh.points, axis=1), 1.0, atol=1e-15)
    # edge nodes are the nodes of edges 01, 12, 20 (triangle6 order), near the chord midpoints
    p = mesh.points
    for node, (a, b) in zip((3, 4, 5), ((0, 1), (1, 2), (2, 0)), strict=True):
        chord = 0.5 * (p[mesh.cells[:, a]] + p[mesh.cells[:, b]])
        cosine = np.einsum("ij,ij->i", p[mesh.cells[:, node]], chord) / np.linalg.norm(
            chord, axis=1
        )
        assert np.all(cosine > 0.99)
    assert outward(mesh).all()


@pytest.mark.parametrize("level", [1, 2, 3])
def test_ring_sphere_has_a_ring_of_edges_at_phi_a(level):
    mesh = ring_sphere(level, PHI_A)
    n = ring_rows(level)
    assert mesh.vertex_count == 4 * n**2 + 2
    assert np.array_equal(mesh.points[mesh.pole], [0.0, 0.0, 1.0])
    assert outward(mesh).all() and euler_characteristic(mesh) == 2
    on_ring = np.abs(mesh.points[:, 2] - math.cos(PHI_A)) < 1e-14
    assert on_ring.sum() >= 4
    # the ring vertices form a closed chain of mesh edges
    t = mesh.triangles
    edges = np.unique(np.sort(t[:, [0, 1, 1, 2, 2, 0]].reshape(-1, 2), axis=1), axis=0)
    ring_edges = edges[on_ring[edges].all(axis=1)]
    assert len(ring_edges) == on_ring.sum()
    assert np.all(np.bincount(ring_edges.ravel(), minlength=len(on_ring))[on_ring] == 2)
    assert min_angle(mesh) > math.radians(25)


def test_ring_edge_nodes_stay_on_the_latitude():
    mesh = ring_sphere(2, PHI_A, order=2)
    z = mesh.points[:, 2]
    ring = np.abs(z - math.cos(PHI_A)) < 1e-14
    cells = mesh.cells
    for node, (a, b) in zip((3, 4, 5), ((0, 1), (1, 2), (2, 0)), strict=True):
        both = ring[cells[:, a]] & ring[cells[:, b]]
        assert np.all(ring[cells[both, node]])


def test_topology_keeps_orientation_and_points():
    mesh = icosphere(1)
    skmesh = topology(mesh)
    assert np.array_equal(skmesh.t.T, mesh.triangles)  # sort_t=False: no reordering
    assert skmesh.p.shape == (3, mesh.vertex_count)
