"""twoball sweep: JSON in order, grids, workers, failed points, bad input in one line."""

import json

import pytest

from tests.helpers import cli_run
from tests.verify.sweeps.helpers import FailAbove
from twoball.cli.main import main
from twoball.verify.sweeps import parallel


def test_sweep_json_in_order(capsys):
    code, out, _ = cli_run(capsys, "sweep", "--param", "v0", "--values", "2:8:4", "--json")
    data = json.loads(out)["results"]
    assert code == 0 and [d["v0_m_s"] for d in data] == pytest.approx([2, 4, 6, 8])
    assert len({d["phi_a_rad"] for d in data}) == 4  # phi_a re-derived per value


def test_sweep_modes(capsys):
    code, out, _ = cli_run(capsys, "sweep", "--param", "modes", "--values", "30:60:2", "--json")
    assert code == 0 and [d["modes"] for d in json.loads(out)["results"]] == [30, 60]


def test_sweep_cli_reports_failed_points(capsys, monkeypatch):
    monkeypatch.setattr("twoball.verify.sweeps.sweeps.SweepSolver", lambda *a, **k: FailAbove(3.0))
    assert main(["sweep", "--param", "v0", "--values", "2:4:3", "--json", "--workers", "1"]) == 0
    rows = json.loads(capsys.readouterr().out)["results"]
    assert [r["error"] is not None for r in rows] == [False, False, True]
    assert all(r["phi_a_source"] == "eq. (3.7)" for r in rows)  # failed points too
    assert main(["sweep", "--param", "v0", "--values", "2:4:3", "--workers", "1"]) == 0
    assert "NumericalError" in capsys.readouterr().out


def test_sweep_cli_workers_give_the_same_json(capsys):
    argv = ["sweep", "--param", "damping", "--values", "0:0.4:24", "--json"]
    main([*argv, "--workers", "1"])
    serial = json.loads(capsys.readouterr().out)
    main([*argv, "--workers", "2"])
    parallel = json.loads(capsys.readouterr().out)
    assert parallel["results"] == serial["results"]  # the provenance names the workers
    assert parallel["provenance"]["call"]["arguments"]["workers"] == 2


def test_grid_cli_json_and_heat_map(capsys, tmp_path):
    png = tmp_path / "grid.png"
    argv = ["sweep", "--param", "damping", "--values", "0.05:0.3:3"]
    argv += ["--param", "v0", "--values", "2:6:2", "--json", "--plot", str(png)]
    assert main(argv) == 0
    rows = json.loads(capsys.readouterr().out)["results"]
    assert [r["index"] for r in rows] == [[i, j] for i in range(3) for j in range(2)]
    assert png.stat().st_size > 10_000 and png.read_bytes()[:4] == b"\x89PNG"
    assert not [p for p in tmp_path.iterdir() if p.name.startswith(".")]


@pytest.mark.parametrize(
    ("argv", "flag"),
    [
        (["--param", "v0", "--values", "1:2"], "--values"),
        (["--param", "v0", "--values", "1:x:3"], "--values"),
        (["--param", "v0", "--param", "damping", "--values", "1:2:3"], "--values"),
        (["--param", "v0", "--values", "1:2:3", "--values", "0:1:2"], "--values"),
        (["--param", "v0", "--param", "v0", "--values", "1:2:3", "--values", "1:2:3"], "--param"),
        (["--param", "v0", "--values", "1:2:3", "--workers", "0"], "--workers"),
        (["--param", "v0", "--values", "1:2:3", "--workers", "two"], "--workers"),
        (["--param", "v0", "--values", "1:2:3", "--plot", "/nonexistent/dir/a.png"], "--plot"),
        (["--param", "v0", "--values", "1:2:3", "--plot", "/tmp/a.xyz"], "--plot"),
    ],
)
def test_bad_sweep_input_is_one_line_exit_2(capsys, argv, flag):
    with pytest.raises(SystemExit) as stop:
        main(["sweep", *argv])
    err = capsys.readouterr().err.strip().splitlines()
    assert stop.value.code == 2 and len(err) == 1 and flag in err[0]


def test_unreachable_scheduler_is_one_line_exit_2(capsys, monkeypatch):
    pytest.importorskip("distributed")
    monkeypatch.setattr(parallel, "CONNECT_TIMEOUT", "0.5s")
    with pytest.raises(SystemExit) as stop:
        main(["sweep", "--param", "v0", "--values", "1:2:3", "--scheduler", "tcp://127.0.0.1:9"])
    err = capsys.readouterr().err.strip().splitlines()
    assert stop.value.code == 2 and len(err) == 1 and "--scheduler" in err[0]


def test_a_sweep_in_which_no_point_could_run_is_an_error(tmp_path, capsys):
    """Every point over the budget (each N's series with its reference above 3 s, the
    sweep's total of 3 s on two workers not): one line naming --max-time, status 2, and
    no table or file; the point's estimate is the cost model's own number."""
    from twoball._common.budget import Budget, BudgetError
    from twoball._common.budget import format_seconds as shown
    from twoball.modal.cost import case_liftoff_work
    from twoball.modal.parameters import Case

    option, estimate = case_liftoff_work(Case.preset("basketball", modes=1400), None)
    assert estimate.seconds > 3.0  # the premise: the point alone is over the limit
    with pytest.raises(BudgetError):
        Budget(2**40, 3.0).check(option, estimate)
    csv = tmp_path / "s.csv"
    argv = ["sweep", "--param", "modes", "--values", "1400,1500", "--workers", "2"]
    capsys.readouterr()
    with pytest.raises(SystemExit) as stop:
        main([*argv, "--max-time", "3s", "--csv", str(csv)])
    out, err = capsys.readouterr()
    lines = err.strip().splitlines()
    assert stop.value.code == 2 and out == "" and not csv.exists()
    assert lines[-1] == (
        "twoball: error: no point of the sweep could run (all 2 points failed); at modes = "
        f"1400: modes 1400 needs ~{shown(estimate.seconds)}; limit 3 s (raise the time limit, "
        "--max-time)"
    )


def test_a_point_over_the_budget_is_named_by_the_flag(capsys):
    """Some points run: the table shows them and the others' errors, flags not keywords."""
    argv = ["sweep", "--param", "modes", "--values", "30,1500", "--workers", "2"]
    assert main([*argv, "--max-time", "3s"]) == 0
    out = capsys.readouterr().out
    assert "--max-time" in out and "max_time" not in out.replace("--max-time", "")


@pytest.mark.parametrize(
    ("param", "values", "own"),
    [("v0", "3,4.1,5", 1), ("wave-speed", "300,320,340", 1), ("v0", "3,5", None)],
)
def test_one_phi_a_rule_and_one_label_per_sweep(capsys, param, values, own):
    """A sweep of v0 or c through the basketball's own point (4.1 m/s, 320 1/s) takes eq.
    (3.7) there too, and says so once: one note, one caption, no label per row."""
    from twoball.modal.initial import phi_a_from_v0

    code, out, err = cli_run(capsys, "sweep", "--param", param, "--values", values)
    assert code == 0
    notes = [line for line in err.splitlines() if line.startswith("twoball: note: phi_a")]
    assert len(notes) == 1 and "eq. (3.7) at every point" in notes[0]
    assert ("own R, c, |v0| included" in notes[0]) == (own is not None)
    assert out.count("eq. (3.7)") == 1 and "phi_a: eq. (3.7) at every point" in out
    assert "phi_a from" not in out and "measured (basketball)" not in out
    _, text, _ = cli_run(capsys, "sweep", "--param", param, "--values", values, "--json")
    points = json.loads(text)["results"]
    assert {p["phi_a_source"] for p in points} == {"eq. (3.7)"}
    assert len({p["phi_a_rule"] for p in points}) == 1
    if own is not None:  # the preset's own point: eq. (3.7)'s angle, not the measured 2.6
        at = points[own]
        assert at["phi_a_rad"] == pytest.approx(phi_a_from_v0(4.1, 0.12, 320.0), rel=1e-12)
        assert at["phi_a_rad"] != 2.6
        (note,) = [n for n in at["notes"] if n.startswith("phi_a = ")]
        assert "as asked, at the basketball preset's own R, c, |v0|" in note


# --- ``twoball sweep --bounce`` with the lower ball's and the body's kinds -----------------

KINDS = ["--ball", "shell", "--body", "lumped", "--pair", "basketball-tennis", "--modes", "16"]


def test_a_gap_sweep_of_the_shell_and_a_lumped_body_is_two_bounces(capsys):
    argv = ["sweep", "--bounce", "--param", "gap", "--values", "0,0.01", *KINDS]
    code, out, _ = cli_run(capsys, *argv, "--workers", "1", "--json")
    points = json.loads(out)["results"]
    assert code == 0 and [p["value"] for p in points] == [0.0, 0.01]
    for point in points:
        code, out, _ = cli_run(capsys, "bounce", *KINDS, "--gap", f"{point['value']:g}", "--json")
        single = json.loads(out)
        assert code == 0 and single["body"]["kind"] == "lumped" == point["body"]["kind"]
        assert single["model"]["ball"] == "shell" == point["model"]["ball"]
        for key in ("v1_ratio", "v2_ratio", "t_liftoff_s", "e2", "body_contacts"):
            assert point[key] == pytest.approx(single[key], rel=1e-9, abs=1e-12), key
    assert "artefact" not in points[0]["caveats"]  # the shell: no degree-1 precursor


def test_the_api_sweeps_a_pairs_body_by_its_kind():
    import twoball

    solver = twoball.MoreauJean(twoball.ShellBall(modes=16))
    drop = twoball.Drop(gap=0.01)
    result = twoball.sweep(
        {"v0": [4.1]}, drop=drop, body="lumped", pair="basketball-tennis", solver=solver
    )
    single = twoball.bounce(drop=drop, body="lumped", pair="basketball-tennis", solver=solver)
    (report,) = result.reports
    assert report.v1_ratio == pytest.approx(single.v1_ratio, rel=1e-9)
    assert result.provenance["call"]["arguments"]["body"] == "lumped"
    with pytest.raises(twoball.ParameterError, match="body"):  # an elastic body's mu is its own
        twoball.sweep({"mass_ratio": [0.1]}, drop=twoball.Drop(), body="lumped", solver=solver)


@pytest.mark.parametrize(
    ("argv", "flag"),
    [
        (["--param", "v0", "--values", "2,3", "--ball", "shell"], "--ball"),
        (["--param", "v0", "--values", "2,3", "--body", "lumped"], "--body"),
        (["--param", "v0", "--values", "2,3", "--backend", "fem"], "--backend"),
        (["--param", "v0", "--values", "2,3", "--wall-stiffness-ratio", "5"], "--wall-stiffness"),
        (["--param", "v0", "--values", "2,3", "--floor-alone"], "--floor-alone"),
        (["--bounce", "--param", "gap", "--values", "0,0.1", "--ball", "bogus"], "--ball"),
        (["--bounce", "--param", "mass-ratio", "--values", "0.1", "--body", "lumped"], "--body"),
        (
            ["--bounce", "--param", "gap", "--values", "0", "--pair", "tennis-coin", "--body", "x"],
            "--body",
        ),  # fmt: skip
        (
            [
                "--bounce",
                "--param",
                "gap",
                "--values",
                "0",
                "--pair",
                "tennis-coin",
                "--body",
                "ball",
            ],
            "--body",
        ),  # fmt: skip
        (["--bounce", "--param", "v0", "--values", "3", "--body-law", "hertz"], "--body-law"),
        (
            [
                "--bounce",
                "--param",
                "v0",
                "--values",
                "3",
                "--ball",
                "solid",
                "--pair",
                "tennis-coin",
            ],
            "--pair",
        ),  # fmt: skip
        (
            ["--bounce", "--param", "v0", "--values", "3", "--thickness-ratio", "0.1"],
            "--thickness-ratio",
        ),  # fmt: skip
        (
            ["--bounce", "--param", "v0", "--values", "3", "--ball", "shell", "--bending", "1"],
            "--bending",
        ),  # fmt: skip
        (["--bounce", "--param", "v0", "--values", "3", "--floor-alone"], "--floor-alone"),
    ],
)
def test_kinds_that_do_not_apply_are_one_line_naming_the_flag(capsys, argv, flag):
    with pytest.raises(SystemExit) as stop:
        main(["sweep", *argv])
    err = capsys.readouterr().err.strip().splitlines()
    assert stop.value.code == 2 and len(err) == 1, err
    assert err[0].startswith(f"twoball: error: {flag}"), err[0]
