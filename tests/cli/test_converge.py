"""twoball converge: report files, refusals in one line, the study as a positional or --study."""

import json

import pytest

from twoball.cli.main import main

FILES = {"report.md", "results.json", "results.csv", "convergence.png"}


def run(capsys, *argv):
    code = main(list(argv))
    out = capsys.readouterr()
    return code, out.out, out.err


def test_converge_modes_cli_writes_every_file(capsys, tmp_path):
    out = tmp_path / "modes"
    code, stdout, _ = run(
        capsys, "converge", "modes", "--modes-list", "30,60,120", "--out", str(out),
        "--json",
    )  # fmt: skip
    assert code == 0
    data = json.loads(stdout)
    assert data["study"] == "modes" and data["passed"] is True
    assert {p.name for p in out.iterdir()} == FILES | {".twoball-output", "provenance.json"}
    report = (out / "report.md").read_text()
    assert "Truncation error of N = 30" in report and "PASS" in report
    csv_lines = (out / "results.csv").read_text().splitlines()
    assert csv_lines[0].startswith("quantity,label,grid") and len(csv_lines) == 1 + 4 * 3
    assert json.loads((out / "results.json").read_text())["quantities"][0]["key"] == "t_l"


def test_converge_replaces_an_old_report_and_leaves_no_scratch(capsys, tmp_path):
    out = tmp_path / "report"
    out.mkdir()
    (out / ".twoball-report").write_text("")  # a report of an earlier twoball version
    (out / "report.md").write_text("old")
    code, _, _ = run(capsys, "converge", "modes", "--modes-list", "30,60,120",
                     "--out", str(out))  # fmt: skip
    assert code == 0 and (out / "report.md").read_text() != "old"
    assert not (out / ".twoball-report").exists()
    assert sorted(p.name for p in tmp_path.iterdir()) == ["report"]


def test_converge_refuses_an_old_report_holding_a_user_file(capsys, tmp_path):
    out = tmp_path / "report"
    out.mkdir()
    (out / ".twoball-report").write_text("")
    (out / "stale.txt").write_text("mine")
    with pytest.raises(SystemExit) as stop:
        main(["converge", "modes", "--modes-list", "30,60,120", "--out", str(out)])
    assert stop.value.code == 2 and "stale.txt" in capsys.readouterr().err
    assert (out / "stale.txt").read_text() == "mine"


@pytest.mark.parametrize(
    ("argv", "flag"),
    [
        (["h", "--levels", "3"], "--levels"),
        (["h", "--levels", "4:2"], "--levels"),
        (["h", "--levels", "a:b"], "--levels"),
        (["h", "--levels", "2:99"], "--levels"),
        (["nonsense"], "STUDY"),
        (["--study", "nonsense"], "--study"),
        ([], "STUDY"),
        (["h", "--study", "order"], "STUDY"),
        (["modes", "--modes-list", "30,20,40"], "--modes-list"),
    ],
)
def test_bad_input_is_one_line_exit_2_and_no_files(capsys, tmp_path, argv, flag):
    out = tmp_path / "never"
    with pytest.raises(SystemExit) as exit_info:
        main(["converge", *argv, "--out", str(out)])
    err = capsys.readouterr().err
    assert exit_info.value.code == 2
    assert err.count("\n") == 1 and err.startswith("twoball: error:") and flag in err
    assert not out.exists() and list(tmp_path.iterdir()) == []


def test_study_option_is_the_positional_study(capsys, tmp_path):
    """``converge --study modes`` gives the numbers of ``converge modes``."""
    results = []
    for argv in (["modes"], ["--study", "modes"], ["modes", "--study", "modes"]):
        out = tmp_path / str(len(results))
        code, text, _ = run(capsys, "converge", *argv, "--modes-list", "30,60,120", "--json",
                            "--out", str(out))  # fmt: skip
        data = json.loads(text)
        assert code == 0 and data["study"] == "modes"
        results.append(json.dumps(data["quantities"], sort_keys=True))
    assert results[0] == results[1] == results[2]


def test_unwritable_out_is_one_line_exit_2(capsys, tmp_path):
    blocker = tmp_path / "file"
    blocker.write_text("x")
    for out in (blocker, blocker / "sub"):
        with pytest.raises(SystemExit) as exit_info:
            main(["converge", "modes", "--out", str(out)])
        err = capsys.readouterr().err
        assert exit_info.value.code == 2 and "--out" in err and err.count("\n") == 1
    assert [p.name for p in tmp_path.iterdir()] == ["file"]


@pytest.mark.slow
def test_converge_cli_takes_orders_3_4_and_the_exact_geometry(capsys, tmp_path):
    code, stdout, _ = run(
        capsys, "converge", "h", "--mesh", "sphere", "--order", "3", "--geometry",
        "exact", "--levels", "1:2", "--out", str(tmp_path / "h"), "--json",
    )  # fmt: skip
    data = json.loads(stdout)
    labels = [row["label"] for row in data["runs"][1:]]
    assert labels == ["sphere P3 L1 exact", "sphere P3 L2 exact"] and code in (0, 1)
    assert "exact" in data["title"]


def test_converge_h_cli_axisym(capsys, tmp_path):
    out = tmp_path / "h"
    code, stdout, _ = run(
        capsys, "converge", "h", "--mesh", "axisym", "--order", "2", "--levels", "2:4",
        "--out", str(out), "--json",
    )  # fmt: skip
    data = json.loads(stdout)
    assert code == 0 and data["study"] == "h" and data["passed"]
    assert {p.name for p in out.iterdir()} == FILES | {".twoball-output", "provenance.json"}
    assert "lambda_6" in (out / "report.md").read_text()


def test_the_case_note_is_printed_once(capsys, tmp_path):
    """A negative v0 is noted on standard error once, not again among the study's notes."""
    code = main(
        ["converge", "modes", "--modes-list", "30,60,120", "--v0=-4.1"]
        + ["--out", str(tmp_path / "c")]
    )
    out, err = capsys.readouterr()
    assert code == 0
    text = out + err
    assert text.count("v0 = -4.1 m/s read as an impact at 4.1 m/s downwards") == 1
    assert "twoball: note: v0 = -4.1 m/s" in err
