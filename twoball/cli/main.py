"""The ``twoball`` command line: SI units in and out, one-line errors, exit status 2.

Each subcommand lives in its own module ``twoball.cli.<name>`` with a
``register(parser)`` function that adds its options and a ``run(args)`` that
does the work.  Only the chosen subcommand's module is imported, so
``twoball --help`` loads no numerical library at all.  This module turns
:class:`~twoball._common.errors.ParameterError` into a one-line message with exit
status 2 (naming the flag through the one table of
:mod:`twoball.cli.flags`) and :class:`~twoball._common.errors.NumericalError`
into one with exit status 3.
"""

from __future__ import annotations

import argparse
import importlib
import os
import re
import sys

from twoball._version import __version__

TYPE_CHECKING = False  # typing is not imported at start-up: annotations only
if TYPE_CHECKING:
    from collections.abc import Sequence
    from types import ModuleType
    from typing import NoReturn

_NEGATIVE_VALUE = re.compile(r"-(\d|\.\d|inf|nan)", re.IGNORECASE)
EXIT_USAGE = 2
EXIT_NUMERICAL = 3

# name -> one-line help; the module is twoball.cli.<name>.
COMMANDS: dict[str, str] = {
    "verify": "check every backend against the closed form; write a report directory",
    "liftoff": "lift-off time and velocity for one case",
    "bounce": "the lower ball dropped on a rigid floor (contact time, e2, flattening), or the "
    "whole two-ball bounce with a body on top (--mass-ratio, --pair; v1, v2, timing)",
    "eigen": "finite-element eigenvalues against l (l + 1)",
    "sweep": "lift-off over a range of one parameter, or a grid of two",
    "fit": "fit model parameters (damping, wave speed, e12) to a measured CSV file",
    "icm": "independent collision model (§2), Table 1",
    "reproduce": "recompute the paper's figures and numbers beside ours (PNG + reproduction.md)",
    "export": "write u, u_t, u_tt of both backends on the sphere mesh (XDMF, PVD or VTU)",
    "render": "picture (PNG) or animation (GIF, MP4) of the deformed ball and the upper body",
    "plot": "figures (PDF, SVG, PNG, ...): waterfall of u(phi), pole motion, FE eigenvalue errors",
    "converge": "refinement studies: observed orders, Richardson extrapolation, GCI",
}


QUIET_HELP = "no progress lines or bars on standard error (warnings and errors still print)"


def command_module(name: str) -> ModuleType:
    """The module of subcommand ``name`` (imported on demand)."""
    return importlib.import_module(f"twoball.cli.{name}")


class _StoreOnce(argparse._StoreAction):
    """``store`` that refuses an option given twice (argparse would keep the last silently)."""

    def __call__(
        self,
        parser: argparse.ArgumentParser,
        namespace: argparse.Namespace,
        values: object,
        option_string: str | None = None,
    ) -> None:
        if option_string is not None:
            seen = namespace.__dict__.setdefault("_given_once", {})
            if self.dest in seen:
                name = max(self.option_strings, key=len)
                parser.error(
                    f"{name} given more than once ({seen[self.dest]}, then {values}); give it once"
                )
            seen[self.dest] = values
        setattr(namespace, self.dest, values)


def _columns() -> int:
    """The terminal's width as :func:`shutil.get_terminal_size` reads it (``COLUMNS``,
    then standard output, else 80), without importing shutil and its compressors."""
    try:
        columns = int(os.environ.get("COLUMNS", "0"))
    except ValueError:
        columns = 0
    if columns <= 0:
        try:
            columns = os.get_terminal_size(sys.__stdout__.fileno()).columns
        except (AttributeError, ValueError, OSError):
            columns = 0
    return columns or 80


class _Formatter(argparse.HelpFormatter):
    """argparse's help layout at the terminal's width (argparse's own default)."""

    def __init__(self, prog: str, **kwargs: object) -> None:
        kwargs.setdefault("width", _columns() - 2)
        super().__init__(prog, **kwargs)  # type: ignore[arg-type]


class _Parser(argparse.ArgumentParser):
    """ArgumentParser whose errors are one line (no usage block) and exit status 2.

    An option that takes one value is refused when given twice (:class:`_StoreOnce`).
    """

    def __init__(self, *args: object, **kwargs: object) -> None:
        kwargs.setdefault("formatter_class", _Formatter)
        super().__init__(*args, **kwargs)  # type: ignore[arg-type]
        self.register("action", None, _StoreOnce)
        self.register("action", "store", _StoreOnce)

    def error(self, message: str) -> NoReturn:
        bad_type = re.fullmatch(r"argument (--[\w-]+): invalid \w+ value: (.*)", message)
        if bad_type:  # every numeric option leaves its range to the API; this is a fallback
            flag, got = bad_type.groups()
            fail(f"{flag} must be {'a number' if 'float' in message else 'an integer'}, got {got}")
        fail(message)


def fail(message: str, status: int = EXIT_USAGE) -> NoReturn:
    """Print ``twoball: error: message`` on one line and exit with ``status``."""
    sys.stderr.write(f"twoball: error: {message}\n")
    raise SystemExit(status)


def build_parser(chosen: str | None = None) -> argparse.ArgumentParser:
    """The ``twoball`` argument parser.

    Every subcommand is listed; only ``chosen`` (all of them if ``chosen`` is
    ``"*"``) gets its options, which imports its module.
    """
    parser = _Parser(
        prog="twoball",
        description="Lift-off of a light body from a vibrating spherical membrane "
        "(two-ball bounce): closed-form Legendre series and finite elements.",
    )
    parser.add_argument("--version", action="version", version=f"twoball {__version__}")
    parser.add_argument("-q", "--quiet", action="store_true", help=QUIET_HELP)
    sub = parser.add_subparsers(dest="command", metavar="COMMAND", parser_class=_Parser)
    for name, help_text in COMMANDS.items():
        command = sub.add_parser(name, help=help_text, description=help_text)
        # also after the subcommand; SUPPRESS keeps a --quiet given before it
        command.add_argument(
            "-q", "--quiet", action="store_true", default=argparse.SUPPRESS, help=QUIET_HELP
        )
        if chosen in (name, "*"):
            module = command_module(name)
            module.register(command)
    return parser


def full_parser() -> argparse.ArgumentParser:
    """The parser with every subcommand's options (for the generated CLI reference)."""
    return build_parser("*")


def value_options(parser: argparse.ArgumentParser) -> set[str]:
    """Every option string of ``parser`` and its loaded subcommands that takes one value."""
    found: set[str] = set()
    for action in parser._actions:
        if isinstance(action, argparse._SubParsersAction):
            for command in action.choices.values():
                found |= value_options(command)
        elif action.option_strings and action.nargs is None:
            found.update(action.option_strings)
    return found


def join_negative_values(argv: Sequence[str], value_options: set[str]) -> list[str]:
    """``["--values", "-1:1:3"]`` -> ``["--values=-1:1:3"]`` for options that take a value.

    argparse reads a word that starts with ``-`` as an option unless it is a
    plain negative number, so ranges and lists starting below zero (and values
    such as ``-1e-3``) are joined to their option here, before parsing.
    """
    out: list[str] = []
    words = list(argv)
    k = 0
    while k < len(words):
        word = words[k]
        nxt = words[k + 1] if k + 1 < len(words) else None
        if word in value_options and nxt is not None and _NEGATIVE_VALUE.match(nxt):
            out.append(f"{word}={nxt}")
            k += 2
            continue
        out.append(word)
        k += 1
    return out


def refuse_unknown_options(parser: argparse.ArgumentParser, argv: Sequence[str]) -> None:
    """Refuse, naming it, an option the chosen subcommand does not have.

    argparse would otherwise take the word after an unknown option as a
    positional argument and blame that (``converge --study h --mesh-file X`` ->
    "invalid choice: 'X'").  Unique abbreviations stay accepted, as argparse does.
    """
    command = chosen_command(argv)
    known = {s for a in parser._actions for s in a.option_strings}
    for action in parser._actions:
        if isinstance(action, argparse._SubParsersAction) and command in action.choices:
            known |= {s for a in action.choices[command]._actions for s in a.option_strings}
    for word in argv:
        if word == "--":
            break
        if not word.startswith("--") or word == "--":
            continue
        name = word.split("=", 1)[0]
        if name in known or len([k for k in known if k.startswith(name)]) == 1:
            continue
        where = f"twoball {command}" if command else "twoball"
        hint = ELSEWHERE.get((command, name)) or _other_commands(name, command)
        fail(f"{name} is not an option of {where}{hint} (see {where} --help)")


#: Where an option that a subcommand lacks does what was asked: a pair (the whole two-ball
#: bounce) is dropped by ``twoball bounce``, which writes its own figure, fields and pictures.
ELSEWHERE: dict[tuple[str | None, str], str] = {
    ("render", "--pair"): "; a pair's drop is drawn by twoball bounce --pair NAME --render FILE",
    ("export", "--pair"): "; a pair's drop is written by twoball bounce --pair NAME --export FILE",
    ("plot", "--pair"): "; a pair's figure is drawn by twoball bounce --pair NAME --plot FILE",
    ("liftoff", "--pair"): "; a pair's whole bounce is twoball bounce --pair NAME",
}


def _other_commands(flag: str, command: str | None) -> str:
    """``; it is an option of twoball bounce, sweep`` (empty if of no other subcommand)."""
    if command is None:
        return ""
    parser = full_parser()
    others = [
        name
        for action in parser._actions
        if isinstance(action, argparse._SubParsersAction)
        for name, sub in action.choices.items()
        if name != command and any(flag in a.option_strings for a in sub._actions)
    ]
    return f"; it is an option of twoball {', '.join(others)}" if others else ""


def chosen_command(argv: Sequence[str]) -> str | None:
    """The subcommand named in ``argv`` (its first word that is not an option), if any."""
    for word in argv:
        if not word.startswith("-"):
            return word if word in COMMANDS else None
    return None


def main(argv: Sequence[str] | None = None) -> int:
    """Entry point of the ``twoball`` console script.

    SIGINT/SIGTERM end it with exit status 130/143 and the line ``twoball:
    interrupted``; an OSError while writing gives one line naming the path and
    exit status 2 (3 if the cause is not the user's path); see
    :mod:`twoball.cli.guard`.
    """
    from twoball.cli.guard import guarded, leave

    # the console script (no argv): this process is the run, its handlers last to the end
    status = guarded(_main, argv, process=argv is None)
    if argv is None and status in (130, 143):  # interrupted: end within the second
        leave(status)
    return status


def _main(argv: Sequence[str] | None = None) -> int:
    """Parse ``argv`` and run the chosen subcommand (errors mapped to one line)."""
    argv = list(sys.argv[1:] if argv is None else argv)
    parser = build_parser(chosen_command(argv))
    if not argv:
        parser.print_help()
        return 0
    argv = join_negative_values(argv, value_options(parser))
    refuse_unknown_options(parser, argv)
    args = parser.parse_args(argv)
    if args.command is None:
        fail("choose a command: " + ", ".join(COMMANDS))
    from twoball._common import progress, provenance

    progress.set_quiet(args.quiet)
    provenance.set_command(argv)  # every JSON and file this run writes names it
    from twoball._common.budget import DeadlineError, running, set_budget
    from twoball._common.errors import NumericalError, ParameterError

    budget_before = set_budget(None)
    set_budget(budget_before)
    try:
        with running():  # the clock of --max-time: long loops stop at its deadline
            return int(args.run(args))
    except ParameterError as error:
        from twoball.cli.flags import cli_message

        fail(cli_message(error, args))
    except DeadlineError as error:
        from twoball.cli.flags import limit_flags

        fail(limit_flags(" ".join(str(error).split())), EXIT_NUMERICAL)
    except NumericalError as error:
        fail(f"numerical trouble: {error}", EXIT_NUMERICAL)
    finally:  # main() called again in one process (tests, scripts) starts afresh
        progress.set_quiet(False)
        provenance.set_command(None)
        set_budget(budget_before)


if __name__ == "__main__":
    raise SystemExit(main())
