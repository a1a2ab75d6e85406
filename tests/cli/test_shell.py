"""``--ball shell`` on the command line: the drop, the whole bounce, the spectrum, the refusals."""

from __future__ import annotations

import math

import pytest

import twoball
from tests._common.commands import refused
from tests.helpers import cli_json, cli_run


def test_bounce_with_the_shell_reports_the_wall(capsys):
    data, _ = cli_json(capsys, "bounce", "--ball", "shell", "--modes", "16")
    api = twoball.bounce(solver=twoball.MoreauJean(twoball.ShellBall(modes=16))).as_dict()
    assert data["e2"] == api["e2"] and data["contact_time_s"] == api["contact_time_s"]
    model = data["model"]
    assert model["ball"] == "shell" and model["resolution"] == "shell legendre N = 16"
    assert model["wall"]["wall_stiffness_ratio"] == pytest.approx(4.0)
    assert (
        model["in_plane_arrival_s"]
        < model["pressure_wave_arrival_s"]
        == pytest.approx(math.pi / 320.0)
    )
    code, out, _ = cli_run(capsys, "bounce", "--ball", "shell", "--modes", "16")
    assert code == 0 and "C/N0, h/R" in out and "pi R/c_e" in out


def test_the_si_wall_and_the_ratios(capsys):
    si, _ = cli_json(
        capsys, "bounce", "--ball", "shell", "--preset", "tennis", "--youngs-modulus", "6e6",
        "--thickness", "0.0032", "--poisson", "0.5", "--backend", "fem", "--elements", "12",
    )  # fmt: skip
    wall = si["model"]["wall"]
    assert wall["given"] == "si" and wall["thickness_m"] == 0.0032
    ratio = wall["wall_stiffness_ratio"]
    same, _ = cli_json(
        capsys, "bounce", "--ball", "shell", "--preset", "tennis", "--wall-stiffness-ratio",
        repr(ratio), "--thickness-ratio", repr(0.0032 / 0.0335), "--backend", "fem",
        "--elements", "12",
    )  # fmt: skip
    assert same["model"]["wall"]["given"] == "ratios"
    assert same["e2"] == pytest.approx(si["e2"], rel=1e-12)
    # for the membrane the same flags are its bending: a different ball
    membrane, _ = cli_json(capsys, "bounce", "--preset", "tennis", "--modes", "16")
    assert membrane["model"]["membrane"] == "pressurised" and "wall" not in membrane["model"]


def test_the_whole_bounce_with_the_pair(capsys):
    data, _ = cli_json(
        capsys, "bounce", "--ball", "shell", "--pair", "tennis-coin", "--gap", "0.01",
        "--modes", "16",
    )  # fmt: skip
    assert data["body"]["pair"] == "tennis-coin" and data["v1_ratio"] > 0.5
    assert data["model"]["wall"]["youngs_modulus_Pa"] == 6e6
    custom, _ = cli_json(
        capsys, "bounce", "--ball", "shell", "--preset", "tennis", "--mass-ratio", "0.05",
        "--modes", "16", "--backend", "legendre",
    )  # fmt: skip
    assert custom["body"]["mass_ratio"] == 0.05


@pytest.mark.parametrize(
    ("argv", "flag"),
    [
        (["--ball", "shell", "--bending", "0.01"], "--bending"),
        (["--ball", "shell", "--membrane", "paper"], "--membrane"),
        (["--ball", "shell", "--mesh", "axisym", "--backend", "fem"], "--mesh"),
        (["--ball", "shell", "--backend", "fem", "--order", "4"], "--order"),
        (["--ball", "shell", "--backend", "fem", "--modes", "32"], "--modes"),
        (["--ball", "shell", "--elements", "32"], "--elements"),
        (["--ball", "shell", "--thickness-ratio", "0.03"], "--thickness-ratio"),
        (["--ball", "shell", "--youngs-modulus", "6e6"], "--thickness"),
        (
            [
                "--ball",
                "shell",
                "--youngs-modulus",
                "6e6",
                "--thickness",
                "0.003",
                "--wall-stiffness-ratio",
                "3",
            ],
            "--wall-stiffness-ratio",
        ),  # fmt: skip
        (["--ball", "shell", "--wall-stiffness-ratio", "-1"], "--wall-stiffness-ratio"),
        (["--ball", "shell", "--modes", "4"], "--modes"),
        (["--wall-stiffness-ratio", "3"], "--wall-stiffness-ratio"),
        (["--ball", "rubber"], "--ball"),  # solid and thick are balls now
    ],
)
def test_flags_that_do_not_apply_are_refused_by_name(capsys, argv, flag):
    line = refused(capsys, ["bounce", *argv])
    assert line.startswith(f"twoball: error: {flag} "), line


def test_eigen_of_the_shell_both_backends(capsys):
    rows, _ = cli_json(
        capsys, "eigen", "--ball", "shell", "--poisson", "0.3", "--count", "5",
    )  # fmt: skip
    assert [(r["degree"], r["branch"]) for r in rows[:5]] == [
        (0, 1),
        (1, 1),
        (1, 2),
        (2, 1),
        (2, 2),
    ]
    assert rows[1]["value"] == 0.0  # the translation
    # Baker's membrane shell (p = beta_h = 0), nu = 0.3: n = 2, 3, 5
    values = {(r["degree"], r["branch"]): r["value"] for r in rows}
    for key, expected in {(2, 1): 0.7009, (2, 2): 2.7219, (3, 1): 0.8299, (5, 2): 5.5750}.items():
        assert values[key] == pytest.approx(expected, abs=6e-5)
    fe, _ = cli_json(
        capsys, "eigen", "--ball", "shell", "--backend", "fem", "--elements", "32",
        "--poisson", "0.5", "--thickness-ratio", "0.05", "--prestress-ratio", "0.05",
        "--gas", "0.2", "--count", "4",
    )  # fmt: skip
    assert all(r["relative_error"] < 1e-4 for r in fe)
    assert "omega_rad_s" not in fe[0]


def test_eigen_of_a_preset_shell_in_hertz(capsys):
    rows, _ = cli_json(capsys, "eigen", "--ball", "shell", "--preset", "tennis", "--count", "2")
    n2 = next(r for r in rows if (r["degree"], r["branch"]) == (2, 1))
    assert n2["frequency_hz"] == pytest.approx(270.6, abs=0.1)  # the tennis wall, no gas
    assert n2["omega_rad_s"] == pytest.approx(2 * math.pi * n2["frequency_hz"])


@pytest.mark.parametrize(
    ("argv", "flag"),
    [
        (["--ball", "shell", "--level", "2"], "--level"),
        (["--ball", "shell", "--elements", "8"], "--elements"),
        (["--ball", "shell", "--gas", "adiabatic"], "--gas"),
        (
            ["--ball", "shell", "--preset", "tennis", "--prestress-ratio", "0.1"],
            "--prestress-ratio",
        ),
        (["--ball", "shell", "--youngs-modulus", "6e6"], "--youngs-modulus"),
        (["--ball", "shell", "--poisson", "0.7"], "--poisson"),
        (["--ball", "shell", "--backend", "spectral"], "--backend"),
        (["--prestress-ratio", "0.1"], "--prestress-ratio"),
    ],
)
def test_eigen_refuses_by_name(capsys, argv, flag):
    line = refused(capsys, ["eigen", *argv])
    assert line.startswith(f"twoball: error: {flag} "), line
