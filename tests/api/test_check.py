"""twoball.check (the verification report; ``twoball verify`` on the command line): its steps."""

from __future__ import annotations

import pytest

import twoball
from twoball import ModalRatio


def test_check_writes_the_report_of_the_basketball(tmp_path):
    """The fast configuration passes and writes its report, named after ``twoball.check``."""
    result = twoball.check(fast=True, out=tmp_path / "report")
    assert result.passed and (tmp_path / "report" / "report.md").is_file()
    settings = result.as_dict()["settings"]
    assert settings["phi_a_source"] == "measured (basketball)"
    assert result.provenance["call"]["function"] == "twoball.check"


def test_verify_steps_counts_the_progress_calls(tmp_path):
    from twoball._studies import verify_steps

    said: list[str] = []
    twoball.check(fast=True, progress=said.append, out=tmp_path / "report")
    assert len(said) == verify_steps(fast=True) and said[-1].startswith("writing ")
    assert verify_steps(fast=True, out=False) == len(said) - 1
    assert said[0].startswith("Legendre series N = 30")


def test_the_studies_take_the_ratio_d_as_a_law():
    """``damping=ModalRatio(D)`` is the case's ratio D; a Rayleigh law is refused by name."""
    case = twoball.Case.preset("basketball")
    given = twoball.converge(case, study="modes", modes_list="30,60,120", damping=ModalRatio(0.2))
    inside = twoball.converge(case.derive(damping=0.2), study="modes", modes_list="30,60,120")
    assert [r["t_liftoff_s"] for r in given.runs] == [r["t_liftoff_s"] for r in inside.runs]
    assert given.provenance["case"]["damping"] == 0.2
    with pytest.raises(twoball.ParameterError, match="^rayleigh must be left out"):
        twoball.converge(case, study="modes", damping=twoball.Rayleigh(1.0, 0.0))
