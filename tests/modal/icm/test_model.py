"""The independent collision model (modal/icm/model.py), §2: hand values, limits, conservation."""

from __future__ import annotations

import dataclasses
import math

import numpy as np
import pytest

from twoball._common.errors import ParameterError
from twoball.modal.icm import (
    ICMResult,
    icm,
    light_touching_limit,
    touching_limit,
)

# A hand-worked case.  With g = 9.81 and H = g / 2 the impact speed is
# |v0| = g = 9.81 m/s and t0 = 1 s.  e2 = 0.5: u0 = 4.905 m/s.
# dx = 0.1 * (1 + e2) * |v0| = 1.4715 m: dt = 0.1 s, t1 = 1.1 s.
# u1 = -g t1 = -10.791, u2 = u0 - g dt = 3.924.
# mu = 0.25, e12 = 0.6:
#   v1 = (0.25 * -10.791 + 3.924 + 0.6 * 14.715) / 1.25 = 10.05525 / 1.25 = 8.0442
#   v2 = (0.25 * -10.791 + 3.924 - 0.25 * 0.6 * 14.715) / 1.25 = -0.981 / 1.25 = -0.7848
HAND = dict(mu=0.25, e2=0.5, e12=0.6, dx=1.4715, drop_height=4.905, g=9.81)
CASES = [
    (0.25, 0.5, 0.6, 1.4715, 4.905),
    (0.101, 0.80, 0.89, 0.05, 1.0),
    (3.0, 0.7, 0.2, 0.3, 0.4),
    (0.0, 0.9, 0.5, 0.01, 2.0),
    (1.0, 1.0, 0.0, 0.0, 1.0),
]


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
