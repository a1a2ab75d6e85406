"""The lower ball on the floor, Legendre modes: geometry, books, orders, limits.

Independent values: the height of a material point by elementary geometry, the
momentum balance of the centre, the energy books of the contact core, the
weight carried at rest, pressure x area's contact area, the closed-form
lift-off of the paper (restitution-only special case), synthetic curves with a
known end or edge, and observed orders in bands (too high fails too).
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from numpy.polynomial.legendre import legval

from twoball.modal.balls.membrane import legendre_ball, mode_decay, mode_spectrum
from twoball.modal.damping import ModalRatio, Rayleigh
from twoball.modal.floor.drop import DropSettings, run_drop
from twoball.modal.floor.measure import (
    contact_edge,
    contact_intervals,
    edge_law,
    hermite_peak,
    separation_time,
    smoothed_minimum,
)
from twoball.modal.floor.restitution import restitution_only
from twoball.modal.floor.settle import settle
from twoball.modal.floor.system import floor_system
from twoball.modal.nonsmooth import MoreauJean
from twoball.modal.stiffness import Stiffness
from twoball.verify.studies.orders import OrderBand

V0 = 4.1 / (0.12 * 320.0)  # the basketball at 4.1 m/s, units R c
GAMMA = 9.81 / (0.12 * 320.0**2)
GAS = 6.0 * 1.4 * (77.2e3 + 101325.0) / 77.2e3  # adiabatic, 6 kappa P_abs / P
PRESSURISED = Stiffness(gas=GAS, membrane="pressurised")
PAPER_GAS = Stiffness(gas=GAS, membrane="paper")


MODAL = ModalRatio(0.13)


def _drop(modes=20, spectrum=PRESSURISED, law=MODAL, dt=0.02, e=0.0, t_end=30.0):
    system = floor_system(legendre_ball(modes, spectrum, law), GAMMA, e)
    return run_drop(system, DropSettings(V0, GAMMA, dt, t_end))


# --- the model ----------------------------------------------------------------------------


def test_spectrum_of_both_operators_bending_and_gas():
    """The drop reads the ball's Stiffness: (n - 1)(n + 2) or n (n + 1), bending, gas."""
    n = np.arange(6)
    lam = n * (n + 1.0)
    stiff = Stiffness(beta=0.1, gas=5.0)
    paper, share = mode_spectrum(stiff, lam)
    assert paper[0] == 5.0 and share.tolist() == [5.0, 0, 0, 0, 0, 0]
    np.testing.assert_allclose(paper[1:], (lam * (1 + 0.1 * (lam - 2)))[1:], rtol=1e-15)
    np.testing.assert_allclose(paper, stiff.legendre_omega(n) ** 2, rtol=1e-14)
    pressed, _ = mode_spectrum(Stiffness(gas=5.0, membrane="pressurised"), lam)
    np.testing.assert_array_equal(pressed, [3.0, 0.0, 4.0, 10.0, 18.0, 28.0])  # (n-1)(n+2)


def test_decay_of_each_law_is_its_ratio():
    w2 = np.array([4.0, 10.0, 400.0])
    np.testing.assert_allclose(mode_decay(ModalRatio(0.13), w2), 2 * 0.13 * np.sqrt(w2))
    law = Rayleigh(0.47, 0.012)
    np.testing.assert_allclose(mode_decay(law, w2), 2 * law.ratios(np.sqrt(w2)) * np.sqrt(w2))


def test_legendre_ball_leaves_degree_one_to_the_centre():
    """Coordinates: the centre's height Z (0), then n = 0, 2..12; degree 1 is Z's."""
    ball = legendre_ball(12, PRESSURISED, ModalRatio(0.1))
    assert ball.centre == 0 and ball.modes == 1 + 12  # Z, then n = 0, 2..12
    assert ball.points == 7  # the Radau nodes with x < 0
    degrees = np.array([0, *range(2, 13)])
    # the translation's entry 2 = 1 (1 + 1): degree 1's Laplace eigenvalue, its own shape
    np.testing.assert_allclose(ball.laplace, [2.0, *(degrees * (degrees + 1.0))])
    np.testing.assert_allclose(ball.masses, [1.0, *(1.0 / (2.0 * degrees + 1.0))])
    assert ball.omega_squared[0] == 0.0 and ball.decay[0] == 0.0  # a free translation
    assert ball.phi[-1] == math.pi and ball.phi[0] > math.pi / 2
    x = np.cos(ball.phi)
    # vertical rows: the centre moves every point by 1, mode n by cos(phi) P_n(cos(phi))
    np.testing.assert_array_equal(ball.floor_rows[:, 0], 1.0)
    np.testing.assert_allclose(ball.floor_rows[:, 2], x * legval(x, [0, 0, 1]), atol=1e-15)
    np.testing.assert_allclose(ball.modes_at(ball.phi)[:, 2], legval(x, [0, 0, 1]), atol=1e-15)
    np.testing.assert_array_equal(ball.modes_at(ball.phi)[:, 0], 0.0)  # Z does not deform
    anchored = legendre_ball(12, PRESSURISED, ModalRatio(0.1), anchored=True)
    assert anchored.centre is None and anchored.modes == 13  # n = 0..12, degree 1 a mode
    assert anchored.omega_squared[1] == 0.0  # (1 - 1)(1 + 2)
    np.testing.assert_allclose(anchored.floor_rows[:, 1], x * x, atol=1e-15)  # cos(phi) P_1


def test_floor_points_make_the_delassus_matrix_diagonal():
    """At the Gauss-Radau nodes the modes are discretely orthogonal: G M^-1 G^T is diagonal
    but for the centre's +1 and the missing degree 1's -3 x_i^2 x_j^2 (rank two)."""
    modes = 40
    system = floor_system(legendre_ball(modes, PRESSURISED, ModalRatio(0.0)), GAMMA)
    G = system.problem.constraints
    D = G @ (G.T / system.problem.mass.diagonal[:, None])
    x = np.cos(system.ball.phi)
    smooth = 1.0 - 3.0 * np.outer(x**2, x**2)
    off = D - smooth
    np.fill_diagonal(off, 0.0)
    assert np.abs(off).max() < 1e-9 * np.abs(D).max()
    assert system.ball.phi[-1] == math.pi  # the south pole is a node


def test_floor_gap_is_the_height_of_the_material_point():
    """g_i = Z + (1 + u(phi_i)) cos(phi_i): the point at radius 1 + u along its ray."""
    system = floor_system(legendre_ball(8, PAPER_GAS, ModalRatio(0.0)), GAMMA)
    rng = np.random.default_rng(1)
    assert system.ball.centre == 0
    q = np.concatenate([[1.3], 0.01 * rng.normal(size=system.ball.modes - 1)])
    degrees = np.array([0, *range(2, 9)])
    for i, phi in enumerate(system.ball.phi):
        coefficients = np.zeros(9)
        coefficients[degrees] = q[1:]
        u = legval(math.cos(phi), coefficients)
        height = 1.3 + (1.0 + u) * math.cos(phi)  # geometry, not the assembled rows
        assert system.floor_gaps(q)[i] == pytest.approx(height, abs=1e-15)


# --- one drop: momentum and energy books ------------------------------------------------------


@pytest.mark.parametrize(
    ("spectrum", "law", "e"),
    [
        (PRESSURISED, ModalRatio(0.13), 0.0),
        (PRESSURISED, ModalRatio(0.0), 0.0),
        (PAPER_GAS, ModalRatio(0.13), 0.0),
        (PRESSURISED, Rayleigh(0.47273, 0.011818), 0.0),
        (PRESSURISED, ModalRatio(0.0), 1.0),
    ],
    ids=["pressurised-D", "undamped", "paper-gas", "rayleigh", "restitution-1"],
)
def test_floor_impulse_is_the_change_of_momentum_and_the_books_close(spectrum, law, e):
    """J = m2 (v2 + |v0|) + m2 g t_c to 1e-10; E + works = E0 to rounding."""
    r = _drop(spectrum=spectrum, law=law, e=e)
    assert r.left and r.stop == "flight"
    assert r.impulse == pytest.approx(r.v2 + V0 + GAMMA * r.contact_time, rel=1e-10)
    assert r.impulse_balance < 1e-10
    kinetic0 = 0.5 * V0**2
    assert r.energy["balance"] < 1e-12 * kinetic0
    parts = ("rigid_kinetic", "membrane_kinetic", "membrane_elastic", "gas", "gravity")
    books = sum(r.energy[k] for k in parts) - r.energy["damped"] - r.energy["impacts"]
    books -= r.energy["contact"]
    assert books == pytest.approx(r.energy["initial"], abs=1e-12 * kinetic0)
    assert 0.0 < r.e2 < 1.0
    assert math.pi < r.contact_time < 2.0 * math.pi  # of the order of pressure x area's pi
    assert V0 < r.flattening_max < 2.0 * V0  # pressure x area flattens by v0 (units R)
    if e == 1.0:  # Newton's e = 1 loses nothing at impacts: the mechanical energy is kept
        assert abs(r.energy["impacts"]) < 1e-13 * kinetic0
    else:
        assert r.energy["impacts"] < 0.0
    if law == ModalRatio(0.0):
        assert r.energy["damped"] == 0.0


def test_no_contact_after_the_stop():
    """The stop's energy bound holds: continued to the apex, the ball never touches again."""
    r = _drop()
    tr, system = r.trajectory, r.system
    apex = tr.t[-1] + tr.v_final[0] / GAMMA
    rest = MoreauJean(system.problem, 0.1).run(tr.q_final, tr.v_final, apex, t0=tr.t[-1])
    assert not rest.impulse.any()
    assert system.floor_gaps(rest.q).min() > 0.0


def test_paper_operator_without_gas_does_not_bounce():
    """omega_0 = 0: the floor's push shrinks the ball for good (the run ends at the window)."""
    paper = Stiffness()
    r = _drop(spectrum=paper, t_end=20.0)
    assert not r.left and r.stop == "window" and r.e2 is None
    assert r.energy["vibration"] > 0.5 * 0.5 * V0**2


# --- convergence ------------------------------------------------------------------------------


def test_time_step_order_of_flattening_impact_loss_and_contact_angle():
    """Second order in dt (N = 20; errors against dt/16): flattening, impact loss and
    phi_a,max (docs/bounce.rst: 2.0 at the defaults); t_c and e2 have no clean order in dt
    (the release of the last floor points), so their errors at dt = 0.005 are held below
    the tolerances the docs state (3e-4 relative, 1e-5)."""
    ref = _drop(dt=0.00125)
    steps = (0.02, 0.01, 0.005)
    runs = [_drop(dt=dt) for dt in steps]
    for name in ("flattening_max", "impacts", "phi_a_max"):
        values = [r.energy[name] if name == "impacts" else getattr(r, name) for r in runs]
        exact = ref.energy[name] if name == "impacts" else getattr(ref, name)
        errors = np.abs(np.array(values) - exact)
        order = np.polyfit(np.log(steps), np.log(errors), 1)[0]
        band = OrderBand(2.0, 0.5, 0.5) if name == "phi_a_max" else OrderBand(2.0, 0.4, 0.4)
        assert band.contains(order), (name, order)
    assert abs(runs[-1].contact_time - ref.contact_time) < 3e-4 * ref.contact_time
    assert abs(runs[-1].e2 - ref.e2) < 1e-5


def test_modes_order_of_restitution():
    """e2 converges at order 2 in 1/N (N = 16, 32, 64; successive differences)."""
    v = [_drop(modes=n, dt=0.01).e2 for n in (16, 32, 64)]
    order = math.log2((v[1] - v[0]) / (v[2] - v[1]))
    assert OrderBand(2.0, 0.5, 0.5).contains(order), order


def test_modes_order_of_contact_time_and_the_contact_angle_within_its_tolerance():
    """t_c converges at about order 1 in 1/N (docs/bounce.rst: 1.0; here N = 32, 64, 128 at
    dt = 0.0025, successive differences, measured 0.81), in the band 1 +- 0.5; phi_a,max
    has no asymptotic order (the phase of the edge between the floor points), and from
    N = 192 it is within the stated 1e-3 rad of a resolution twice as fine."""
    t_c = [_drop(modes=n, dt=0.0025).contact_time for n in (32, 64, 128)]
    order = math.log2((t_c[1] - t_c[0]) / (t_c[2] - t_c[1]))
    assert OrderBand(1.0, 0.5, 0.5).contains(order), order
    default, finer = (_drop(modes=n, dt=0.0025).phi_a_max for n in (192, 384))
    assert abs(default - finer) < 1e-3


@pytest.mark.slow
def test_modes_orders_of_contact_time_flattening_and_restitution():
    """Least-squares orders in 1/N against N = 512 (dt = 0.005), measured 0.76, 1.2, 2.4:
    t_c ~1 (the last floor point's logarithmic tail), the flattening ~1 from N = 64 (the
    impact losses of the touches it sums), e2 ~2."""
    sizes = (32, 64, 128, 256)
    runs = dict(zip(sizes, (_drop(modes=n, dt=0.005) for n in sizes), strict=True))
    ref = _drop(modes=512, dt=0.005)
    for name, used, band in (
        ("contact_time", sizes, OrderBand(1.0, 0.6, 0.6)),
        ("flattening_max", sizes[1:], OrderBand(1.2, 0.6, 0.6)),
        ("e2", sizes, OrderBand(2.0, 0.5, 1.0)),
    ):
        errors = [abs(getattr(runs[n], name) - getattr(ref, name)) for n in used]
        order = -np.polyfit(np.log(used), np.log(errors), 1)[0]
        assert band.contains(order), (name, order)


# --- energy without damping -------------------------------------------------------------------


@pytest.mark.slow
def test_the_plastic_floor_loses_the_energy_of_the_supersonic_start():
    """D = 0, e = 0: the impact loss over its continuum estimate KE0 (v0 / (R c))^2 / 4 (the
    material the supersonic contact edge sweeps, docs/bounce.rst) is a property of the
    model, not of the step: (i) at N = 192 it changes by less than 1 % from dt = 0.0025 to
    0.000625 (measured 0.59 %), and by less each time dt halves; (ii) at N = 384 it is of
    order one and the same at 2 and 8 m/s within 20 % (measured 0.64 and 0.55)."""
    from twoball.verify.studies.floor import normalised_loss, plastic_loss

    steps = (0.005, 0.0025, 0.00125, 0.000625)
    ratios = np.array([normalised_loss(plastic_loss(4.1, 192, dt)) for dt in steps])
    changes = np.abs(np.diff(ratios))
    assert np.all(np.diff(changes) < 0.0), ratios
    assert abs(ratios[1] / ratios[-1] - 1.0) < 0.01, ratios
    slow, fast = (normalised_loss(plastic_loss(v, 384, 0.0025)) for v in (2.0, 8.0))
    assert 0.4 < fast < slow < 1.0
    assert slow / fast < 1.2, (slow, fast)


def test_a_floor_with_restitution_one_keeps_the_energy_at_every_step():
    """D = 0, e = 1: the mechanical energy E = kinetic + elastic + gravity stays at its start
    to rounding at every step end, for every dt (no loss at impacts to converge away):
    within 1e-12 of the initial kinetic energy over 1200 to 5000 steps (measured 3e-15 at
    dt = 0.02, 1.2e-13 at dt = 0.00125)."""
    from twoball.verify.studies.floor import plastic_loss

    for dt in (0.02, 0.005, 0.00125):
        r = plastic_loss(4.1, 64, dt, 1.0)
        kinetic = 0.5 * r.settings.v0**2
        drift = np.abs(r.trajectory.energy - r.trajectory.energy[0]).max() / kinetic
        assert drift < 1e-12, (dt, drift)
        assert abs(r.energy["impacts"]) < 1e-15 * kinetic and r.energy["damped"] == 0.0


# --- at rest on the floor ---------------------------------------------------------------------


def test_resting_ball_carries_its_weight():
    r = settle(floor_system(legendre_ball(60, PRESSURISED, ModalRatio(0.9)), GAMMA), t_end=1200.0)
    assert r.residual_speed < 1e-12
    assert r.floor_force == pytest.approx(r.weight, rel=1e-9)


@pytest.mark.slow
def test_resting_contact_area_tends_to_pressure_times_area():
    """m2 g / P (pressurised): the cap through the edge estimated between the points and the
    cap through the outermost point in contact both tend to it (N = 240, 480)."""
    runs = [
        settle(floor_system(legendre_ball(n, PRESSURISED, ModalRatio(0.9)), GAMMA))
        for n in (240, 480)
    ]
    edge = [abs(r.edge_area / r.pressure_area - 1.0) for r in runs]
    inner = [abs(r.contact_area[0] / r.pressure_area - 1.0) for r in runs]
    assert edge[0] < 0.1 and edge[1] < 0.04 and edge[0] / edge[1] > 2.0, edge
    assert inner[0] < 0.15 and inner[1] < 0.06 and inner[0] / inner[1] > 2.0, inner
    for r in runs:
        assert r.floor_force == pytest.approx(r.weight, rel=1e-9)


# --- the restitution-only model as a special case ---------------------------------------------


def test_restitution_only_reproduces_the_closed_form_lift_off():
    """Started at (3.10) without floor or weight, the paper's operator with its degree-1 mode
    gives the closed-form lift-off of eq. (3.16) (Lanczos, N = 30) at second order in dt."""
    import twoball

    case = twoball.Case.preset("basketball")
    exact = twoball.liftoff(case).result
    paper = Stiffness()
    errors = []
    for dt in (0.01, 0.005):
        run = restitution_only(paper, ModalRatio(0.13), 30, case.phi_a, case.gamma, dt).result
        errors.append((abs(run.t - exact.t), abs(run.velocity - exact.velocity)))
    assert errors[-1][0] < 2e-4 and errors[-1][1] < 3e-5
    assert 3.0 < errors[0][0] / errors[1][0] < 5.0  # second order
    assert 3.0 < errors[0][1] / errors[1][1] < 5.0


def test_restitution_only_pressurised_centre_or_mode_is_the_same():
    """omega_1 = 0: the degree-1 content kept as a mode or carried by Z gives one motion."""
    runs = [
        restitution_only(PRESSURISED, ModalRatio(0.13), 30, 2.6, GAMMA, 0.01, anchored=a)
        for a in (True, False)
    ]
    t = np.linspace(0.0, 12.0, 50)
    np.testing.assert_allclose(runs[0].motion.pole(t).u, runs[1].motion.pole(t).u, atol=1e-13)
    assert runs[0].result.t == pytest.approx(runs[1].result.t, abs=1e-12)


# --- the measures on curves with known answers ------------------------------------------------


def test_separation_time_of_a_force_falling_linearly():
    """F = 2 (t_e - t) on a grid: sqrt of the remaining impulse is linear -> t_e exactly."""
    t_e = 1.2345
    t = np.arange(0.0, 1.4, 0.1)
    cumulative = np.minimum(t, t_e) * 2 * t_e - np.minimum(t, t_e) ** 2
    last = int(np.searchsorted(t, t_e)) - 1
    assert separation_time(t, cumulative, last, 0.1) == pytest.approx(t_e, abs=1e-12)
    impulses = np.diff(cumulative)
    (interval,) = contact_intervals(t, impulses, 0.1)
    assert interval.start == 0.0 and interval.end == pytest.approx(t_e, abs=1e-12)


def test_contact_edge_of_a_tangential_gap():
    """gap = a (phi_e - phi)^2 outside the contact: the edge between the points is found."""
    phi = np.linspace(math.pi / 2, math.pi, 41)[1:]
    edge = 2.71
    gap = np.where(phi < edge, 0.3 * (edge - phi) ** 2, 0.0)
    assert contact_edge(phi, gap, 1e-14) == pytest.approx(edge, abs=1e-12)
    assert contact_edge(phi, gap, 1e-14, skip=0) == pytest.approx(edge, abs=1e-12)
    assert contact_edge(phi, np.ones_like(phi), 1e-14) == math.pi  # no contact
    # with bending the gap grows like the cube of the distance: its cube root is linear
    cubic = np.where(phi < edge, 0.3 * (edge - phi) ** 3, 0.0)
    assert contact_edge(phi, cubic, 1e-14, skip=0, power=3.0) == pytest.approx(edge, abs=1e-12)
    assert abs(contact_edge(phi, cubic, 1e-14) - edge) > 1e-4  # the square root misses it
    assert edge_law(False) == {"skip": 1, "power": 2.0}
    assert edge_law(True) == {"skip": 0, "power": 3.0}


def test_the_contact_angle_of_a_ball_with_bending_from_the_cube_root_of_the_gap():
    """The tennis ball (bending): the gap leaves the floor like the cube of the distance,
    and the edge from its cube root at N = 96 and 192 is within 3e-3 rad of N = 384
    (measured 2.6695, 2.6739 against 2.6715); the square root's edge moved by 1.9e-2 over
    the same N."""
    from twoball.verify.studies.floor import drop_model, run

    model = drop_model("tennis", "pressurised", "modal")
    *coarse, fine = (run(model, "legendre", n, 0.005).result.phi_a_max for n in (96, 192, 384))
    assert all(abs(angle - fine) < 3e-3 for angle in coarse), (coarse, fine)


def test_smoothed_minimum_and_hermite_peak():
    t = np.linspace(0.0, 2.0, 2001)
    values = (t - 1.2) ** 2
    values[600] = -5.0  # one isolated dip is averaged away
    low, when = smoothed_minimum(t, values, 0.2)
    assert low == pytest.approx(0.1**2 / 3, rel=1e-3) and when == pytest.approx(1.2, abs=1e-3)
    coarse = np.linspace(0.0, 3.0, 7)
    peak, at = hermite_peak(coarse, np.sin(coarse), np.cos(coarse))
    assert peak == pytest.approx(1.0, abs=2e-4) and at == pytest.approx(math.pi / 2, abs=2e-2)
