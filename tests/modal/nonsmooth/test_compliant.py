"""Compliant rows (C1)-(C3) in the Moreau-Jean core against closed forms.

Independent values: the undamped linear contact's half period ``pi sqrt(m/k)``;
Hertz's contact time (H4) of :mod:`twoball.modal.solid.hertz`; the damped linear
law that never pulls, ``e = exp(-q (pi - 2 arctan q))`` and its duration
(Schwager & Pöschel 2007, :func:`~twoball.modal.lumped.fitting.linear_restitution`);
Tsuji's Hertz dashpot against the reduced equation integrated by DOP853
(:func:`~twoball.modal.lumped.fitting.hertz_restitution`); the books (the
discrete gradient: rounding); the parent's steps bit for bit without compliant
rows.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

import twoball
from twoball.modal.lumped.fitting import (
    _q_from_e,
    hertz_damping,
    hertz_restitution,
    linear_restitution,
)
from twoball.modal.nonsmooth import ContactProblem, MoreauJean
from twoball.modal.nonsmooth.compliant import CompliantMoreauJean, CompliantRow, PowerLaw
from twoball.modal.solid.hertz import hertz_contact_time


def _drop(law: PowerLaw, mass=1.0, speed=1.0, steps=200, update=None):
    """A mass hitting a rigid stop through ``law`` without gravity: (e, duration, books)."""
    problem = ContactProblem.create(
        np.array([mass]), None, np.zeros(1), np.zeros(1), np.ones((1, 1)), np.zeros(1)
    )
    tc = law.contact_time(mass, speed)
    stepper = CompliantMoreauJean(problem, tc / 10, [CompliantRow(0, law, tc / steps, update)])
    tr = stepper.run(np.zeros(1), np.array([-speed]), 2.0 * tc, keep_states=True)
    books = stepper.final_books()
    delta, rate = -tr.q[:, 0], -tr.v[:, 0]
    # the force's zero between step ends (linear in the force, or in delta)
    force = np.array([law.force(d) + law.dashpot(d) * r for d, r in zip(delta, rate, strict=True)])
    force = np.where(delta > 0.0, force, delta)
    j = int(np.flatnonzero(force > 0.0)[-1])
    share = force[j] / (force[j] - force[j + 1])
    duration = tr.t[j] + share * (tr.t[j + 1] - tr.t[j])
    last = int(np.flatnonzero(tr.impulse[:, 0] > 0.0)[-1]) + 1
    e = tr.v[last, 0] / speed
    energy = tr.energy + books["stored"] + books["dissipated"]
    works = tr.damping_work + tr.contact_work - books["work"] + tr.impact_work
    balance = float(np.max(np.abs(energy - energy[0] - works)))
    return e, duration, balance, books


def test_linear_law_half_period_and_no_loss():
    law = PowerLaw(4.0, 1.0)
    e, duration, balance, books = _drop(law, mass=2.0, speed=0.5)
    assert e == pytest.approx(1.0, abs=1e-12)
    assert duration == pytest.approx(math.pi * math.sqrt(2.0 / 4.0), rel=1e-4)
    assert balance < 1e-15 and abs(books["dissipated"][-1]) < 1e-15


@pytest.mark.parametrize("speed", [0.1, 1.0, 10.0])
def test_hertz_contact_time_is_the_closed_form(speed):
    """2.8683 (m^2 / (R E*^2 v))^(1/5): k = (4/3) E* sqrt(R), here E* = 3, R = 0.25."""
    modulus, radius, mass = 3.0, 0.25, 0.7
    law = PowerLaw(4.0 / 3.0 * modulus * math.sqrt(radius), 1.5)
    e, duration, balance, _ = _drop(law, mass=mass, speed=speed, steps=400)
    assert duration == pytest.approx(hertz_contact_time(mass, radius, modulus, speed), rel=1e-4)
    assert e == pytest.approx(1.0, abs=1e-12) and balance < 1e-14 * mass * speed**2


@pytest.mark.parametrize("e_target", [0.5, 0.83, 0.95])
def test_kelvin_voigt_restitution_and_duration(e_target):
    q = _q_from_e(e_target, tensile=False)
    zeta = q / math.sqrt(1.0 + q * q)
    law = PowerLaw(1.0, 1.0, 2.0 * zeta, 0.0)
    e, duration, balance, books = _drop(law)
    assert e == pytest.approx(e_target, abs=1e-4)
    assert duration == pytest.approx(linear_restitution(q, tensile=False)[1], rel=1e-3)
    assert balance < 1e-15
    dissipated = 0.5 * (1.0 - e * e)  # what the dashpot took
    assert books["dissipated"][-1] == pytest.approx(dissipated, rel=1e-12)


@pytest.mark.parametrize("e_target", [0.6, 0.9])
def test_tsuji_dashpot_restitution_and_duration(e_target):
    b = hertz_damping(e_target, 0.25)
    law = PowerLaw(1.0, 1.5, b, 0.25)
    e, duration, balance, _ = _drop(law, steps=400)
    e_ode, t_ode, _ = hertz_restitution(b, 0.25)
    assert e == pytest.approx(e_ode, abs=1e-4)
    assert duration == pytest.approx(t_ode, rel=1e-3)
    assert balance < 1e-15


def test_a_moving_row_keeps_the_books_and_the_momentum():
    """A row that changes with the compression (a disc): the gap stays continuous."""
    problem = ContactProblem.create(
        np.array([1.0, 3.0]), None, np.array([0.0, 2.0]), np.zeros(2),
        np.array([[1.0, -1.0]]), np.zeros(1),
    )  # fmt: skip
    law = PowerLaw(50.0, 1.5, 0.5, 0.25)

    def update(delta):
        weight = 1.0 - 0.3 * min(delta, 1.0)  # the second body's share moves with delta
        return np.array([1.0, -weight]), delta

    stepper = CompliantMoreauJean(problem, 0.01, [CompliantRow(0, law, 0.002, update)])
    tr = stepper.run(np.zeros(2), np.array([-1.0, 0.2]), 3.0, keep_states=True)
    books = stepper.final_books()
    energy = tr.energy + books["stored"] + books["dissipated"]
    works = tr.damping_work + tr.contact_work - books["work"] + tr.impact_work
    assert np.max(np.abs(energy - energy[0] - works)) < 1e-14
    assert np.any(books["drift"] != 0.0)
    assert books["dissipated"][-1] > 0.0


def test_without_compliant_rows_the_parent_steps_bit_for_bit():
    rng = np.random.default_rng(3)
    G = rng.normal(size=(4, 6))
    args = (np.ones(6), 0.1 * np.ones(6), np.arange(6.0), -np.ones(6), G, np.full(4, 0.5))
    problem = ContactProblem.create(*args)
    q0, v0 = np.zeros(6), rng.normal(size=6)
    a = MoreauJean(problem, 0.01).run(q0, v0, 2.0)
    b = CompliantMoreauJean(ContactProblem.create(*args), 0.01, []).run(q0, v0, 2.0)
    np.testing.assert_array_equal(a.q, b.q)
    np.testing.assert_array_equal(a.impulse, b.impulse)


def test_refusals():
    problem = ContactProblem.create(np.ones(1), None, np.zeros(1), None, np.ones((1, 1)), [0.0])
    law = PowerLaw(1.0)
    with pytest.raises(twoball.ParameterError, match="theta"):
        CompliantMoreauJean(problem, 0.1, [CompliantRow(0, law, 0.01)], theta=0.6)
    with pytest.raises(twoball.ParameterError, match="rows"):
        CompliantMoreauJean(problem, 0.1, [CompliantRow(3, law, 0.01)])
    with pytest.raises(twoball.ParameterError, match="damping_power"):
        PowerLaw(1.0, 1.0, 1.0, 1.0)
    with pytest.raises(twoball.ParameterError, match="substep"):
        CompliantRow(0, law, 0.0)


def test_the_bracketed_fallback_gives_newtons_answer(monkeypatch):
    """With Newton's iteration cut off, Illinois' regula falsi on the impulse takes over."""
    import twoball.modal.nonsmooth.compliant as compliant

    problem = ContactProblem.create(
        np.array([1.0, 2.0]), None, np.array([0.0, 3.0]), np.array([0.0, -0.5]),
        np.array([[0.0, 1.0], [1.0, -1.0]]), np.zeros(2),
    )  # fmt: skip
    law = PowerLaw(40.0, 1.5, 1.0, 0.25)
    q0, v0 = np.zeros(2), np.array([-1.0, 0.0])

    def run():
        stepper = CompliantMoreauJean(problem, 0.01, [CompliantRow(1, law, 0.002)])
        return stepper.run(q0, v0, 1.5, keep_states=True), stepper.final_books()

    newton, _ = run()
    monkeypatch.setattr(compliant, "_NEWTON", 0)
    falsi, books = run()
    np.testing.assert_allclose(falsi.q[-1], newton.q[-1], atol=1e-9)
    assert np.any(falsi.impulse[:, 1] > 0.0) and np.any(falsi.impulse[:, 0] > 0.0)
    energy = falsi.energy + books["stored"] + books["dissipated"]
    works = falsi.damping_work + falsi.contact_work - books["work"] + falsi.impact_work
    assert np.max(np.abs(energy - energy[0] - works)) < 1e-14
