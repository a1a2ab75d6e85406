"""Standard output of the command line (twoball/cli/console.py) when it cannot be written."""

from __future__ import annotations

import pytest

from tests._common.commands import start


@pytest.mark.parametrize(
    "argv",
    [["liftoff", "--json"], ["sweep", "--param", "damping", "--values", "0.1:0.2:2", "--json"]],
)
def test_full_stdout_is_one_line(argv):
    with open("/dev/full", "wb") as full:
        process = start(argv, stdout=full)
        _, err = process.communicate(timeout=120)
    lines = err.decode().strip().splitlines()
    assert process.returncode == 2 and lines == [
        "twoball: error: cannot write standard output: No space left on device"
    ]
