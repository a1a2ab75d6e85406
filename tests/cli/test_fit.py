"""twoball fit: the CSV columns in --help, the API's numbers, one-line refusals, the figure."""

from __future__ import annotations

import json

import pytest

import twoball
from tests.helpers import cli_run
from twoball._common.choices import FIT_PARAMETERS, MEASURED_COLUMNS
from twoball.cli.main import main

PAPER = "# the paper's one point (§4(b))\nv0_m_s,phi_a_rad,v1_m_s\n4.1,2.6,3.7\n"


@pytest.fixture
def paper(tmp_path):
    path = tmp_path / "paper.csv"
    path.write_text(PAPER)
    return path


def refused(capsys, *argv: str) -> str:
    """The one error line of ``twoball ARGV`` (exit status 2)."""
    with pytest.raises(SystemExit) as stop:
        main(list(argv))
    lines = capsys.readouterr().err.strip().splitlines()
    assert stop.value.code == 2, lines
    errors = [line for line in lines if line.startswith("twoball: error: ")]
    assert len(errors) == 1 and len(lines) == 1, lines
    return errors[0]


def test_help_documents_the_csv_columns(capsys):
    with pytest.raises(SystemExit) as stop:
        main(["fit", "--help"])
    out = capsys.readouterr().out
    assert stop.value.code == 0
    for column in (*MEASURED_COLUMNS, "sigma_COLUMN"):
        assert f"- {column}: " in out
    for name in FIT_PARAMETERS:
        assert name in out
    assert "v0_m_s,phi_a_rad,v1_m_s" in out  # the example file


def test_the_papers_fit_on_the_command_line_is_the_apis(capsys, paper):
    code, out, err = cli_run(capsys, "fit", "--data", str(paper), "--param", "damping", "--json")
    data = json.loads(out)
    api = twoball.fit(paper, "damping").as_dict()
    assert code == 0 and data["parameters"] == api["parameters"]
    assert data["rows"] == api["rows"] and data["chi2"] == api["chi2"]
    assert data["provenance"]["command"].startswith("twoball fit --data")
    assert "no degrees of freedom" in err  # said as a warning, with the JSON's
    code, out, _ = cli_run(capsys, "fit", "--data", str(paper), "--param", "damping")
    assert code == 0 and "0.132896" in out and "Rows: measured, model and residual" in out


def test_a_synthetic_file_with_the_figure_and_the_bootstrap(capsys, tmp_path):
    case = twoball.Case.preset("basketball", damping=0.2)
    lines = ["v0_m_s,v1_m_s,sigma_v1_m_s"]
    for k, v0 in enumerate((3.0, 3.5, 4.5, 5.0, 5.5)):
        v1 = twoball.liftoff(case.derive(v0=v0)).v_liftoff_m_s + (-1) ** k * 0.02
        lines.append(f"{v0},{v1!r},0.02")
    path = tmp_path / "rows.csv"
    path.write_text("\n".join(lines) + "\n")
    figure = tmp_path / "fit.svg"
    argv = ["fit", "--data", str(path), "--param", "damping", "--plot", str(figure)]
    code, out, _ = cli_run(capsys, *argv, "--bootstrap", "5", "--start", "damping=0.15")
    assert code == 0 and figure.stat().st_size > 5_000
    assert "bootstrap error" in out and "chi^2 = " in out and "sigma weights" in out
    code, out, _ = cli_run(capsys, *argv, "--json")
    data = json.loads(out)
    assert data["parameters"]["damping"]["value"] == pytest.approx(0.2, abs=3e-3)
    assert data["weighting"] == "sigma" and len(data["rows"]) == 5


@pytest.mark.parametrize(
    ("text", "parts"),
    [
        (None, ["missing.csv", "no such file"]),
        ("", ["an empty file"]),
        ("4.1,2.6,3.7\n", ["line 1", "header"]),
        ("v0_m_s,velocity\n4.1,3\n", ["line 1", "column velocity"]),
        ("v0_m_s,v1_m_s\n4.1,3.7\n4.0,fast\n", ["row 2 (line 3)", "column v1_m_s", "'fast'"]),
        ("v0_m_s,v1_m_s\n", ["at least one row"]),
        ("v0_m_s,v2_m_s\n4.1,3\n", ["column v2_m_s", "model bounce"]),
    ],
)
def test_a_bad_file_is_one_line_naming_the_file_the_row_and_the_column(
    capsys, tmp_path, text, parts
):
    path = tmp_path / "missing.csv"
    if text is not None:
        path = tmp_path / "data.csv"
        path.write_text(text)
    line = refused(capsys, "fit", "--data", str(path), "--param", "damping")
    assert line.startswith(f"twoball: error: --data {path}")
    for part in parts:
        assert part in line


@pytest.mark.parametrize(
    ("extra", "flag"),
    [
        (["--param", "restitution"], "--param"),
        (["--model", "whole"], "--model"),
        (["--start", "damping"], "--start"),
        (["--start", "wave-speed=300"], "--start"),
        (["--start", "damping=2"], "--start"),
        (["--bounds", "damping=0.3"], "--bounds"),
        (["--bounds", "damping=0.3:0.1"], "--bounds"),
        (["--bootstrap", "-1"], "--bootstrap"),
        (["--pair", "tennis-coin"], "--pair"),
        (["--gap", "0.1"], "--gap"),
        (["--mass-ratio", "0.1"], "--mass-ratio"),
        (["--dt", "1e-5"], "--dt"),
        (["--damping", "2"], "--damping"),
        (["--plot", "fit.bogus"], "--plot"),
        (["--model", "bounce"], "--data"),  # phi_a_rad: the closed form's input
        (["--model", "bounce", "--phi-a", "2.6"], "--phi-a"),
        (["--model", "bounce", "--sigma", "none"], "--sigma"),
        (["--model", "bounce", "--pair", "tennis-coin", "--preset", "tennis"], "--preset"),
        (["--model", "bounce", "--pair", "tennis-coin", "--restitution", "0.5"], "--restitution"),
    ],
)
def test_bad_options_are_one_line_naming_the_flag(capsys, paper, extra, flag):
    line = refused(capsys, "fit", "--data", str(paper), "--param", "damping", *extra)
    assert flag in line


def test_the_whole_bounce_on_the_command_line(capsys, tmp_path):
    """e12 of the tennis-coin pair from one row made at e12 = 0.5 (coarse ball and step)."""
    solver = twoball.MoreauJean(twoball.LegendreBall(8), dt=4e-5)
    body = twoball.Body(0.062, contact_radius=0.01015, restitution=0.5)
    made = twoball.bounce(
        twoball.Case.preset("tennis"), twoball.Drop(gap=0.05), solver=solver, body=body
    )
    path = tmp_path / "coin.csv"
    path.write_text(f"gap_m,v1_m_s\n0.05,{made.v1_m_s!r}\n")
    argv = ["fit", "--data", str(path), "--param", "restitution", "--model", "bounce"]
    argv += ["--pair", "tennis-coin", "--modes", "8", "--dt", "4e-5", "--json"]
    code, out, _ = cli_run(capsys, *argv)
    data = json.loads(out)
    assert code == 0 and data["parameters"]["restitution"]["value"] == pytest.approx(0.5, abs=2e-3)
    assert data["solver"]["pair"] == "tennis-coin" and data["solver"]["ball"]["modes"] == 8
