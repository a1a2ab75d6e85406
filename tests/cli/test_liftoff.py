"""twoball liftoff: JSON contract, tables, the phi_a rule, a body of finite mass, refusals."""

from __future__ import annotations

import json
import math
import subprocess
import sys

import pytest

import twoball
from tests import ROOT
from tests.helpers import cli_run
from twoball import Body
from twoball.cli.main import main
from twoball.modal.parameters import Case

BASKETBALL = Case.preset("basketball")


def _cli(*args):
    return subprocess.run(
        [sys.executable, "-m", "twoball", *args], capture_output=True, text=True, check=False
    )


@pytest.mark.parametrize(
    ("argv", "line"),
    [
        (["liftoff", "--level", "2"], "--level must be left out with backend legendre"),
        (["liftoff", "--backend", "fem", "--mesh", "axisym", "--level", "2"], "--level must be"),
        (["liftoff", "--backend", "fem", "--elements", "50"], "--elements must be left out"),
        (["liftoff", "--backend", "fem", "--dt", "1e-5"], "--dt must be left out with scheme"),
        (["eigen", "--mesh", "sphere", "--elements", "9"], "--elements must be left out"),
        (["liftoff", "--phi-a", "3.5"], "--phi-a must be in (pi/2, pi - 1e-6]"),
        # the flags map onto one solver object: those it has no field for are refused
        (["liftoff", "--mesh", "axisym"], "--mesh must be left out with backend legendre"),
        (
            ["liftoff", "--backend", "fem", "--scheme", "alpha", "--route", "krylov"],
            "--route must be full or auto with scheme alpha",
        ),
        (
            ["liftoff", "--mass-ratio", "0.1", "--scheme", "alpha"],
            "--scheme must be left out with --mass-ratio (its contacts are stepped)",
        ),
        (
            ["liftoff", "--mass-ratio", "0.1", "--route", "full"],
            "--route must be left out with --mass-ratio (its contacts are stepped)",
        ),
        (["liftoff", "--mass-ratio", "0.1", "--recontact", "paper"], "--recontact must be window"),
    ],
)
def test_cli_refuses_options_that_do_not_apply(capsys, argv, line):
    with pytest.raises(SystemExit) as stop:
        main(argv)
    err = capsys.readouterr().err
    assert stop.value.code == 2 and err.startswith(f"twoball: error: {line}")
    assert err.count("\n") == 1


def test_liftoff_json_contract(capsys):
    code, out, _ = cli_run(capsys, "liftoff", "--json")
    data = json.loads(out)
    assert code == 0
    for key in ("lifted", "t_liftoff_s", "v_liftoff_m_s", "ratio", "phi_a_rad", "gamma", "backend"):
        assert key in data
    assert data["backend"] == "legendre" and data["lifted"] is True
    assert data["t_liftoff_s"] == pytest.approx(0.0099, rel=0.01)
    assert data["ratio"] == pytest.approx(data["v_liftoff_m_s"] / 4.1)
    assert isinstance(data["rejected"], list) and data["rejected"][0]["reason"]


def test_liftoff_table_for_people(capsys):
    code, out, _ = cli_run(capsys, "liftoff")
    assert code == 0 and "t_l [ms]" in out and "v_l [m/s]" in out


def test_v0_without_phi_a_uses_eq_3_7(capsys):
    # a speed other than the preset's own: phi_a from eq. (3.7), checked by the forward formula
    _, out, err = cli_run(capsys, "liftoff", "--v0", "-3", "--json")
    data = json.loads(out)
    c = math.cos(data["phi_a_rad"])
    v0 = 0.12 * 320 * math.sqrt((-1 + 2 * c**3 + 3 * c**2) / (6 * c))  # eq. (3.7)
    assert v0 == pytest.approx(3.0, rel=1e-12)
    assert data["phi_a_source"] == "eq. (3.7)"
    assert "note:" in err and "eq. (3.7)" in err and "measured 2.6 rad" in err


def test_preset_own_v0_keeps_the_measured_phi_a(capsys):
    # typing the preset's own value (negative: the paper's downward sign) never changes
    # the answer; how the sign was read is said in a note
    _, default, err_default = cli_run(capsys, "liftoff", "--json")
    _, typed, err = cli_run(capsys, "liftoff", "--v0", "-4.1", "--json")
    typed, default = json.loads(typed), json.loads(default)
    assert typed.pop("provenance")["case"] == default.pop("provenance")["case"]
    (note,) = typed.pop("notes")
    assert note.startswith("v0 = -4.1 m/s read as an impact at 4.1 m/s downwards")
    assert default.pop("notes") == [] and typed == default
    assert typed["phi_a_source"] == "measured (basketball)"
    assert err == f"twoball: note: {note}\n" and err_default == ""


def test_pressure_and_mass_give_the_wave_speed(capsys):
    _, out, _ = cli_run(capsys, "liftoff", "--pressure", "77200", "--mass", "0.567", "--json")
    assert json.loads(out)["wave_speed_1_s"] == pytest.approx(320.40, abs=0.01)


def test_no_liftoff_is_a_normal_result(capsys):
    code, out, _ = cli_run(capsys, "liftoff", "--damping", "0.9", "--json")
    data = json.loads(out)
    assert code == 0 and data["lifted"] is False and data["t_liftoff_s"] is None
    assert math.isfinite(data["gamma"])


def test_fem_liftoff_json_adds_backend_details(capsys):
    argv = ["liftoff", "--backend", "fem", "--mesh", "axisym", "--elements", "200", "--json"]
    code, out, _ = cli_run(capsys, *argv)
    data = json.loads(out)
    assert code == 0 and data["backend"] == "fem"
    for key in ("dofs", "modes_used", "mesh", "order", "time_scheme", "seconds"):
        assert key in data
    assert data["dofs"] == 401 and data["time_scheme"] == "modal"
    _, out, _ = cli_run(capsys, "liftoff", "--json")
    legendre = json.loads(out)
    assert data["t_liftoff_s"] == pytest.approx(legendre["t_liftoff_s"], rel=1e-6)
    assert data["v_liftoff_m_s"] == pytest.approx(legendre["v_liftoff_m_s"], rel=1e-6)


def test_fem_alpha_liftoff_with_step_in_seconds(capsys):
    argv = ["liftoff", "--backend", "fem", "--mesh", "axisym", "--elements", "100"]
    code, out, _ = cli_run(capsys, *argv, "--scheme", "alpha", "--dt", "2e-6", "--json")
    data = json.loads(out)
    assert code == 0 and data["time_scheme"] == "alpha"
    assert data["dt_s"] == pytest.approx(2e-6)
    assert data["t_liftoff_s"] == pytest.approx(0.0099, rel=0.01)


def test_cli_mass_ratio_json_matches_api():
    import json

    out = _cli("liftoff", "--mass-ratio", "0.004", "--contact-radius", "0.006", "--json")
    assert out.returncode == 0, out.stderr
    data = json.loads(out.stdout)
    api = twoball.liftoff(BASKETBALL, body=Body(0.004, contact_radius=0.006))
    assert data["v_liftoff_m_s"] == api.v_liftoff_m_s
    assert data["impacts"] == len(api.history.impacts)


def test_cli_dt_with_a_mass_ratio_is_the_moreau_jean_step(capsys):
    """``--dt`` with ``--mass-ratio`` is the step of the body's contacts: the API's
    ``MoreauJean(dt=...)``, bit for bit."""
    argv = ["--mass-ratio", "0.1", "--dt", "2.5e-5"]
    code, out, err = cli_run(capsys, "liftoff", *argv, "--json")
    assert code == 0, err
    data = json.loads(out)
    api = twoball.liftoff(BASKETBALL, body=Body(0.1), solver=twoball.MoreauJean(dt=2.5e-5))
    assert data["dt_s"] == 2.5e-5 and data["integrator"] == "moreau-jean"
    assert data["v_liftoff_m_s"] == api.v_liftoff_m_s and data["events"] == api.as_dict()["events"]
    assert (
        data["provenance"]["call"]["arguments"]["solver"]
        == api.provenance["call"]["arguments"]["solver"]
    )


def test_cli_bad_mass_ratio_is_one_line():
    out = _cli("liftoff", "--mass-ratio", "-1")
    assert out.returncode == 2
    assert out.stdout == ""
    assert (
        out.stderr.strip() == "twoball: error: --mass-ratio must be a number in [0, 100], got -1.0"
    )


def test_cli_plot_contact_sequence(tmp_path):
    target = tmp_path / "sequence.png"
    out = _cli("liftoff", "--mass-ratio", "0.004", "--plot", str(target))
    assert out.returncode == 0, out.stderr
    assert target.stat().st_size > 0
    bad = _cli("liftoff", "--plot", str(tmp_path / "x.png"))
    assert bad.returncode == 2
    assert bad.stderr.strip() == (
        "twoball: error: --plot must be given only with a mass ratio > 0 (the body's path is "
        f"drawn), got '{tmp_path / 'x.png'}'"
    )


def test_cli_refuses_unresolvable_speed_in_one_line():
    done = subprocess.run(
        [sys.executable, "-m", "twoball", "liftoff", "--v0", "1e-30", "--json"],
        cwd=ROOT,
        capture_output=True,
        text=True,
        timeout=120,
    )
    assert done.returncode == 2
    assert done.stderr.count("\n") == 1 and "--v0 must be at least" in done.stderr


def _cli_quiet(*args: str) -> subprocess.CompletedProcess[str]:
    return subprocess.run([sys.executable, "-m", "twoball", "--quiet", *args],
                          capture_output=True, text=True, timeout=300)  # fmt: skip


def test_liftoff_command_runs_the_pressurised_ball_on_both_backends():
    ball = ["--membrane", "pressurised", "--gas", "adiabatic", "--pressure", "77200",
            "--mass", "0.567", "--json"]  # fmt: skip
    closed = _cli_quiet("liftoff", *ball)
    fem = _cli_quiet("liftoff", *ball, "--backend", "fem", "--mesh", "axisym", "--elements", "200")
    assert closed.returncode == fem.returncode == 0, closed.stderr + fem.stderr
    a, b = json.loads(closed.stdout), json.loads(fem.stdout)
    assert a["membrane"] == b["membrane"] == "pressurised"
    assert b["t_liftoff_s"] == pytest.approx(a["t_liftoff_s"], rel=1e-4)  # E = 200, P2
    api = twoball.liftoff(twoball.Case.from_pressure(77200, 0.567, gas="adiabatic",
                                                     membrane="pressurised"))  # fmt: skip
    assert api.t_liftoff_s == a["t_liftoff_s"]
