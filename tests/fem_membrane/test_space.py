"""Finite-element spaces on the sphere (fem_membrane/space.py).

P1 to P4, conformity, area, clusters.
"""

from __future__ import annotations

import numpy as np
import pytest
from skfem import ElementTriP3, ElementTriP4

from tests.helpers import rates
from twoball.fem_membrane.eigen import eigenpairs, lowest_eigenpairs
from twoball.fem_membrane.mesh import _edges, icosphere, ring_sphere
from twoball.fem_membrane.space import dof_nodes, sphere_space

PHI_A = 2.6
BAND = 0.3  # observed order within +-0.3 of the expected one (too high fails too)


GEOMETRIC_RATE = {3: 4.0, 4: 6.0}  # p + 1 for odd p, p + 2 for even p (equispaced nodes)
REFERENCE_ELEMENTS = {3: ElementTriP3, 4: ElementTriP4}


def cluster_errors(level: int, order: int, degrees: range) -> np.ndarray:
    """Largest relative error in each cluster l of ``degrees`` (2l + 1 eigenvalues l (l + 1))."""
    space = sphere_space(icosphere(level, order))
    last = degrees[-1]
    if last <= 3:
        values = lowest_eigenpairs(space.stiffness, space.mass, (last + 1) ** 2).values
    else:  # every eigenvalue below the midpoint between clusters last and last + 1
        values = eigenpairs(space.stiffness, space.mass, (last + 1) ** 2, next_value=False).values
    assert values.size == (last + 1) ** 2
    return np.array(
        [np.abs(values[d * d : (d + 1) ** 2] / (d * (d + 1.0)) - 1.0).max() for d in degrees]
    )


@pytest.mark.parametrize("order", [3, 4])
def test_element_maps_and_fields_agree_along_shared_edges(order):
    """Both triangles of an edge map the same reference points of it to one point, one value.

    A numbering that ignored the edge direction would swap the P3/P4 edge nodes
    of every second triangle: the maps and the field would tear along the edge.
    """
    mesh = icosphere(1, order)
    space = sphere_space(mesh)
    basis = space.basis
    assert np.allclose(basis.doflocs, mesh.points[dof_nodes(basis, mesh)].T, atol=1e-15)
    x = basis.doflocs
    u = x[0] * x[1] + x[2] ** 3 - 2.0 * x[0] ** 2 * x[2]  # any smooth field, interpolated
    triangles = mesh.triangles
    _, local = _edges(triangles)
    element = REFERENCE_ELEMENTS[order]()
    s = np.array([0.17, 0.5, 0.71])
    found: dict[tuple[int, float], list[np.ndarray]] = {}
    for j, (a, b) in enumerate(((0, 1), (1, 2), (0, 2))):
        start, end = element.doflocs[a], element.doflocs[b]
        for t in range(len(triangles)):
            forward = triangles[t, a] < triangles[t, b]
            for value in s:
                w = value if forward else 1.0 - value  # position counted from the lower vertex
                point = (start + w * (end - start))[:, None]
                phi = np.array([element.lbasis(point, i)[0][0] for i in range(basis.Nbfun)])
                dofs = basis.element_dofs[:, t]
                found.setdefault((local[t, j], value), []).append(
                    np.append(x[:, dofs] @ phi, u[dofs] @ phi)
                )
    sides = np.array([pair for pair in found.values()])
    assert sides.shape[1] == 2  # every edge seen from exactly two triangles
    assert np.abs(sides[:, 0] - sides[:, 1]).max() < 1e-14


@pytest.mark.parametrize("order", [3, 4])
def test_stiffness_kills_constants_and_mass_is_symmetric(order):
    space = sphere_space(ring_sphere(1, PHI_A, order))
    assert np.abs(space.stiffness @ np.ones(space.dofs)).max() < 1e-12
    assert abs(space.mass - space.mass.T).max() < 1e-15
    assert space.pole == int(np.argmax(space.basis.doflocs[2]))


@pytest.mark.parametrize("order", [3, 4])
def test_area_converges_at_the_interpolation_rate(order):
    """4 pi - area: O(h^4) for P3 and O(h^6) for P4 (equispaced nodes; both bands two-sided)."""
    errors = np.array(
        [4 * np.pi - sphere_space(icosphere(level, order)).mass.sum() for level in (1, 2, 3)]
    )
    assert np.all(errors < 0.0)  # the curved surfaces bulge out between the nodes
    observed = rates(np.abs(errors))
    assert np.all(np.abs(observed - GEOMETRIC_RATE[order]) < BAND), observed
    assert abs(errors[-1]) < {3: 5e-5, 4: 2e-7}[order]


@pytest.mark.parametrize("order", [3, 4])
def test_sphere_low_clusters_converge_at_the_geometric_rate(order):
    """Clusters l = 1, 2 on icospheres 1 -> 2 -> 3: the geometric error dominates (4 or 6)."""
    levels = (2, 3) if order == 3 else (1, 2, 3)
    errors = np.array([cluster_errors(level, order, range(1, 3)) for level in levels])
    observed = rates(errors)
    assert np.all(np.abs(observed - GEOMETRIC_RATE[order]) < BAND), observed


@pytest.mark.slow
@pytest.mark.parametrize(
    ("order", "levels", "degrees"), [(3, (2, 3), range(7, 13)), (4, (2, 3), range(7, 13))]
)
def test_sphere_galerkin_clusters_converge_at_2p(order, levels, degrees):
    """Clusters whose Galerkin error dominates at these levels converge at 2p (+-0.3)."""
    errors = np.array([cluster_errors(level, order, degrees) for level in levels])
    observed = rates(errors)
    assert np.all(np.abs(observed - 2 * order) < BAND), observed
