"""The one list syntax (twoball._common.ranges), checked against values written out by hand."""

import numpy as np
import pytest

from twoball._common.errors import ParameterError
from twoball._common.ranges import parse_values


@pytest.mark.parametrize(
    ("text", "integer", "expected"),
    [
        ("1,2,3", False, (1.0, 2.0, 3.0)),
        ("-1,0.5", False, (-1.0, 0.5)),
        ("0:1:5", False, (0.0, 0.25, 0.5, 0.75, 1.0)),
        ("-1:1:3", False, (-1.0, 0.0, 1.0)),
        ("2:2:1", False, (2.0,)),
        ("1:-1:3", False, (1.0, 0.0, -1.0)),  # descending as written
        ("2:5", True, (2, 3, 4, 5)),
        ("2:8:4", True, (2, 4, 6, 8)),
        ("3", True, (3,)),
    ],
)
def test_values(text, integer, expected):
    got = parse_values(text, "x", integer=integer)
    assert got == expected
    assert all(isinstance(v, int if integer else float) for v in got)


def test_range_matches_linspace_to_the_last_bit_at_the_ends():
    got = np.array(parse_values("0.05:0.35:7", "x"))
    assert got[0] == 0.05 and got[-1] == 0.35
    assert np.allclose(got, np.linspace(0.05, 0.35, 7), rtol=0, atol=1e-15)


@pytest.mark.parametrize(
    ("text", "integer"),
    [
        ("", False),
        ("a,b", False),
        ("1:2", False),  # a real range needs COUNT
        ("1:2:0", False),
        ("1:2:1", False),  # COUNT 1 needs START = STOP
        ("1:2:2.5", False),
        ("0:inf:3", False),
        ("nan", False),
        ("1,inf", False),
        ("1:2:3:4", False),
        ("1,2:3", False),
        ("1.5", True),
        ("0:1:3", True),  # 0, 0.5, 1: not whole
        ("0:2000000", True),  # more than a million values
    ],
)
def test_refused_with_the_syntax_named(text, integer):
    with pytest.raises(ParameterError, match=r"^x must be v1,v2,\.\.\. or START:STOP"):
        parse_values(text, "x", integer=integer)


@pytest.mark.parametrize("text", ["0_1,0.2", "0:0_5:3", "1_0:20", "0:1:1_0", "\u0661,2", "1, 2_0"])
def test_digit_separators_and_other_digits_are_refused(text):
    """float("0_5") is 5.0 and float("\u0661") is 1.0: neither is a number as written."""
    with pytest.raises(ParameterError) as caught:
        parse_values(text, "values", integer=":" in text and text.count(":") == 1)
    assert caught.value.name == "values"


def test_a_python_list_takes_numbers_only():
    assert parse_values([1, 2.5, np.float64(3.0)], "x") == (1.0, 2.5, 3.0)
    for items in (["1"], [True], [None], [[1.0]]):
        with pytest.raises(ParameterError):
            parse_values(items, "x")
