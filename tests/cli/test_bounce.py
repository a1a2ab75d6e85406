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
    api = twoball.bounce(solver=twoball.MoreauJean(twoball.LegendreBall(16))).as_dict()
    assert data["e2"] == api["e2"] and data["contact_time_s"] == api["contact_time_s"]


def test_drop_height_and_table(capsys):
    code, out, _ = run(capsys, "bounce", "--modes", "16", "--drop-height", "0.5")
    assert code == 0
    assert "contact time [ms]" in out and "e2 = v2/|v0|" in out
    assert f"{math.sqrt(2 * 9.81 * 0.5):g}" in out


def test_json_damping_and_bending_in_si_under_their_own_names(capsys):
    """--rayleigh ALPHA,BETA comes back as given in SI (alpha_1_s, beta_s), the same law in
    units of c as alpha / c and beta c; the bending has its own keys (B in N m and the
    ratio B / (T R^2)), so no key of the model block is Rayleigh's and the bending's at once."""
    code, out, err = run(capsys, "bounce", "--modes", "16", "--rayleigh", "94.5,1.133e-4", "--json")
    assert code == 0, err
    model = json.loads(out)["model"]
    law = model["damping"]
    assert law["law"] == "rayleigh" and law["fitted"] is False
    assert law["alpha_1_s"] == 94.5 and law["beta_s"] == 1.133e-4
    assert law["alpha_c_units"] == pytest.approx(94.5 / 320.0, rel=1e-15)
    assert law["beta_c_units"] == pytest.approx(1.133e-4 * 320.0, rel=1e-15)
    assert "alpha" not in law and "beta" not in law and "beta" not in model
    assert model["bending_N_m"] == 0.0 and model["bending_beta"] == 0.0
    code, out, _ = run(capsys, "bounce", "--modes", "16", "--preset", "tennis", "--json")
    data = json.loads(out)
    model, case = data["model"], twoball.Case.preset("tennis")
    tension = data["pressure_Pa"] * case.radius / 2.0  # T = P R / 2
    assert model["bending_N_m"] == case.bending > 0.0
    assert model["bending_beta"] == pytest.approx(case.bending / (tension * case.radius**2))
    code, out, _ = run(capsys, "bounce", "--modes", "16", "--damping-model", "rayleigh", "--json")
    law = json.loads(out)["model"]["damping"]
    assert law["fitted"] is True
    assert law["alpha_1_s"] == pytest.approx(law["alpha_c_units"] * 320.0, rel=1e-14)
    assert law["beta_s"] == pytest.approx(law["beta_c_units"] / 320.0, rel=1e-14)
    code, out, _ = run(capsys, "bounce", "--modes", "16", "--rayleigh", "94.5,1.133e-4")
    assert "rayleigh, alpha 94.5 1/s, beta 0.0001133 s" in out


def test_a_drop_height_below_the_radius_names_the_range_and_v0(capsys):
    with pytest.raises(SystemExit) as stop:
        main(["bounce", "--drop-height", "0.05"])
    (line,) = capsys.readouterr().err.strip().splitlines()
    assert stop.value.code == 2 and line.startswith("twoball: error: --drop-height must be")
    assert ">= R = 0.12 m" in line and "--v0" in line and line.endswith("got 0.05")


def test_the_centre_height_is_the_papers_x2(capsys):
    # eq. (2.1): x2 = 0.92 m, R = 0.12 m -> a fall of 0.80 m -> sqrt(2 g 0.80) = 3.96 m/s
    argv = ["bounce", "--modes", "16", "--json"]
    code, out, err = run(capsys, *argv, "--centre-height", "0.92")
    data = json.loads(out)
    assert code == 0 and round(data["v0_m_s"], 2) == 3.96
    assert data["v0_m_s"] == pytest.approx(math.sqrt(2 * 9.81 * 0.80), rel=1e-12)
    assert data["drop_height_m"] == pytest.approx(0.80, rel=1e-12)
    assert data["centre_height_m"] == 0.92 and "x2 - R = 0.8 m" in err
    code, out, _ = run(capsys, *argv, "--drop-height", "0.80")
    same = json.loads(out)
    assert same["v0_m_s"] == pytest.approx(data["v0_m_s"], rel=1e-12)
    assert same["e2"] == pytest.approx(data["e2"], rel=1e-9)
    assert same["contact_time_s"] == pytest.approx(data["contact_time_s"], rel=1e-9)


def test_fem_backend_with_its_mesh(capsys):
    code, out, _ = run(capsys, "bounce", "--backend", "fem", "--elements", "8", "--json")
    data = json.loads(out)
    assert code == 0 and data["model"]["resolution"] == "axisym 8 P2"


@pytest.mark.parametrize(
    ("argv", "flag"),
    [
        (["--drop-height", "-1"], "--drop-height"),
        (["--drop-height", "0.05"], "--drop-height"),
        (["--v0", "3", "--drop-height", "1"], "--drop-height"),
        (["--centre-height", "0.92", "--drop-height", "0.8"], "--centre-height"),
        (["--centre-height", "0.92", "--v0", "4.1"], "--centre-height"),
        (["--centre-height", "0.2"], "--centre-height"),
        (["--centre-height", "-1"], "--centre-height"),
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
        (["sweep", "--bounce", "--param", "wave-speed", "--values", "300"], "--param"),
        (["bounce", "--plot", "drop.bogus"], "--plot"),
    ],
)
def test_sweep_and_plot_refusals(capsys, argv, flag):
    with pytest.raises(SystemExit) as stop:
        main(argv)
    err = capsys.readouterr().err
    assert stop.value.code == 2 and err.startswith(f"twoball: error: {flag}"), err


# --- ``twoball bounce`` with a body and ``twoball sweep --bounce --param gap|mass-ratio``


def test_json_of_a_pair_is_the_apis(capsys):
    code, out, err = run(capsys, "bounce", "--pair", "basketball-tissue", "--modes", "24", "--json")
    data = json.loads(out)
    assert code == 0 and "pair basketball-tissue (Table 1 row 5)" in err
    for key in (
        "v1_m_s",
        "v1_ratio",
        "v2_ratio",
        "t_liftoff_s",
        "t_liftoff_from_max_compression_s",
    ):
        assert isinstance(data[key], float), key
    assert isinstance(data["body_left_first"], bool) and "e12_effective" in data
    solver = twoball.MoreauJean(twoball.LegendreBall(24))
    api = twoball.bounce(solver=solver, pair="basketball-tissue").as_dict()
    assert data["v1_ratio"] == api["v1_ratio"] and data["events"] == api["events"]
    assert data["baselines"]["models"]["icm"] == api["baselines"]["models"]["icm"]


def test_a_body_by_its_options_with_a_gap_and_the_table(capsys):
    argv = ["bounce", "--modes", "24", "--mass-ratio", "0.05", "--contact-radius", "0.02"]
    code, out, _ = run(capsys, *argv, "--restitution", "0.6", "--gap", "0.2")
    assert code == 0
    for row in ("v1 [m/s], v1/|v0|", "e12 effective", "sequence, body left first", "icm"):
        assert row in out, row
    assert "independent" in out


def test_export_render_and_plot_of_the_whole_bounce(capsys, tmp_path):
    files = [tmp_path / "w.pvd", tmp_path / "w.gif", tmp_path / "w.svg"]
    code, _, _ = run(
        capsys,
        "bounce",
        "--pair",
        "tennis-coin",
        "--modes",
        "16",
        "--export",
        str(files[0]),
        "--render",
        str(files[1]),
        "--frames",
        "3",
        "--plot",
        str(files[2]),
    )
    assert code == 0
    assert all(f.stat().st_size > 400 for f in files)
    assert len(list(tmp_path.glob("w_frames*/*.vtu"))) == 3  # one per frame beside the .pvd


def test_sweep_of_the_gap_on_two_workers(capsys, tmp_path):
    figure = tmp_path / "gap.png"
    argv = ["sweep", "--bounce", "--pair", "basketball-table-tennis", "--param", "gap"]
    code, out, _ = run(
        capsys, *argv, "--values", "0,0.2", "--modes", "16", "--workers", "2", "--plot", str(figure)
    )
    assert code == 0 and "Whole bounce against gap" in out and figure.stat().st_size > 1000
    code, out, _ = run(capsys, *argv, "--values", "0,0.2", "--modes", "16", "--json")
    points = json.loads(out)["results"]
    assert [p["value"] for p in points] == [0.0, 0.2]
    assert points[1]["sequence"] == "independent" and points[0]["body_left_first"] is True


def test_the_table_says_the_artefact_and_the_undefined_e12(capsys):
    code, out, err = run(capsys, "bounce", "--pair", "basketball-tennis", "--modes", "32")
    section = "'The degree-1 artefact, and what depends on it'"
    assert code == 0 and section in err  # stderr: twoball: warning: ...
    rows = {line.split("│")[1].strip(): line for line in out.splitlines() if "│" in line}
    assert "depends on that artefact" in rows["warning"]
    assert "not defined" in rows["e12 effective (eq. (2.4))"]
    assert "not defined" in rows["ICM (2.5), this e2 and e12_eff"]
    assert "the contacts overlap" in err  # the note
    code, out, _ = run(capsys, "bounce", "--pair", "basketball-tennis", "--modes", "32", "--json")
    data = json.loads(out)
    assert set(data["caveats"]) == {"artefact", "overlap"}
    assert any(section in w for w in data["warnings"])


def test_a_gap_sweep_marks_its_caveats_in_the_table_json_and_plot(capsys, tmp_path):
    figure = tmp_path / "gap.svg"
    argv = ["sweep", "--bounce", "--pair", "basketball-tennis", "--param", "gap"]
    argv += ["--values", "0,0.25", "--modes", "32", "--workers", "1"]
    code, out, err = run(capsys, *argv, "--plot", str(figure))
    assert code == 0
    rows = [line for line in out.splitlines() if line.startswith("│")]
    assert "artefact, overlap" in rows[0] and "e12_low" in rows[1]
    caption = " ".join(out.split())  # the table's caption, wrapped to the terminal
    assert "'What the whole bounce reproduces, and what it does not'" in caption
    assert "1 of 2 points (gap = 0.25): e12_effective below 0.5" in err
    drawing = figure.read_text()
    assert "depends on the degree-1 artefact" in drawing
    assert "The degree-1 artefact, and what depends on it" in drawing
    code, out, _ = run(capsys, *argv, "--json")
    points = json.loads(out)["results"]
    assert [p["caveats"] for p in points] == [["artefact", "overlap"], ["e12_low"]]


@pytest.mark.parametrize(
    ("argv", "flag"),
    [
        (["bounce", "--pair", "bogus"], "--pair"),
        (["bounce", "--pair", "tennis-coin", "--mass-ratio", "0.1"], "--mass-ratio"),
        (["bounce", "--pair", "tennis-coin", "--preset", "basketball"], "--preset"),
        (["bounce", "--gap", "0.05"], "--gap"),
        (["bounce", "--mass-ratio", "0.1", "--gap", "-1"], "--gap"),
        (["bounce", "--mass-ratio", "0"], "--mass-ratio"),
        (["bounce", "--mass-ratio", "0.1", "--restitution", "1.5"], "--restitution"),
        (["bounce", "--mass-ratio", "0.1", "--energy", "both"], "--energy"),
        (["bounce", "--export", "x.bogus"], "--export"),
        (["bounce", "--render", "x.bogus"], "--render"),
        (["bounce", "--frames", "3"], "--frames"),
        (["sweep", "--bounce", "--param", "gap", "--values", "0,0.1"], "--gap"),
        (["sweep", "--param", "gap", "--values", "0,0.1"], "--param"),
        (["sweep", "--param", "damping", "--values", "0.1", "--gap", "0.1"], "--gap"),
    ],
)
def test_refusals_are_one_line_naming_the_flag(capsys, argv, flag):
    with pytest.raises(SystemExit) as stop:
        main(argv)
    err = capsys.readouterr().err
    lines = err.strip().splitlines()
    assert stop.value.code == 2 and len(lines) == 1, err
    assert lines[0].startswith(f"twoball: error: {flag}") and "Traceback" not in err


@pytest.mark.parametrize(
    ("argv", "resolution"),
    [
        ([], "axisym 96 P2"),
        (["--order", "2"], "axisym 96 P2"),
        (["--mesh", "axisym"], "axisym 96 P2"),
        (["--order", "3"], "axisym 64 P3"),
        (["--order", "4", "--elements", "20"], "axisym 20 P4"),
    ],
)
def test_an_explicit_default_order_is_the_default_line(capsys, argv, resolution):
    """``--order 2`` is what no ``--order`` gives; other orders keep the node spacing pi/192."""
    window = ["--t-end", "0.002"]
    code, out, _ = run(capsys, "bounce", "--backend", "fem", *argv, *window, "--json")
    assert code == 0 and json.loads(out)["model"]["resolution"] == resolution


@pytest.mark.parametrize("argv", [["--mass-ratio", "0.1"], ["--pair", "tennis-coin"]])
def test_the_whole_bounce_runs_at_order_three(capsys, argv):
    """P3 with a body (its cap average probes the line) ends in a report, not a traceback."""
    fem = ["--backend", "fem", "--order", "3", "--elements", "16", "--t-end", "0.004"]
    code, out, _ = run(capsys, "bounce", *fem, *argv, "--json")
    assert code == 0 and json.loads(out)["model"]["resolution"] == "axisym 16 P3"
