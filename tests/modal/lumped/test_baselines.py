"""The lumped baselines beside the whole bounce: the pair's own models, any body's inputs."""

from __future__ import annotations

import math

import pytest

from twoball.modal.icm.limits import touching_ratios
from twoball.modal.lumped import MODELS
from twoball.modal.lumped.baselines import BASELINE_NAMES, baselines, body_inputs, pair_inputs
from twoball.modal.pairs import PAIRS


def test_a_pair_runs_its_own_models():
    pair = PAIRS["basketball-table-tennis"]
    out = baselines(pair_inputs(pair), 4.1, 0.03, 9.81)
    assert tuple(out["models"]) == BASELINE_NAMES == tuple(MODELS)
    for name, build in MODELS.items():
        assert out["models"][name] == build(pair).run(v0=4.1, dx=0.03, g=9.81).summary()
    assert out["inputs"]["pair"] == pair.name and out["inputs"]["e12"] == pair.e12


def test_any_body_by_the_pressure_rule_and_its_refusals():
    inputs = body_inputs(0.01, 0.5, 0.1, 50000.0, 0.02, 0.9, 0.0, "test")
    c = inputs.contacts
    r_star = 0.02 * 0.1 / 0.12
    assert c.k12 == pytest.approx(2 * math.pi * r_star * 50000.0, rel=1e-15)
    assert c.tau2 == pytest.approx(math.pi * math.sqrt(0.5 / (2 * math.pi * 0.1 * 50000.0)))
    out = baselines(inputs, 4.0, 0.0, 9.81)
    assert out["models"]["icm"]["v1_ratio"] == pytest.approx(touching_ratios(0.02, 0.9, 0.0)[0])
    for name in ("two-spring-dashpot", "bartz2020", "hertz-viscoelastic"):
        assert "error" in out["models"][name]  # e12 = 0: no linear or Hertz fit
    assert "the pressure rule" not in out["inputs"]["source"] and "test" in out["inputs"]["source"]


def test_bartz_dip_on_the_tissue_curve_is_a_third_contact_in_flight():
    """docs/whole_bounce.rst, "The Bartz 2020 baseline's dip at 2 mm": the numbers."""
    from twoball.modal.lumped.bartz import Bartz2020

    g = 9.81  # the preset's (STANDARD_GRAVITY): the catch's time depends on it
    model = Bartz2020.from_pair(PAIRS["basketball-tissue"])
    dip = model.run(v0=4.1, dx=0.002, g=g)
    assert (round(dip.v1_ratio, 3), round(dip.v2_ratio, 3)) == (0.809, 0.809)
    pair = [(e.kind, round(e.time * 1e3, 2)) for e in dip.events if e.contact == "pair"]
    assert pair == [
        ("touch", 2.92), ("release", 5.28), ("touch", 5.81), ("release", 8.73),
        ("touch", 45.7), ("release", 47.37),
    ]  # fmt: skip
    (floor,) = [e for e in dip.events if e.contact == "floor" and e.kind == "release"]
    # the ball leaves the floor after the body's second release, 1.2 mm/s faster than it
    assert floor.time == pytest.approx(9.882e-3, abs=1e-6)
    assert floor.v2 - floor.v1 == pytest.approx(1.17e-3, abs=0.05e-3)
    # the third contact, in flight, exchanges almost nothing: the drop is gravity's
    assert floor.time < 45.7e-3 and abs(dip.v1 - dip.v2) < 1e-3
    back = (dip.v1 + g * (dip.t_liftoff - dip.t_floor_release)) / 4.1
    assert back == pytest.approx(0.899, abs=1e-3)
    # on either side of the narrow window (1.775 to 2.003 mm) no dip: v1 ~ 0.90
    for dx, pairs in ((0.0017, 1), (0.00195, 3), (0.00205, 2)):
        run = model.run(v0=4.1, dx=dx, g=g)
        assert run.pair_contacts == pairs
        late = max(0.0, run.t_liftoff - run.t_floor_release)
        assert (run.v1 + g * late) / 4.1 == pytest.approx(0.90, abs=0.015)
    # the baseline beside the whole bounce is this run
    shown = baselines(pair_inputs(PAIRS["basketball-tissue"]), 4.1, 0.002, g)
    assert shown["models"]["bartz2020"]["v1_ratio"] == pytest.approx(dip.v1_ratio, rel=1e-12)
