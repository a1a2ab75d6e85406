"""The reproduction's parts of the balls and bodies: Table 1 and the gap (coarse runs).

The parts run N = 16 here on two of Table 1's pairs and two gaps, so that the
file stays fast; the numbers at the parts' own settings are in docs/shell.rst
and docs/bodies.rst.  Independent values: the single ``twoball.bounce`` with
the same inputs, Table 1 as printed and eq. (2.6).
"""

from __future__ import annotations

import pytest

import twoball
from twoball.modal.icm.limits import touching_ratios
from twoball.modal.icm.table1 import TABLE1
from twoball.modal.pairs import PAIRS
from twoball.verify.reproduce import driver
from twoball.verify.reproduce import kinds as part
from twoball.verify.reproduce.common import Context
from twoball.verify.sweeps.parallel import Runner

CHOSEN = ("basketball-tennis", "basketball-tissue")


@pytest.fixture()
def ctx(tmp_path, monkeypatch):
    monkeypatch.setattr(part, "MODES", 16)
    monkeypatch.setattr(part, "GAPS", (0.0, 0.2))
    monkeypatch.setattr(part, "GAP_PAIRS", ("basketball-tissue",))
    monkeypatch.setattr(part, "PAIRS", {name: PAIRS[name] for name in CHOSEN})
    part._RUNS.clear()
    return Context(tmp_path, Runner(workers=1))


def single(ball: str, pair: str, kind: str, gap: float) -> twoball.BounceReport:
    """The same whole bounce through the face, as ``twoball bounce`` runs it."""
    lower = twoball.LegendreBall(16) if ball == "membrane" else twoball.ShellBall(modes=16)
    solver = twoball.MoreauJean(lower)
    return twoball.bounce(drop=twoball.Drop(gap=gap), body=kind, pair=pair, solver=solver)


def test_the_parts_are_registered_after_the_whole_bounce():
    names = list(driver.PARTS)
    assert names[-2:] == ["kinds_table1", "kinds_gap"]
    assert "N = 64" in driver.models_line(["kinds_gap"])


def test_what_each_row_reads_as():
    for name, pair in PAIRS.items():
        membrane = part.reading("membrane", name)
        hangs = pair.lower == "tennis" or pair.row == 4  # docs/whole_bounce.rst
        assert ("degree-1 artefact" in membrane) is hangs, name
        assert part.reading("shell", name) == "prediction"
    assert part.kinds_of("basketball-tennis") == ("rigid", "lumped", "ball")
    assert part.kinds_of("basketball-table-tennis") == ("rigid", "lumped")


def test_table1_with_each_ball_and_body_is_the_single_bounces(ctx):
    sec = part.part_kinds_table1(ctx)
    rows = sec.data["rows"]
    combos = {(r["pair"], r["ball"], r["kind"]) for r in rows}
    assert combos == {(p, b, k) for p in CHOSEN for b in part.BALLS for k in part.kinds_of(p)}
    for r in rows:
        printed = TABLE1[r["row"] - 1]
        assert r["measured"] == [printed.measured_v1, printed.measured_v2]
        assert r["icm_2_6"] == pytest.approx(touching_ratios(printed.mu, printed.e2, printed.e12))
    row4 = {(r["ball"], r["kind"]): r for r in rows if r["row"] == 4}
    for ball, kind in (("shell", "lumped"), ("membrane", "ball")):
        alone = single(ball, "basketball-tennis", kind, 0.0)
        assert row4[ball, kind]["whole"] == pytest.approx([alone.v1_ratio, alone.v2_ratio])
        assert row4[ball, kind]["caveats"] == list(alone.caveats)
    assert "artefact" not in row4["shell", "rigid"]["caveats"]
    table = sec.tables[0]
    assert "hangs on the degree-1 artefact" in table and "| prediction |" in table
    assert len(sec.comparisons) == 2 * len(rows)
    assert [f for f, _ in sec.figures] == ["kinds_table1.png"]
    assert ctx.path("kinds_table1.png").stat().st_size > 1000


@pytest.mark.slow
def test_the_gap_with_each_ball_and_body(ctx):
    sec = part.part_kinds_gap(ctx)
    curves = sec.data["curves"]["basketball-tissue"]
    # two gaps of the shell with both kinds and of the membrane with the lumped body (its
    # rigid body's curves are whole_gap's)
    assert sorted({(c["ball"], c["kind"]) for c in curves}) == [
        ("membrane", "lumped"),
        ("shell", "lumped"),
        ("shell", "rigid"),
    ]
    assert len(curves) == 3 * 2
    far = next(c for c in curves if (c["ball"], c["kind"], c["gap_m"]) == ("shell", "lumped", 0.2))
    alone = single("shell", "basketball-tissue", "lumped", 0.2)
    assert far["v1_ratio"] == pytest.approx(alone.v1_ratio)
    assert far["t_l_s"] == pytest.approx(alone.t_liftoff_from_max_compression_s)
    assert [f for f, _ in sec.figures] == ["kinds_gap_basketball-tissue.png"]
    assert ctx.path(sec.figures[0][0]).stat().st_size > 1000
