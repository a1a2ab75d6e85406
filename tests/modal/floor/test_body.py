"""The whole bounce's model: the body as one coordinate and one row of the drop's system.

Independent values: the cap average by a separate quadrature and in closed form,
the finite-element cap functional on polynomials, the drop of the ball alone
(a body that never touches changes nothing), the closed-form event-driven
finite-mass solver of :mod:`twoball.modal.contact` (limit (a): the floor removed,
the start at maximal compression), the ICM's algebra (limit (b): an isolated
collision without gravity), exact energy and momentum books (limit (c)) and the
integration continued past the stop (nothing touches again).
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from numpy.polynomial.legendre import leggauss, legval

import twoball
from twoball.fem_membrane.floor import axisym_ball, cap_functional_exact
from twoball.modal.balls.membrane import legendre_ball
from twoball.modal.contact.caps import legendre_cap_averages_closed
from twoball.modal.damping import ModalRatio
from twoball.modal.floor.drop import DropSettings, run_drop
from twoball.modal.floor.restitution import body_liftoff
from twoball.modal.floor.system import BodyOnTop, floor_system
from twoball.modal.nonsmooth import MoreauJean
from twoball.modal.stiffness import Stiffness

R, C = 0.12, 320.0
V0 = 4.1 / (R * C)
GAMMA = 9.81 / (R * C**2)
GAS = 6.0 * 1.4 * (77.2e3 + 101325.0) / 77.2e3
PRESSURISED = Stiffness(gas=GAS, membrane="pressurised")
THETA = math.asin(0.0262 / R)  # the tennis ball's cap on the basketball


MODAL = ModalRatio(0.13)


def _whole(modes=32, mu=0.101, e12=0.89, gap=0.0, law=MODAL, gamma=GAMMA, e=0.0):
    ball = legendre_ball(modes, PRESSURISED, law)
    body = BodyOnTop(mu, ball.cap_average(THETA), THETA, e12, gap / R)
    system = floor_system(ball, gamma, e, body)
    return system, run_drop(system, DropSettings(V0, gamma, 0.01, 60.0))


# --- the model ------------------------------------------------------------------------------


def test_cap_average_of_the_legendre_modes_against_closed_form_and_quadrature():
    """The translation's entry is 1 (the whole cap rises with Z); the modes' are their means."""
    ball = legendre_ball(24, PRESSURISED, ModalRatio(0.1))
    average = ball.cap_average(0.3)
    assert ball.centre == 0 and average.size == 1 + 24 and average[0] == 1.0
    b = average[1:]  # n = 0, 2..24
    n = np.array([0, *range(2, 25)])
    np.testing.assert_allclose(b, legendre_cap_averages_closed(0.3, 24)[n], atol=1e-12)
    x, w = leggauss(200)  # a second rule: 200 points on [cos 0.3, 1]
    c = math.cos(0.3)
    xs = c + (1 - c) * (x + 1) / 2
    direct = [0.5 * w @ legval(xs, np.eye(25)[k]) for k in n]
    np.testing.assert_allclose(b, direct, atol=1e-12)
    assert b[0] == pytest.approx(1.0, abs=1e-15)


def test_finite_element_cap_functional_is_exact_on_the_element_polynomials():
    """P2 holds x and x^2 exactly: their means over [cos theta, 1] in closed form."""
    from twoball.fem_membrane.floor import axisym_matrices

    _, _, x = axisym_matrices(12, 2)
    f = cap_functional_exact(12, 2, 0.41)
    c = math.cos(0.41)
    assert f.sum() == pytest.approx(1.0, abs=1e-14)
    assert f @ x == pytest.approx((1 + c) / 2, abs=1e-14)
    assert f @ x**2 == pytest.approx((1 + c + c * c) / 3, abs=1e-14)
    ball = axisym_ball(12, 2, PRESSURISED, ModalRatio(0.1))
    assert abs(ball.cap_average(0.41)[np.argmin(ball.laplace)]) == pytest.approx(1.0, abs=1e-12)


def test_the_body_is_one_coordinate_and_one_row_with_the_gap_of_the_caps_mean():
    ball = legendre_ball(16, PRESSURISED, ModalRatio(0.1))
    body = BodyOnTop(0.1, ball.cap_average(THETA), THETA, 0.5, 0.2)
    alone, system = floor_system(ball, GAMMA), floor_system(ball, GAMMA, 0.0, body)
    p = system.problem
    assert p.dofs == alone.problem.dofs + 1 and p.count == alone.problem.count + 1
    assert system.body_coordinate == ball.modes and system.body_row == ball.points
    assert ball.modes == 1 + 16  # Z, then n = 0, 2..16: s comes after them
    np.testing.assert_array_equal(p.constraints[: ball.points, :-1], alone.problem.constraints)
    assert p.restitution[-1] == 0.5 and np.all(p.restitution[:-1] == 0.0)
    assert p.load[-1] == pytest.approx(-0.1 * GAMMA)
    q, v = system.falling(V0)
    assert system.body_gap(q) == pytest.approx(0.2)  # Delta x / R above the top
    assert v[system.body_coordinate] == v[system.centre] == -V0
    rng = np.random.default_rng(1)
    q = q + 1e-3 * rng.standard_normal(q.size)
    a = q[system.membrane]
    np.testing.assert_array_equal(q[system.membrane], q[1:-1])  # all but Z and s
    # s - (Z + 1 + the cap's mean deformation), the caps' means of P_n in closed form
    n = np.array([0, *range(2, 17)])
    expected = q[-1] - q[0] - 1.0 - legendre_cap_averages_closed(THETA, 16)[n] @ a
    assert system.body_gap(q) == pytest.approx(expected, abs=1e-15)
    with pytest.raises(twoball.ParameterError):
        BodyOnTop(0.0, ball.cap_average(THETA), THETA)
    with pytest.raises(twoball.ParameterError):
        BodyOnTop(0.1, ball.cap_average(THETA), THETA, gap=-1.0)


def test_a_body_that_never_touches_leaves_the_drop_unchanged():
    """A body 5 m above: the floor phase is the ball alone to rounding."""
    ball = legendre_ball(24, PRESSURISED, ModalRatio(0.13))
    alone = run_drop(floor_system(ball, GAMMA), DropSettings(V0, GAMMA, 0.01, 30.0))
    body = BodyOnTop(0.1, ball.cap_average(THETA), THETA, 0.5, 5.0 / R)
    whole = run_drop(floor_system(ball, GAMMA, 0.0, body), DropSettings(V0, GAMMA, 0.01, 30.0))
    assert whole.e2 == pytest.approx(alone.e2, abs=1e-13)
    assert whole.contact_time == pytest.approx(alone.contact_time, abs=1e-12)
    assert not whole.body.touched and whole.stop == "window"


# --- limits ---------------------------------------------------------------------------------


@pytest.mark.parametrize("mu", [1e-2, 1e-3])
def test_limit_a_floor_removed_start_at_compression_gives_the_finite_mass_solver(mu):
    """The body row on the paper's special case against the exact event-driven solver
    (:func:`~twoball.modal.contact.report.legendre_contact` with ``exact=True``).

    Same modes (N = 30, paper's operator, D = 0.13, Lanczos filter), same cap
    (a = 26.2 mm), no floor: v1 to 1e-4 relative at dt = 0.0025 and second
    order in dt (the error falls by >= 3 when dt halves); the last separation
    within 2e-5 s (separations are not localised: first order).
    """
    from twoball.modal.contact.report import legendre_contact

    case = twoball.Case.preset("basketball")
    body_si = twoball.Body(mu, contact_radius=0.0262)
    ref = legendre_contact(case, body_si, reference=False, exact=True)
    body = BodyOnTop(mu, np.zeros(1), THETA)
    errors = []
    for dt in (0.005, 0.0025):
        run = body_liftoff(Stiffness(), ModalRatio(0.13), 30, case.phi_a, case.gamma, dt, body)
        v1 = run.v1 * case.scalings.velocity
        errors.append(abs(v1 / ref.v_liftoff_m_s - 1.0))
        assert run.t_liftoff / C == pytest.approx(ref.t_liftoff_s, abs=2e-5)
    assert errors[1] < 1e-4 and errors[0] / errors[1] > 3.0


def test_limit_b_an_isolated_collision_without_gravity_is_the_icm():
    """g -> 0, a large gap: the ball leaves the floor first, then (2.5) holds exactly with
    the run's own e2 (the ball alone) and e12_effective (momentum books of the collision)."""
    system, r = _whole(gap=0.25, gamma=1e-12)
    b = r.body
    assert b.sequence == "independent" and b.left and not b.body_left_first
    mu, e2, e12 = 0.101, r.e2, b.e12_effective
    u1, u2 = -V0, e2 * V0
    v1 = (mu * u1 + u2 + e12 * (u2 - u1)) / (mu + 1.0)
    v2 = (mu * u1 + u2 + mu * e12 * (u1 - u2)) / (mu + 1.0)
    assert b.v1 == pytest.approx(v1, abs=1e-9 * V0)
    assert b.v2 == pytest.approx(v2, abs=1e-9 * V0)
    assert 0.0 < e12 < 0.89  # the membrane keeps part of the collision's energy


@pytest.mark.parametrize("floor_e", [0.0, 1.0])
def test_limit_c_energy_and_momentum_at_d_zero_and_e12_one(floor_e):
    """D = 0, e12 = 1, Delta x = 0: E + W = E0 to 1e-13 of the impact energy (the scheme's
    identity), momentum with the floor's impulse to 1e-12; with e = 1 at the floor too no
    energy is lost at all."""
    system, r = _whole(e12=1.0, law=ModalRatio(0.0), e=floor_e)
    tr = r.trajectory
    scale = tr.kinetic[0]
    assert np.max(np.abs(tr.balance)) < 1e-13 * scale
    assert r.impulse_balance < 1e-12
    assert np.max(np.abs(tr.damping_work)) == 0.0
    if floor_e == 1.0:
        assert np.max(np.abs(tr.energy - tr.energy[0])) < 1e-12 * scale
        assert abs(tr.impact_work[-1]) < 1e-13 * scale
    else:
        assert tr.impact_work[-1] < 0.0  # the floor's e = 0 touches lose a little


def test_after_the_stop_nothing_touches_again():
    """The run stops when both are apart for good: integrating on finds no impulse."""
    system, r = _whole(modes=24, gap=0.02)
    assert r.stop == "flight" and r.body.left
    tr = r.trajectory
    rest = MoreauJean(system.problem, 0.01).run(tr.q_final, tr.v_final, 25.0, t0=tr.t[-1])
    assert not rest.impulse.any()


# --- the degree-1 artefact of the radial membrane --------------------------------------------


def test_the_tops_first_response_is_the_degree_one_artefact():
    """The known defect of the radial membrane, pinned: a floor force F accelerates the
    centre by F / m2 and, through the degree-1 content the radial field may not carry, every
    point's radial displacement by -3 F cos(phi) / m2 at once.  The mean over a cap of
    half-angle theta at the top then starts at ``-(1 + 3 cos theta) / 2`` times the centre's
    velocity change (-2 for a point; closed form, independent of the run), where a causal
    membrane would leave the top at rest until the wave arrives at about pi / c.

    D = 0, the ball alone, N = 128: within 3 % at t = 0.05 and 0.1 (units 1/c; the
    truncation's ringing before, the gas's breathing after).  The top then sinks below a body
    falling freely from touching it and comes back to it before pi / c.
    """
    ball = legendre_ball(128, PRESSURISED, ModalRatio(0.0))
    average = ball.cap_average(THETA)
    assert ball.centre == 0 and average[0] == 1.0  # Z lifts the cap as a whole
    cap = average[1:]  # the modes' means over the cap
    run = run_drop(floor_system(ball, GAMMA), DropSettings(V0, GAMMA, 0.005, math.pi))
    tr = run.trajectory
    top, rate = tr.q[:, 0] + 1.0 + tr.q[:, 1:] @ cap, tr.v[:, 0] + tr.v[:, 1:] @ cap
    body, body_rate = 2.0 - V0 * tr.t - 0.5 * GAMMA * tr.t**2, -V0 - GAMMA * tr.t
    closed = -(1.0 + 3.0 * math.cos(THETA)) / 2.0
    assert closed == pytest.approx(-1.964, abs=1e-3)
    for t in (0.05, 0.1):
        k = int(np.searchsorted(tr.t, t))
        ratio = (rate[k] - body_rate[k]) / (tr.v[k, 0] - body_rate[k])
        assert ratio == pytest.approx(closed, rel=0.03), (t, ratio)
    depth = body - top  # > 0: the top below the free-falling body
    deepest = int(np.argmax(depth))
    assert depth[deepest] * R > 1e-3  # more than a millimetre (2.4 mm)
    back = deepest + int(np.flatnonzero(depth[deepest:] <= 0.0)[0])
    assert tr.t[back] < math.pi - 0.5  # back at the body before the wave can be there


def test_a_body_released_later_starts_higher_and_slower():
    """The tower lets the body go tau after the ball (both at rest, touching): at the ball's
    floor touch after a fall H, the body has fallen for T - tau, T = sqrt(2 H / g)."""
    from twoball.modal.floor.system import release_delay

    g, height, tau = 9.81, 0.86, 0.003
    fall = math.sqrt(2.0 * height / g)
    gap = 0.5 * g * (fall**2 - (fall - tau) ** 2)  # how much less the body has fallen
    speed = g * (fall - tau)
    v0 = g * fall
    scale = R * C  # dimensionless: units R, 1/c, R c
    start, body_speed = release_delay(tau * C, v0 / scale, g / (R * C**2))
    assert start * R == pytest.approx(gap, rel=1e-12)
    assert body_speed * scale == pytest.approx(speed, rel=1e-12)
    ball = legendre_ball(8, PRESSURISED, MODAL)
    row = BodyOnTop(0.1, ball.cap_average(THETA), THETA, 0.5, start, speed=body_speed)
    q, v = floor_system(ball, GAMMA, 0.0, row).falling(v0 / scale)
    assert q[-1] - q[0] - 1.0 == pytest.approx(start, rel=1e-15)
    assert v[-1] == -body_speed and v[0] == -v0 / scale
    with pytest.raises(twoball.ParameterError):
        release_delay(1e3, 0.1, 0.01)  # the body would be rising


def test_a_body_started_touching_records_its_separation_at_the_start():
    """Delta x = 0: the top drops away at once with no impulse (the degree-1 response), so
    the events list a body touch and separation at t = 0, not counted as a contact; with a
    gap the body's first event is its first real touch."""
    for gap, first in ((0.0, 0.0), (0.01, None)):
        _, r = _whole(modes=64, gap=gap)
        body = [e for e in r.body.events if e.contact == "body"]
        if first is None:
            assert body[0].kind == "touch" and body[0].t > 1.0
            continue
        assert [(e.kind, e.t) for e in body[:2]] == [("touch", 0.0), ("separation", 0.0)]
        assert body[0].body_velocity == body[0].ball_velocity == -V0
        assert body[2].kind == "touch" and body[2].t > 1.0
        assert r.body.contacts == sum(1 for e in body[2:] if e.kind == "touch")
