"""The study of the whole bounce prints the tables docs/whole_bounce.rst quotes (quick ones)."""

from __future__ import annotations

import pytest

from twoball.verify.studies import whole


def test_a_run_as_the_face_resolves_it():
    """The study's run is the face's: the same v1 for a pair at a coarse resolution."""
    import twoball

    ours = whole.whole("basketball-tissue", 0.0, size=24)
    solver = twoball.MoreauJean(twoball.LegendreBall(24))
    face = twoball.bounce(solver=solver, pair="basketball-tissue")
    assert ours.v1 == pytest.approx(face.v1_ratio, rel=1e-14)
    assert ours.v2 == pytest.approx(face.v2_ratio, rel=1e-14)


def test_the_books_table_closes():
    text = whole.limit_c_table()
    rows = [line.split("|")[1:-1] for line in text.splitlines()[2:]]
    assert [r[0].strip() for r in rows] == ["0", "1"]
    for row in rows:
        assert float(row[1]) < 1e-13 and float(row[2]) < 1e-12
    assert float(rows[1][3]) < 1e-12  # e = 1 at the floor: nothing lost


def test_the_precursor_of_the_degree_one_artefact():
    """The study's numbers of docs/whole_bounce.rst's artefact table (a coarse run): the top
    starts near -(1 + 3 cos theta) / 2 times the centre's velocity change and strikes a
    free-falling body before pi / c (basketball, the tennis ball's cap, D = 0)."""
    p = whole.precursor("basketball", 0.0262, 0.0, modes=64, times=(0.05,))
    assert p.closed_form == pytest.approx(-1.9638, abs=1e-4)
    assert p.ratios[0][1] == pytest.approx(p.closed_form, rel=0.05)
    assert p.t_wave == pytest.approx(3.14159265 / 320.0, rel=1e-8)  # c = 320 1/s, Table 2
    assert 1e-3 < p.opening < 4e-3 and p.t_opening < p.t_strike < p.t_wave - 1e-3
    assert 0.5 < p.strike_speed < 1.2
