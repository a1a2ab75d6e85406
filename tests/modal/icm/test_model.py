"""Tests of the independent collision model, twoball.modal.icm (§2 and Table 1)."""

from __future__ import annotations

import dataclasses
import math

import numpy as np
import pytest
from twoball.modal.icm import (
    TABLE1,
    ICMResult,
    icm,
    impact_time,
    impact_velocity,
    light_touching_limit,
    max_separation,
    post_impact_velocities,
    rebound_velocity,
    round_significant,
    second_impact_delay,
    table1_check,
    touching_limit,
    touching_ratios,
)
from twoball.modal.parameters import STANDARD_GRAVITY

from twoball._common.errors import ParameterError

# A hand-worked case.  With g = 9.81 and H = g / 2 the impact speed is
# |v0| = g = 9.81 m/s and t0 = 1 s.  e2 = 0.5: u0 = 4.905 m/s.
# dx = 0.1 * (1 + e2) * |v0| = 1.4715 m: dt = 0.1 s, t1 = 1.1 s.
# u1 = -g t1 = -10.791, u2 = u0 - g dt = 3.924.
# mu = 0.25, e12 = 0.6:
#   v1 = (0.25 * -10.791 + 3.924 + 0.6 * 14.715) / 1.25 = 10.05525 / 1.25 = 8.0442
#   v2 = (0.25 * -10.791 + 3.924 - 0.25 * 0.6 * 14.715) / 1.25 = -0.981 / 1.25 = -0.7848
HAND = dict(mu=0.25, e2=0.5, e12=0.6, dx=1.4715, drop_height=4.905, g=9.81)


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


def test_icm_hand_values():
    r = icm(**HAND)
    assert isinstance(r, ICMResult)
    assert r.v0 == pytest.approx(-9.81, rel=1e-14)
    assert r.u0 == pytest.approx(4.905, rel=1e-14)
    assert r.t0 == pytest.approx(1.0, rel=1e-14)
    assert r.dt == pytest.approx(0.1, rel=1e-13)
    assert r.t1 == pytest.approx(1.1, rel=1e-13)
    assert r.u1 == pytest.approx(-10.791, rel=1e-13)
    assert r.u2 == pytest.approx(3.924, rel=1e-13)
    assert r.v1 == pytest.approx(8.0442, rel=1e-12)
    assert r.v2 == pytest.approx(-0.7848, rel=1e-12)
    assert r.v1_ratio == pytest.approx(8.0442 / 9.81, rel=1e-12)
    assert r.v2_ratio == pytest.approx(-0.7848 / 9.81, rel=1e-12)
    assert (r.mu, r.e2, r.e12, r.dx, r.drop_height, r.g) == tuple(
        HAND[k] for k in ("mu", "e2", "e12", "dx", "drop_height", "g")
    )


def test_result_is_frozen():
    r = icm(0.1, 0.8, 0.9)
    with pytest.raises(dataclasses.FrozenInstanceError):
        r.v1 = 0.0  # type: ignore[misc]


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


def test_touching_limit_hand_values():
    # mu = 0.25, e2 = 0.5, e12 = 0.6:
    # k1 = (0.25 - 0.5 - 0.9) / 1.25 = -0.92, k2 = (0.25 - 0.5 + 0.225) / 1.25 = -0.02.
    k1, k2 = touching_limit(0.25, 0.5, 0.6)
    assert k1 == pytest.approx(-0.92, rel=1e-14)
    assert k2 == pytest.approx(-0.02, rel=1e-12)
    assert touching_ratios(0.25, 0.5, 0.6) == pytest.approx((0.92, 0.02), rel=1e-12)
    # Table 1 row 1 by hand: (0.062 - 0.83 - 0.46 * 1.83) / 1.062 = -1.6098 / 1.062.
    k1, _ = touching_limit(0.062, 0.83, 0.46)
    assert k1 == pytest.approx(-1.6098 / 1.062, rel=1e-14)


def test_light_touching_limit_hand_values():
    assert light_touching_limit(0.5, 0.6) == pytest.approx((-1.4, -0.5), rel=1e-14)
    assert light_touching_limit(0.0, 0.0) == (0.0, -0.0)


@pytest.mark.parametrize("mu,e2,e12", [(0.25, 0.5, 0.6), (0.062, 0.83, 0.46), (2.0, 1.0, 0.3)])
def test_zero_separation_equals_touching_limit(mu, e2, e12):
    r = icm(mu, e2, e12, dx=0.0, drop_height=0.7)
    k1, k2 = touching_limit(mu, e2, e12)
    assert r.v1 == pytest.approx(k1 * r.v0, rel=1e-13)
    assert r.v2 == pytest.approx(k2 * r.v0, rel=1e-13)
    assert r.dt == 0.0
    assert r.t1 == r.t0


@pytest.mark.parametrize("mu,e2,e12", [(0.25, 0.5, 0.6), (0.101, 0.80, 0.89), (0.004, 0.9, 0.56)])
def test_small_separation_approaches_eq_2_6(mu, e2, e12):
    k1, k2 = touching_limit(mu, e2, e12)
    errors = []
    for dx in (1e-1, 1e-2, 1e-3, 1e-4, 1e-5):
        r = icm(mu, e2, e12, dx=dx, drop_height=1.0)
        errors.append((abs(r.v1 - k1 * r.v0), abs(r.v2 - k2 * r.v0)))
    errors = np.array(errors)
    assert errors[-1].max() < 1e-4
    # First order in dx: each tenfold reduction of dx cuts the error tenfold.
    ratios = errors[:-1] / errors[1:]
    assert ratios == pytest.approx(10.0, rel=1e-6)


def test_small_separation_exact_offset():
    # Both balls lose g dt between the impacts, so the post-impact velocities
    # are the touching values shifted by -g dt (momentum and restitution are
    # Galilean invariant).
    mu, e2, e12, h = 0.101, 0.80, 0.89, 1.0
    k1, k2 = touching_limit(mu, e2, e12)
    r = icm(mu, e2, e12, dx=0.03, drop_height=h)
    assert r.v1 == pytest.approx(k1 * r.v0 - r.g * r.dt, rel=1e-13)
    assert r.v2 == pytest.approx(k2 * r.v0 - r.g * r.dt, rel=1e-13)


@pytest.mark.parametrize("e2,e12", [(0.5, 0.6), (0.83, 0.46), (1.0, 1.0), (0.0, 0.3)])
def test_small_mass_ratio_approaches_eq_2_7(e2, e12):
    target = np.array(light_touching_limit(e2, e12))
    assert np.array(touching_limit(0.0, e2, e12)) == pytest.approx(target, abs=1e-15)
    errors = []
    for mu in (1e-2, 1e-3, 1e-4, 1e-5):
        errors.append(np.abs(np.array(touching_limit(mu, e2, e12)) - target).max())
    assert errors[-1] < 1e-4
    assert all(a > b for a, b in zip(errors[:-1], errors[1:], strict=True))
    # And through the full model with dx = 0.
    r = icm(0.0, e2, e12, dx=0.0, drop_height=0.5)
    assert (r.v1, r.v2) == pytest.approx(tuple(target * r.v0), rel=1e-13, abs=1e-15)


def test_elastic_classic_three_times_nine_heights():
    h = 0.8
    r = icm(0.0, 1.0, 1.0, dx=0.0, drop_height=h)
    assert r.v1 == pytest.approx(-3.0 * r.v0, rel=1e-14)
    assert r.v2 == pytest.approx(-r.v0, rel=1e-14)
    assert r.v1_ratio == pytest.approx(3.0, rel=1e-14)
    assert r.v1**2 / (2.0 * r.g) == pytest.approx(9.0 * h, rel=1e-13)
    # A very light upper ball approaches the same limit.
    r = icm(1e-9, 1.0, 1.0, dx=0.0, drop_height=h)
    assert r.v1_ratio == pytest.approx(3.0, rel=1e-8)
    assert light_touching_limit(1.0, 1.0) == (-3.0, -1.0)


CASES = [
    (0.25, 0.5, 0.6, 1.4715, 4.905),
    (0.101, 0.80, 0.89, 0.05, 1.0),
    (3.0, 0.7, 0.2, 0.3, 0.4),
    (0.0, 0.9, 0.5, 0.01, 2.0),
    (1.0, 1.0, 0.0, 0.0, 1.0),
]


@pytest.mark.parametrize("mu,e2,e12,dx,h", CASES)
def test_momentum_always_conserved(mu, e2, e12, dx, h):
    r = icm(mu, e2, e12, dx=dx, drop_height=h)
    # In units of m2: mu u1 + u2 = mu v1 + v2, eq. (2.3).
    assert mu * r.u1 + r.u2 == pytest.approx(mu * r.v1 + r.v2, rel=1e-13, abs=1e-13)
    # Restitution law, eq. (2.4).
    assert r.v2 - r.v1 == pytest.approx(e12 * (r.u1 - r.u2), rel=1e-13, abs=1e-13)


@pytest.mark.parametrize("mu,e2,e12,dx,h", CASES)
def test_energy_conserved_when_elastic(mu, e2, e12, dx, h):
    r = icm(mu, e2, 1.0, dx=dx, drop_height=h)
    before = mu * r.u1**2 + r.u2**2
    after = mu * r.v1**2 + r.v2**2
    assert after == pytest.approx(before, rel=1e-13)
    # Otherwise the loss (in units of m2 / 2) is mu / (1 + mu) (1 - e12^2) (u1 - u2)^2.
    r = icm(mu, e2, e12, dx=dx, drop_height=h)
    loss = (mu * r.u1**2 + r.u2**2) - (mu * r.v1**2 + r.v2**2)
    expected = mu / (1 + mu) * (1 - e12**2) * (r.u1 - r.u2) ** 2
    assert loss == pytest.approx(expected, rel=1e-12, abs=1e-12)


def test_max_separation():
    assert max_separation(1.0, 0.5) == pytest.approx(3.0, rel=1e-15)
    assert max_separation(2.0, 0.0) == 0.0
    # At the bound the lower ball is just back on the floor: u2 = -u0.
    h, e2 = 0.6, 0.7
    r = icm(0.1, e2, 0.5, dx=max_separation(h, e2) * (1 - 1e-12), drop_height=h)
    assert r.u2 == pytest.approx(-r.u0, rel=1e-9)


# ---------------------------------------------------------------------------
# Table 1
# ---------------------------------------------------------------------------


def test_table1_data_complete():
    assert len(TABLE1) == 6
    assert [(r.lower, r.upper) for r in TABLE1] == [
        ("Tennis", "Coin"),
        ("Tennis", "Nut"),
        ("Tennis", "Table tennis"),
        ("Basketball", "Tennis"),
        ("Basketball", "Tissue"),
        ("Basketball", "Table tennis"),
    ]
    assert TABLE1[3].mu == 0.101 and TABLE1[3].measured_v2 == 0.61


@pytest.mark.parametrize("index", [1, 2, 3])
def test_table1_rows_1_to_3_match(index):
    c = table1_check()[index - 1]
    assert c.index == index
    assert not c.differs
    assert c.v1_rounded == c.row.icm_v1
    assert c.v2_rounded == c.row.icm_v2


def test_table1_findings_rows_4_to_6():
    checks = table1_check()
    flags = [(c.v1_differs, c.v2_differs) for c in checks]
    assert flags == [
        (False, False),
        (False, False),
        (False, False),
        (False, True),
        (True, True),
        (True, True),
    ]
    rounded = [(c.v1_rounded, c.v2_rounded) for c in checks[3:]]
    assert rounded == [(2.1, 0.49), (2.0, 0.89), (2.0, 0.88)]
    assert checks[3].v2_difference == pytest.approx(-0.072, abs=5e-4)
    assert checks[4].v1_difference == pytest.approx(0.152, abs=5e-4)
    assert checks[5].v1_difference == pytest.approx(0.125, abs=5e-4)


def test_table1_normalisation_is_impact_speed():
    # Dividing by |u0| = e2 |v0| instead (the header's wording) misses rows 1-3.
    for c in table1_check()[:3]:
        e2 = c.row.e2
        assert round_significant(c.v1 / e2) != c.row.icm_v1
        assert round_significant(c.v2 / e2) != c.row.icm_v2


def test_round_significant():
    assert round_significant(1.5158) == 1.5
    assert round_significant(0.48788) == 0.49
    assert round_significant(1.9522) == 2.0
    assert round_significant(-0.0123456, 3) == -0.0123
    assert round_significant(0.0) == 0.0
    with pytest.raises(ParameterError):
        round_significant(1.0, 0)


# ---------------------------------------------------------------------------
# validation
# ---------------------------------------------------------------------------

GOOD = dict(mu=0.1, e2=0.8, e12=0.9, dx=0.01, drop_height=1.0, g=9.81)

BAD = [
    ("mu", "mu", -0.1),
    ("mu", "mu", math.nan),
    ("mu", "mu", math.inf),
    ("mu", "mu", "heavy"),
    ("e2", "e2", -0.01),
    ("e2", "e2", 1.01),
    ("e2", "e2", math.nan),
    ("e2", "e2", None),
    ("e12", "e12", -0.5),
    ("e12", "e12", 1.5),
    ("e12", "e12", math.nan),
    ("dx", "dx", -1e-3),
    ("dx", "dx", math.nan),
    ("dx", "dx", math.inf),
    ("dx", "dx", 100.0),  # beyond 4 e2 (1 + e2) H = 5.76 m
    ("drop_height", "drop_height", 0.0),
    ("drop_height", "drop_height", -1.0),
    ("drop_height", "drop_height", math.inf),
    ("drop_height", "drop_height", math.nan),
    ("g", "g", 0.0),
    ("g", "g", -9.81),
    ("g", "g", math.nan),
]


@pytest.mark.parametrize("key,flag,value", BAD)
def test_icm_rejects(key, flag, value):
    kwargs = dict(GOOD, **{key: value})
    with pytest.raises(ParameterError) as info:
        icm(**kwargs)
    err = info.value
    assert err.name == flag
    assert isinstance(err, ValueError)
    assert flag in str(err)
    assert err.valid in str(err)
    if value is not None:
        assert err.got is not None


def test_icm_accepts_boundaries():
    icm(0.0, 0.0, 0.0, dx=0.0, drop_height=1e-9)
    icm(1e6, 1.0, 1.0, dx=0.0, drop_height=1.0)


def test_e2_zero_needs_touching_balls():
    # The lower ball does not bounce, so a gap never closes in flight.
    with pytest.raises(ParameterError) as info:
        icm(0.1, 0.0, 0.5, dx=1e-6)
    assert info.value.name == "dx"


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
