"""The Table 1 pair presets of twoball.modal.pairs and the contact data derived from them."""

from __future__ import annotations

import math

import pytest

from twoball._common.errors import ParameterError
from twoball.modal.icm import TABLE1
from twoball.modal.lumped.pair_inputs import pair_contacts
from twoball.modal.pairs import BODIES, PAIRS, pair
from twoball.modal.presets import MEASURED
from twoball.modal.scalings import wave_speed_from_pressure

# Table 1 as printed (the paper, §4): lower ball, upper body, mu, e2, e12.
PRINTED = [
    ("tennis-coin", "Tennis", "Coin", 0.062, 0.83, 0.46),
    ("tennis-nut", "Tennis", "Nut", 0.035, 0.83, 0.41),
    ("tennis-table-tennis", "Tennis", "Table tennis", 0.050, 0.83, 0.59),
    ("basketball-tennis", "Basketball", "Tennis", 0.101, 0.80, 0.89),
    ("basketball-tissue", "Basketball", "Tissue", 0.004, 0.90, 0.56),
    ("basketball-table-tennis", "Basketball", "Table tennis", 0.005, 0.90, 0.60),
]


def test_six_pairs_in_table_order():
    assert [p.name for p in PAIRS.values()] == [row[0] for row in PRINTED]
    assert [p.row for p in PAIRS.values()] == [1, 2, 3, 4, 5, 6]


@pytest.mark.parametrize(("name", "lower", "upper", "mu", "e2", "e12"), PRINTED)
def test_pair_carries_its_table1_row(name, lower, upper, mu, e2, e12):
    p = PAIRS[name]
    assert (p.mu, p.e2, p.e12) == (mu, e2, e12)
    assert (p.table1.lower, p.table1.upper) == (lower, upper)
    assert p.table1 is TABLE1[p.row - 1]
    assert p.lower == lower.lower()
    assert p.ball is MEASURED[p.lower]


@pytest.mark.parametrize("name", list(PAIRS))
def test_body_mass_is_mu_times_the_ball_and_near_the_published_mass(name):
    """m1 = mu m2; where a body's mass is published, within 7 % of it.

    Table 1 gives mu to two significant figures (0.050 for the table tennis ball on
    the tennis ball gives 2.89 g against the rule book's 2.7 g: 6.9 %).
    """
    p = PAIRS[name]
    assert p.m1 == pytest.approx(p.mu * p.ball.mass, rel=1e-15)
    if p.body.mass is not None:
        assert p.m1 == pytest.approx(p.body.mass, rel=0.07)


def test_published_body_data():
    """UK 1p: 3.56 g, 20.3 mm (Royal Mint); table tennis ball 2.7 g, 40 mm (ITTF 2.3)."""
    assert BODIES["coin"].mass == 3.56e-3
    assert 2 * BODIES["coin"].radius == pytest.approx(20.3e-3)
    assert BODIES["table-tennis"].mass == 2.7e-3
    assert 2 * BODIES["table-tennis"].radius == pytest.approx(40e-3)
    assert BODIES["tennis"].mass == MEASURED["tennis"].mass
    for body in BODIES.values():
        assert body.source


@pytest.mark.parametrize(
    ("name", "expected"),
    [
        ("tennis-coin", 0.0335),  # flat face: R* = R2
        ("tennis-nut", 0.0335),
        ("tennis-table-tennis", 0.02 * 0.0335 / 0.0535),
        ("basketball-tennis", 0.0335 * 0.12 / 0.1535),
        ("basketball-table-tennis", 0.02 * 0.12 / 0.14),
    ],
)
def test_contact_radius_rule(name, expected):
    assert PAIRS[name].contact_radius == pytest.approx(expected, rel=1e-12)


def test_floor_contact_time_of_a_pressurised_ball_is_pi_over_c():
    """k = 2 pi R P gives pi sqrt(m / k) = pi / c, c of eq. (3.8): 9.81 ms for the basketball."""
    for name in ("basketball-tennis", "tennis-coin"):
        p = PAIRS[name]
        ball = p.ball
        c = wave_speed_from_pressure(ball.pressure, ball.mass, ball.radius)
        assert pair_contacts(p).tau2 == pytest.approx(math.pi / c, rel=1e-12)
    assert pair_contacts(PAIRS["basketball-tissue"]).tau2 == pytest.approx(9.81e-3, abs=5e-6)


def test_pair_contact_time_uses_the_reduced_mass_and_contact_radius():
    p = PAIRS["basketball-tennis"]
    c = pair_contacts(p)
    k12 = 2 * math.pi * p.contact_radius * p.ball.pressure
    reduced = p.m1 * p.m2 / (p.m1 + p.m2)
    assert c.tau12 == pytest.approx(math.pi * math.sqrt(reduced / k12), rel=1e-12)
    assert c.tau12 < c.tau2


def test_unknown_pair_names_the_choices():
    with pytest.raises(ParameterError) as info:
        pair("basketball-golf")
    assert info.value.name == "pair"
    assert "basketball-tennis" in str(info.value)
    assert pair("tennis-nut") is PAIRS["tennis-nut"]
