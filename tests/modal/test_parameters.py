"""The case (modal/parameters.py): units, presets, the phi_a rule of eq. (3.7), refusals."""

from __future__ import annotations

import math

import pytest

import twoball
from twoball._common.errors import ParameterError
from twoball.modal.parameters import PRESETS, Case, Scalings, preset, wave_speed_from_pressure


def v0_of_phi_a(phi_a: float, radius: float = 0.12, wave_speed: float = 320.0) -> float:
    """Eq. (3.7) forwards: the impact speed [m/s] that flattens the ball up to phi_a."""
    c = math.cos(phi_a)
    return radius * wave_speed * math.sqrt((-1 + 2 * c**3 + 3 * c**2) / (6 * c))


# --------------------------------------------------------------------------- phi_a rule
def test_phi_a_rule_given_measured_or_eq_3_7():
    assert twoball.Case().phi_a_source == "measured (basketball)" and twoball.Case().phi_a == 2.6
    assert twoball.Case(v0=-4.1) == twoball.Case.preset("basketball")  # sign ignored
    given = twoball.Case(phi_a=2.5)
    assert (given.phi_a, given.phi_a_source, given.phi_a_note) == (2.5, "given", None)
    derived = twoball.Case(v0=3.0)  # today's Case(v0=3.0) no longer keeps 2.6 silently
    assert derived.phi_a_source == "eq. (3.7)"
    assert v0_of_phi_a(derived.phi_a) == pytest.approx(3.0, rel=1e-12)
    assert derived.phi_a_note.startswith(f"phi_a = {derived.phi_a:.4f} rad from eq. (3.7)")
    assert "|v0| = 3 m/s" in derived.phi_a_note and "measured 2.6 rad" in derived.phi_a_note


def test_phi_a_rule_through_derive_and_sweeps():
    base = twoball.Case.preset("basketball")
    there_and_back = base.derive(v0=3.0).derive(v0=4.1)
    assert there_and_back == base and there_and_back.phi_a_source == "measured (basketball)"
    assert base.derive(damping=0.2).phi_a_source == "measured (basketball)"
    kept = base.derive(v0=3.0).derive(damping=0.2)
    assert kept.phi_a_source == "eq. (3.7)" and kept.phi_a == base.derive(v0=3.0).phi_a
    assert base.derive(phi_a=2.5).derive(damping=0.2).phi_a_source == "given"
    wider = base.derive(radius=0.2)
    assert "R = 0.2 m" in wider.phi_a_note
    assert v0_of_phi_a(wider.phi_a, radius=0.2) == pytest.approx(4.1, rel=1e-12)
    explicit = base.derive(phi_a="eq. (3.7)")  # eq. (3.7) even at the preset's own values
    assert explicit.phi_a_source == "eq. (3.7)" and v0_of_phi_a(explicit.phi_a) == pytest.approx(
        4.1
    )


def test_own_measurements_have_no_preset_and_no_note():
    case = twoball.Case.from_measurements(radius=0.12, v0=4.1, pressure=77200, mass=0.567)
    assert case.preset_name is None and case.phi_a_source == "eq. (3.7)" and case.phi_a_note is None
    assert twoball.Case(preset_name=None).phi_a_source == "eq. (3.7)"


@pytest.mark.parametrize(
    "changes",
    [
        {"phi_a": 2.5, "phi_a_source": "measured (basketball)"},
        {"phi_a": 2.5, "phi_a_source": "eq. (3.7)"},
        {"phi_a": 2.6, "phi_a_source": "measured (basketball)", "v0": 3.0},
    ],
)
def test_phi_a_source_cannot_be_faked(changes):
    with pytest.raises(twoball.ParameterError) as error:
        twoball.Case(**changes)
    assert error.value.name == "phi_a_source"


def test_table2_wave_speed_from_pressure():
    # Table 2: P = 77200 Pa, m = 0.567 kg, R = 0.12 m gives c ~ 320 1/s
    c = wave_speed_from_pressure(77200.0, 0.567, 0.12)
    tension, density = 77200 * 0.12 / 2, 0.567 / (4 * math.pi * 0.12**2)
    assert c == pytest.approx(math.sqrt(tension / density) / 0.12, rel=1e-15)
    assert c == pytest.approx(320.0, rel=0.01)


def test_scalings_units():
    s = Scalings(0.12, 320.0)
    assert s.time == pytest.approx(1 / 320)
    assert s.velocity == pytest.approx(0.12 * 320)
    assert s.acceleration == pytest.approx(0.12 * 320**2)
    assert s.gamma == pytest.approx(9.81 / (0.12 * 320**2))


def test_basketball_preset():
    case = preset("basketball")
    assert (case.radius, case.wave_speed, case.v0, case.phi_a) == (0.12, 320.0, 4.1, 2.6)
    assert (case.damping, case.modes) == (0.13, 30)
    assert PRESETS["basketball"] is case


def test_negative_speed_is_a_speed():
    assert Case(v0=-4.1).v0 == 4.1


def test_derive_rederives_phi_a_only_for_v0_c_r():
    case = preset("basketball")
    assert case.derive(damping=0.2).phi_a == 2.6
    assert case.derive(v0=4.1).phi_a == 2.6  # the preset's own value: measured phi_a
    moved = case.derive(v0=4.5)
    assert moved.phi_a != 2.6 and 2.5 < moved.phi_a < 2.7
    assert case.derive(phi_a="eq. (3.7)").phi_a == pytest.approx(2.5928, abs=1e-4)
    assert case.derive(v0=5.0, phi_a=2.4).phi_a == 2.4


def test_from_measurements_pressure():
    case = Case.from_measurements(radius=0.12, v0=4.1, pressure=77200, mass=0.567)
    assert case.wave_speed == pytest.approx(320.40, abs=0.01)


@pytest.mark.parametrize(
    ("changes", "name"),
    [
        ({"radius": 0.0}, "radius"),
        ({"radius": -1.0}, "radius"),
        ({"wave_speed": 0.0}, "wave_speed"),
        ({"damping": 1.0}, "damping"),
        ({"damping": -0.1}, "damping"),
        ({"phi_a": math.pi / 2}, "phi_a"),
        ({"phi_a": math.pi}, "phi_a"),
        ({"modes": 0}, "modes"),
        ({"modes": 2.5}, "modes"),
        ({"v0": 0.0}, "v0"),
        ({"v0": math.nan}, "v0"),
    ],
)
def test_invalid_case_names_parameter_and_range(changes, name):
    with pytest.raises(ParameterError) as error:
        Case(**changes)
    assert error.value.name == name
    assert str(error.value).startswith(name + " must be ")


def test_unknown_preset():
    valid = "basketball, superball, tennis, volleyball"
    with pytest.raises(ParameterError, match=f"preset must be one of {valid}"):
        preset("squash")


@pytest.mark.parametrize("args", [(0, 0.5, 0.1), (1e5, -1, 0.1), (1e5, 0.5, 0)])
def test_invalid_pressure_inputs(args):
    with pytest.raises(ParameterError):
        wave_speed_from_pressure(*args)
