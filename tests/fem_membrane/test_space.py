"""P3 and P4 isoparametric elements: nodes, conformity, area, eigenvalue orders, lift-off.

Independent values: the unit sphere (|x| = 1, area 4 pi), the exact eigenvalues
l (l + 1) of eq. (3.11), and the Legendre-series lift-off.  The observed orders
are banded on both sides.  On the icosphere the eigenvalue error is the
Galerkin error O(h^2p) plus the geometric error of the nodal sphere
interpolation, O(h^(p+1)) for odd p and O(h^(p+2)) for even p (equispaced
interpolation points; see docs/method.rst): the low clusters l = 1, 2 show
the geometric rate (4 for P3, 6 for P4), the clusters whose error the
Galerkin part dominates at the levels used show 2p.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from skfem import ElementTriP3, ElementTriP4
from twoball.fem_membrane.axisym import axisym_space
from twoball.fem_membrane.eigen import eigenpairs, lowest_eigenpairs
from twoball.fem_membrane.initial import initial_load
from twoball.fem_membrane.locate import locate_pole, shape_functions
from twoball.fem_membrane.mesh import _edges, icosphere, ring_sphere
from twoball.fem_membrane.solve import modal_model
from twoball.fem_membrane.space import dof_nodes, sphere_space
from twoball.modal.filters import SpectralFilter
from twoball.modal.legendre import legendre_series, mean_displacement
from twoball.modal.liftoff import find_liftoff
from twoball.modal.parameters import Case

PHI_A, DAMPING = 2.6, 0.13
FILTER = SpectralFilter("lanczos", 30)
GAMMA = Case().gamma
BAND = 0.3  # observed order within +-0.3 of the expected one (too high fails too)
GEOMETRIC_RATE = {3: 4.0, 4: 6.0}  # p + 1 for odd p, p + 2 for even p (equispaced nodes)
REFERENCE_ELEMENTS = {3: ElementTriP3, 4: ElementTriP4}


def rates(errors: np.ndarray, ratio: float = 2.0) -> np.ndarray:
    """Observed orders between successive rows of ``errors`` (h halves per row)."""
    errors = np.asarray(errors, dtype=float)
    return np.log(errors[:-1] / errors[1:]) / math.log(ratio)


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


# --- nodes, numbering and conformity -------------------------------------------------------


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


# --- geometry: area --------------------------------------------------------------------------


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


# --- eigenvalues -----------------------------------------------------------------------------


# Straight line, no geometric error: every Legendre eigenvalue n (n + 1) at order 2p, each on
# the pair of element counts where it is asymptotic and above round-off (measured on
# E = 12 .. 320, ratios 1.5 and 2: P1 2.00-2.01, P2 3.98-4.02, P3 5.96-6.13, P4 7.79-8.24;
# P4 n = 5 reaches round-off, ~1e-13, one pair earlier than the others).
AXISYM_SCHEDULE = {
    1: (((160, 320), range(2, 30)),),
    2: (((160, 320), range(3, 30)),),
    3: (((90, 135), range(4, 30)),),
    4: (((27, 40), range(5, 6)), ((40, 60), range(6, 30))),
}


def axisym_errors(elements: int, order: int) -> np.ndarray:
    """Relative errors of the eigenvalues n (n + 1), n = 1..29, on the axisymmetric line."""
    space = axisym_space(elements, PHI_A, order)
    values = lowest_eigenpairs(space.stiffness, space.mass, 30).values[1:]
    n = np.arange(1, 30)
    return np.abs(values / (n * (n + 1.0)) - 1.0)


@pytest.mark.parametrize("order", [1, 2, 3, 4])
def test_axisymmetric_eigenvalues_converge_at_2p(order):
    """Every n = 1..29: exact for n <= p, else observed order 2p (+-0.3, too high fails too).

    The modes P_n(x) with n <= p are polynomials of degree n in x = cos(phi), in the
    space on the straight line: their eigenvalues are exact to round-off.
    """
    exact = axisym_errors(40, order)[:order]
    assert np.all(exact < 1e-11), exact
    for (coarse, fine), degrees in AXISYM_SCHEDULE[order]:
        pair = np.array([axisym_errors(e, order)[degrees.start - 1 : degrees.stop - 1]
                         for e in (coarse, fine)])  # fmt: skip
        assert pair[1].min() > 1e-12  # above round-off
        observed = np.log(pair[0] / pair[1]) / np.log(fine / coarse)
        assert np.all(np.abs(observed - 2 * order) < BAND), (coarse, fine, observed)


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


# --- initial load and lift-off ---------------------------------------------------------------


@pytest.mark.parametrize("order", [3, 4])
def test_axisymmetric_liftoff_matches_legendre(order):
    reference = find_liftoff(legendre_series(PHI_A, DAMPING, FILTER), GAMMA)
    model = modal_model(PHI_A, DAMPING, FILTER, mesh="axisym", order=order, elements=100)
    result = find_liftoff(model.series, GAMMA)
    tolerance = {3: 1e-8, 4: 1e-11}[order]  # measured 3.6e-10 | 4.3e-10 and 1.2e-13 | 1.3e-13
    assert abs(result.t / reference.t - 1.0) < tolerance
    assert abs(result.velocity / reference.velocity - 1.0) < tolerance


@pytest.mark.parametrize("order", [3, 4])
def test_load_of_f_integrates_the_mean_through_the_kink(order):
    """``sum(b) = int F dS = 4 pi a_0`` (eq. (3.13)) on icospheres, whose elements the kink cuts.

    The error is the geometric one (rate 4 for P3, 6 for P4, +-0.3) as long
    as the composite rule on the cut elements (4**4 sub-triangles) resolves the
    kink; measured: P3 2.4e-6, 1.8e-7, 1.2e-8 (levels 1, 2, 3), P4 1.1e-7,
    1.6e-9, then 1.1e-10 at level 3, where the kink quadrature floor shows.
    """
    levels = (1, 2, 3) if order == 3 else (1, 2)
    errors = []
    for level in levels:
        space = sphere_space(icosphere(level, order))
        errors.append(initial_load(space, PHI_A).sum() / (4 * np.pi) - mean_displacement(PHI_A))
    observed = rates(np.abs(errors))
    assert np.all(np.abs(observed - GEOMETRIC_RATE[order]) < BAND), observed


def test_routes_agree_at_p3():
    """Full eigen and Krylov routes give the same lift-off on a P3 sphere (level 1)."""
    full = modal_model(PHI_A, DAMPING, FILTER, mesh="sphere", order=3, level=1, route="full")
    krylov = modal_model(PHI_A, DAMPING, FILTER, mesh="sphere", order=3, level=1, route="krylov")
    a, b = find_liftoff(full.series, GAMMA), find_liftoff(krylov.series, GAMMA)
    assert a.lifted and b.lifted
    assert abs(a.t / b.t - 1.0) < 1e-9 and abs(a.velocity / b.velocity - 1.0) < 1e-8


@pytest.mark.slow
def test_sphere_liftoff_at_level_3_is_closer_to_legendre_at_higher_order():
    """P2, P3, P4 on the level-3 icosphere against the Legendre series (Krylov route).

    Measured (relative, t_l | v_l): P2 1.3e-4 | 1.1e-5, P3 3.5e-6 | 2.8e-5,
    P4 3.5e-9 | 2.0e-7.  The P3 velocity is not better than P2's: its
    geometric error is O(h^4), like P2's.
    """
    reference = find_liftoff(legendre_series(PHI_A, DAMPING, FILTER), GAMMA)
    diffs = {}
    for order in (2, 3, 4):
        model = modal_model(
            PHI_A, DAMPING, FILTER, mesh="sphere", order=order, level=3, route="krylov"
        )
        result = find_liftoff(model.series, GAMMA)
        diffs[order] = np.array(
            [abs(result.t / reference.t - 1.0), abs(result.velocity / reference.velocity - 1.0)]
        )
    assert diffs[3][0] < diffs[2][0] / 10 and np.all(diffs[3] < 1e-4)
    assert np.all(diffs[4] < diffs[2] / 50) and np.all(diffs[4] < 1e-6)


@pytest.mark.parametrize("order", [3, 4])
def test_generalized_alpha_matches_the_modal_series_at_order_2_in_dt(order):
    """The time-stepping route on P3/P4 (axisymmetric, 30 elements) against modal superposition."""
    from twoball.fem_membrane.solve import alpha_motion

    model = modal_model(PHI_A, DAMPING, FILTER, mesh="axisym", order=order, elements=30)
    differences = []
    for steps in (500, 1000, 2000):
        motion, _ = alpha_motion(model, dt=2 * np.pi / steps, t_end=2 * np.pi)
        exact = model.series.pole(motion.times)
        sampled = motion.pole(motion.times)
        differences.append([np.abs(a - b).max() for a, b in zip(sampled, exact, strict=True)])
    observed = rates(np.array(differences))
    assert np.all(np.abs(observed - 2.0) < 0.2), observed


@pytest.mark.parametrize("order", [3, 4])
def test_file_mesh_raised_to_order_p_and_the_pole_inside_an_element(order):
    """A P1 mesh given as data, raised to P3/P4: the generated mesh's space; then a tilted pole."""
    import meshio
    from twoball.fem_membrane.mesh_input import load_sphere_mesh

    generated = icosphere(2)
    data = meshio.Mesh(2.5 * generated.points + 1.0, [("triangle", generated.cells)])
    loaded = load_sphere_mesh(data, order=order)
    assert loaded.source_order == 1 and loaded.mesh.order == order
    area = sphere_space(loaded.mesh).mass.sum()
    assert area == pytest.approx(sphere_space(icosphere(2, order)).mass.sum(), rel=1e-13)
    tilted = load_sphere_mesh(data, order=order, pole=(0.3, -0.2, 1.0))
    assert not tilted.pole_at_node
    space = sphere_space(tilted.mesh)
    row = space.pole_row
    assert row.nnz == (order + 1) * (order + 2) // 2 and row.sum() == pytest.approx(1.0, abs=1e-13)
    element, xi = locate_pole(tilted.mesh)
    values, _ = shape_functions(order, xi)
    point = values @ tilted.mesh.points[tilted.mesh.cells[element]]
    assert np.abs(point[:2]).max() < 1e-13 and point[2] > 0.99  # on the +z axis
    assert row @ space.basis.doflocs[2] == pytest.approx(point[2], abs=1e-13)


@pytest.mark.parametrize(
    "argv",
    [
        ["export", "--level", "1", "--order", "3", "--out", "{tmp}/series.xdmf"],
        ["render", "--level", "1", "--order", "4", "--out", "{tmp}/ball.png"],
    ],
)
def test_field_files_and_pictures_refuse_p3_p4_in_one_line(tmp_path, capsys, argv):
    """No node order for 10/15-node triangles is shared by the writers: refused, exit 2."""
    from twoball.cli.main import main

    with pytest.raises(SystemExit) as stop:
        main([part.format(tmp=tmp_path) for part in argv])
    err = capsys.readouterr().err
    assert stop.value.code == 2
    assert len(err.strip().splitlines()) == 1 and "--order" in err and "Traceback" not in err


@pytest.mark.slow
def test_lowest_eigenpairs_with_a_tie_across_the_cut():
    """P3 level 2, 676 pairs (plot eigen's default there): a multiple eigenvalue straddles the
    cut, which deflation used to chase for ever; against the dense generalized solver."""
    from scipy.linalg import eigh

    space = sphere_space(icosphere(2, 3))
    values = lowest_eigenpairs(space.stiffness, space.mass, 676).values
    dense = eigh(space.stiffness.toarray(), space.mass.toarray(), eigvals_only=True)[:676]
    assert np.allclose(values, dense, rtol=1e-9, atol=1e-9)
