"""Impacts of the independent collision model (modal/icm/impacts.py), §2, against hand values."""

from __future__ import annotations

import math

import pytest

from twoball._common.errors import ParameterError
from twoball.modal.icm import (
    icm,
    impact_time,
    impact_velocity,
    light_touching_limit,
    max_separation,
    post_impact_velocities,
    rebound_velocity,
    second_impact_delay,
    touching_limit,
    touching_ratios,
)
from twoball.modal.parameters import STANDARD_GRAVITY


def test_impact_closed_forms_hand_values():
    assert impact_velocity(4.905, 9.81) == pytest.approx(-9.81, rel=1e-14)
    assert impact_time(4.905, 9.81) == pytest.approx(1.0, rel=1e-14)
    assert rebound_velocity(4.905, 0.5, 9.81) == pytest.approx(4.905, rel=1e-14)
    # H = 1 m with the default gravity: sqrt(19.62) and sqrt(2 / 9.81).
    assert impact_velocity(1.0) == pytest.approx(-4.429446918070020, rel=1e-14)
    assert impact_time(1.0) == pytest.approx(0.451523640985731, rel=1e-14)
    assert STANDARD_GRAVITY == 9.81


def test_second_impact_delay_hand_value():
    assert second_impact_delay(1.4715, 4.905, 0.5, 9.81) == pytest.approx(0.1, rel=1e-13)
    assert second_impact_delay(0.0, 4.905, 0.5, 9.81) == 0.0
    # Linear in dx.
    assert second_impact_delay(0.7, 1.0, 0.8) == pytest.approx(
        7 * second_impact_delay(0.1, 1.0, 0.8), rel=1e-13
    )


def test_post_impact_velocities_hand_values():
    v1, v2 = post_impact_velocities(-10.791, 3.924, 0.25, 0.6)
    assert v1 == pytest.approx(8.0442, rel=1e-12)
    assert v2 == pytest.approx(-0.7848, rel=1e-12)
    # Equal masses, elastic: the velocities are exchanged.
    v1, v2 = post_impact_velocities(-3.0, 2.0, 1.0, 1.0)
    assert (v1, v2) == pytest.approx((2.0, -3.0), abs=1e-15)
    # Perfectly plastic: common velocity = centre-of-mass velocity.
    v1, v2 = post_impact_velocities(-3.0, 2.0, 0.5, 0.0)
    assert v1 == pytest.approx(v2, abs=1e-15)
    assert v1 == pytest.approx((0.5 * -3.0 + 2.0) / 1.5, rel=1e-15)


def test_max_separation():
    assert max_separation(1.0, 0.5) == pytest.approx(3.0, rel=1e-15)
    assert max_separation(2.0, 0.0) == 0.0
    # At the bound the lower ball is just back on the floor: u2 = -u0.
    h, e2 = 0.6, 0.7
    r = icm(0.1, e2, 0.5, dx=max_separation(h, e2) * (1 - 1e-12), drop_height=h)
    assert r.u2 == pytest.approx(-r.u0, rel=1e-9)


@pytest.mark.parametrize(
    "call,flag",
    [
        (lambda: impact_velocity(-1.0), "drop_height"),
        (lambda: impact_velocity(1.0, g=0.0), "g"),
        (lambda: impact_time(0.0), "drop_height"),
        (lambda: impact_time(1.0, g=-1.0), "g"),
        (lambda: rebound_velocity(1.0, 2.0), "e2"),
        (lambda: rebound_velocity(0.0, 0.5), "drop_height"),
        (lambda: max_separation(1.0, -0.1), "e2"),
        (lambda: max_separation(-1.0, 0.5), "drop_height"),
        (lambda: second_impact_delay(-0.1, 1.0, 0.5), "dx"),
        (lambda: second_impact_delay(10.0, 1.0, 0.5), "dx"),
        (lambda: second_impact_delay(0.1, 1.0, 1.5), "e2"),
        (lambda: second_impact_delay(0.1, 0.0, 0.5), "drop_height"),
        (lambda: post_impact_velocities(-1.0, 1.0, -1.0, 0.5), "mu"),
        (lambda: post_impact_velocities(-1.0, 1.0, 0.1, 1.1), "e12"),
        (lambda: touching_limit(-0.1, 0.5, 0.5), "mu"),
        (lambda: touching_limit(0.1, 1.5, 0.5), "e2"),
        (lambda: touching_limit(0.1, 0.5, -0.5), "e12"),
        (lambda: touching_ratios(math.nan, 0.5, 0.5), "mu"),
        (lambda: light_touching_limit(1.2, 0.5), "e2"),
        (lambda: light_touching_limit(0.5, 1.2), "e12"),
    ],
)
def test_helpers_reject(call, flag):
    with pytest.raises(ParameterError) as info:
        call()
    assert info.value.name == flag
