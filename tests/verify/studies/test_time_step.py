"""The time-step study (verify/studies/time_step.py): order 2 of generalized-alpha."""

import re

import pytest

import twoball
from tests.helpers import by_key
from twoball.modal.parameters import preset
from twoball.verify.output.report_files import study_csv, study_markdown, verify_markdown
from twoball.verify.studies.time_step import run_dt_study


@pytest.mark.slow
def test_dt_study_is_second_order_for_generalized_alpha():
    study = run_dt_study(preset("basketball"), mesh="axisym", order=2, levels=(1, 2, 3))
    assert study.passed
    q = by_key(study)
    for key in ("t_l", "v_l", "pole_l2", "pole_samples"):
        assert q[key].checked_order == pytest.approx(2.0, abs=0.15)
    assert q["t_l_hermite"].spec.band is None  # reported, not checked


# --- Time steps are written as the user types them: seconds, with c dt beside

SECONDS = re.compile(r"dt = ([0-9.e+-]+) s \(c dt = ([0-9.e+-]+)\)")
BARE = re.compile(r"(?<!c )\bdt = [0-9.e+-]+(?![0-9.e+-]| s)")  # a dt without its unit


def test_dt_study_labels_are_seconds_that_reproduce_the_run() -> None:
    case = twoball.Case.preset("basketball")
    study = run_dt_study(case, levels=(1, 2))
    row = study.runs[1]
    seconds, dimensionless = map(float, SECONDS.fullmatch(row["label"]).groups())
    assert seconds == pytest.approx(0.005 / case.wave_speed, rel=1e-12)  # level 1
    assert dimensionless == 0.005 and row["dt_s"] == pytest.approx(seconds, rel=1e-12)
    mesh = twoball.MeshOptions("axisym", elements=100)
    copied = twoball.liftoff(solver=twoball.GeneralizedAlpha(mesh, dt=seconds))
    assert copied.t_liftoff_s == pytest.approx(row["t_liftoff_s"], rel=1e-9)
    assert copied.v_liftoff_m_s == pytest.approx(row["v_liftoff_m_s"], rel=1e-9)
    report = study_markdown(study)
    assert "| dt [s] | c dt | steps |" in report and not BARE.search(report)
    assert study_csv(study).splitlines()[1].endswith(f",{seconds!r}")  # level 1 first


def test_verify_tables_and_checks_state_seconds() -> None:
    result = twoball.check(fast=True)
    text = verify_markdown(result)
    assert "dt = 1.5625e-05 s (c dt = 0.005)" in text and not BARE.search(text)
    names = [c.name for c in result.checks if "alpha" in c.name]
    assert names and all(SECONDS.search(n) for n in names)
