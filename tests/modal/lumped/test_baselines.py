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
