"""The lower ball on the floor, axisymmetric finite elements in their own modes.

Independent values: the eigenvalues against l (l + 1), the degree-1 vector
against x = cos(phi), the same drop integrated on the dense finite-element
matrices (the change of coordinates is exact), the Legendre backend, and the
order of the restitution in the elements.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
import scipy.linalg as sla
import scipy.sparse as sp

from twoball.fem_membrane.floor import axisym_ball, axisym_matrices
from twoball.modal.balls.membrane import legendre_ball
from twoball.modal.damping import ModalRatio, Rayleigh
from twoball.modal.floor.drop import DropSettings, run_drop
from twoball.modal.floor.measure import contact_intervals
from twoball.modal.floor.settle import settle
from twoball.modal.floor.system import floor_system
from twoball.modal.nonsmooth import ContactProblem, MoreauJean
from twoball.modal.stiffness import Stiffness
from twoball.verify.studies.orders import OrderBand

V0 = 4.1 / (0.12 * 320.0)
GAMMA = 9.81 / (0.12 * 320.0**2)
GAS = 6.0 * 1.4 * (77.2e3 + 101325.0) / 77.2e3
PRESSURISED = Stiffness(gas=GAS, membrane="pressurised")


MODAL = ModalRatio(0.13)


def _fe_drop(elements, law=MODAL, dt=0.02, order=2):
    ball = axisym_ball(elements, order, PRESSURISED, law)
    return run_drop(floor_system(ball, GAMMA), DropSettings(V0, GAMMA, dt, 30.0))


def test_eigenvalues_and_the_degree_one_vector():
    """lambda_h -> l (l + 1) at order 2p; the degree-1 vector x is left out exactly (the
    centre's translation Z, coordinate 0, carries degree 1 with its own entry 2)."""
    paper = Stiffness()
    exact = np.array([0, 6, 12, 20, 30, 42])
    errors = []
    for elements in (20, 40):
        ball = axisym_ball(elements, 2, paper, ModalRatio(0.0))
        assert ball.centre == 0 and ball.laplace[0] == 2.0 and ball.omega_squared[0] == 0.0
        assert ball.modes == 2 * elements + 1  # Z and the 2E + 1 P2 vectors but x
        deformation = ball.laplace[ball.deformation]
        lam = np.sort(deformation)[:6]
        np.testing.assert_allclose(lam, exact, rtol=2e-3, atol=1e-11)
        assert not np.any(np.abs(deformation - 2.0) < 0.5)  # degree 1 is the centre's
        np.testing.assert_array_equal(ball.floor_rows[:, 0], 1.0)  # Z lifts every point
        np.testing.assert_array_equal(ball.top[0], 1.0)
        errors.append(lam[3:] - exact[3:])
    ratios = errors[0] / errors[1]
    assert np.all((ratios > 12.0) & (ratios < 20.0)), ratios  # order 2p = 4
    np.testing.assert_allclose(ball.masses, 1.0)
    held = axisym_ball(40, 2, paper, ModalRatio(0.0), anchored=True)  # the paper's start
    assert held.centre is None and held.modes == 2 * 40 + 1  # every vector, x among them
    assert np.count_nonzero(np.abs(held.laplace - 2.0) < 1e-8) == 1
    gassy = axisym_ball(10, 2, PRESSURISED, ModalRatio(0.0))
    assert gassy.omega_squared[np.argmin(gassy.laplace)] == pytest.approx(GAS - 2.0, rel=1e-14)
    K, M, x = axisym_matrices(10, 2)
    np.testing.assert_allclose(K @ x, 2.0 * M @ x, atol=1e-13)  # x is an eigenvector exactly


def _dense_reference(elements, law, dt):
    """The drop on the dense FE matrices, degree 1 removed by eliminating the north node."""
    K, M, x = axisym_matrices(elements, 2)
    n = x.size
    first = M @ x
    k = int(np.argmax(x))
    others = np.delete(np.arange(n), k)
    rows = np.concatenate([others, np.full(n - 1, k)])
    cols = np.concatenate([np.arange(n - 1), np.arange(n - 1)])
    vals = np.concatenate([np.ones(n - 1), -first[others] / first[k]])
    B = sp.csr_matrix((vals, (rows, cols)), shape=(n, n - 1)).toarray()
    ones = M @ np.ones(n)
    Mr = B.T @ M @ B
    Kr = B.T @ (K - 2.0 * M) @ B + GAS * np.outer(B.T @ ones, B.T @ ones)
    if isinstance(law, Rayleigh):
        Cr = law.alpha * Mr + law.beta * Kr
    else:
        w2, V = sla.eigh(Kr, Mr)
        MV = Mr @ V
        Cr = (MV * (2.0 * law.ratio * np.sqrt(w2))) @ MV.T
    size = n
    Mf, Kf, Cf = (np.zeros((size, size)) for _ in range(3))
    Mf[0, 0] = 1.0
    Mf[1:, 1:], Kf[1:, 1:], Cf[1:, 1:] = Mr, Kr, 0.5 * (Cr + Cr.T)
    floor = np.flatnonzero(x < 0.0)
    floor = floor[np.argsort(-x[floor])]
    G = np.column_stack([np.ones(floor.size), x[floor, None] * B[floor]])
    f = np.zeros(size)
    f[0] = -GAMMA
    problem = ContactProblem.create(Mf, Cf, Kf, f, G, x[floor], 0.0)
    q0, v0 = np.zeros(size), np.zeros(size)
    q0[0], v0[0] = 1.0, -V0
    tr = MoreauJean(problem, dt, gap_tolerance=1e-10).run(q0, v0, 7.0)
    end = contact_intervals(tr.t, tr.impulse.sum(axis=1), dt)[-1].end
    return end, tr.v_final[0] + GAMMA * (tr.t[-1] - end)


@pytest.mark.parametrize("law", [ModalRatio(0.13), Rayleigh(0.47273, 0.011818)])
def test_modes_of_the_elements_are_the_dense_elements(law):
    """The drop in the eigenvectors equals the drop on the dense matrices (E = 8, P2)."""
    r = _fe_drop(8, law)
    end, v2 = _dense_reference(8, law, 0.02)
    assert r.contact_time == pytest.approx(end, rel=1e-6)
    assert r.v2 == pytest.approx(v2, rel=1e-7)


def test_elements_agree_with_legendre_modes():
    """P2 with E elements has the node spacing of N = 2E Legendre modes: E = 20 / N = 40."""
    fe = _fe_drop(20)
    system = floor_system(legendre_ball(40, PRESSURISED, ModalRatio(0.13)), GAMMA)
    modal = run_drop(system, DropSettings(V0, GAMMA, 0.02, 30.0))
    assert fe.impulse_balance < 1e-10 and fe.energy["balance"] < 1e-12
    assert fe.e2 == pytest.approx(modal.e2, rel=1e-3)
    assert fe.contact_time == pytest.approx(modal.contact_time, rel=3e-3)
    assert fe.phi_a_max == pytest.approx(modal.phi_a_max, rel=2e-3)
    assert fe.flattening_max == pytest.approx(modal.flattening_max, rel=2e-3)


def test_elements_order_of_restitution():
    """e2 converges at order 2 in 1/E (E = 16, 32, 64, P2)."""
    v = [_fe_drop(e, dt=0.01).e2 for e in (16, 32, 64)]
    order = math.log2((v[1] - v[0]) / (v[2] - v[1]))
    assert OrderBand(2.0, 0.5, 0.5).contains(order), order


def test_elements_order_of_contact_time_and_the_contact_angle_within_its_tolerance():
    """t_c converges at about order 1.2 in 1/E (docs/bounce.rst; here E = 16, 32, 64 at
    dt = 0.0025, successive differences, measured 1.26), in the band 1.2 +- 0.5; phi_a,max
    has no asymptotic order, and from E = 96 it is within the stated 1e-3 rad of a mesh
    twice as fine."""
    t_c = [_fe_drop(e, dt=0.0025).contact_time for e in (16, 32, 64)]
    order = math.log2((t_c[1] - t_c[0]) / (t_c[2] - t_c[1]))
    assert OrderBand(1.2, 0.5, 0.5).contains(order), order
    default, finer = (_fe_drop(e, dt=0.0025).phi_a_max for e in (96, 192))
    assert abs(default - finer) < 1e-3


def test_time_step_order_of_the_contact_angle_on_elements():
    """phi_a,max converges at order 2 in dt on the elements too (E = 10; errors against
    dt/16); t_c and e2 within the stated tolerances at dt = 0.005 (3e-4 relative, 1e-5)."""
    ref = _fe_drop(10, dt=0.00125)
    steps = (0.02, 0.01, 0.005)
    runs = [_fe_drop(10, dt=dt) for dt in steps]
    errors = np.abs(np.array([r.phi_a_max for r in runs]) - ref.phi_a_max)
    order = np.polyfit(np.log(steps), np.log(errors), 1)[0]
    assert OrderBand(2.0, 0.5, 0.5).contains(order), order
    assert abs(runs[-1].contact_time - ref.contact_time) < 3e-4 * ref.contact_time
    assert abs(runs[-1].e2 - ref.e2) < 1e-5


def test_resting_ball_on_elements_carries_its_weight():
    r = settle(floor_system(axisym_ball(30, 2, PRESSURISED, ModalRatio(0.9)), GAMMA))
    assert r.floor_force == pytest.approx(r.weight, rel=1e-8)


@pytest.mark.slow
def test_resting_contact_area_on_elements_tends_to_pressure_times_area():
    """m2 g / P (pressurised) on P2 elements too, E = 120 and 240 (the point spacing of
    Legendre N = 240, 480): the cap through the edge estimated between the nodes (measured
    0.905, 0.988 of m2 g/P) and the cap through the outermost node in contact (1.073, 0.966)
    within the Legendre test's bounds, each error shrinking by more than 2."""
    runs = [
        settle(floor_system(axisym_ball(e, 2, PRESSURISED, ModalRatio(0.9)), GAMMA))
        for e in (120, 240)
    ]
    edge = [abs(r.edge_area / r.pressure_area - 1.0) for r in runs]
    inner = [abs(r.contact_area[0] / r.pressure_area - 1.0) for r in runs]
    assert edge[0] < 0.1 and edge[1] < 0.04 and edge[0] / edge[1] > 2.0, edge
    assert inner[0] < 0.15 and inner[1] < 0.06 and inner[0] / inner[1] > 2.0, inner
    for r in runs:
        assert r.floor_force == pytest.approx(r.weight, rel=1e-8)


@pytest.mark.parametrize("order", [1, 2, 3, 4])
def test_cap_average_is_exact_for_polynomials_of_the_order(order):
    """The cap average of u = x^k (k <= p: in the space) is (1 - c^(k+1)) / ((k + 1)(1 - c)).

    P3 and P4 (twoball's own Lagrange line element) are probed at points, as
    the whole bounce does for its cap: the shape scikit-fem's ``probes`` hands in.
    """
    from twoball.fem_membrane.floor import cap_functional_exact

    elements, theta = 7, 0.35
    _, _, x = axisym_matrices(elements, order)
    c = math.cos(theta)
    f = cap_functional_exact(elements, order, theta)
    for k in range(order + 1):
        exact = (1.0 - c ** (k + 1)) / ((k + 1) * (1.0 - c))
        assert f @ x**k == pytest.approx(exact, rel=1e-12, abs=1e-14)


@pytest.mark.parametrize("order", [3, 4])
def test_lagrange_line_basis_takes_probe_shaped_points(order):
    """The values at points shaped (1, N, 1) are those at (1, N): the same polynomial."""
    from twoball.fem_membrane.axisym import ElementLineLagrange

    element = ElementLineLagrange(order)
    points = np.linspace(0.0, 1.0, 9)
    for i in range(order + 1):
        flat, dflat = element.lbasis(points[None, :], i)
        deep, ddeep = element.lbasis(points[None, :, None], i)
        np.testing.assert_array_equal(deep[:, 0], flat)
        np.testing.assert_array_equal(ddeep[0, :, 0], dflat[0])
        nodal = element.lbasis(element.doflocs.T, i)[0]
        np.testing.assert_allclose(nodal, np.eye(order + 1)[i], atol=1e-14)
