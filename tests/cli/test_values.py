"""Numeric options (twoball/cli/values.py).

Unparsable text reaches the API, which names the range.
"""

import pytest

from twoball.cli.main import main


@pytest.mark.parametrize(
    ("argv", "expected"),
    [
        (["liftoff", "--damping", "abc"], "--damping must be in [0, 1), got 'abc'"),
        (["liftoff", "--modes", "2.5"], "--modes must be an integer in [1, 1000000], got 2.5"),
        (["liftoff", "--modes", "abc"], "--modes must be an integer in [1, 1000000], got 'abc'"),
        (
            ["icm", "--mu", "x", "--e2", "0.8", "--e12", "0.9"],
            "--mu must be a number in [0, 1e+06], got 'x'",
        ),
        # float("0_5") is 5.0 and int("1_6") is 16: a digit separator stays text
        (["liftoff", "--damping", "0_5"], "--damping must be in [0, 1), got '0_5'"),
        (["liftoff", "--modes", "1_6"], "--modes must be an integer in [1, 1000000], got '1_6'"),
        # float("\u0663") is 3.0: digits of other scripts stay text too
        (
            ["liftoff", "--modes", "\u0663\u0660"],
            "--modes must be an integer in [1, 1000000], got '\u0663\u0660'",
        ),
    ],
)
def test_unparsable_numbers_state_the_valid_range(capsys, argv, expected):
    with pytest.raises(SystemExit) as stop:
        main(argv)
    assert stop.value.code == 2
    assert capsys.readouterr().err.strip() == f"twoball: error: {expected}"


def test_the_number_types_read_numbers_as_written():
    from twoball.cli.values import integer, number

    assert number("0.01") == 0.01 and number("-4.1") == -4.1 and number("1e-3") == 1e-3
    assert integer("16") == 16 and integer("2.5") == 2.5
    assert number("nan") != number("nan")  # read: the range refuses it by name
    for text in ("0_01", "4_1", "1_0e3", "\u0663", "\uff11"):  # separators, other digits
        assert number(text) == text and integer(text) == text
