"""The study of the whole bounce prints the tables docs/whole_bounce.rst quotes (quick ones)."""

from __future__ import annotations

import pytest
from twoball.verify.studies import whole


def test_a_run_as_the_face_resolves_it():
    """The study's run is the face's: the same v1 for a pair at a coarse resolution."""
    import twoball

    ours = whole.whole("basketball-tissue", 0.0, size=24)
    face = twoball.bounce(drop=twoball.Drop(modes=24), pair="basketball-tissue")
    assert ours.v1 == pytest.approx(face.v1_ratio, rel=1e-14)
    assert ours.v2 == pytest.approx(face.v2_ratio, rel=1e-14)


def test_the_books_table_closes():
    text = whole.limit_c_table()
    rows = [line.split("|")[1:-1] for line in text.splitlines()[2:]]
    assert [r[0].strip() for r in rows] == ["0", "1"]
    for row in rows:
        assert float(row[1]) < 1e-13 and float(row[2]) < 1e-12
    assert float(rows[1][3]) < 1e-12  # e = 1 at the floor: nothing lost
