"""Every subcommand refuses every invalid value in one line, exit 2, before any work.

The table (:mod:`validation_table`) is generated from the parser: every numeric
option of every subcommand with each bad value outside its valid range, every
path option with empty, over-long and unwritable paths, and the options that
do not apply.  All cases run in one child interpreter (``validation_child.py``),
each in its own empty folder and under a CPU-time alarm, so a value that slips
through and starts the work shows as ``ran`` instead of taking minutes.
"""

from __future__ import annotations

import json
import os
import re
import subprocess
import sys
from pathlib import Path

import pytest

from tests import ROOT
from tests.meshes import on_ball, write
from tests.project import validation_table as table
from twoball.cli.main import COMMANDS, full_parser
from twoball.fem_membrane.mesh import icosphere

CHILD = Path(__file__).with_name("validation_child.py")
#: CPU seconds a refusal may take (imports of the subcommand's modules included).
REFUSAL_CPU_S = 2.0


def run_child(cases: list[tuple[str, list[str]]], tmp_path: Path) -> list[dict]:
    """Run ``cases`` in one child interpreter; each in a fresh folder holding ``a-file``
    (and ``ball.vtu``, a readable sphere mesh, where the case names it)."""
    items = []
    for k, (_, argv) in enumerate(cases):
        folder = tmp_path / f"case{k}"
        folder.mkdir()
        (folder / "a-file").write_text("")
        if any("{tmp}/ball.vtu" in word for word in argv):
            mesh = icosphere(1)
            write(folder / "ball.vtu", on_ball(mesh), mesh.cells)
        items.append({"argv": argv, "folder": str(folder)})
    (tmp_path / "cases.json").write_text(json.dumps(items))
    env = dict(os.environ, OPENBLAS_NUM_THREADS="1", MPLBACKEND="Agg", PYTHONPATH=str(ROOT))
    for name in ("TWOBALL_MAX_MEMORY", "TWOBALL_MAX_TIME"):
        env.pop(name, None)
    done = subprocess.run(
        [sys.executable, str(CHILD), str(tmp_path / "cases.json"), str(tmp_path / "out.json")],
        cwd=ROOT,
        env=env,
        capture_output=True,
        text=True,
        timeout=600,
    )
    assert done.returncode == 0, done.stderr[-3000:]
    return json.loads((tmp_path / "out.json").read_text())


def names_flag(line: str, flag: str) -> bool:
    """Whether ``line`` names ``flag`` as a whole word (``--level`` is not ``--levels``)."""
    return re.search(rf"(?<![\w-]){re.escape(flag)}(?![\w-])", line) is not None


#: A snake_case word outside quotes and dotted names: a Python keyword, where a line
#: should show the flag the user types.
PYTHON_KEYWORD = re.compile(r"(?<![\w.'\"-])[a-z][a-z0-9]*(?:_[a-z0-9]+)+(?![\w'\"(-])")


def python_keywords(line: str) -> list[str]:
    """The API's keywords in ``line`` that have a flag (the paper's symbol phi_a aside)."""
    from twoball.cli.flags import FLAGS, SYMBOLS

    text = line.partition(", got ")[0]  # the value given is the user's own text
    return sorted({w for w in PYTHON_KEYWORD.findall(text) if w in FLAGS and w not in SYMBOLS})


def check_refusals(cases: list[tuple[str, list[str]]], results: list[dict]) -> list[str]:
    """The cases that did not give exit 2 and one line naming the flag (with what they gave):
    the line names flags, not the API's keywords (``--mass-ratio``, not ``mass_ratio``)."""
    bad = []
    for (flag, argv), result in zip(cases, results, strict=True):
        err = result["stderr"]
        lines = err.strip().splitlines()
        ok = (
            result["status"] == 2
            and len(lines) == 1
            and lines[0].startswith("twoball: error: ")
            and names_flag(lines[0], flag)
            and not python_keywords(lines[0])
            and "Traceback" not in err
            and not result["left"]
            and result["cpu_s"] < REFUSAL_CPU_S
        )
        if not ok:
            shown = " ".join(a if len(a) < 80 else a[:40] + "..." for a in argv)
            bad.append(
                f"{flag}: twoball {shown} -> {result['status']}, {result['cpu_s']:.2f} s CPU, "
                f"left {result['left'][:3]}: {err.strip()[-400:]}"
            )
    return bad


CONTROL = [
    ["liftoff", "--json"],
    ["liftoff", "--json", "--v0", "-4.1"],  # the sign of v0 is ignored
    ["liftoff", "--json", "--damping", "0"],
    ["liftoff", "--json", "--phi-a", repr(table.PHI_A_HIGH)],
    ["eigen", "--json", "--level", "0", "--order", "1", "--count", "3"],
    ["sweep", "--param", "damping", "--values", "0:0.5:3", "--json"],
    ["icm", "--mu", "0", "--e2", "0", "--e12", "1", "--json"],
    ["icm", "--table1", "--json"],
    ["converge", "modes", "--modes-list", "30,60,120", "--out", "{tmp}/c", "--json"],
    ["export", "--level", "1", "--order", "1", "--out", "{tmp}/x.vtu"],
    ["render", "--level", "1", "--order", "1", "--size", "64x48", "--out", "{tmp}/x.png"],
    ["plot", "pole", "--level", "1", "--order", "1", "--out", "{tmp}/p.png"],
    ["plot", "eigen", "--levels", "0", "--orders", "1", "--max-degree", "2"]
    + ["--out", "{tmp}/p.png"],
]


def test_every_subcommand_and_numeric_option_is_in_the_table() -> None:
    parser = full_parser()
    assert set(table.BASE) == set(COMMANDS)
    options = table.numeric_options(parser)
    missing = sorted({f for flags in options.values() for f in flags} - set(table.RANGES))
    assert not missing, f"numeric options without a valid range in validation_table: {missing}"
    paths = {  # options whose value names a file or folder
        action.option_strings[0]
        for sub in table.subparsers(parser).values()
        for action in sub._actions
        if action.option_strings and re.search(r"PATH|DIR|FILE", str(action.metavar or ""))
    }
    assert paths == set(table.PATH_OPTIONS)
    # each bad value is tried where it is invalid: the table is not empty for any option
    for flags in options.values():
        for flag in flags:
            assert {"nan", "inf", "-inf", "", "abc"} <= set(table.bad_values(flag)), flag


def test_ranges_of_the_table() -> None:
    """The table's own logic: pi - 1e-9 is refused for phi_a, 0 allowed for damping."""
    assert not table.RANGES["--phi-a"].accepts(table.PI_MINUS)
    assert table.RANGES["--phi-a"].accepts("2.6")
    assert table.RANGES["--damping"].accepts("0") and not table.RANGES["--damping"].accepts("1")
    assert not table.RANGES["--level"].accepts("1e-308")  # not an integer
    assert "0" in table.bad_values("--v0") and "-1" not in table.bad_values("--v0")
    assert table.with_option("plot", "--max-degree", "-1")[:2] == ["plot", "eigen"]
    assert "--level" not in table.with_option("plot", "--max-degree", "-1")
    fem = table.with_option("bounce", "--elements", "-1")
    assert fem == ["bounce", "--json", "--backend", "fem", "--elements", "-1"]  # no --modes


def test_invalid_command_lines_exit_2_with_one_line(tmp_path: Path) -> None:
    parser = full_parser()
    cases = table.numeric_cases(parser) + table.path_cases(parser) + table.NOT_APPLICABLE
    assert len(cases) > 900
    assert {argv[0] for _, argv in cases} == set(COMMANDS)
    gaps = [case for case in cases if tuple(case[1]) in table.KNOWN_GAPS]
    assert len(gaps) == len(table.KNOWN_GAPS)  # every known gap is a case of the table
    results = run_child(cases, tmp_path)
    known = [k for k, case in enumerate(cases) if tuple(case[1]) in table.KNOWN_GAPS]
    rest = [k for k in range(len(cases)) if k not in set(known)]
    bad = check_refusals([cases[k] for k in rest], [results[k] for k in rest])
    assert not bad, f"{len(bad)} of {len(cases)} cases:\n" + "\n".join(bad[:40])
    # the known gaps are still gaps (a fixed one must leave KNOWN_GAPS)
    fixed = [cases[k][1] for k in known if not check_refusals([cases[k]], [results[k]])]
    assert not fixed, f"refused now, delete from KNOWN_GAPS: {fixed}"
    # refused before the work: the slowest refusal is a fraction of one real run
    slowest = max(results[k]["cpu_s"] for k in rest)
    assert slowest < REFUSAL_CPU_S


def test_the_base_lines_run(tmp_path: Path) -> None:
    """The lines the table starts from (and edge values inside the ranges) are accepted.

    Otherwise a refusal in the table could come from the base line, not from the
    value under test.  verify and reproduce are left to their own tests (minutes).
    """
    results = run_child([("", argv) for argv in CONTROL], tmp_path)
    for argv, result in zip(CONTROL, results, strict=True):
        assert result["status"] in (0, 1), (argv, result["status"], result["stderr"][-800:])
        assert "Traceback" not in result["stderr"]
        assert not any(
            line.startswith("twoball: error") for line in result["stderr"].splitlines()
        ), (argv, result["stderr"])


def test_refusals_name_the_value_given(tmp_path: Path) -> None:
    """The line shows the value the user typed, under the flag they typed it with; a
    budget refusal names this subcommand's flags and says which values are defaults."""
    cases = [("", argv) for argv, _, _ in table.MESSAGES]
    results = run_child(cases, tmp_path)
    for (argv, held, absent), result in zip(table.MESSAGES, results, strict=True):
        err = result["stderr"].strip()
        assert result["status"] == 2 and len(err.splitlines()) == 1, (argv, err)
        assert err.startswith("twoball: error: ") and not result["left"], (argv, err)
        assert all(words in err for words in held), (argv, err)
        assert not any(words in err for words in absent), (argv, err)


def test_unit_slips_warn_with_the_value_meant(tmp_path: Path) -> None:
    """A value far outside any ball runs (exit 0) and says, on standard error and in the
    JSON, what was probably meant."""
    cases = [("", [*argv, "--json"]) for argv, _ in table.UNIT_SLIPS]
    results = run_child(cases, tmp_path)
    for (argv, words), result in zip(table.UNIT_SLIPS, results, strict=True):
        err = result["stderr"]
        assert result["status"] == 0 and "Traceback" not in err, (argv, err[-600:])
        said = [line for line in err.splitlines() if line.startswith("twoball: warning: ")]
        assert any(all(w in line for w in words) for line in said), (argv, said)
        data = json.loads(result["stdout"])
        points = data["results"] if "results" in data else [data]
        kept = [w for point in points for w in point["warnings"]]
        first = words[2:] if argv[0] == "sweep" else words  # per point: the warning itself
        assert any(all(w in text for w in first) for text in kept), (argv, kept)


@pytest.mark.parametrize("flag", ["--phi-a", "--radius", "--wave-speed", "--v0", "--t-end"])
def test_api_and_cli_share_the_message(flag: str) -> None:
    """The CLI prints the API's ParameterError with the flag in place of the parameter name."""
    from twoball._common.errors import ParameterError
    from twoball.cli.flags import FLAGS, cli_message

    name = next(k for k, v in FLAGS.items() if v == flag)
    error = ParameterError(name, "a number in [1, 2]", 3.0)
    assert cli_message(error) == f"{flag} must be a number in [1, 2], got 3.0"


def test_the_keywords_a_message_names_become_flags() -> None:
    """Every keyword with a flag in the valid range is the flag; a body comes from either
    --mass-ratio or --pair where the subcommand takes both; quoted values and symbols stay."""
    from argparse import Namespace

    from twoball._common.errors import ParameterError
    from twoball.cli.flags import cli_message

    error = ParameterError("restitution", "given only with mass_ratio", 0.5)
    with_pair = Namespace(pair=None, mass_ratio=None)
    assert cli_message(error, with_pair) == (
        "--restitution must be given only with --mass-ratio or --pair, got 0.5"
    )
    assert cli_message(error, Namespace(mass_ratio=None)) == (
        "--restitution must be given only with --mass-ratio, got 0.5"
    )
    error = ParameterError("levels", "left out with study modes (use modes_list)", "1:2")
    assert (
        cli_message(error)
        == "--levels must be left out with study modes (use --modes-list), got '1:2'"
    )
    error = ParameterError("max_time", "above 'max_time' of phi_a and case.t_end", "x_y")
    assert (
        cli_message(error)
        == "--max-time must be above 'max_time' of phi_a and case.t_end, got 'x_y'"
    )
    assert python_keywords("twoball: error: --gap must be given only with mass_ratio, got 1") == [
        "mass_ratio"
    ]
