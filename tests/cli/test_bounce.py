"""``twoball bounce``: JSON contract, the table for people, one-line refusals (exit 2)."""

from __future__ import annotations

import json
import math

import pytest

import twoball
from twoball.cli.main import main


def run(capsys, *argv):
    code = main(list(argv))
    out = capsys.readouterr()
    return code, out.out, out.err


def test_json_carries_the_drop_in_si(capsys):
    code, out, err = run(capsys, "bounce", "--modes", "16", "--json")
    data = json.loads(out)
    assert code == 0 and "twoball: note: P = 77200 Pa" in err
    for key in ("contact_time_s", "v2_m_s", "e2", "phi_a_max_rad", "flattening_max_m"):
        assert isinstance(data[key], float), key
    for key in ("t_max_compression_s", "floor_impulse_N_s", "events", "energy_J", "warnings"):
        assert key in data, key
    assert data["provenance"]["command"].startswith("twoball bounce")
    # the command line calls the face: the same numbers
    api = twoball.bounce(drop=twoball.Drop(modes=16)).as_dict()
    assert data["e2"] == api["e2"] and data["contact_time_s"] == api["contact_time_s"]


def test_drop_height_and_table(capsys):
    code, out, _ = run(capsys, "bounce", "--modes", "16", "--drop-height", "0.5")
    assert code == 0
    assert "contact time [ms]" in out and "e2 = v2/|v0|" in out
    assert f"{math.sqrt(2 * 9.81 * 0.5):g}" in out


def test_fem_backend_with_its_mesh(capsys):
    code, out, _ = run(capsys, "bounce", "--backend", "fem", "--elements", "8", "--json")
    data = json.loads(out)
    assert code == 0 and data["model"]["resolution"] == "axisym 8 P2"


@pytest.mark.parametrize(
    ("argv", "flag"),
    [
        (["--drop-height", "-1"], "--drop-height"),
        (["--v0", "3", "--drop-height", "1"], "--drop-height"),
        (["--gas", "none", "--membrane", "pressurised"], "--gas"),
        (["--membrane", "flat"], "--membrane"),
        (["--floor-restitution", "2"], "--floor-restitution"),
        (["--elements", "10"], "--elements"),
        (["--mesh", "axisym"], "--mesh"),
        (["--backend", "fem", "--modes", "20"], "--modes"),
        (["--backend", "fem", "--mesh", "sphere"], "--mesh"),
        (["--dt", "1"], "--dt"),
        (["--dt", "1e-308"], "--dt"),
        (["--sigma", "none"], "--sigma"),
        (["--damping-model", "bogus"], "--damping-model"),
    ],
)
def test_bad_input_is_one_line_exit_2(capsys, argv, flag):
    with pytest.raises(SystemExit) as stop:
        main(["bounce", *argv])
    err = capsys.readouterr().err
    lines = err.strip().splitlines()
    assert stop.value.code == 2 and len(lines) == 1, err
    assert lines[0].startswith(f"twoball: error: {flag}") and "Traceback" not in err


def test_sweep_of_the_drop_and_figures(capsys, tmp_path):
    out = tmp_path / "speeds.png"
    code, stdout, _ = run(
        capsys,
        "sweep",
        "--bounce",
        "--param",
        "v0",
        "--values",
        "2,4.1",
        "--modes",
        "16",
        "--plot",
        str(out),
        "--json",
    )
    data = json.loads(stdout)
    assert code == 0 and len(data["results"]) == 2 and out.stat().st_size > 1000
    assert data["results"][1]["e2"] < data["results"][0]["e2"]
    figure = tmp_path / "drop.pdf"
    code, _, _ = run(capsys, "bounce", "--modes", "16", "--plot", str(figure))
    assert code == 0 and figure.stat().st_size > 1000


@pytest.mark.parametrize(
    ("argv", "flag"),
    [
        (["sweep", "--param", "drop-height", "--values", "1,2"], "--param"),
        (
            ["sweep", "--param", "v0", "--values", "1,2", "--floor-restitution", "1"],
            "--floor-restitution",
        ),
        (["sweep", "--bounce", "--param", "damping", "--values", "0.1"], "--param"),
        (["bounce", "--plot", "drop.bogus"], "--plot"),
    ],
)
def test_sweep_and_plot_refusals(capsys, argv, flag):
    with pytest.raises(SystemExit) as stop:
        main(argv)
    err = capsys.readouterr().err
    assert stop.value.code == 2 and err.startswith(f"twoball: error: {flag}"), err
