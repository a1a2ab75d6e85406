"""The Krylov route (fem_membrane/krylov.py) against the full eigen route."""

from __future__ import annotations

import numpy as np
import pytest

from tests.meshes import OFF_NODE_POLES
from twoball._common.errors import NumericalError, ParameterError
from twoball.fem_membrane.build import build_space
from twoball.fem_membrane.eigen import eigenpairs
from twoball.fem_membrane.initial import initial_moments
from twoball.fem_membrane.krylov import default_shifts, krylov_modal_series
from twoball.fem_membrane.mesh import icosphere
from twoball.fem_membrane.mesh_input import (
    load_sphere_mesh,
)
from twoball.fem_membrane.modal import modal_series
from twoball.fem_membrane.space import sphere_space
from twoball.modal.filters import SpectralFilter
from twoball.modal.liftoff import find_liftoff
from twoball.modal.series import ModalSeries

PHI_A = 2.6
DAMPING = 0.13


GAMMA = 9.81 / (0.12 * 320.0**2)
FILTER = SpectralFilter("lanczos", 30)


CASES = {
    "axisym-P2": {"mesh": "axisym", "elements": 120, "order": 2},
    "sphere-P1-3": {"mesh": "sphere", "level": 3, "order": 1},
    "sphere-P2-2": {"mesh": "sphere", "level": 2, "order": 2},
}


@pytest.fixture(scope="module", params=sorted(CASES))
def routes(request):
    space = build_space(phi_a=PHI_A, **CASES[request.param])
    moments = initial_moments(space, PHI_A)
    pairs = eigenpairs(space.stiffness, space.mass, FILTER.omega_cut**2)
    full = modal_series(pairs, moments, space.pole, DAMPING, FILTER)
    fast, info = krylov_modal_series(space, moments, DAMPING, FILTER)
    return space, moments, pairs, full, fast, info


def test_pole_motion_agrees_with_full_route(routes):
    _, _, _, full, fast, _ = routes
    assert isinstance(fast, ModalSeries)
    t = np.linspace(0.0, 4.0 * np.pi, 2001)
    a, b = fast.pole(t), full.pole(t)
    for mine, ref in ((a.u, b.u), (a.u_t, b.u_t), (a.u_tt, b.u_tt)):
        assert np.abs(mine - ref).max() <= 1e-8 * np.abs(ref).max()


def test_liftoff_agrees_with_full_route(routes):
    _, _, _, full, fast, _ = routes
    mine, ref = find_liftoff(fast, GAMMA), find_liftoff(full, GAMMA)
    assert mine.lifted and ref.lifted
    assert abs(mine.t / ref.t - 1.0) <= 1e-8
    assert abs(mine.velocity / ref.velocity - 1.0) <= 1e-8


def test_converged_ritz_values_are_eigenvalues(routes):
    _, _, pairs, full, _, info = routes
    good = info.residuals <= 1e-8
    assert np.count_nonzero(good) >= 10  # at least the low zonal modes converge individually
    for theta in info.residual_values[good]:
        nearest = np.min(np.abs(pairs.values - theta))
        assert nearest <= 1e-8 * (1.0 + theta)
    # conversely: the strongly excited low modes of the full route are all found
    weight = np.abs(full.pole_amplitudes) * (1.0 + full.omega**2)
    low = (weight >= 1e-3 * weight.max()) & (full.omega**2 <= 100.0)
    ritz = info.residual_values
    for value in pairs.values[low]:
        assert np.min(np.abs(ritz - value)) <= 1e-8 * (1.0 + value)


def test_axisymmetric_ritz_values_match_every_mode():
    space = build_space("axisym", elements=120, order=2, phi_a=PHI_A)
    moments = initial_moments(space, PHI_A)
    pairs = eigenpairs(space.stiffness, space.mass, FILTER.omega_cut**2)
    _, info = krylov_modal_series(space, moments, DAMPING, FILTER, vectors=True)
    assert info.pairs is not None and len(info.pairs) == len(pairs) == 31
    np.testing.assert_allclose(info.pairs.values, pairs.values, rtol=1e-9, atol=1e-9)
    gram = info.pairs.vectors.T @ (space.mass @ info.pairs.vectors)
    np.testing.assert_allclose(gram, np.eye(31), atol=1e-10)


def test_stopping_rule_triggers(routes):
    space, moments, _, _, _, info = routes
    assert info.converged
    assert info.trajectory_change <= 1e-10
    assert info.basis_size < space.dofs
    assert info.factorizations == len(info.shifts) + 1
    _, loose = krylov_modal_series(space, moments, DAMPING, FILTER, tol=1e-4, residuals=False)
    assert loose.converged and loose.trajectory_change <= 1e-4
    assert loose.iterations < info.iterations
    assert loose.residuals.size == 0


def test_not_converged_raises():
    space = build_space("sphere", level=2, order=1, phi_a=PHI_A)
    moments = initial_moments(space, PHI_A)
    with pytest.raises(NumericalError, match="not converged"):
        krylov_modal_series(space, moments, DAMPING, FILTER, max_basis=10)


def test_matrices_and_explicit_shifts():
    space = build_space("sphere", level=2, order=1, phi_a=PHI_A)
    moments = initial_moments(space, PHI_A)
    problem = (space.stiffness, space.mass, space.pole)
    one, _ = krylov_modal_series(problem, moments, DAMPING, FILTER, shifts=[-1.0])
    three, info = krylov_modal_series(space, moments, DAMPING, FILTER)
    assert info.shifts == tuple(default_shifts(FILTER.omega_cut**2))
    t = np.linspace(0.0, 4.0 * np.pi, 501)
    a, b = one.pole(t).u_tt, three.pole(t).u_tt
    assert np.abs(a - b).max() <= 1e-8 * np.abs(b).max()


def test_default_shifts_lie_in_gaps():
    shifts = default_shifts(FILTER.omega_cut**2, 4)
    assert shifts[0] < 0.0 and shifts.size == 4
    roots = np.sqrt(shifts[1:])
    np.testing.assert_array_equal(roots, np.round(roots))  # (l + 1)^2: midway in a gap
    assert shifts[-1] == 31.0**2


def test_choose_route():
    from twoball._common.errors import ParameterError
    from twoball.fem_membrane.krylov import AUTO_THRESHOLD, choose_route

    assert choose_route("auto", AUTO_THRESHOLD) == "krylov"
    assert choose_route("auto", AUTO_THRESHOLD - 1) == "full"
    assert choose_route("full", 10**6) == "full"
    assert choose_route("krylov", 10) == "krylov"
    with pytest.raises(ParameterError):
        choose_route("fast", 10)


def test_fem_pole_motion_routes_agree_and_auto_picks_krylov_on_large_meshes():
    from twoball.fem_membrane.solve import fem_pole_motion
    from twoball.modal.liftoff import find_liftoff

    gamma = 9.81 / (0.12 * 320.0**2)
    full, info_full = fem_pole_motion(2.6, 0.13, mesh="sphere", level=2, order=2, route="full")
    fast, info_fast = fem_pole_motion(2.6, 0.13, mesh="sphere", level=2, order=2, route="krylov")
    assert info_full["route"] == "full" and info_fast["route"] == "krylov"
    a, b = find_liftoff(full, gamma), find_liftoff(fast, gamma)
    assert b.t == pytest.approx(a.t, rel=1e-8) and b.velocity == pytest.approx(a.velocity, rel=1e-8)
    _, auto_small = fem_pole_motion(2.6, 0.13, mesh="axisym", elements=100, order=2)
    _, auto_large = fem_pole_motion(2.6, 0.13, mesh="sphere", level=3, order=2)
    assert auto_small["route"] == "full" and auto_large["route"] == "krylov"
    with pytest.raises(ParameterError, match="route"):
        fem_pole_motion(2.6, 0.13, mesh="axisym", elements=50, scheme="alpha", route="krylov")


def test_krylov_route_with_the_pole_inside_an_element():
    # the Krylov start block holds the functional itself: same series as the full route
    space = sphere_space(load_sphere_mesh(icosphere(2), pole=OFF_NODE_POLES[0]).mesh)
    moments = initial_moments(space, PHI_A)
    pairs = eigenpairs(space.stiffness, space.mass, FILTER.omega_cut**2)
    full = find_liftoff(modal_series(pairs, moments, space.pole_row, DAMPING, FILTER), GAMMA)
    series, info = krylov_modal_series(space, moments, DAMPING, FILTER, residuals=False)
    krylov = find_liftoff(series, GAMMA)
    assert info.converged
    assert krylov.t == pytest.approx(full.t, rel=1e-9)
    assert krylov.velocity == pytest.approx(full.velocity, rel=1e-8)
