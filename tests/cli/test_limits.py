"""Every long verb takes --max-time and --max-memory; its budget errors name the flags."""

from __future__ import annotations

import pytest

from twoball.cli.main import build_parser, main

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
    """Under a 1 s limit each is refused (status 2) or stopped (status 3) in one line
    that names --max-time, never the Python keyword max_time."""
    argv = [verb, *(a.replace("OUT", str(tmp_path / "out")) for a in LONG[verb])]
    capsys.readouterr()
    with pytest.raises(SystemExit) as stop:
        main(["-q", *argv, "--max-time", "1s"])
    err = capsys.readouterr().err.strip().splitlines()
    assert stop.value.code in (2, 3) and len(err) == 1, err
    assert "--max-time" in err[0] and "max_time" not in err[0].replace("--max-time", ""), err
