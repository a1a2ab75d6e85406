"""The pole anywhere on the mesh (fem_membrane/locate.py).

Unit rows at nodes, shape functions inside.
"""

from __future__ import annotations

import numpy as np
import pytest

from tests.meshes import OFF_NODE_POLES
from twoball.fem_membrane.alpha import GeneralizedAlpha
from twoball.fem_membrane.eigen import eigenpairs
from twoball.fem_membrane.initial import initial_moments
from twoball.fem_membrane.krylov import krylov_modal_series
from twoball.fem_membrane.locate import locate_pole, shape_functions
from twoball.fem_membrane.mesh import elevate, icosphere, ring_sphere
from twoball.fem_membrane.mesh_input import (
    load_sphere_mesh,
)
from twoball.fem_membrane.modal import modal_series
from twoball.fem_membrane.space import pole_value, sphere_space
from twoball.modal.filters import SpectralFilter

PHI_A, DAMPING = 2.6, 0.13
FILTER = SpectralFilter("lanczos", 30)


@pytest.mark.parametrize("order", [2, 4])
def test_pole_inside_an_element_is_located_on_the_exact_sphere(order):
    mesh = load_sphere_mesh(icosphere(2), order=order, pole=(0.31, -0.52, 0.79)).mesh
    space = sphere_space(mesh, geometry="exact")
    row = space.pole_row
    assert row.nnz == (order + 1) * (order + 2) // 2 and row.sum() == pytest.approx(1.0, abs=1e-13)
    element, xi = locate_pole(elevate(mesh, 1))  # the flat triangle: its image is the pole
    point = space.basis.mapping.F(xi[:, None], tind=np.array([element]))[:, 0, 0]
    assert np.abs(point - [0.0, 0.0, 1.0]).max() < 1e-14


@pytest.mark.parametrize(
    "mesh", [icosphere(2), icosphere(2, 2), ring_sphere(2, PHI_A, 2)], ids=["P1", "P2", "ring"]
)
def test_pole_node_gives_the_unit_row(mesh):
    space = sphere_space(mesh)
    row = space.pole_row
    assert row.shape == (1, space.dofs) and row.nnz == 1 and row.data[0] == 1.0
    assert space.pole == row.indices[0] == space.basis.nodal_dofs[0, mesh.pole]


def test_pole_row_is_bit_identical_to_the_pole_index():
    """The functional of a pole node reproduces indexing by its dof exactly, on every route."""
    space = sphere_space(icosphere(2, 2))
    moments = initial_moments(space, PHI_A)
    pairs = eigenpairs(space.stiffness, space.mass, FILTER.omega_cut**2)
    by_index = modal_series(pairs, moments, space.pole, DAMPING, FILTER)
    by_row = modal_series(pairs, moments, space.pole_row, DAMPING, FILTER)
    assert np.array_equal(by_index.pole_values, by_row.pole_values)
    problem = (space.stiffness, space.mass, space.pole)
    krylov_index, _ = krylov_modal_series(problem, moments, DAMPING, FILTER, residuals=False)
    krylov_row, _ = krylov_modal_series(space, moments, DAMPING, FILTER, residuals=False)
    for name in ("omega", "coefficients", "pole_values"):
        assert np.array_equal(getattr(krylov_index, name), getattr(krylov_row, name))
    stepper = GeneralizedAlpha(space.mass, space.stiffness, 0.01)
    u0 = pairs.vectors @ (by_row.weights * by_row.coefficients)
    a = stepper.run(u0, np.zeros_like(u0), 0.3, space.pole)
    b = stepper.run(u0, np.zeros_like(u0), 0.3, space.pole_row)
    assert np.array_equal(np.stack([a.u, a.u_t, a.u_tt]), np.stack([b.u, b.u_t, b.u_tt]))


@pytest.mark.parametrize("order", [1, 2])
@pytest.mark.parametrize("pole", OFF_NODE_POLES)
def test_pole_inside_an_element_reproduces_the_coordinates(order, pole):
    loaded = load_sphere_mesh(icosphere(2, order), pole=pole)
    assert not loaded.pole_at_node and "inside an element" in loaded.description
    space = sphere_space(loaded.mesh)
    row = space.pole_row
    assert row.nnz == 3 * order  # the values of one element's basis functions
    assert row.sum() == pytest.approx(1.0, abs=1e-14)
    with pytest.raises(ValueError, match="inside an element"):
        _ = space.pole
    # isoparametric: the coordinate functions lie in the space, so the functional
    # returns the coordinates of the pole point itself -- on the z-axis, on the surface
    nodes = space.basis.doflocs  # (3, dofs), the node of each degree of freedom
    x, y, z = pole_value(row, nodes.T)
    assert abs(x) < 1e-15 and abs(y) < 1e-15
    sag = 0.05 if order == 1 else 1e-3  # chord and P2 interpolation of the sphere at level 2
    assert 1.0 - sag < z < 1.0
    element, xi = locate_pole(loaded.mesh)
    values, _ = shape_functions(order, xi)
    point = values @ loaded.mesh.points[loaded.mesh.cells[element]]
    assert np.allclose(point, [x, y, z], atol=1e-15)


def test_pole_at_an_edge_node_gives_its_unit_row():
    generated = icosphere(1, 2)
    node = generated.cells[7, 4]  # the node on edge 12 of triangle 7
    loaded = load_sphere_mesh(generated, pole=generated.points[node])
    assert loaded.pole_at_node and loaded.mesh.pole_node >= loaded.mesh.vertex_count
    space = sphere_space(loaded.mesh)
    dof = space.pole
    assert np.allclose(space.basis.doflocs[:, dof], [0.0, 0.0, 1.0], atol=1e-15)
    assert space.pole_row.nnz == 1 and space.pole_row[0, dof] == 1.0
    with pytest.raises(ValueError, match="no vertex at the north pole"):
        _ = loaded.mesh.pole  # the vertex-only accessor says where to look
