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
    ],
)
def test_unparsable_numbers_state_the_valid_range(capsys, argv, expected):
    with pytest.raises(SystemExit) as stop:
        main(argv)
    assert stop.value.code == 2
    assert capsys.readouterr().err.strip() == f"twoball: error: {expected}"
