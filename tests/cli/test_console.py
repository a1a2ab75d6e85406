"""Standard output of the command line (twoball/cli/console.py) when it cannot be written."""

from __future__ import annotations

import contextlib
import io
import json
import re

import pytest

from tests import ROOT
from tests._common.commands import start
from twoball.cli.main import main


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


# --- Tables written to a pipe or a file keep every value whole; the README shows the real output


def run(argv: list[str]) -> tuple[int, str, str]:
    """``twoball argv`` in this process with standard output a pipe (not a terminal)."""
    out, err = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
        try:
            status = main(argv)
        except SystemExit as stop:
            status = int(stop.code or 0)
    return status, out.getvalue(), err.getvalue()


@pytest.mark.parametrize(
    "argv",
    [
        ["liftoff", "--preset", "tennis"],  # a long warning row
        ["sweep", "--param", "v0", "--values", "2,4.1"],  # the "phi_a from" column
        ["sweep", "--param", "damping", "--values", "0.05,0.13", "--param", "radius"]
        + ["--values", "0.1,0.12"],
    ],
)
def test_piped_tables_cut_no_value(argv: list[str]) -> None:
    status, table, _ = run(argv)
    assert status == 0
    assert "…" not in table  # rich's ellipsis: a cell cut short
    rows = [line for line in table.splitlines() if line.startswith("│")]
    assert rows and all(line.endswith("│") for line in rows)
    assert len({len(line) for line in rows}) == 1  # one line per row: nothing wrapped
    if argv[0] == "sweep":  # the rule of phi_a named in full (eq. (3.7) or the preset's)
        assert "eq. (3.7)" in table or "measured (basketball)" in table
    else:
        _, text, _ = run([*argv, "--json"])
        warning = json.loads(text)["warnings"][0]
        assert warning in table  # the whole warning, on one row


def test_readme_sample_is_what_liftoff_prints() -> None:
    readme = (ROOT / "README.md").read_text()
    block = re.search(r"```\n\$ twoball liftoff\n(.*?)```", readme, re.S)
    assert block is not None
    status, table, _ = run(["liftoff"])
    assert status == 0
    printed = [line.rstrip() for line in table.splitlines()]
    assert block.group(1).splitlines() == printed


def test_sweep_warning_names_the_point_by_its_value() -> None:
    status, _, err = run(["sweep", "--param", "modes", "--values", "5,30"])
    assert status == 0
    line = next(ln for ln in err.splitlines() if ln.startswith("twoball: warning:"))
    assert "the first at modes = 5:" in line and "(0,)" not in line
