"""The presets of Table 1's bodies: sources, and their inputs give back their restitution.

Each preset body dropped alone on a rigid floor (the same integrator as the
whole bounce) returns its stated restitution and its law's contact time; the
tennis ball's ball body returns Table 1's 0.83.
"""

from __future__ import annotations

import pytest

import twoball
from twoball.modal.bodies import BODIES, TENNIS_BALL_DAMPING, preset_body
from twoball.modal.pairs import PAIRS
from twoball.modal.upper.alone import ball_alone, lumped_alone
from twoball.modal.upper.laws import LAWS


def test_every_value_has_a_source():
    for name, preset in BODIES.items():
        needed = {"law", "restitution", *LAWS[preset.law.law]}
        stated = {part.strip() for key in preset.sources for part in key.split(",")}
        assert needed <= stated, (name, needed - stated)
        assert all(text.strip() for text in preset.sources.values())
    assert "weakest" in BODIES["tissue"].sources["law"]
    assert all("assumed" in BODIES["tissue"].sources[k] for k in ("radius", "restitution"))
    assert "Table 1" in BODIES["tennis"].sources["restitution"]


@pytest.mark.parametrize("pair", sorted(PAIRS))
def test_each_lumped_preset_gives_its_restitution_and_contact_time(pair):
    body = preset_body(pair, "lumped")
    m1 = PAIRS[pair].m1
    alone = lumped_alone(body, m1, 4.1, g=0.0)
    assert alone.restitution == pytest.approx(body.restitution, abs=1e-4)
    assert alone.contact_time == pytest.approx(alone.stated_contact_time, rel=1e-3)
    with_weight = lumped_alone(body, m1, 4.1)  # gravity through the contact too
    assert with_weight.restitution == pytest.approx(body.restitution, abs=1e-3)
    assert with_weight.energy["balance"] < 1e-13 * with_weight.energy["initial"]


def test_the_tennis_ball_body_gives_table_1s_e2():
    body = preset_body("basketball-tennis", "ball")
    assert body.damping.ratio == TENNIS_BALL_DAMPING and body.restitution == 0.83
    alone, report = ball_alone(body, 4.1)
    assert alone.restitution == pytest.approx(0.83, abs=1e-3)
    assert report.model["resolution"] == "legendre N = 64"
    assert 6e-3 < alone.contact_time < 9e-3  # its membrane's, longer than pressure x area


def test_kinds_and_changes():
    rigid = preset_body("basketball-tennis", "rigid")
    assert isinstance(rigid, twoball.Body) and rigid.restitution == 0.89
    changed = preset_body("tennis-coin", "lumped", restitution=0.9, steps=50)
    assert changed.law.restitution == 0.9 and changed.steps == 50
    assert changed.mass_ratio == PAIRS["tennis-coin"].mu
    for pair in ("tennis-coin", "tennis-nut", "basketball-tissue", "tennis-table-tennis"):
        with pytest.raises(twoball.ParameterError, match="tennis ball only"):
            preset_body(pair, "ball")
    with pytest.raises(twoball.ParameterError, match="kind"):
        preset_body("tennis-coin", "soft")
