"""The twoball command line: JSON contract, tables, and one-line errors with exit status 2."""

import json
import math
import shutil
import subprocess
import sys

import pytest

from twoball.cli.main import main


def run(capsys, *argv):
    code = main(list(argv))
    out = capsys.readouterr()
    return code, out.out, out.err


def test_liftoff_json_contract(capsys):
    code, out, _ = run(capsys, "liftoff", "--json")
    data = json.loads(out)
    assert code == 0
    for key in ("lifted", "t_liftoff_s", "v_liftoff_m_s", "ratio", "phi_a_rad", "gamma", "backend"):
        assert key in data
    assert data["backend"] == "legendre" and data["lifted"] is True
    assert data["t_liftoff_s"] == pytest.approx(0.0099, rel=0.01)
    assert data["ratio"] == pytest.approx(data["v_liftoff_m_s"] / 4.1)
    assert isinstance(data["rejected"], list) and data["rejected"][0]["reason"]


def test_liftoff_table_for_people(capsys):
    code, out, _ = run(capsys, "liftoff")
    assert code == 0 and "t_l [ms]" in out and "v_l [m/s]" in out


def test_v0_without_phi_a_uses_eq_3_7(capsys):
    # a speed other than the preset's own: phi_a from eq. (3.7), checked by the forward formula
    _, out, err = run(capsys, "liftoff", "--v0", "-3", "--json")
    data = json.loads(out)
    c = math.cos(data["phi_a_rad"])
    v0 = 0.12 * 320 * math.sqrt((-1 + 2 * c**3 + 3 * c**2) / (6 * c))  # eq. (3.7)
    assert v0 == pytest.approx(3.0, rel=1e-12)
    assert data["phi_a_source"] == "eq. (3.7)"
    assert "note:" in err and "eq. (3.7)" in err and "measured 2.6 rad" in err


def test_preset_own_v0_keeps_the_measured_phi_a(capsys):
    # typing the preset's own value (sign ignored) never changes the answer
    _, default, err_default = run(capsys, "liftoff", "--json")
    _, typed, err = run(capsys, "liftoff", "--v0", "-4.1", "--json")
    typed, default = json.loads(typed), json.loads(default)
    assert typed.pop("provenance")["case"] == default.pop("provenance")["case"]
    assert typed == default
    assert typed["phi_a_source"] == "measured (basketball)"
    assert err == err_default == ""


def test_pressure_and_mass_give_the_wave_speed(capsys):
    _, out, _ = run(capsys, "liftoff", "--pressure", "77200", "--mass", "0.567", "--json")
    assert json.loads(out)["wave_speed_1_s"] == pytest.approx(320.40, abs=0.01)


def test_sweep_json_in_order(capsys):
    code, out, _ = run(capsys, "sweep", "--param", "v0", "--values", "2:8:4", "--json")
    data = json.loads(out)["results"]
    assert code == 0 and [d["v0_m_s"] for d in data] == pytest.approx([2, 4, 6, 8])
    assert len({d["phi_a_rad"] for d in data}) == 4  # phi_a re-derived per value


def test_sweep_modes(capsys):
    code, out, _ = run(capsys, "sweep", "--param", "modes", "--values", "30:60:2", "--json")
    assert code == 0 and [d["modes"] for d in json.loads(out)["results"]] == [30, 60]


@pytest.mark.parametrize(
    ("argv", "flag"),
    [
        (["liftoff", "--radius", "0"], "--radius"),
        (["liftoff", "--radius", "-0.1"], "--radius"),
        (["liftoff", "--damping", "1"], "--damping"),
        (["liftoff", "--damping", "-0.01"], "--damping"),
        (["liftoff", "--phi-a", "1.2"], "--phi-a"),
        (["liftoff", "--phi-a", "3.2"], "--phi-a"),
        (["liftoff", "--preset", "squash"], "--preset"),
        (["liftoff", "--modes", "0"], "--modes"),
        (["liftoff", "--v0", "0"], "--v0"),
        (["liftoff", "--wave-speed", "-3"], "--wave-speed"),
        (["liftoff", "--pressure", "77200"], "--pressure"),
        (["liftoff", "--wave-speed", "300", "--pressure", "1", "--mass", "1"], "--wave-speed"),
        (["liftoff", "--t-end", "-1"], "--t-end"),
        (["liftoff", "--sigma", "hann"], "--sigma"),
        (["liftoff", "--recontact", "never"], "--recontact"),
        (["liftoff", "--damping", "abc"], "--damping"),
        (["liftoff", "--radius", "nan"], "--radius"),
        (["sweep", "--param", "damping", "--values", "0:1"], "--values"),
        (["sweep", "--param", "damping", "--values", "a:b:3"], "--values"),
        (["sweep", "--param", "damping", "--values", "0:0.5:0"], "--values"),
        (["sweep", "--param", "modes", "--values", "1:2:3"], "--values"),
        (["sweep", "--param", "mass", "--values", "0:1:3"], "--param"),
        (["sweep", "--param", "damping", "--values", "0:1:3"], "--damping"),
    ],
)
def test_bad_input_is_one_line_exit_2(capsys, argv, flag):
    with pytest.raises(SystemExit) as stop:
        main(argv)
    err = capsys.readouterr().err
    assert stop.value.code == 2
    lines = err.strip().splitlines()
    assert len(lines) == 1, err
    assert flag in lines[0] and "Traceback" not in err


def test_console_script_error_has_no_traceback():
    exe = shutil.which("twoball")
    cmd = [exe] if exe else [sys.executable, "-m", "twoball"]
    proc = subprocess.run(
        [*cmd, "liftoff", "--damping", "2"], capture_output=True, text=True, check=False
    )
    assert proc.returncode == 2
    assert proc.stderr.strip() == "twoball: error: --damping must be in [0, 1), got 2.0"
    assert proc.stdout == ""


def test_no_liftoff_is_a_normal_result(capsys):
    code, out, _ = run(capsys, "liftoff", "--damping", "0.9", "--json")
    data = json.loads(out)
    assert code == 0 and data["lifted"] is False and data["t_liftoff_s"] is None
    assert math.isfinite(data["gamma"])


def test_icm_table1_rows_1_to_3_match(capsys):
    code, out, _ = run(capsys, "icm", "--table1", "--json")
    rows = json.loads(out)["results"]
    assert code == 0 and len(rows) == 6
    for row in rows[:3]:
        assert not row["v1_differs"] and not row["v2_differs"]
        assert row["ours_v1_rounded"] == row["icm_v1"]
    assert any(r["v1_differs"] or r["v2_differs"] for r in rows[3:])
    code, out, _ = run(capsys, "icm", "--table1")
    assert code == 0 and "DIFFERS" in out and "Table 1 recomputed" in out
    assert "0.488 *" in out and "1.516 *" not in out


def test_icm_single_case(capsys):
    # elastic, light upper ball, touching: v1 -> -3 v0 (eq. (2.7))
    code, out, _ = run(capsys, "icm", "--mu", "0", "--e2", "1", "--e12", "1", "--json")
    data = json.loads(out)
    assert code == 0 and data["v1_ratio"] == pytest.approx(3.0)


@pytest.mark.parametrize(
    ("argv", "flag"),
    [
        (["icm", "--mu", "0.1"], "--e2"),
        (["icm", "--mu", "-1", "--e2", "0.5", "--e12", "0.5"], "--mu"),
        (["icm", "--mu", "0.1", "--e2", "1.5", "--e12", "0.5"], "--e2"),
        (["icm", "--mu", "0.1", "--e2", "0.5", "--e12", "-0.5"], "--e12"),
        (["icm", "--mu", "0.1", "--e2", "0.5", "--e12", "0.5", "--dx", "-1"], "--dx"),
    ],
)
def test_icm_bad_input(capsys, argv, flag):
    with pytest.raises(SystemExit) as stop:
        main(argv)
    err = capsys.readouterr().err.strip().splitlines()
    assert stop.value.code == 2 and len(err) == 1 and flag in err[0]


@pytest.mark.parametrize(
    ("argv", "expected"),
    [
        (["liftoff", "--damping", "abc"], "--damping must be in [0, 1), got 'abc'"),
        (["liftoff", "--modes", "2.5"], "--modes must be an integer in [1, 1000000], got 2.5"),
        (["liftoff", "--modes", "abc"], "--modes must be an integer in [1, 1000000], got 'abc'"),
        (
            ["icm", "--mu", "x", "--e2", "0.8", "--e12", "0.9"],
            "--mu must be a number in [0, 1e+06], got 'x'",
        ),
    ],
)
def test_unparsable_numbers_state_the_valid_range(capsys, argv, expected):
    with pytest.raises(SystemExit) as stop:
        main(argv)
    assert stop.value.code == 2
    assert capsys.readouterr().err.strip() == f"twoball: error: {expected}"


def test_fem_liftoff_json_adds_backend_details(capsys):
    argv = ["liftoff", "--backend", "fem", "--mesh", "axisym", "--elements", "200", "--json"]
    code, out, _ = run(capsys, *argv)
    data = json.loads(out)
    assert code == 0 and data["backend"] == "fem"
    for key in ("dofs", "modes_used", "mesh", "order", "time_scheme", "seconds"):
        assert key in data
    assert data["dofs"] == 401 and data["time_scheme"] == "modal"
    _, out, _ = run(capsys, "liftoff", "--json")
    legendre = json.loads(out)
    assert data["t_liftoff_s"] == pytest.approx(legendre["t_liftoff_s"], rel=1e-6)
    assert data["v_liftoff_m_s"] == pytest.approx(legendre["v_liftoff_m_s"], rel=1e-6)


def test_fem_alpha_liftoff_with_step_in_seconds(capsys):
    argv = ["liftoff", "--backend", "fem", "--mesh", "axisym", "--elements", "100"]
    code, out, _ = run(capsys, *argv, "--scheme", "alpha", "--dt", "2e-6", "--json")
    data = json.loads(out)
    assert code == 0 and data["time_scheme"] == "alpha"
    assert data["dt_s"] == pytest.approx(2e-6)
    assert data["t_liftoff_s"] == pytest.approx(0.0099, rel=0.01)


def test_eigen_json_lists_clusters(capsys):
    code, out, _ = run(
        capsys, "eigen", "--mesh", "sphere", "--level", "1", "--count", "8", "--json"
    )
    rows = json.loads(out)["results"]
    assert code == 0 and [r["l"] for r in rows[:4]] == [0, 1, 1, 1]
    assert all(r["multiplicity"] == 2 * r["l"] + 1 for r in rows)


@pytest.mark.parametrize(
    ("argv", "flag"),
    [
        (["liftoff", "--backend", "fem", "--level", "-1"], "--level"),
        (["liftoff", "--backend", "fem", "--order", "5"], "--order"),
        (["liftoff", "--backend", "fem", "--dt", "0"], "--dt"),
        (["liftoff", "--backend", "fem", "--dt", "-1e-5"], "--dt"),
        (["liftoff", "--backend", "fem", "--mesh", "axisym", "--elements", "1"], "--elements"),
        (["liftoff", "--backend", "fem", "--mesh", "cube"], "--mesh"),
        (["liftoff", "--backend", "fem", "--scheme", "euler"], "--scheme"),
        (["liftoff", "--backend", "fem", "--damping-model", "viscous"], "--damping-model"),
        (["liftoff", "--backend", "spectral"], "--backend"),
        (["eigen", "--level", "-2"], "--level"),
        (["eigen", "--count", "0"], "--count"),
        (["eigen", "--order", "x"], "--order"),
    ],
)
def test_fem_bad_input_is_one_line_exit_2(capsys, argv, flag):
    with pytest.raises(SystemExit) as stop:
        main(argv)
    err = capsys.readouterr().err.strip().splitlines()
    assert stop.value.code == 2 and len(err) == 1 and flag in err[0], err
