"""twoball converge: refinement studies, their orders and their report files."""

import json

import numpy as np
import pytest
from twoball.modal.parameters import preset
from twoball.verify.studies.modes import parse_modes, run_modes_study
from twoball.verify.studies.reference import converged_legendre
from twoball.verify.studies.refinement import run_h_study, run_order_study
from twoball.verify.studies.time_step import run_dt_study

from twoball._common.errors import ParameterError
from twoball.cli.main import main

FILES = {"report.md", "results.json", "results.csv", "convergence.png"}


def run(capsys, *argv):
    code = main(list(argv))
    out = capsys.readouterr()
    return code, out.out, out.err


def test_converged_reference_settles_to_1e7():
    case = preset("basketball")
    limit = converged_legendre(case)
    assert limit.converged and limit.clear
    (_, t0, v0), (_, t1, v1) = limit.history[-2:]
    assert abs(v1 - v0) <= 1e-7 * abs(v1) and abs(t1 - t0) <= 1e-7 * t1
    assert limit.velocity * case.scalings.velocity == pytest.approx(3.94537, abs=1e-5)


def test_modes_study_is_second_order_and_states_the_n30_truncation():
    study = run_modes_study(preset("basketball"), modes=(30, 60, 120, 240))
    assert study.passed
    orders = {q.spec.key: q.checked_order for q in study.quantities}
    assert set(orders) == {"t_l", "v_l", "pole_l2", "energy_end"}
    for order in orders.values():
        assert order == pytest.approx(2.0, abs=0.1)
    v_l = next(q for q in study.quantities if q.spec.key == "v_l")
    assert v_l.relative_errors[0] == pytest.approx(0.0287, abs=5e-4)  # N = 30
    assert v_l.analysis.gci is not None and v_l.analysis.gci.convergence == "monotone"
    assert any("Truncation error of N = 30" in note for note in study.notes)


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


def test_parse_modes():
    assert parse_modes("30,60,120,240") == (30, 60, 120, 240)
    assert parse_modes("30,45,60") == (30, 45, 60)
    assert parse_modes("1:3") == (1, 2, 3)  # the one list syntax: every integer
    assert parse_modes("30:60:3") == (30, 45, 60)
    with pytest.raises(ParameterError, match="modes_list"):
        parse_modes("30:480")  # 451 counts: not a study


def _by_key(study):
    return {q.spec.key: q for q in study.quantities}


@pytest.mark.parametrize(("order", "expected"), [(1, 2.0), (2, 4.0)])
def test_axisym_h_study_orders(order, expected):
    study = run_h_study(preset("basketball"), mesh="axisym", order=order, levels=(1, 2, 3, 4))
    assert study.passed, [(q.spec.key, q.checked_order) for q in study.quantities if not q.passed]
    q = _by_key(study)
    assert q["lambda_6"].checked_order == pytest.approx(expected, abs=0.1)
    assert q["t_l"].checked_order == pytest.approx(expected, abs=0.2)
    assert q["v_l"].analysis.reference_kind == "reference"  # the Legendre series, same filter
    # P_1(x) = x (and P_2 for P2) lies in the space: those eigenvalues are exact
    assert q["lambda_1"].remark == "exact to round-off"
    assert (q["lambda_2"].remark == "exact to round-off") == (order == 2)
    assert q["strain_energy"].checked_order == pytest.approx(order + 1.0, abs=0.3)


def test_axisym_order_study_compares_p1_to_p4_at_equal_dofs():
    study = run_order_study(preset("basketball"), mesh="axisym", levels=(2, 3, 4))
    assert study.passed
    keys = {q.spec.key for q in study.quantities}
    assert {"v_l (P1)", "v_l (P2)", "lambda_6 (P1)", "lambda_6 (P2)"} <= keys
    assert {"t_l (P3)", "t_l (P4)", "pole_l2 (P3)", "pole_l2 (P4)"} <= keys
    assert any("times smaller with P2" in note for note in study.notes)
    q = _by_key(study)
    # equal unknowns (P3 up to rounding of 2E/3 elements), and each order's own 2p
    for p in (1, 2, 3, 4):
        assert np.allclose(q[f"t_l (P{p})"].dofs, q["t_l (P2)"].dofs, rtol=0.01)
    assert q["pole_l2 (P3)"].checked_order == pytest.approx(6.0, abs=0.5)
    assert q["pole_l2 (P4)"].checked_order == pytest.approx(8.0, abs=0.6)
    # at equal unknowns (401) each order lowers the t_l error by orders of magnitude, down to
    # round-off (measured 9.0e-6, 2.2e-9, 1.0e-12, 1.1e-13)
    finest = [q[f"t_l (P{p})"].relative_errors[-1] for p in (1, 2, 3, 4)]
    assert finest[0] > 100 * finest[1] > 1e4 * finest[2] and finest[3] <= finest[2], finest
    assert all("seconds" in row for row in study.runs[1:])


@pytest.mark.parametrize(("order", "levels"), [(3, (0, 1, 2, 3)), (4, (0, 1, 2))])
def test_axisym_h_study_at_p3_p4_converges_at_2p(order, levels):
    """The line has no geometric error: t_l, v_l and the trajectory at 2p (+-0.5)."""
    study = run_h_study(preset("basketball"), mesh="axisym", order=order, levels=levels)
    assert study.passed, [(q.spec.key, q.checked_order) for q in study.quantities if not q.passed]
    q = _by_key(study)
    for key in ("t_l", "v_l", "pole_l2"):
        assert q[key].checked_order == pytest.approx(2.0 * order, abs=0.5), key
    assert q["strain_energy"].checked_order == pytest.approx(order + 1.0, abs=0.5)


def test_converge_cli_takes_orders_3_4_and_the_exact_geometry(capsys, tmp_path):
    code, stdout, _ = run(
        capsys, "converge", "h", "--mesh", "sphere", "--order", "3", "--geometry",
        "exact", "--levels", "1:2", "--out", str(tmp_path / "h"), "--json",
    )  # fmt: skip
    data = json.loads(stdout)
    labels = [row["label"] for row in data["runs"][1:]]
    assert labels == ["sphere P3 L1 exact", "sphere P3 L2 exact"] and code in (0, 1)
    assert "exact" in data["title"]


def test_dt_study_is_second_order_for_generalized_alpha():
    study = run_dt_study(preset("basketball"), mesh="axisym", order=2, levels=(1, 2, 3))
    assert study.passed
    q = _by_key(study)
    for key in ("t_l", "v_l", "pole_l2", "pole_samples"):
        assert q[key].checked_order == pytest.approx(2.0, abs=0.15)
    assert q["t_l_hermite"].spec.band is None  # reported, not checked


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


@pytest.mark.slow
@pytest.mark.parametrize(
    ("order", "levels", "expected"), [(1, (2, 3, 4), 2.0), (2, (1, 2, 3), 4.0)]
)
def test_sphere_h_study_eigenvalue_orders(order, levels, expected):
    study = run_h_study(preset("basketball"), mesh="sphere", order=order, levels=levels)
    q = _by_key(study)
    for degree in range(1, 7):
        assert q[f"lambda_{degree}"].checked_order == pytest.approx(expected, abs=0.35)
    assert q["v_l"].relative_errors[-1] < q["v_l"].relative_errors[0]
    assert np.isfinite(q["v_l"].checked_order)
