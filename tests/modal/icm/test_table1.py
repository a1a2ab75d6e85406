"""Table 1 of the paper (modal/icm/table1.py): data, rows 1 to 6, rounding."""

from __future__ import annotations

import pytest

from twoball._common.errors import ParameterError
from twoball.modal.icm import (
    TABLE1,
    round_significant,
    table1_check,
)


def test_table1_data_complete():
    assert len(TABLE1) == 6
    assert [(r.lower, r.upper) for r in TABLE1] == [
        ("Tennis", "Coin"),
        ("Tennis", "Nut"),
        ("Tennis", "Table tennis"),
        ("Basketball", "Tennis"),
        ("Basketball", "Tissue"),
        ("Basketball", "Table tennis"),
    ]
    assert TABLE1[3].mu == 0.101 and TABLE1[3].measured_v2 == 0.61


@pytest.mark.parametrize("index", [1, 2, 3])
def test_table1_rows_1_to_3_match(index):
    c = table1_check()[index - 1]
    assert c.index == index
    assert not c.differs
    assert c.v1_rounded == c.row.icm_v1
    assert c.v2_rounded == c.row.icm_v2


def test_table1_findings_rows_4_to_6():
    checks = table1_check()
    flags = [(c.v1_differs, c.v2_differs) for c in checks]
    assert flags == [
        (False, False),
        (False, False),
        (False, False),
        (False, True),
        (True, True),
        (True, True),
    ]
    rounded = [(c.v1_rounded, c.v2_rounded) for c in checks[3:]]
    assert rounded == [(2.1, 0.49), (2.0, 0.89), (2.0, 0.88)]
    assert checks[3].v2_difference == pytest.approx(-0.072, abs=5e-4)
    assert checks[4].v1_difference == pytest.approx(0.152, abs=5e-4)
    assert checks[5].v1_difference == pytest.approx(0.125, abs=5e-4)


def test_table1_normalisation_is_impact_speed():
    # Dividing by |u0| = e2 |v0| instead (the header's wording) misses rows 1-3.
    for c in table1_check()[:3]:
        e2 = c.row.e2
        assert round_significant(c.v1 / e2) != c.row.icm_v1
        assert round_significant(c.v2 / e2) != c.row.icm_v2


def test_round_significant():
    assert round_significant(1.5158) == 1.5
    assert round_significant(0.48788) == 0.49
    assert round_significant(1.9522) == 2.0
    assert round_significant(-0.0123456, 3) == -0.0123
    assert round_significant(0.0) == 0.0
    with pytest.raises(ParameterError):
        round_significant(1.0, 0)
