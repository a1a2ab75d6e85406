"""The case options of the command line (twoball/cli/case_options.py): stiffness and presets."""

from __future__ import annotations

import json
import subprocess
import sys

import pytest

import twoball
from twoball import Case
from twoball.cli.main import main

# today's results (main at d34289e, `twoball liftoff --json ...`), bit for bit
MAIN = {
    (): (0.009882475691423885, 3.8321572905988326),
    ("--v0", "3.0"): (0.009878799082480655, 2.628216966275543),
    ("--pressure", "60000", "--mass", "0.6"): (0.01152225258566044, 4.1002966852973985),
}


class _Out:
    def __init__(self, code: int, out: str, err: str) -> None:
        self.returncode, self.stdout, self.stderr = code, out, err


@pytest.fixture
def cli(capsys):
    def run(*args: str) -> _Out:
        try:
            code = main(["liftoff", *args])
        except SystemExit as stop:
            code = stop.code
        out, err = capsys.readouterr()
        return _Out(code, out, err)

    return run


@pytest.mark.parametrize("args", list(MAIN))
def test_membrane_results_are_todays_bit_for_bit(cli, args):
    data = json.loads(cli("--json", *args).stdout)
    assert (data["t_liftoff_s"], data["v_liftoff_m_s"]) == MAIN[args]
    assert "bending_N_m" not in data and "beta" not in data


@pytest.mark.parametrize(
    "args, flag",
    [
        (("--bending", "-2"), "--bending"),
        (("--preset", "tennis", "--gas", "air"), "--gas"),
        (("--bending", "1", "--thickness", "0.003"), "--bending"),
        (("--youngs-modulus", "1e6"), "--youngs-modulus/--thickness"),
        (("--poisson", "0.3"), "--poisson"),
        (("--preset", "tennis", "--youngs-modulus", "1e6", "--thickness", "3e-3",
          "--poisson", "0.7"), "--poisson"),
        (("--preset", "squash"), "--preset"),
        (("--gas", "adiabatic", "--radius", "0.1"), "--pressure"),  # not the preset's ball
    ],
)  # fmt: skip
def test_cli_refuses_bad_stiffness_in_one_line(cli, args, flag):
    out = cli(*args)
    assert out.returncode == 2 and out.stdout == ""
    lines = out.stderr.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith(f"twoball: error: {flag}"), out.stderr


def test_cli_preset_equals_the_api_bit_for_bit(cli):
    data = json.loads(cli("--preset", "tennis", "--json").stdout)
    api = twoball.liftoff(Case.preset("tennis")).as_dict()
    for key in ("t_liftoff_s", "v_liftoff_m_s", "floor_time_s", "beta", "omega0_squared"):
        assert data[key] == api[key]
    e = cli("--preset", "tennis", "--youngs-modulus", "6e6", "--thickness", "3.2e-3", "--json")
    assert json.loads(e.stdout)["t_liftoff_s"] == api["t_liftoff_s"]


def _cli(*args: str) -> subprocess.CompletedProcess[str]:
    return subprocess.run([sys.executable, "-m", "twoball", "--quiet", *args],
                          capture_output=True, text=True, timeout=300)  # fmt: skip


@pytest.mark.parametrize(
    ("args", "flag"),
    [
        (["liftoff", "--membrane", "pressurised"], "--gas"),
        (["liftoff", "--membrane", "flat"], "--membrane"),
        (["eigen", "--membrane", "flat"], "--membrane"),
        (["converge", "modes", "--membrane", "pressurised", "--gas", "adiabatic", "--pressure",
          "77200", "--mass", "0.567", "--phi-a", "2.6", "--out", "/tmp/twoball-never-written"],
         "--membrane"),
        (["liftoff", "--membrane", "pressurised", "--gas", "adiabatic", "--pressure", "77200",
          "--mass", "0.567", "--mass-ratio", "0.1"], "--mass-ratio"),
    ],
)  # fmt: skip
def test_the_command_line_refuses_what_does_not_apply_in_one_line(args, flag):
    done = _cli(*args)
    assert done.returncode == 2
    lines = done.stderr.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith(f"twoball: error: {flag} "), done.stderr
