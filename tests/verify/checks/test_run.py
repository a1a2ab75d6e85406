"""twoball verify: checks, exit status, and the report directory written all at once."""

import json
import math

import numpy as np
import pytest
from twoball.modal.parameters import preset
from twoball.verify.checks.alpha import decay_band
from twoball.verify.checks.config import config
from twoball.verify.checks.results import Check, bounded
from twoball.verify.checks.run import run_verify
from twoball.verify.output.report_files import write_report_dir

from twoball.cli.main import main

FILES = {
    "report.md",
    "results.json",
    "results.csv",
    "checks.csv",
    "summary.csv",
    "eigenvalues.csv",
    "pole.png",
    "eigenvalues.png",
    "energy.png",
}


@pytest.fixture(scope="module")
def fast_result():
    return run_verify(preset("basketball"), configuration=config("fast"))


def test_fast_configuration_passes_every_check(fast_result):
    assert fast_result.passed, [c.name for c in fast_result.checks if not c.passed]
    names = {c.name.split(" ")[0] for c in fast_result.checks}
    assert {"lift-off", "eigenvalues", "spectrum", "energy", "alpha", "modal"} <= names
    backends = [r.backend for r in fast_result.rows]
    assert backends[:2] == ["legendre", "legendre N->inf"]
    assert "fem modal" in backends and "fem alpha" in backends


def test_rows_state_differences_to_both_references(fast_result):
    n30, limit = fast_result.rows[0], fast_result.rows[1]
    assert n30.t_diff == 0.0 and n30.v_diff == 0.0
    assert limit.v_diff_converged == 0.0
    assert n30.v_diff_converged == pytest.approx(-0.0287, abs=5e-4)  # N = 30 truncation
    axisym = next(r for r in fast_result.rows if r.mesh == "axisym P2 100 el.")
    assert abs(axisym.t_diff) < 1e-5 and abs(axisym.v_diff) < 1e-5
    assert axisym.ratio == pytest.approx(axisym.v_l_m_s / 4.1)


def test_energy_decay_band_is_exact_for_one_mode():
    low, high = decay_band(0.13)
    assert low == pytest.approx(1 / 1.13) and high == pytest.approx(1 / 0.87)
    d, t = 0.13, np.linspace(0.0, 20.0, 20001)
    wd = math.sqrt(1 - d * d)
    q = np.exp(-d * t) * (np.cos(wd * t) + d / wd * np.sin(wd * t))
    qt = -np.exp(-d * t) * np.sin(wd * t) / wd
    factor = (qt**2 + q**2) * np.exp(2 * d * t)  # E(t) e^{2 D t} / E(0) with E(0) = 1/2
    assert factor.min() == pytest.approx(low, rel=1e-6)
    assert factor.max() == pytest.approx(high, rel=1e-6)


def test_bounded_fails_on_missing_or_nan_values():
    assert bounded("a", "", 1e-3, 1e-2).passed
    assert not bounded("a", "", 2e-2, 1e-2).passed
    assert not bounded("a", "", None, 1e-2).passed
    assert not bounded("a", "", math.nan, 1e-2).passed
    assert Check("a", "", 1.0, None, False).verdict == "FAIL"


def test_verify_cli_writes_every_file_and_exits_0(capsys, tmp_path):
    out = tmp_path / "report"
    code = main(["verify", "--fast", "--out", str(out), "--json"])
    data = json.loads(capsys.readouterr().out)
    assert code == 0 and data["passed"] is True and data["configuration"] == "fast"
    assert {p.name for p in out.iterdir()} == FILES | {".twoball-output", "provenance.json"}
    report = (out / "report.md").read_text()
    assert report.startswith("# twoball verify: PASS") and "![" in report
    header = (out / "results.csv").read_text().splitlines()[0]
    assert header.startswith("backend,mesh,dofs,t_liftoff_s,v_liftoff_m_s,ratio")
    saved = json.loads((out / "results.json").read_text())
    assert len(saved["checks"]) == len(data["checks"]) and saved["runs"][0]["backend"] == "legendre"
    for name in ("pole.png", "eigenvalues.png", "energy.png"):
        assert (out / name).read_bytes()[:4] == b"\x89PNG"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["report"]  # no scratch left


def test_verify_table_and_failing_check_exit_1(capsys, tmp_path, monkeypatch):
    strict = config("fast")
    target = strict.fem[0]
    strict = type(strict)(
        "strict", (type(target)(target.spec, 1e-15, target.eigen, target.energy),), ()
    )
    monkeypatch.setattr("twoball.verify.checks.config.config", lambda name: strict)
    code = main(["verify", "--out", str(tmp_path / "r")])
    out = capsys.readouterr().out
    assert code == 1
    assert "FAIL" in out and "lift-off axisym P2 100 el." in out and "t_l [ms]" in out
    assert (tmp_path / "r" / "report.md").read_text().startswith("# twoball verify: FAIL")


@pytest.mark.parametrize("kind", ["file", "missing-parent"])
def test_unwritable_out_is_one_line_exit_2_before_any_work(capsys, tmp_path, kind):
    blocker = tmp_path / "file"
    blocker.write_text("x")
    out = blocker if kind == "file" else tmp_path / "no" / "such" / "dir"
    with pytest.raises(SystemExit) as exit_info:
        main(["verify", "--fast", "--out", str(out)])
    err = capsys.readouterr().err
    assert exit_info.value.code == 2 and err.count("\n") == 1 and "--out" in err
    assert sorted(p.name for p in tmp_path.iterdir()) == ["file"]


def test_bad_case_option_is_exit_2(capsys, tmp_path):
    with pytest.raises(SystemExit) as exit_info:
        main(["verify", "--fast", "--damping", "1.5", "--out", str(tmp_path / "r")])
    assert exit_info.value.code == 2 and "--damping" in capsys.readouterr().err
    assert not (tmp_path / "r").exists()


def test_old_report_survives_a_failed_write(tmp_path):
    out = tmp_path / "report"
    write_report_dir(out, {"a.txt": lambda p: p.write_text("old")})

    def broken(path):
        path.write_text("half")
        raise RuntimeError("disk full")

    with pytest.raises(RuntimeError):
        write_report_dir(out, {"a.txt": lambda p: p.write_text("new"), "b.txt": broken})
    assert (out / "a.txt").read_text() == "old" and not (out / "b.txt").exists()
    assert sorted(p.name for p in tmp_path.iterdir()) == ["report"]
    write_report_dir(out, {"c.txt": lambda p: p.write_text("newer")})
    assert sorted(p.name for p in out.iterdir()) == [".twoball-output", "c.txt"]


@pytest.mark.slow
def test_default_verify_passes(capsys, tmp_path):
    out = tmp_path / "report"
    code = main(["verify", "--out", str(out), "--json"])
    data = json.loads(capsys.readouterr().out)
    assert code == 0 and data["passed"], [c["name"] for c in data["checks"] if not c["passed"]]
    assert {p.name for p in out.iterdir()} == FILES | {".twoball-output", "provenance.json"}
    meshes = {r["mesh"] for r in data["runs"]}
    assert {"axisym P2 400 el.", "sphere P1 L4", "sphere P2 L3"} <= meshes


def test_out_refuses_a_folder_that_is_not_a_report(tmp_path):
    from twoball.verify.output.report_files import MARKER, check_output_dir, write_report_dir

    from twoball._common.errors import ParameterError

    foreign = tmp_path / "home"
    foreign.mkdir()
    (foreign / "thesis.tex").write_text("precious")
    with pytest.raises(ParameterError, match="out"):
        check_output_dir(foreign)
    assert (foreign / "thesis.tex").read_text() == "precious"
    report = tmp_path / "report"
    write_report_dir(report, {"a.txt": lambda p: p.write_text("1")})
    assert (report / MARKER).is_file()
    write_report_dir(report, {"a.txt": lambda p: p.write_text("2")})  # an earlier report
    assert (report / "a.txt").read_text() == "2"


def test_thorough_runs_p3_and_p4_and_their_line_checks_pass():
    """verify --thorough has P3 and P4 on the line and the sphere (full and Krylov routes).

    The line's P3/P4 targets are run here through the same checks (measured
    lift-off 6.6e-12 and 1.3e-13, eigenvalues 6.3e-12 and 2.0e-13 against their
    bounds); the sphere targets belong to the thorough run (minutes).
    """
    thorough = config("thorough")
    specs = [t.spec for t in thorough.fem]
    assert {(s.mesh, s.order) for s in specs} >= {
        ("axisym", 3), ("axisym", 4), ("sphere", 3), ("sphere", 4)
    }  # fmt: skip
    assert {(t.spec.order, t.spec.geometry) for t in thorough.krylov} >= {
        (4, "isoparametric"), (4, "exact")
    }  # fmt: skip
    line = tuple(t for t in thorough.fem if t.spec.mesh == "axisym" and t.spec.order > 2)
    small = type(thorough)("p34", line, ())
    result = run_verify(preset("basketball"), configuration=small)
    assert result.passed, [(c.name, c.value) for c in result.checks if not c.passed]
    names = {c.name for c in result.checks}
    assert {"lift-off axisym P3 200 el.", "eigenvalues axisym P4 100 el."} <= names
