"""What a whole bounce says beside its numbers: the degree-1 artefact, a low e12, overlap.

The rule of :func:`twoball.modal.floor.bounce.answer_caveats` is checked against
values taken independently of it: the wave's arrival at the top, pi / c (unit
wave speed, eq. (3.9)); Table 1's e12 of the pair; the contact intervals of the
run itself; and the docs section the warnings name.
"""

from __future__ import annotations

import json
import math
from functools import cache

import pytest

import twoball
from tests import ROOT
from twoball.modal.floor.bounce import (
    ARTEFACT_SECTION,
    E12_FAR_BELOW,
    LARGE_GAP_SECTION,
    OVERLAP_NOTE,
    answer_caveats,
)

MODES = 32


@cache
def _run(pair: str, gap: float) -> twoball.BounceReport:
    solver = twoball.MoreauJean(twoball.LegendreBall(MODES))
    return twoball.bounce(drop=twoball.Drop(gap=gap), pair=pair, solver=solver)


def _section_titles() -> set[str]:
    """The section titles of docs/whole_bounce.rst (the line above an underline)."""
    lines = (ROOT / "docs" / "whole_bounce.rst").read_text().splitlines()
    return {
        a.strip()
        for a, b in zip(lines, lines[1:], strict=False)
        if b and set(b) <= set("-=~") and len(b) >= len(a.strip()) > 0
    }


def test_the_sections_named_by_the_warnings_exist() -> None:
    titles = _section_titles()
    for where in (ARTEFACT_SECTION, LARGE_GAP_SECTION):
        path, _, title = where.partition(", ")
        assert path == "docs/whole_bounce.rst"
        assert title.strip("'") in titles


def test_a_tennis_ball_touching_the_basketball_is_struck_by_the_precursor() -> None:
    report = _run("basketball-tennis", 0.0)
    wave = math.pi / report.case.wave_speed  # the wave's arrival at the top [s]: 9.82 ms
    touches = [e["t_s"] for e in report.events if e["contact"] == "body" and e["t_s"] > 0]
    assert touches[0] < wave  # the first strike before the wave could be there
    assert wave == pytest.approx(9.82e-3, abs=5e-6)
    assert "artefact" in report.caveats
    said = [w for w in report.warnings if ARTEFACT_SECTION in w]
    assert len(said) == 1 and f"{touches[0] * 1e3:.3g} ms" in said[0]


def test_overlapping_contacts_say_that_e12_and_the_icm_are_undefined() -> None:
    report = _run("basketball-tennis", 0.0)
    body = report.result.body
    floor_release = body.t_floor_release
    assert floor_release is not None and body.intervals[0].start < floor_release  # overlap
    assert report.e12_effective is None and report.icm_solver is None
    assert "overlap" in report.caveats and OVERLAP_NOTE in report.notes
    data = json.loads(json.dumps(report.as_dict()))
    assert "overlap" in data["caveats"] and OVERLAP_NOTE in data["notes"]


def test_a_large_gap_far_below_newtons_e12_is_flagged() -> None:
    report = _run("basketball-tennis", 0.25)
    e12 = report.e12_effective
    assert e12 is not None and e12 < E12_FAR_BELOW * 0.89  # Table 1 row 4's e12
    assert report.result.body.sequence == "independent"
    assert "e12_low" in report.caveats and "artefact" not in report.caveats
    said = [w for w in report.warnings if LARGE_GAP_SECTION in w]
    assert len(said) == 1 and "0.89" in said[0]
    assert report.icm_solver is not None  # defined: the contacts do not overlap


def test_the_rule_reads_the_ball_kind_and_newtons_e12() -> None:
    touching = _run("basketball-tennis", 0.0)
    for kind in ("shell", "solid"):  # translation is material motion: no artefact
        tags, warnings, _ = answer_caveats(touching.result, touching.whole, kind, touching.case)
        assert "artefact" not in tags and not any(ARTEFACT_SECTION in w for w in warnings)
    far = _run("basketball-tennis", 0.25)
    body = twoball.Body(0.101, contact_radius=0.0262, restitution=0.0)
    from dataclasses import replace

    inelastic = replace(far.whole, body=body, pair=None)  # Newton's e12 = 0: nothing to fall below
    tags, _, _ = answer_caveats(far.result, inelastic, "membrane", far.case)
    assert "e12_low" not in tags


def test_the_shell_ball_has_no_artefact_warning() -> None:
    solver = twoball.MoreauJean(twoball.ShellBall(modes=24))
    report = twoball.bounce(pair="basketball-tennis", solver=solver)
    assert report.result.body.touched
    assert "artefact" not in report.caveats
    assert not any(ARTEFACT_SECTION in w for w in report.warnings)
