"""Surface mapping for scikit-fem: area element, tangential gradient, P1 = cotangent Laplacian."""

from __future__ import annotations

import math

import numpy as np
import pytest
import scipy.sparse as sp
from skfem import BilinearForm, asm
from skfem.helpers import dot, grad
from twoball.fem_membrane.axisym import axisym_space
from twoball.fem_membrane.mesh import elevate, icosphere, ring_sphere
from twoball.fem_membrane.space import dof_nodes, sphere_space, surface_basis


def cotangent_laplacian(points: np.ndarray, triangles: np.ndarray) -> sp.csr_matrix:
    """Independent P1 stiffness on flat triangles: L_ij = -(cot a_ij + cot b_ij) / 2."""
    rows, cols, vals = [], [], []
    for k in range(3):
        i, j, o = triangles[:, (k + 1) % 3], triangles[:, (k + 2) % 3], triangles[:, k]
        u, v = points[i] - points[o], points[j] - points[o]
        cot = np.einsum("ij,ij->i", u, v) / np.linalg.norm(np.cross(u, v), axis=1)
        rows += [i, j, i, j]
        cols += [j, i, i, j]
        vals += [-cot / 2, -cot / 2, cot / 2, cot / 2]
    n = len(points)
    return sp.csr_matrix(
        (np.concatenate(vals), (np.concatenate(rows), np.concatenate(cols))), (n, n)
    )


@pytest.mark.parametrize("mesh", [icosphere(2), ring_sphere(2, 2.6)])
def test_p1_stiffness_is_the_cotangent_laplacian(mesh):
    space = sphere_space(mesh, 1)
    reference = cotangent_laplacian(mesh.points, mesh.triangles)
    assert abs(space.stiffness - reference).max() < 1e-12
    assert space.mass.sum() == pytest.approx(mesh.area(), rel=1e-13)


def test_mass_sums_to_the_area_and_tends_to_4pi():
    flat = [sphere_space(icosphere(level), 1).mass.sum() for level in (2, 3, 4)]
    curved = [sphere_space(icosphere(level), 2).mass.sum() for level in (1, 2, 3)]
    flat_error = 4 * np.pi - np.array(flat)
    curved_error = 4 * np.pi - np.array(curved)
    assert np.all(flat_error > 0)  # inscribed polyhedra
    assert np.log2(flat_error[:-1] / flat_error[1:]) == pytest.approx([2, 2], abs=0.05)
    assert np.log2(np.abs(curved_error[:-1] / curved_error[1:])) == pytest.approx([4, 4], abs=0.15)
    assert abs(curved_error[-1]) < 1e-4
    assert axisym_space(10, 2.6, 1).mass.sum() == pytest.approx(4 * np.pi, rel=1e-14)


@pytest.mark.parametrize("order", [1, 2])
def test_gradient_is_tangential_and_kills_constants(order):
    mesh = elevate(icosphere(2)) if order == 2 else icosphere(2)
    basis = surface_basis(mesh, order)
    J = basis.mapping.DF(basis.X)
    normal = np.cross(J[:, 0], J[:, 1], axis=0)
    for field in basis.basis:
        assert np.abs(np.einsum("itq,itq->tq", field[0].grad, normal)).max() < 1e-12
    K = asm(BilinearForm(lambda u, v, w: dot(grad(u), grad(v))), basis)
    assert np.abs(K @ np.ones(basis.N)).max() < 1e-12


def test_gradient_of_the_height_function():
    # z restricted to the sphere has surface gradient e_z - z n, |grad z|^2 = 1 - z^2 = sin^2
    mesh = elevate(icosphere(3))
    basis = surface_basis(mesh, 2)
    z = basis.doflocs[2]
    field = basis.interpolate(z)
    x = np.asarray(basis.global_coordinates())
    normal = x / np.linalg.norm(x, axis=0)
    expected = np.array([0.0, 0.0, 1.0])[:, None, None] - normal[2] * normal
    assert np.abs(field.grad - expected).max() < 2e-3


def test_doflocs_match_mesh_nodes():
    mesh = elevate(icosphere(1))
    basis = surface_basis(mesh, 2)
    nodes = dof_nodes(basis, mesh)
    assert np.allclose(basis.doflocs, mesh.points[nodes].T, atol=1e-15)
    assert math.isclose(float(np.abs(basis.doflocs[2]).max()), 1.0)
