"""The command line's entry point (twoball/cli/main.py): one-line errors, negative values."""

import argparse
import json
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

from tests.project import validation_table as table
from tests.project.test_validation import check_refusals, run_child
from twoball.cli.main import build_parser, full_parser, join_negative_values, main


@pytest.mark.parametrize(
    ("argv", "flag"),
    [
        (["liftoff", "--radius", "0"], "--radius"),
        (["liftoff", "--radius", "-0.1"], "--radius"),
        (["liftoff", "--damping", "1"], "--damping"),
        (["liftoff", "--damping", "-0.01"], "--damping"),
        (["liftoff", "--phi-a", "1.2"], "--phi-a"),
        (["liftoff", "--phi-a", "3.2"], "--phi-a"),
        (["liftoff", "--preset", "squash"], "--preset"),
        (["liftoff", "--modes", "0"], "--modes"),
        (["liftoff", "--v0", "0"], "--v0"),
        (["liftoff", "--wave-speed", "-3"], "--wave-speed"),
        (["liftoff", "--pressure", "77200"], "--pressure"),
        (["liftoff", "--wave-speed", "300", "--pressure", "1", "--mass", "1"], "--wave-speed"),
        (["liftoff", "--t-end", "-1"], "--t-end"),
        (["liftoff", "--sigma", "hann"], "--sigma"),
        (["liftoff", "--recontact", "never"], "--recontact"),
        (["liftoff", "--damping", "abc"], "--damping"),
        (["liftoff", "--radius", "nan"], "--radius"),
        (["sweep", "--param", "damping", "--values", "0:1"], "--values"),
        (["sweep", "--param", "damping", "--values", "a:b:3"], "--values"),
        (["sweep", "--param", "damping", "--values", "0:0.5:0"], "--values"),
        (["sweep", "--param", "modes", "--values", "1:2:3"], "--values"),
        (["sweep", "--param", "mass", "--values", "0:1:3"], "--param"),
        (["sweep", "--param", "damping", "--values", "0:1:3"], "--values"),  # typed there
    ],
)
def test_bad_input_is_one_line_exit_2(capsys, argv, flag):
    with pytest.raises(SystemExit) as stop:
        main(argv)
    err = capsys.readouterr().err
    assert stop.value.code == 2
    lines = err.strip().splitlines()
    assert len(lines) == 1, err
    assert flag in lines[0] and "Traceback" not in err


def test_console_script_error_has_no_traceback():
    exe = shutil.which("twoball")
    cmd = [exe] if exe else [sys.executable, "-m", "twoball"]
    proc = subprocess.run(
        [*cmd, "liftoff", "--damping", "2"], capture_output=True, text=True, check=False
    )
    assert proc.returncode == 2
    assert proc.stderr.strip() == "twoball: error: --damping must be in [0, 1), got 2.0"
    assert proc.stdout == ""


def test_negative_values_join_their_option_only():
    options = {"--values", "--g"}
    assert join_negative_values(["sweep", "--values", "-1:1:3"], options) == [
        "sweep",
        "--values=-1:1:3",
    ]
    assert join_negative_values(["--g", "-1e-3"], options) == ["--g=-1e-3"]
    assert join_negative_values(["--json", "-1"], options) == ["--json", "-1"]
    assert join_negative_values(["--values", "--json"], options) == ["--values", "--json"]


def test_cli_sweep_negative_start_is_a_value_not_an_option(capsys):
    """v0 is a speed: its sign is irrelevant, so -3:-1:3 runs the same cases as 3:1:3."""
    assert main(["sweep", "--param", "v0", "--values", "-3:-1:3", "--json"]) == 0
    negative = capsys.readouterr().out
    assert main(["sweep", "--param", "v0", "--values", "3,2,1", "--json"]) == 0
    positive = capsys.readouterr().out

    def rows(text):
        data = json.loads(text)
        data = data["results"] if isinstance(data, dict) else data
        return [(r["t_liftoff_s"], r["v_liftoff_m_s"]) for r in data]

    assert rows(negative) == rows(positive)


# --- Options that were silently ignored, repeated or blamed on another option: refused by name


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
        # an option of another subcommand: where it is (a pair's pictures: bounce --render)
        (
            ["render", "--pair", "basketball-tennis", "--out", "x.png"],
            "--pair is not an option of twoball render; a pair's drop is drawn by twoball "
            "bounce --pair NAME --render FILE (see twoball render --help)",
        ),
        (
            ["export", "--gap", "0.01", "--out", "x.vtu"],
            "--gap is not an option of twoball export; it is an option of twoball bounce, "
            "sweep, fit",
        ),
        # digit separators: float("0_01") is 1.0, a typo for 0.01
        (["bounce", "--mass-ratio", "0.1", "--gap", "0_01"], "--gap must be"),
        (["liftoff", "--v0", "4_1"], "--v0 must be"),
        (["liftoff", "--preset", "basketball", "--modes", "3_0"], "--modes must be"),
        # the keywords of the valid range as flags too
        (
            ["bounce", "--restitution", "0.5"],
            "--restitution must be given only with --mass-ratio or --pair, got 0.5",
        ),
    ],
)
def test_the_line_names_the_option_given(argv: list[str], expected: str, tmp_path: Path) -> None:
    [result] = run_child([("", argv)], tmp_path)
    assert result["status"] == 2
    assert result["stderr"].startswith(f"twoball: error: {expected}"), result["stderr"]


#: Each long verb, with options that make it do real work (a file or folder: OUT).
LONG = {
    "reproduce": ["--only", "table2,fig11", "--workers", "1", "--out", "OUT"],
    "converge": ["modes", "--out", "OUT"],
    "verify": ["--fast", "--out", "OUT"],
    "sweep": ["--param", "damping", "--values", "0:0.6:121", "--workers", "1"],
    "bounce": [],
    "render": ["--level", "1", "--frames", "30", "--out", "OUT.gif"],
    "export": ["--level", "2", "--out", "OUT.pvd"],
}


@pytest.mark.parametrize("verb", sorted(LONG))
def test_every_long_verb_has_both_limits(verb):
    parser = build_parser(verb)
    command = parser._subparsers._group_actions[0].choices[verb]
    flags = {s for action in command._actions for s in action.option_strings}
    assert {"--max-time", "--max-memory"} <= flags


@pytest.mark.parametrize("verb", sorted(LONG))
def test_a_budget_stop_names_the_flag(verb, tmp_path, capsys):
    """Under a 50 ms limit each is refused (status 2) or stopped (status 3) in one line
    that names --max-time, never the Python keyword max_time."""
    argv = [verb, *(a.replace("OUT", str(tmp_path / "out")) for a in LONG[verb])]
    capsys.readouterr()
    with pytest.raises(SystemExit) as stop:
        main(["-q", *argv, "--max-time", "0.05s"])
    err = capsys.readouterr().err.strip().splitlines()
    assert stop.value.code in (2, 3) and len(err) == 1, err
    assert "--max-time" in err[0] and "max_time" not in err[0].replace("--max-time", ""), err


def test_bounce_help_lists_no_option_it_only_refuses(tmp_path: Path) -> None:
    """The shared case options the drop only refuses are parsed (the refusal says why) but
    not offered in ``twoball bounce --help``."""
    from twoball.cli.bounce import REFUSED

    text = table.subparsers(full_parser())["bounce"].format_help()
    for flag in REFUSED:
        assert flag not in text.split(), flag
    cases = [
        (flag, ["bounce", flag, value])
        for flag, value in (
            ("--phi-a", "2.6"),
            ("--sigma", "none"),
            ("--recontact", "paper"),
            ("--energy", "both"),
        )
    ]
    assert {flag for flag, _ in cases} == set(REFUSED)
    assert not check_refusals(cases, run_child(cases, tmp_path))
