"""Accuracy guards of the closed form (modal/guards.py).

Truncation in N and the re-contact window.
"""

from __future__ import annotations

import json
import math

import pytest

import twoball
from tests.helpers import assert_printed, run_json
from twoball.cli.main import main
from twoball.modal.converged import converged_legendre
from twoball.modal.guards import TRUNCATION_WARNING, truncation, window_warnings
from twoball.modal.parameters import Case, preset
from twoball.modal.report import legendre_liftoff


def test_legendre_default_is_quiet_and_reports_the_converged_series(capsys) -> None:
    data, lines = run_json(capsys)
    assert data["warnings"] == [] and lines == []
    block = data["truncation"]
    reference = converged_legendre(preset("basketball"))
    scale = preset("basketball").scalings
    assert block["converged"] and block["converged_modes"] == reference.modes
    assert block["t_liftoff_s"] == pytest.approx(reference.t * scale.time, rel=1e-12)
    assert block["v_liftoff_m_s"] == pytest.approx(reference.velocity * scale.velocity, rel=1e-12)
    # N = 30 is 2.9 % below the converged series in v_l (3.9454 m/s at N = 120)
    assert block["v_difference"] == pytest.approx(data["v_liftoff_m_s"] / 3.9454 - 1, abs=2e-4)
    assert -0.030 < block["v_difference"] < -0.028
    assert abs(block["v_difference"]) < TRUNCATION_WARNING


def test_truncation_warns_above_five_percent() -> None:
    coarse = legendre_liftoff(preset("basketball").derive(modes=20))
    (text,) = coarse.warnings
    assert text.startswith("N = 20 truncation: t_l ") and text.endswith(
        "; raise the number of modes N"
    )
    assert coarse.extra["truncation"]["v_difference"] < -TRUNCATION_WARNING  # -6.3 %
    fine = legendre_liftoff(preset("basketball").derive(modes=60))
    assert fine.warnings == ()
    assert abs(fine.extra["truncation"]["v_difference"]) < 0.01


def test_truncation_difference_shrinks_with_n() -> None:
    case = preset("basketball")
    gaps = [
        abs(
            truncation(
                case.derive(modes=n), legendre_liftoff(case.derive(modes=n)).result
            ).v_difference
        )
        for n in (15, 30, 60)
    ]
    assert gaps[0] > gaps[1] > gaps[2] > 0


def test_short_window_warns(capsys) -> None:
    data, lines = run_json(capsys, "--t-end", "0.005")
    assert data["lifted"] and data["t_liftoff_s"] == pytest.approx(4.8e-4, rel=0.01)
    assert_printed(data, lines)
    window, falling = data["warnings"][:2]
    assert window.startswith("window too short for the re-contact check")
    assert "2 pi / c = 19.6 ms" in window
    assert falling.startswith("the body is falling back at the end of the window")


def test_window_criterion_edges() -> None:
    """Quiet from one refocusing period after t_l on, while the body still rises."""
    case = preset("basketball")
    base = legendre_liftoff(case).result
    t_l = base.t
    enough = type(base)(**{**base.__dict__, "t_end": t_l + 2 * math.pi * 1.01})
    short = type(base)(**{**base.__dict__, "t_end": t_l + 2 * math.pi * 0.99})
    assert window_warnings(case, enough) == []
    assert len(window_warnings(case, short)) == 1


# --- Unit and sign slips are said: R, |v0| far outside any ball, windows where nothing can lift off


def cli(capsys, *argv: str) -> tuple[dict, list[str]]:
    assert main(["liftoff", "--json", *argv]) == 0
    out, err = capsys.readouterr()
    return json.loads(out), err.splitlines()


def test_radius_in_millimetres_is_said(capsys) -> None:
    data, lines = cli(capsys, "--radius", "120")
    assert not data["lifted"]
    (text,) = [w for w in data["warnings"] if w.startswith("R = 120 m")]
    assert "did you mean 0.12 m (120 mm)" in text
    assert f"twoball: warning: {text}" in lines
    meant = legendre_liftoff(preset("basketball").derive(radius=0.12))
    assert meant.lifted and not [w for w in meant.warnings if w.startswith("R = ")]


def test_speed_in_millimetres_per_second_is_said() -> None:
    report = legendre_liftoff(preset("basketball").derive(v0=4100.0))
    assert any("did you mean 4.1 m/s (4100 mm/s)" in w for w in report.warnings)


@pytest.mark.parametrize("seconds", [5.0, 1.0])
def test_window_in_milliseconds_typed_as_seconds_is_said(seconds: float) -> None:
    """Longer than the flight 2 |v0| / g = 0.836 s: every lift-off falls back inside it."""
    case = preset("basketball")
    assert seconds > 2 * case.v0 / case.g
    report = legendre_liftoff(case, t_end_s=seconds)
    assert not report.lifted
    (text,) = [w for w in report.warnings if w.startswith("the window t_end")]
    assert f"did you mean {seconds:g} ms" in text
    # the paper's horizon (re-contact only for t - t_l < t_l) lifts off in the same window:
    # the window, not the physics, rejected the lift-off
    assert legendre_liftoff(case, recontact="paper", t_end_s=seconds).lifted
    # the window meant (milliseconds) lifts off where the default does (within 5 ms)
    default = legendre_liftoff(case)
    assert default.lifted and default.t_liftoff_s < 0.01 * seconds


def test_window_before_the_wave_reaches_the_pole_is_said(capsys) -> None:
    data, _ = cli(capsys, "--t-end", "0.001")
    (text,) = [w for w in data["warnings"] if w.startswith("the window ends at 1 ms")]
    case = preset("basketball")
    front = case.phi_a / case.wave_speed  # s: the pole is still before this (eq. (3.9))
    assert 0.001 < front and f"phi_a / c = {front * 1e3:.3g} ms" in text
    assert f"pi / c = {math.pi / case.wave_speed * 1e3:.3g} ms" in text
    stiff = legendre_liftoff(preset("tennis"), t_end_s=3e-4)  # lifts off at 0.52 ms
    assert not stiff.lifted
    assert any(w.startswith("the window ends at 0.3 ms") for w in stiff.warnings)


def test_defaults_and_ordinary_balls_are_quiet() -> None:
    for name in ("basketball", "tennis", "volleyball"):
        report = legendre_liftoff(preset(name))
        assert not [w for w in report.warnings if w.startswith(("R = ", "|v0| = ", "the window"))]


def test_negative_v0_is_the_papers_downward_velocity(capsys) -> None:
    data, lines = cli(capsys, "--v0=-4.1")
    positive, _ = cli(capsys, "--v0", "4.1")
    assert data["v_liftoff_m_s"] == positive["v_liftoff_m_s"]  # only |v0| enters (3.6)-(3.7)
    (note,) = data["notes"]
    assert note.startswith("v0 = -4.1 m/s read as an impact at 4.1 m/s downwards")
    assert f"twoball: note: {note}" in lines and positive["notes"] == []
    case = Case.preset("basketball", v0=-3.0)
    assert case.v0 == 3.0 and case.notes[-1].startswith("v0 = -3 m/s")
    assert case.derive(v0=3.0).v0_note is None and case.derive(damping=0.2).v0_note is not None


def test_sweep_points_carry_the_warning() -> None:
    result = twoball.sweep({"radius": [0.12, 120.0]})
    first, second = (p.report for p in result.points)
    assert not [w for w in first.warnings if w.startswith("R = ")]
    assert [w for w in second.warnings if w.startswith("R = 120 m")]


def test_converge_says_it_too() -> None:
    slip = twoball.Case.preset("basketball", radius=120.0)
    study = twoball.converge(slip, study="modes", modes_list="30,60,120")
    assert [w for w in study.warnings if w.startswith("R = 120 m")]
    assert study.as_dict()["warnings"] == study.warnings
    assert twoball.converge(study="modes", modes_list="30,60,120").warnings == []


def test_a_default_window_is_no_slip_to_guess_at(capsys) -> None:
    """|v0| = 4.1 mm/s: every lift-off falls back inside the default 4 pi / c window; the
    warning says so, but suggests no t_end the user never typed."""
    data, lines = cli(capsys, "--v0", "0.0041")
    (text,) = [w for w in data["warnings"] if w.startswith("the window t_end")]
    flight = 2 * 0.0041 / 9.81  # s: 2 |v0| / g
    assert f"2 |v0| / g = {flight:.3g} s" in text and "did you mean" not in text
    assert f"twoball: warning: {text}" in lines
    typed, _ = cli(capsys, "--v0", "0.0041", "--t-end", str(4 * math.pi / 320))
    assert any("did you mean" in w for w in typed["warnings"])  # the window typed: said


def test_a_default_window_is_no_slip_in_the_field_outputs_either(tmp_path) -> None:
    slow = twoball.Case.preset("basketball", v0=0.0041)
    result = twoball.export(tmp_path / "e.vtu", slow, backend="legendre")
    (text,) = [w for w in result.warnings if "the window t_end" in w]
    assert "did you mean" not in text


def test_drop_height_and_gap_far_from_any_drop_are_said() -> None:
    """H = 1000 m falls at sqrt(2 g H) = 140.07 m/s; a 5 m gap between stacked balls."""
    from twoball.modal.guards import case_warnings

    case = preset("basketball").derive(v0=math.sqrt(2 * 9.81 * 1000.0))
    (text,) = case_warnings(case, drop_height=1000.0)
    assert text.startswith("the drop height H = 1000 m") and "= 140.1 m/s" in text
    assert text.endswith("did you mean 1 m (1000 mm) or 10 m (1000 cm)?")
    # the speed came from the height: judged by the height, not as a typed |v0|
    assert not [w for w in case_warnings(case, drop_height=1000.0) if w.startswith("|v0|")]
    # 500 m is 99 m/s, under the speed's bound, yet far above any drop
    slower = preset("basketball").derive(v0=math.sqrt(2 * 9.81 * 500.0))
    assert case_warnings(slower) == [] and case_warnings(slower, drop_height=500.0)
    (gap,) = case_warnings(preset("basketball"), gap=5.0)
    assert "did you mean 0.005 m (5 mm) or 0.05 m (5 cm)?" in gap
    assert case_warnings(preset("basketball"), drop_height=1.0, gap=0.005) == []


def test_a_wave_speed_a_thousand_times_the_presets_is_said_with_320() -> None:
    """c = 3.2e5 1/s on the basketball (c = 320 1/s, Table 2): 1000 times, meant 320."""
    from twoball.modal.guards import case_warnings

    (text,) = case_warnings(preset("basketball").derive(wave_speed=3.2e5))
    assert text.startswith("the wave speed c = 320000 1/s is 1000 times")
    assert text.endswith("did you mean 320 1/s?")
    assert case_warnings(preset("basketball").derive(wave_speed=3.2e4)) == []  # 100x: no slip
    tennis = preset("tennis")  # c = sqrt(2 pi R P / m) = 549 1/s of its own preset
    assert case_warnings(tennis.derive(wave_speed=549e3))[0].endswith("did you mean 549 1/s?")


def test_a_mass_in_grams_with_the_pressure_is_said_with_the_kilograms() -> None:
    """m = 567 kg with the basketball's P = 77200 Pa: c = sqrt(2 pi R P / m) = 10.13 1/s, eq.
    (3.8), which lies inside c's range; the mass is judged, 1000 times Table 2's 0.567 kg."""
    from twoball.modal.guards import case_mass, case_warnings

    case = Case.from_pressure(77200.0, 567.0)
    assert case.wave_speed == pytest.approx(math.sqrt(2 * math.pi * 0.12 * 77200 / 567), rel=1e-12)
    assert case_mass(case) == pytest.approx(567.0, rel=1e-12)
    (text,) = case_warnings(case)
    assert text.startswith("the mass m = 567 kg (with P = 77200 Pa, c = 10.13 1/s")
    assert text.endswith("did you mean 0.567 kg (567 g)?")
    assert case_warnings(Case.from_pressure(77200.0, 0.567)) == []


def test_a_sweep_of_slips_is_said_on_its_values_before_any_point() -> None:
    from twoball.modal.guards import sweep_slips

    base = preset("basketball")
    text = sweep_slips("wave_speed", "wave-speed", [3.2e5, 3.3e5], base)
    assert text is not None and text.startswith("2 of 2 values of wave-speed (every value)")
    assert "did you mean 320 1/s?" in text
    partly = sweep_slips("v0", "v0", [4.1, 4100.0], base)
    assert partly is not None and partly.startswith("1 of 2 values of v0 lie")
    assert "did you mean 4.1 m/s" in partly
    assert sweep_slips("wave_speed", "wave-speed", [300.0, 340.0], base) is None
    assert sweep_slips("damping", "damping", [0.1, 0.9], base) is None  # no unit to slip


def test_a_sweep_the_budget_refuses_still_says_its_slips() -> None:
    """2e5 points need more than the time budget: refused before any point, with the slip."""
    from twoball._common.budget import BudgetError

    values = {"wave_speed": [3.2e5 + k for k in range(200_000)]}
    with pytest.raises(BudgetError) as caught:
        twoball.sweep(values, workers=1)
    assert "200000 of 200000 values of wave-speed (every value)" in str(caught.value)
    assert "did you mean 320 1/s?" in str(caught.value)
