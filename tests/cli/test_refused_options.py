"""Options that were silently ignored, repeated or blamed on another option: refused by name.

Each row of :data:`validation_table.NO_LONGER_IGNORED` ran (and ignored the
option), raised a traceback, ran for minutes, or named another option; it must
now give exit 2 and one line naming the option the user typed, before any work
and with nothing written.  Every option that takes one value is refused when
given twice, in every subcommand (argparse keeps the last one silently).
"""

from __future__ import annotations

import argparse
from pathlib import Path

import pytest
import validation_table as table
from test_validation import check_refusals, run_child

from twoball.cli.main import full_parser


def test_options_that_were_ignored_are_refused_by_name(tmp_path: Path) -> None:
    cases = table.NO_LONGER_IGNORED
    results = run_child(cases, tmp_path)
    bad = check_refusals(cases, results)
    assert not bad, f"{len(bad)} of {len(cases)}:\n" + "\n".join(bad)


def _repeat_cases() -> list[tuple[str, list[str]]]:
    """Every single-value option of every subcommand, given twice on the base line."""
    cases = []
    for command, parser in table.subparsers(full_parser()).items():
        for action in parser._actions:
            if not action.option_strings or type(action).__name__ != "_StoreOnce":
                continue
            flag = max(action.option_strings, key=len)
            value = str(action.choices[0]) if action.choices else "1"
            argv = [w for w in table.BASE[command]]
            cases.append((flag, [*argv, flag, value, flag, value]))
    return cases


def test_every_single_value_option_given_twice_is_refused(tmp_path: Path) -> None:
    cases = _repeat_cases()
    assert len(cases) > 150  # every subcommand's options, not a sample
    assert {argv[0] for _, argv in cases} == set(table.BASE)
    results = run_child(cases, tmp_path)
    bad = check_refusals(cases, results)
    assert not bad, f"{len(bad)} of {len(cases)}:\n" + "\n".join(bad[:20])
    for (flag, _), result in zip(cases, results, strict=True):
        assert "more than once" in result["stderr"], (flag, result["stderr"])


def test_parser_registers_store_once_for_every_value_option() -> None:
    """No single-value option escapes the check (a plain argparse store would keep the last)."""
    for parser in table.subparsers(full_parser()).values():
        for action in parser._actions:
            if action.option_strings and action.nargs is None and action.const is None:
                if isinstance(action, argparse._StoreAction):
                    assert type(action).__name__ == "_StoreOnce", action.option_strings


@pytest.mark.parametrize(
    ("argv", "expected"),
    [
        (
            ["converge", "--study", "h", "--mesh-file", "X"],
            "--mesh-file is not an option of twoball converge",
        ),
        (
            ["liftoff", "--youngs-modulus", "1e7", "--thickness", "1"],
            "--youngs-modulus must be such that B = E h^3 / (12 (1 - nu^2)) is at most 1e+06",
        ),
        (["liftoff", "--mass-ratio", "0.1", "--geometry", "exact"], "--geometry must be left out"),
        (["liftoff", "--radius", "1", "--radius", "2"], "--radius given more than once (1.0, then"),
    ],
)
def test_the_line_names_the_option_given(argv: list[str], expected: str, tmp_path: Path) -> None:
    [result] = run_child([("", argv)], tmp_path)
    assert result["status"] == 2
    assert result["stderr"].startswith(f"twoball: error: {expected}"), result["stderr"]
