"""The nonsmooth contact core: LCP, Moreau-Jean with localised touches, energy and momentum.

Every check compares with an independent value: brute-force enumeration of an
LCP, closed-form motions of a falling particle and of two masses on a spring,
exact energy and momentum identities, and the same problem stored three ways.
"""

from __future__ import annotations

import itertools
import math

import numpy as np
import pytest
import scipy.sparse as sp

from twoball._common.errors import ParameterError
from twoball.modal.nonsmooth import ContactProblem, MoreauJean, solve_lcp
from twoball.verify.studies.orders import OrderBand, least_squares_order

# --- LCP ----------------------------------------------------------------------------


def _brute_force_lcp(D: np.ndarray, b: np.ndarray) -> np.ndarray:
    """The LCP solution by trying every active set (unique for positive definite D)."""
    m = b.size
    for size in range(m + 1):
        for active in itertools.combinations(range(m), size):
            z = np.zeros(m)
            idx = list(active)
            if idx:
                z[idx] = np.linalg.solve(D[np.ix_(idx, idx)], -b[idx])
            w = D @ z + b
            if np.all(z >= -1e-12) and np.all(w >= -1e-12):
                return z
    raise AssertionError("no solution")


@pytest.mark.parametrize("seed", range(8))
def test_lcp_matches_enumeration_of_active_sets(seed):
    rng = np.random.default_rng(seed)
    m = 6
    A = rng.normal(size=(m, m))
    D = A @ A.T + 0.1 * np.eye(m)
    b = rng.normal(size=m)
    sol = solve_lcp(D, b)
    np.testing.assert_allclose(sol.z, _brute_force_lcp(D, b), atol=1e-10)
    assert sol.w.min() >= -1e-12 and abs(sol.w @ sol.z) < 1e-10


def test_lcp_with_dependent_rows_is_complementary():
    """More constraints than independent rows: D singular, b in its range (NNLS path)."""
    rng = np.random.default_rng(3)
    G = rng.normal(size=(7, 3))  # 7 constraints on 3 coordinates
    D = G @ G.T
    b = G @ rng.normal(size=3)
    sol = solve_lcp(D, b)
    assert sol.z.min() >= 0.0
    assert sol.w.min() >= -1e-10 * np.abs(b).max()
    assert abs(sol.w @ sol.z) <= 1e-10 * max(1.0, sol.z.sum())


def test_first_crossings_of_many_gaps_are_the_scalar_ones_to_the_bit():
    """The stacked companion matrices give numpy.roots' roots: the same crossing times,
    bit for bit, including gaps that start at zero and a vanishing cubic term."""
    from twoball.modal.nonsmooth.crossing import first_crossing, first_crossings

    rng = np.random.default_rng(11)
    for _ in range(400):
        k = int(rng.integers(1, 9))
        h = 10.0 ** rng.uniform(-4, -1)
        scale = h * 10.0 ** rng.uniform(-3, 0)
        g0 = np.where(rng.random(k) < 0.3, 0.0, scale * np.abs(rng.normal(size=k)))
        u0, u1 = rng.normal(size=k), rng.normal(size=k)
        g1 = -scale * np.abs(rng.normal(size=k))
        if rng.random() < 0.1:
            u0[:] = 0.0
        expected = [first_crossing(h, *x) for x in zip(g0, u0, g1, u1, strict=True)]
        assert first_crossings(h, g0, u0, g1, u1).tolist() == expected
    # a straight line: the cubic and quadratic terms vanish (numpy.roots trims them)
    assert first_crossings(
        1.0, np.array([1.0]), np.array([-2.0]), np.array([-1.0]), np.array([-2.0])
    ).tolist() == [0.5]


# --- the problem bundle ------------------------------------------------------------


def test_problem_refuses_bad_input():
    ok = dict(M=[1.0], C=None, K=[0.0], f=None, G=[[1.0]], g0=[0.0])
    ContactProblem.create(**ok)
    with pytest.raises(ParameterError, match="restitution"):
        ContactProblem.create(**ok, restitution=1.5)
    with pytest.raises(ParameterError, match="M"):
        ContactProblem.create(**{**ok, "M": [-1.0]})
    with pytest.raises(ParameterError, match="G"):
        ContactProblem.create(**{**ok, "G": [[1.0, 2.0]]})
    with pytest.raises(ParameterError, match="g0"):
        ContactProblem.create(**{**ok, "g0": [0.0, 1.0]})
    with pytest.raises(ParameterError, match="K"):
        ContactProblem.create(**{**ok, "K": [np.nan]})
    problem = ContactProblem.create(**ok)
    with pytest.raises(ParameterError, match="theta"):
        MoreauJean(problem, 0.1, theta=0.4)
    with pytest.raises(ParameterError, match="dt"):
        MoreauJean(problem, 0.0)


# --- a particle falling on the floor ---------------------------------------------------


def _particle(e: float) -> ContactProblem:
    return ContactProblem.create([1.0], None, [0.0], [-1.0], [[1.0]], [0.0], e)


@pytest.mark.parametrize("e", [0.0, 0.5, 1.0])
def test_falling_particle_is_exact_with_localised_touches(e):
    """Drop from height 1 (g = 1): impact at t = sqrt 2, rebound e sqrt 2; exact at t = 2.

    The trapezoidal rule integrates a constant acceleration exactly, so only the
    touch time could err; it is localised to rounding.
    """
    tr = MoreauJean(_particle(e), 0.1).run([1.0], [0.0], 2.0)
    s = 2.0 - math.sqrt(2.0)
    v_up = e * math.sqrt(2.0)
    height, speed = (v_up * s - 0.5 * s * s, v_up - s) if e > 0 else (0.0, 0.0)
    assert tr.q_final[0] == pytest.approx(height, abs=1e-12)
    assert tr.v_final[0] == pytest.approx(speed, abs=1e-12)
    assert tr.impact_work[-1] == pytest.approx(-0.5 * (1.0 - e * e) * 2.0, abs=1e-12)
    assert np.max(np.abs(tr.balance)) < 1e-13


# --- two masses on a spring dropped on the floor ---------------------------------------------

M1, M2, SPRING, SPEED = 0.5, 1.0, 4.0, 1.0


def _two_masses(e: float = 0.0, storage: str = "diagonal") -> ContactProblem:
    K = np.array([[SPRING, -SPRING], [-SPRING, SPRING]])
    M = np.array([M1, M2])
    if storage == "dense":
        M = np.diag(M)
    elif storage == "sparse":
        M, K = sp.diags(M), sp.csr_matrix(K)
    return ContactProblem.create(M, None, K, None, [[1.0, 0.0]], [0.0], e)


def _two_masses_exact(t: float) -> tuple[np.ndarray, np.ndarray]:
    """Lower mass stops (e = 0), the upper one swings down and back; lift-off at pi/omega."""
    w = math.sqrt(SPRING / M2)
    t_l = math.pi / w
    if t < t_l:
        return (
            np.array([0.0, -SPEED * math.sin(w * t) / w]),
            np.array([0.0, -SPEED * math.cos(w * t)]),
        )
    total = M1 + M2
    V = M2 * SPEED / total
    wr = math.sqrt(SPRING * (1.0 / M1 + 1.0 / M2))
    s = t - t_l
    r, rd = SPEED * math.sin(wr * s) / wr, SPEED * math.cos(wr * s)
    x = np.array([V * s - M2 / total * r, V * s + M1 / total * r])
    v = np.array([V - M2 / total * rd, V + M1 / total * rd])
    return x, v


def _two_mass_errors(localise: bool, steps=(0.02, 0.01, 0.005, 0.0025)) -> np.ndarray:
    T = 3.0
    qe, ve = _two_masses_exact(T)
    errors = []
    for dt in steps:
        tr = MoreauJean(_two_masses(), dt, localise=localise).run([0.0, 0.0], [-SPEED, -SPEED], T)
        errors.append(np.abs(tr.q_final - qe).max() + np.abs(tr.v_final - ve).max())
    return np.array(errors)


def test_localised_scheme_is_second_order_on_two_masses():
    steps = (0.02, 0.01, 0.005, 0.0025)
    order = least_squares_order(steps, _two_mass_errors(True, steps)).order
    assert OrderBand(2.0, 0.3, 0.3).contains(order), order


def test_classical_moreau_jean_is_first_order_on_two_masses():
    steps = (0.02, 0.01, 0.005, 0.0025)
    order = least_squares_order(steps, _two_mass_errors(False, steps)).order
    assert OrderBand(1.0, 0.2, 0.3).contains(order), order


def test_two_masses_lose_exactly_the_lower_mass_kinetic_energy():
    tr = MoreauJean(_two_masses(), 0.01).run([0.0, 0.0], [-SPEED, -SPEED], 3.0)
    assert tr.impact_work[-1] == pytest.approx(-0.5 * M1 * SPEED**2, rel=1e-13)
    assert abs(tr.contact_work[-1]) < 1e-14
    assert np.max(np.abs(tr.balance)) < 1e-13
    # momentum: the floor's impulse is the change of momentum (exactly, in the
    # scheme), and the momentum after lift-off is m2 v0 (to the O(dt^2) of lift-off)
    momentum = M1 * tr.v_final[0] + M2 * tr.v_final[1]
    assert momentum == pytest.approx(M2 * SPEED, rel=1e-4)
    assert tr.impulse.sum() == pytest.approx((M1 + M2) * SPEED + momentum, rel=1e-13)


@pytest.mark.parametrize("storage", ["dense", "sparse"])
def test_storage_does_not_change_the_result(storage):
    ref = MoreauJean(_two_masses(), 0.01).run([0.0, 0.0], [-SPEED, -SPEED], 2.0)
    other = MoreauJean(_two_masses(storage=storage), 0.01).run([0.0, 0.0], [-SPEED, -SPEED], 2.0)
    np.testing.assert_allclose(other.q, ref.q, atol=1e-13)
    np.testing.assert_allclose(other.impulse, ref.impulse, atol=1e-13)


# --- a chain with many contacts: energy identity, momentum, restitution 1 ------------------


def _chain(n: int = 8, damping: float = 0.0, e: float = 0.0):
    """n masses on springs, a free rigid translation (K singular), each over the floor."""
    K = np.zeros((n, n))
    for i in range(n - 1):
        K[np.ix_([i, i + 1], [i, i + 1])] += 40.0 * np.array([[1.0, -1.0], [-1.0, 1.0]])
    M = np.linspace(0.5, 1.5, n)
    C = damping * (np.diag(M) + 0.01 * K)
    f = -0.3 * M
    heights = 0.02 * np.arange(n) ** 2  # a curved body: the points touch one after another
    problem = ContactProblem.create(M, C, K, f, np.eye(n), heights, e)
    return problem, np.zeros(n), np.full(n, -1.0)


@pytest.mark.parametrize("damping", [0.0, 0.2])
def test_energy_identity_with_many_contacts(damping):
    """E_n - E_0 = damping work + impact work, to rounding, for theta = 1/2 (eq. (MJ5))."""
    problem, q0, v0 = _chain(damping=damping)
    tr = MoreauJean(problem, 0.01).run(q0, v0, 3.0)
    scale = tr.energy[0] - tr.potential[0]
    assert len([e for e in tr.events if e.kind == "impact"]) >= problem.count
    assert np.max(np.abs(tr.balance)) < 1e-12 * scale
    assert tr.impact_work[-1] < 0.0
    assert abs(tr.contact_work[-1]) < 1e-10 * scale


def test_momentum_balance_with_many_contacts():
    """Floor impulses = change of momentum + the weight's impulse (K: a free translation)."""
    problem, q0, v0 = _chain()
    tr = MoreauJean(problem, 0.01).run(q0, v0, 3.0)
    mass = problem.mass.diagonal
    weight = -problem.load.sum()
    expected = mass @ (tr.v_final - v0) + weight * tr.t[-1]
    assert tr.impulse.sum() == pytest.approx(expected, rel=1e-12)


def test_restitution_one_conserves_mechanical_energy():
    problem, q0, v0 = _chain(e=1.0)
    tr = MoreauJean(problem, 0.01).run(q0, v0, 3.0)
    scale = tr.kinetic[0]
    assert np.max(np.abs(tr.energy - tr.energy[0])) < 1e-12 * scale
    assert abs(tr.impact_work[-1]) < 1e-12 * scale


def test_theta_above_half_dissipates_numerically():
    problem, q0, v0 = _chain()
    tr = MoreauJean(problem, 0.01, theta=0.6).run(q0, v0, 3.0)
    assert tr.balance[-1] < -1e-6 * tr.kinetic[0]
    assert np.all(np.diff(tr.balance) <= 1e-14 * tr.kinetic[0])


# --- a body on top of the membrane (the floor's tests: tests/modal/test_floor.py) -------------


def test_rigid_body_on_top_matches_the_event_driven_solver():
    """A body (mass ratio 0.05) on the paper's membrane, started at maximal compression
    (phi_a = 2.6, no floor): the core reproduces the closed-form event-driven solver of
    :mod:`twoball.modal.contact` (same modes, one constraint ``s - b . q >= 0``)."""
    from twoball.modal.contact.events import integrate
    from twoball.modal.contact.system import ContactSystem
    from twoball.modal.floor.measure import contact_intervals
    from twoball.modal.legendre import legendre_series

    gamma = 7.98e-4
    series = legendre_series(2.6, 0.1, filter="lanczos", modes=30)
    b = np.asarray(series.pole_values, dtype=float)
    system = ContactSystem.from_series(series, b, mass_ratio=0.05, gamma=gamma)
    history = integrate(system, 6.0, restitution=0.0)
    m, w, mu = system.masses, system.omega, system.body_mass
    problem = ContactProblem.create(
        np.append(m, mu),
        np.append(2.0 * system.damping * w * m, 0.0),
        np.append(m * w**2, 0.0),
        np.append(np.zeros(m.size), -mu * gamma),
        np.append(-b, 1.0)[None, :],
        [0.0],
        0.0,
    )
    q0 = np.append(system.initial, b @ system.initial)
    tr = MoreauJean(problem, 0.0025).run(q0, np.zeros(q0.size), 6.0)
    t_l = contact_intervals(tr.t, tr.impulse.sum(axis=1), 0.0025)[-1].end
    velocity = tr.v_final[-1] + gamma * (tr.t[-1] - t_l)  # free flight after lift-off
    assert history.lifted
    assert velocity == pytest.approx(history.velocity, rel=2e-4)
    assert t_l == pytest.approx(history.t, abs=2e-3)
