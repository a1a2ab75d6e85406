"""The ball dropped on the floor (modal/floor_prototype.py) on the nonsmooth contact core.

Impulse and energy balances, orders in the time step and in N, the resting ball,
and a body on top against the event-driven solver of :mod:`twoball.modal.contact`.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from twoball.modal.floor_prototype import FloorModel, drop, settle
from twoball.modal.nonsmooth import ContactProblem, MoreauJean
from twoball.verify.studies.orders import OrderBand, least_squares_order


@pytest.mark.parametrize(
    "model",
    [
        FloorModel(modes=20, points=10, damping=0.13),
        FloorModel(modes=20, points=10, damping=0.0),
        FloorModel(modes=20, points=10, operator="paper", damping=0.13),
        FloorModel(modes=20, points=10, rayleigh=(0.47, 0.012)),
    ],
    ids=["pressurised-D", "pressurised-undamped", "paper", "rayleigh"],
)
def test_floor_impulse_and_energy_balance(model):
    """Floor impulse = m2 (v2 + |v0|) + weight impulse to 1e-10; energy books close to rounding."""
    r = drop(model, 0.02)
    assert r.impulse_balance < 1e-10
    assert r.energy_error < 1e-12
    assert 0.0 < r.e2 < 1.0
    assert r.energy_lost_impacts > 0.0
    # contact time of the order of pi (pressure x area spring) and flattening of v0 (units R)
    assert math.pi < r.contact_time < 2.0 * math.pi
    assert model.v0 < r.flattening_max < 2.0 * model.v0
    if model.damping == 0.0 and model.rayleigh is None:
        assert r.energy_damped == 0.0
        # what the floor did not take is in the flight and the vibration
        assert r.e2**2 + r.final_vibration + r.energy_lost_impacts == pytest.approx(1.0, abs=0.05)


def test_floor_time_step_orders():
    """Second order in dt for the flattening and the impact loss (N = 20; reference dt/8)."""
    model = FloorModel(modes=20, points=10, damping=0.13)
    ref = drop(model, 0.00125)
    steps = (0.04, 0.02, 0.01)
    runs = [drop(model, dt) for dt in steps]
    for name in ("flattening_max", "energy_lost_impacts"):
        errors = [abs(getattr(r, name) - getattr(ref, name)) for r in runs]
        order = least_squares_order(steps, errors).order
        assert OrderBand(2.0, 0.35, 0.35).contains(order), (name, order)
    assert abs(runs[-1].e2 - ref.e2) < 1e-5
    assert abs(runs[-1].contact_time - ref.contact_time) < 1e-4


def test_floor_modes_order_of_restitution():
    """e2 converges in N at order 2: ``log2`` of successive differences over N = 20, 40, 80."""
    values = [drop(FloorModel(modes=n, points=n // 2, damping=0.13), 0.02).e2 for n in (20, 40, 80)]
    order = math.log2((values[1] - values[0]) / (values[2] - values[1]))
    assert OrderBand(2.0, 0.35, 0.35).contains(order), order


def test_paper_operator_without_gas_keeps_the_energy_in_the_breathing_mode():
    """omega_0 = 0: the floor's push shrinks the ball for good, and it does not bounce."""
    r = drop(FloorModel(modes=20, points=10, operator="paper", gas=0.0, damping=0.13), 0.02)
    assert r.impulse_balance < 1e-10
    assert r.e2 < 0.1
    assert r.final_vibration > 0.5


def test_resting_ball_carries_its_weight():
    """Settled under gravity with damping: the floor force equals the weight."""
    r = settle(FloorModel(modes=60, points=30, damping=0.9))
    assert r.residual_speed < 1e-12
    assert r.floor_force == pytest.approx(r.weight, rel=1e-9)


@pytest.mark.slow
@pytest.mark.parametrize("modes", [240, 360, 480])
def test_resting_contact_brackets_pressure_times_area(modes):
    """The contact set lies between the caps through the last point in contact and the next
    point out; from N = 240 on that bracket holds m2 g / P (pressure x area), and it narrows
    like 1/N."""
    r = settle(FloorModel(modes=modes, points=modes // 2, damping=0.9))
    assert r.floor_force == pytest.approx(r.weight, rel=1e-9)
    inner, outer = r.contact_area
    assert inner <= r.pressure_area <= outer
    assert outer - inner < 0.8 * r.pressure_area * 240 / modes


def test_rigid_body_on_top_matches_the_event_driven_solver():
    """A body (mass ratio 0.05) on the paper's membrane, started at maximal compression
    (phi_a = 2.6, no floor): the core reproduces the closed-form event-driven solver of
    :mod:`twoball.modal.contact` (same modes, one constraint ``s - b . q >= 0``)."""
    from twoball.modal.contact.events import integrate
    from twoball.modal.contact.system import ContactSystem
    from twoball.modal.floor_prototype import lift_off_time
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
    t_l, _ = lift_off_time(tr.t, tr.impulse - tr.impact_impulse, tr.impact_impulse)
    velocity = tr.v_final[-1] + gamma * (tr.t[-1] - t_l)  # free flight after lift-off
    assert history.lifted
    assert velocity == pytest.approx(history.velocity, rel=2e-4)
    assert t_l == pytest.approx(history.t, abs=2e-3)
