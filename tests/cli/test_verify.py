"""twoball verify: report files, exit status 0 or 1, bad input exit 2 before any work."""

import json

import pytest

from twoball.cli.main import main
from twoball.verify.checks.config import config

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


@pytest.mark.slow
def test_default_verify_passes(capsys, tmp_path):
    out = tmp_path / "report"
    code = main(["verify", "--out", str(out), "--json"])
    data = json.loads(capsys.readouterr().out)
    assert code == 0 and data["passed"], [c["name"] for c in data["checks"] if not c["passed"]]
    assert {p.name for p in out.iterdir()} == FILES | {".twoball-output", "provenance.json"}
    meshes = {r["mesh"] for r in data["runs"]}
    assert {"axisym P2 400 el.", "sphere P1 L4", "sphere P2 L3"} <= meshes
