"""The lumped baselines of twoball.modal.lumped against published numbers, closed forms and limits.

Reference values are independent of the code under test: Table 1's ICM column
recomputed from eq. (2.6) (values in shared/notes/physics-sources.md), Müller &
Pöschel's published Padé formula for the viscoelastic restitution, Hertz's
contact time, the closed forms of the linear contacts and of a light body on a
spring (mu -> 0), eqs. (2.5) and (2.7), and energy and momentum balances.
"""

from __future__ import annotations

import math

import pytest

from twoball._common.errors import ParameterError
from twoball.modal.icm import TABLE1, light_touching_limit, post_impact_velocities
from twoball.modal.lumped import (
    MODELS,
    Bartz2020,
    HertzViscoelastic,
    ICMBaseline,
    TwoSpringDashpot,
    simulate,
)
from twoball.modal.lumped.fitting import (
    LINEAR_FORCE_RULE_MIN_E,
    fit_hertz,
    fit_linear,
    hertz_restitution,
)
from twoball.modal.lumped.laws import HertzLaw, LinearLaw
from twoball.modal.lumped.pair_inputs import pair_contacts
from twoball.modal.pairs import PAIRS

SPEED = 4.1  # m/s, the paper's basketball impact speed (§4(b))
CONTACT_MODELS = ("two-spring-dashpot", "bartz2020", "hertz-viscoelastic")
FAR = LinearLaw(stiffness=1.0, damping=0.0, tensile=False)  # a pair contact never reached


def _isolated_floor_contact(law, mass: float, speed: float) -> tuple[float, float]:
    """Restitution and duration of one floor contact, g = 0, through the shared solver."""
    r = simulate("isolated", 1e-9, mass, law, FAR, speed, 1e3, 0.0, (1e-3, 1e-3))
    release = next(e for e in r.events if e.contact == "floor" and e.kind == "release")
    return release.v2 / speed, release.time


# -- published numbers -------------------------------------------------------------------


@pytest.mark.parametrize(
    ("name", "v1", "v2"),
    [
        ("tennis-coin", 1.516, 0.674),
        ("tennis-nut", 1.493, 0.743),
        ("tennis-table-tennis", 1.771, 0.691),
    ],
)
def test_icm_recomputes_table1_tennis_rows(name, v1, v2):
    """Eq. (2.6) from Table 1's mu, e2, e12: the ICM column of the tennis rows (2 s.f.)."""
    pair = PAIRS[name]
    r = ICMBaseline.from_pair(pair).run(v0=SPEED, dx=0.0)
    assert r.v1_ratio == pytest.approx(v1, abs=5e-4)
    assert r.v2_ratio == pytest.approx(v2, abs=5e-4)
    assert float(f"{r.v1_ratio:.2g}") == pair.table1.icm_v1
    assert float(f"{r.v2_ratio:.2g}") == pair.table1.icm_v2


@pytest.mark.parametrize("b", [0.01, 0.05, 0.1, 0.2, 0.3])
def test_kuwabara_kono_restitution_matches_mueller_poeschel_pade(b):
    """Viscoelastic Hertz (p = 1/2): e(v*) of Müller & Pöschel, PRE 84, 021302 (2011).

    Their Padé approximant in ``v* = sqrt(beta) v^(1/10)`` (``b = v*^2``), coefficients
    as published; the approximant itself is accurate to ~1e-5 for v* <= 0.55.
    """
    num = (1.0, 1.07232, 0.574198, 0.141552)
    den = (1.0, 1.07232, 1.72765, 1.37842, 1.19449, 0.467273, 0.235585)
    x = math.sqrt(b)
    pade = sum(c * x**i for i, c in enumerate(num)) / sum(c * x**i for i, c in enumerate(den))
    assert hertz_restitution(b, 0.5)[0] == pytest.approx(pade, abs=5e-6)


def test_kuwabara_kono_through_the_shared_solver():
    """A fitted p = 1/2 contact, integrated by the shared solver, restitutes Padé's e."""
    law = fit_hertz(0.05, 0.005, 0.9, SPEED, 0.5)
    e, _ = _isolated_floor_contact(law, 0.05, SPEED)
    assert e == pytest.approx(0.9, abs=1e-8)


def test_hertz_elastic_contact_time_is_hertz():
    """Elastic Hertz contact time 2.87 (m^2 / (R E*^2 v))^(1/5) (Johnson 1985, §11.4)."""
    e_star, radius, mass = 1.0e7, 0.03, 0.05  # Pa, m, kg
    law = HertzLaw(stiffness=4.0 / 3.0 * e_star * math.sqrt(radius), damping=0.0, exponent=0.25)
    for speed in (1.0, 4.0):
        e, duration = _isolated_floor_contact(law, mass, speed)
        hertz = 2.87 * (mass**2 / (radius * e_star**2 * speed)) ** 0.2
        assert duration == pytest.approx(hertz, rel=2e-3)  # 2.87 is printed to 3 s.f.
        assert e == pytest.approx(1.0, abs=1e-9)


# -- closed forms of the isolated contacts -------------------------------------------


@pytest.mark.parametrize("tensile", [True, False])
@pytest.mark.parametrize("e", [0.41, 0.6, 0.83, 0.95])
def test_linear_contact_fit_reproduces_its_duration_and_restitution(tensile, e):
    """fit_linear's closed form against the integration: e and tau of the isolated contact.

    Overlap rule: ``e = exp(-pi q)``; force rule: ``e = exp(-q (pi - 2 arctan q))``.
    """
    law = fit_linear(0.3, 0.006, e, tensile)
    got_e, got_tau = _isolated_floor_contact(law, 0.3, 2.0)
    assert got_e == pytest.approx(e, rel=1e-9)
    assert got_tau == pytest.approx(0.006, rel=1e-9)


def test_damped_oscillator_restitution_is_the_classical_formula():
    """Overlap rule: ``e = exp(-pi zeta / sqrt(1 - zeta^2))`` for a given zeta."""
    zeta, mass, w0 = 0.2, 0.5, 300.0
    law = LinearLaw(mass * w0**2, 2.0 * mass * zeta * w0, tensile=True)
    e, duration = _isolated_floor_contact(law, mass, 3.0)
    assert e == pytest.approx(math.exp(-math.pi * zeta / math.sqrt(1 - zeta**2)), rel=1e-9)
    assert duration == pytest.approx(math.pi / (w0 * math.sqrt(1 - zeta**2)), rel=1e-9)


def test_tsuji_restitution_does_not_depend_on_speed():
    """p = 1/4: the same e at 1 and 8 m/s; the duration scales as v^(-1/5) (Hertz)."""
    law = fit_hertz(0.05, 0.005, 0.6, SPEED, 0.25)
    e_slow, t_slow = _isolated_floor_contact(law, 0.05, 1.0)
    e_fast, t_fast = _isolated_floor_contact(law, 0.05, 8.0)
    assert e_slow == pytest.approx(0.6, abs=1e-8)
    assert e_fast == pytest.approx(0.6, abs=1e-8)
    assert t_slow / t_fast == pytest.approx(8.0**0.2, rel=1e-7)


# -- balances and limits ---------------------------------------------------------------


def _elastic(name: str):
    """The model of basketball-tennis with every restitution 1."""
    c = pair_contacts(PAIRS["basketball-tennis"])
    if name == "two-spring-dashpot":
        return TwoSpringDashpot(c.m1, c.m2, 1.0, 1.0, c.tau2, c.tau12)
    if name == "bartz2020":
        return Bartz2020.from_stiffness(c.m1, c.m2, c.k2, c.k12, 1.0, 1.0)
    return HertzViscoelastic(c.m1, c.m2, 1.0, 1.0, c.tau2, c.tau12)


# Energy error of an elastic run, relative to the impact energy.  The linear laws are
# smooth inside each phase (measured <= 4e-15); the Hertz force k delta^(3/2) is not smooth
# at delta = 0, where each contact starts and ends, and conserves to <= 9e-10 at rtol 1e-10
# (tightening rtol to 1e-12 does not lower it).
ENERGY_TOLERANCE = {"two-spring-dashpot": 1e-11, "bartz2020": 1e-11, "hertz-viscoelastic": 1e-8}


@pytest.mark.parametrize("name", CONTACT_MODELS)
@pytest.mark.parametrize("dx", [0.0, 0.004, 0.03])
def test_elastic_limit_conserves_energy(name, dx):
    """e2 = e12 = 1: kinetic + gravitational energy conserved (tolerances above)."""
    r = _elastic(name).run(v0=SPEED, dx=dx)
    budget = r.energy
    tolerance = ENERGY_TOLERANCE[name] * budget.initial
    assert abs(budget.lost) < 1e-12 * budget.initial  # no dashpot; releases at zero overlap
    assert abs(budget.residual) < tolerance
    change = budget.final_kinetic + budget.potential_change - budget.initial
    assert abs(change) < tolerance


@pytest.mark.parametrize("name", [*CONTACT_MODELS, "icm"])
@pytest.mark.parametrize("pair", ["basketball-tennis", "tennis-coin"])
@pytest.mark.parametrize("dx", [0.0, 0.02])
def test_momentum_balance_with_the_floor_impulse(name, pair, dx):
    """``m1 v1 + m2 v2 - (m1 + m2) v0 = J_floor - (m1 + m2) g t`` at the end of the run."""
    r = MODELS[name](PAIRS[pair]).run(v0=SPEED, dx=dx)
    total = r.m1 + r.m2
    change = r.m1 * r.v1_end + r.m2 * r.v2_end - total * r.v0
    assert change == pytest.approx(
        r.floor_impulse - total * r.g * r.t_end, abs=1e-9 * total * SPEED
    )
    assert abs(r.energy.residual) < 1e-8 * r.energy.initial


@pytest.mark.parametrize("name", CONTACT_MODELS)
@pytest.mark.parametrize("pair", ["basketball-tennis", "tennis-table-tennis"])
def test_large_gap_without_gravity_is_icm(name, pair):
    """g = 0, contacts apart in time: exactly eq. (2.5) with each model's isolated-contact e.

    The floor contact ends before the body arrives; the lower ball leaves at
    ``e2 |v0|`` and the pair contact restitutes e12 (Bartz: from its zetas).
    """
    model = MODELS[name](PAIRS[pair])
    r = model.run(v0=SPEED, dx=0.5, g=0.0)
    assert r.pair_contacts == 1 and not r.body_left_first
    e2, e12 = model.e2, model.e12
    v1, v2 = post_impact_velocities(-SPEED, e2 * SPEED, r.mu, e12)
    assert r.v1 == pytest.approx(v1, rel=1e-7)
    assert r.v2 == pytest.approx(v2, rel=1e-7)


@pytest.mark.parametrize("name", CONTACT_MODELS)
@pytest.mark.parametrize("pair", ["basketball-tennis", "tennis-coin"])
def test_large_gap_with_gravity_approaches_icm(name, pair):
    """dx = 0.25 m, g = 9.81: within ``g (tau2 + tau12)`` of the ICM (2.5).

    The ICM ignores gravity while the contacts last (tau2 + tau12); each rebound
    velocity can differ by at most the velocity gravity gives in that time.
    """
    p = PAIRS[pair]
    c = pair_contacts(p)
    tolerance = 9.81 * (c.tau2 + c.tau12)
    lumped = MODELS[name](p).run(v0=SPEED, dx=0.25)
    icm = ICMBaseline.from_pair(p).run(v0=SPEED, dx=0.25)
    assert abs(lumped.v1 - icm.v1) < tolerance
    assert abs(lumped.v2 - icm.v2) < tolerance


@pytest.mark.parametrize("name", CONTACT_MODELS)
def test_light_body_far_apart_gives_eq_2_7(name):
    """mu -> 0 (1e-9) and a large gap, g = 0: eq. (2.7), ``v1 = (e2 + e12 (1 + e2)) |v0|``."""
    c = pair_contacts(PAIRS["basketball-table-tennis"])
    m1 = 1e-9 * c.m2
    model = {
        "two-spring-dashpot": TwoSpringDashpot(m1, c.m2, c.e2, c.e12, c.tau2, c.tau12),
        "bartz2020": Bartz2020.from_stiffness(m1, c.m2, c.k2, c.k12, c.e2, c.e12),
        "hertz-viscoelastic": HertzViscoelastic(m1, c.m2, c.e2, c.e12, c.tau2, c.tau12, SPEED),
    }[name]
    r = model.run(v0=SPEED, dx=0.5, g=0.0)
    k1, k2 = light_touching_limit(model.e2, model.e12)
    assert r.v1_ratio == pytest.approx(-k1, rel=1e-7)
    assert r.v2_ratio == pytest.approx(-k2, rel=1e-7)


def _light_body_on_spring(omega: float) -> tuple[float, float]:
    """First release (time, body velocity) of a massless body on an elastic spring, g = 0.

    Lower ball (unit mass, unit speed) on an elastic floor spring of unit frequency:
    ``z2 = -sin t`` until ``t = pi``, then ``z2 = t - pi``.  The overlap d of the body's
    spring (frequency omega) obeys ``d'' + omega^2 d = z2''`` with d(0) = d'(0) = 0:
    ``d = A (sin t - sin(omega t) / omega)``, ``A = 1 / (omega^2 - 1)``, until t = pi, a free
    oscillation after.  The body leaves when d returns to 0, at velocity ``z2' - d'``.
    """

    def overlap(t: float) -> tuple[float, float, float]:  # d, d', z2'
        a = 1.0 / (omega**2 - 1.0)
        if t <= math.pi:
            d = a * (math.sin(t) - math.sin(omega * t) / omega)
            return d, a * (math.cos(t) - math.cos(omega * t)), -math.cos(t)
        d0, r0, _ = overlap(math.pi)
        s = t - math.pi
        d = d0 * math.cos(omega * s) + r0 / omega * math.sin(omega * s)
        return d, -d0 * omega * math.sin(omega * s) + r0 * math.cos(omega * s), 1.0

    from scipy.optimize import brentq

    step = 1e-3 / omega
    t = step
    while overlap(t)[0] > 0.0:
        t += step
    release = brentq(lambda s: overlap(s)[0], t - step, t, xtol=1e-15)
    d, rate, ball = overlap(release)
    return release, ball - rate


@pytest.mark.parametrize("omega", [3.7, 10.6])
def test_light_body_touching_matches_spring_closed_form(omega):
    """mu -> 0, dx = 0, elastic, g = 0: the first release against the closed form above.

    omega = 10.6 releases before the lower ball leaves the floor, 3.7 after.
    """
    model = TwoSpringDashpot(1e-9, 1.0, 1.0, 1.0, math.pi, math.pi / omega)
    r = model.run(v0=1.0, dx=0.0, g=0.0)
    first = next(e for e in r.events if e.contact == "pair" and e.kind == "release")
    time, velocity = _light_body_on_spring(omega)
    assert first.time == pytest.approx(time, abs=1e-7)
    assert first.v1 == pytest.approx(velocity, abs=1e-7)


def test_bartz_elastic_equals_spring_model_elastic():
    """Two code paths, one physics: dimensionless Bartz2020 and SI TwoSpringDashpot, e = 1."""
    c = pair_contacts(PAIRS["basketball-tennis"])
    bartz = Bartz2020.from_stiffness(c.m1, c.m2, c.k2, c.k12, 1.0, 1.0).run(v0=SPEED, dx=0.003)
    spring = TwoSpringDashpot(c.m1, c.m2, 1.0, 1.0, c.tau2, c.tau12).run(v0=SPEED, dx=0.003)
    assert bartz.v1 == pytest.approx(spring.v1, rel=1e-8)
    assert bartz.v2 == pytest.approx(spring.v2, rel=1e-8)
    assert bartz.t_liftoff == pytest.approx(spring.t_liftoff, rel=1e-8)
    assert [e.kind for e in bartz.events] == [e.kind for e in spring.events]


def _same_springs_and_dashpots(e2: float, e12: float) -> tuple[Bartz2020, TwoSpringDashpot]:
    """Bartz2020 of basketball-tennis and the TwoSpringDashpot with the same k and c.

    TwoSpringDashpot is built from the (tau, e) that its force rule gives for those k, c
    (Schwager & Pöschel 2007: with ``q = zeta / sqrt(1 - zeta^2)`` the force vanishes at
    ``w t = pi - 2 arctan q``, ``e = exp(-q (pi - 2 arctan q))``, ``tau w0 = sqrt(1 + q^2)
    (pi - 2 arctan q)``).
    """
    c = pair_contacts(PAIRS["basketball-tennis"])
    bartz = Bartz2020.from_stiffness(c.m1, c.m2, c.k2, c.k12, e2, e12)
    force_rule = []
    for k, zeta, mass in ((c.k2, bartz.zeta2, c.m2), (c.k12, bartz.zeta12, c.reduced_mass)):
        q = zeta / math.sqrt(1.0 - zeta * zeta)
        angle = math.pi - 2.0 * math.atan(q)
        force_rule.append(
            (math.exp(-q * angle), math.sqrt(1 + q * q) * angle * math.sqrt(mass / k))
        )
    (ef, tf), (ep, tp) = force_rule
    spring = TwoSpringDashpot(c.m1, c.m2, ef, ep, tf, tp)
    for law, k, zeta, mass in (
        (spring.floor_law, c.k2, bartz.zeta2, c.m2),
        (spring.pair_law, c.k12, bartz.zeta12, c.reduced_mass),
    ):
        assert law.stiffness == pytest.approx(k, rel=1e-12)
        assert law.damping == pytest.approx(2.0 * zeta * math.sqrt(k * mass), rel=1e-12, abs=1e-12)
    return bartz, spring


def test_bartz_and_the_spring_dashpots_differ_by_their_end_of_contact_rule():
    """The same springs and dashpots, two rules: Bartz2020's contact lasts while the bodies
    overlap (the dashpot pulls at the end), TwoSpringDashpot's opens when the force vanishes.

    Isolated floor contact (g = 0, the body far away): Bartz restitutes the damped
    oscillator's ``exp(-pi zeta / sqrt(1 - zeta^2))``, the force rule
    ``exp(-q (pi - 2 arctan q))`` (closed forms); released at zero overlap, resp. with the
    spring still compressed.  Touching with gravity: different rebounds when damped, the
    same when elastic.
    """
    bartz, spring = _same_springs_and_dashpots(0.8, 0.6)
    zeta = bartz.zeta2
    q = zeta / math.sqrt(1.0 - zeta * zeta)
    for model, expected in (
        (bartz, math.exp(-math.pi * q)),
        (spring, math.exp(-q * (math.pi - 2.0 * math.atan(q)))),
    ):
        far = model.run(v0=SPEED, dx=1.0, g=0.0)
        release = next(e for e in far.events if e.contact == "floor" and e.kind == "release")
        assert release.v2 / SPEED == pytest.approx(expected, rel=1e-8)
    assert math.exp(-math.pi * q) == pytest.approx(0.8, rel=1e-12)  # Bartz: e2 as given
    assert math.exp(-q * (math.pi - 2.0 * math.atan(q))) > 0.805  # the force rule: livelier
    b_far = bartz.run(v0=SPEED, dx=1.0, g=0.0)
    s_far = spring.run(v0=SPEED, dx=1.0, g=0.0)
    releases = [e for e in b_far.events if e.kind == "release"]
    assert max(abs(e.overlap) for e in releases) < 1e-12
    assert all(e.overlap > 1e-6 for e in s_far.events if e.kind == "release")
    damped = bartz.run(v0=SPEED, dx=0.0), spring.run(v0=SPEED, dx=0.0)
    assert abs(damped[0].v1_ratio - damped[1].v1_ratio) > 1e-2
    bartz, spring = _same_springs_and_dashpots(1.0, 1.0)
    elastic = bartz.run(v0=SPEED, dx=0.0), spring.run(v0=SPEED, dx=0.0)
    assert elastic[0].v1 == pytest.approx(elastic[1].v1, rel=1e-8)
    assert elastic[0].v2 == pytest.approx(elastic[1].v2, rel=1e-8)


def test_bartz_shows_the_abstracts_delayed_rebound_below_the_icm():
    """Bartz (2020), abstract: a small first bounce followed by a higher second one, most
    commonly where the first bounce is below the ICM.  Found here (the paper's own examples
    could not be consulted): mu = 0.01, kappa = 1, zeta from e2 = 0.8 and e12 = 0.6, g = 0,
    gap 0.5 |v0| / w2: the body leaves upwards at 0.68 |v0|, is caught by the rising lower
    ball and leaves at 0.87 |v0|, both below eq. (2.5)'s 1.85."""
    zeta2 = -math.log(0.8) / math.sqrt(math.pi**2 + math.log(0.8) ** 2)  # e = exp(-pi q)
    zeta12 = -math.log(0.6) / math.sqrt(math.pi**2 + math.log(0.6) ** 2)
    model = Bartz2020(mu=0.01, kappa=1.0, zeta2=zeta2, zeta12=zeta12)
    r = model.run_dimensionless(0.5, 0.0)
    releases = [e.v1 for e in r.events if e.contact == "pair" and e.kind == "release"]
    assert len(releases) == 2 and r.delayed_rebound
    assert 0.6 < releases[0] < 0.75 and 0.8 < releases[1] < 0.95
    icm = (0.01 * -1.0 + 0.8 + 0.6 * (0.8 + 1.0)) / 1.01  # eq. (2.5), u1 = -1, u2 = e2
    assert icm == pytest.approx(1.8515, abs=1e-4)
    assert releases[0] < releases[1] < icm


def test_touching_differs_from_icm_and_large_gap_does_not():
    """dx = 0 lowers the body's rebound below (2.6) in every contact model; dx = 0.25 m does not."""
    p = PAIRS["basketball-table-tennis"]
    icm = ICMBaseline.from_pair(p)
    for name in CONTACT_MODELS:
        model = MODELS[name](p)
        touching = model.run(v0=SPEED, dx=0.0)
        assert touching.v1_ratio < icm.run(v0=SPEED).v1_ratio - 0.5
        apart = model.run(v0=SPEED, dx=0.25)
        assert apart.v1_ratio == pytest.approx(icm.run(v0=SPEED, dx=0.25).v1_ratio, abs=0.03)


def test_small_gap_gives_repeated_contacts():
    """Müller & Pöschel (2011) and Bartz (2020): several body-ball contacts at small gaps.

    Elastic contacts (mu = 0.01, kappa = 1, gap 0.05 |v0| / w2): three contacts, the
    body leaving the first with a downward velocity and rebounding at last.
    """
    r = Bartz2020(mu=0.01, kappa=1.0, zeta2=0.0, zeta12=0.0).run_dimensionless(0.05, 0.0)
    assert r.pair_contacts == 3
    assert r.first_release_v1 < 0.0 < r.v1
    assert r.delayed_rebound


def test_run_reports_events_in_order_and_the_liftoff_time():
    """Events are time-ordered; t_liftoff is the last pair release, v1 the body's velocity then."""
    r = TwoSpringDashpot.from_pair(PAIRS["tennis-table-tennis"]).run(drop_height=0.5, dx=0.0)
    times = [e.time for e in r.events]
    assert times == sorted(times)
    last = [e for e in r.events if e.contact == "pair" and e.kind == "release"][-1]
    assert (r.t_liftoff, r.v1) == (last.time, last.v1)
    assert r.v0 == pytest.approx(-math.sqrt(2 * 9.81 * 0.5))
    assert r.summary()["pair_contacts"] == r.pair_contacts


# -- input checks --------------------------------------------------------------------------


@pytest.mark.parametrize(
    ("build", "name"),
    [
        (lambda: TwoSpringDashpot(-1.0, 1.0, 0.5, 0.5, 0.01, 0.01), "m1"),
        (lambda: TwoSpringDashpot(1.0, 1.0, 1.5, 0.5, 0.01, 0.01), "e2"),
        (lambda: TwoSpringDashpot(1.0, 1.0, 0.5, LINEAR_FORCE_RULE_MIN_E, 0.01, 0.01), "e12"),
        (lambda: TwoSpringDashpot(1.0, 1.0, 0.5, 0.5, 0.0, 0.01), "tau2"),
        (lambda: Bartz2020(mu=0.1, kappa=-1.0, zeta2=0.1, zeta12=0.1), "kappa"),
        (lambda: Bartz2020(mu=0.1, kappa=1.0, zeta2=1.0, zeta12=0.1), "zeta2"),
        (lambda: HertzViscoelastic(0.1, 1.0, 0.5, 0.5, 0.01, 0.01, law="hunt"), "law"),
        (lambda: HertzViscoelastic(0.1, 1.0, 0.5, 0.5, 0.01, 0.01, speed=0.0), "speed"),
        (lambda: ICMBaseline(mu=-0.1, e2=0.5, e12=0.5), "mu"),
        (lambda: HertzLaw(1.0, 0.0, 0.25, tensile=True), "tensile"),
    ],
)
def test_models_refuse_bad_parameters(build, name):
    with pytest.raises(ParameterError) as info:
        build()
    assert info.value.name == name


@pytest.mark.parametrize(
    ("kwargs", "name"),
    [
        ({"v0": 1.0, "drop_height": 1.0}, "v0"),
        ({}, "v0"),
        ({"v0": 0.0}, "v0"),
        ({"v0": 1.0, "dx": -0.1}, "dx"),
        ({"v0": 1.0, "g": -1.0}, "g"),
        ({"drop_height": -1.0}, "drop_height"),
        ({"drop_height": 1.0, "g": 0.0}, "g"),
    ],
)
def test_run_refuses_bad_drops(kwargs, name):
    model = TwoSpringDashpot.from_pair(PAIRS["tennis-coin"])
    with pytest.raises(ParameterError) as info:
        model.run(**kwargs)
    assert info.value.name == name


def test_table1_rows_feed_every_model():
    """Every model builds from every pair and returns rebound ratios of the right sign."""
    assert len(PAIRS) == len(TABLE1)
    for pair in PAIRS.values():
        for name, build in MODELS.items():
            r = build(pair).run(v0=SPEED, dx=0.0)
            assert r.v1_ratio > 0.0 and r.v2_ratio > 0.0, (pair.name, name)
