"""The Legendre contact solution (modal/contact/report.py) of a body of finite mass."""

from __future__ import annotations

import math

import numpy as np
import pytest
from twoball.modal.parameters import Case

import twoball
from twoball import Body
from twoball._common.errors import ParameterError

BASKETBALL = Case.preset("basketball")


def test_massless_mode_recovers_todays_pole_result():
    """mu = 0 on a cap of a = 1e-5 m: the paper's criteria on the cap = today's pole result."""
    today = twoball.liftoff(BASKETBALL)
    massless = twoball.liftoff(BASKETBALL, body=Body(0.0, contact_radius=1e-5))
    assert massless.t_liftoff_s == pytest.approx(today.t_liftoff_s, rel=1e-4)
    assert massless.v_liftoff_m_s == pytest.approx(today.v_liftoff_m_s, rel=1e-4)


def test_energy_option_both_deforms_more():
    ball = twoball.liftoff(BASKETBALL, body=Body(0.1))
    both = twoball.liftoff(BASKETBALL, body=Body(0.1, energy="both"))
    assert both.as_dict()["phi_a_rad"] < ball.as_dict()["phi_a_rad"]  # eq. (3.7) at larger v0


def test_converges_in_modes_at_second_order():
    """a = R/10, mu = 0.101: v1(N) converges like N^-2 (the Lanczos filter); band 1.6-2.6."""
    v = {}
    for modes in (30, 60, 120):
        case = BASKETBALL.derive(modes=modes)
        v[modes] = twoball.liftoff(case, body=Body(0.101, contact_radius=0.012)).v_liftoff_m_s
    order = math.log2(abs(v[60] - v[30]) / abs(v[120] - v[60]))
    assert 1.6 < order < 2.6


def test_event_grid_does_not_change_the_result():
    """The events are exact roots: 16, 32 or 64 grid points per period give the same v1."""
    from twoball.modal.contact.report import legendre_contact

    body = Body(0.101, contact_radius=0.012)
    v = [legendre_contact(BASKETBALL, body, samples_per_period=n).v_liftoff_m_s for n in (16, 64)]
    assert v[0] == pytest.approx(v[1], rel=1e-10)


def test_trajectory_follows_the_events():
    """The sampled path: gap >= 0, body on the cap in contact phases, event values hit."""
    report = twoball.liftoff(BASKETBALL, body=Body(0.004))
    data = report.trajectory_si(400)
    gap = data["body_height_m"] - data["cap_displacement_m"]
    assert gap.min() > -1e-12 * BASKETBALL.radius
    on = data["contact"]
    assert on.any() and (~on).any()
    np.testing.assert_allclose(gap[on], 0.0, atol=1e-12 * BASKETBALL.radius)
    final = report.events_si()[-1]
    after = data["t_s"] > final["t_s"]
    t = data["t_s"][after] - final["t_s"]
    g = BASKETBALL.g
    expected = final["height_m"] + final["velocity_m_s"] * t - 0.5 * g * t * t
    np.testing.assert_allclose(data["body_height_m"][after], expected, rtol=1e-9, atol=1e-12)


@pytest.mark.parametrize("mass_ratio", [0.0, 0.1])
def test_a_body_on_a_stiff_ball_is_refused_not_solved_as_a_membrane(mass_ratio):
    """The contact system holds the membrane's modes only: bending or gas would be dropped."""
    with pytest.raises(ParameterError, match="mass_ratio.*bending or gas"):
        twoball.liftoff(Case.preset("tennis"), body=Body(mass_ratio))
    with pytest.raises(ParameterError, match="mass_ratio.*bending or gas"):
        twoball.sweep({"mass_ratio": [0.01]}, Case.preset("volleyball"))
