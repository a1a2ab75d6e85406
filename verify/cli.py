"""The ``twoball`` command line: SI units in and out, one-line errors, exit status 2.

Each subcommand lives in its own module ``verify/cli_<name>.py`` with a
``register(subparsers)`` function; this module only assembles them and turns
:class:`~modal.errors.ParameterError` into a one-line message with exit status 2
and :class:`~modal.errors.NumericalError` into one with exit status 3.
"""

from __future__ import annotations

import argparse
import re
import sys
from collections.abc import Sequence
from typing import NoReturn

from modal.errors import NumericalError, ParameterError

from . import (
    cli_converge,
    cli_eigen,
    cli_export,
    cli_icm,
    cli_liftoff,
    cli_plot,
    cli_render,
    cli_reproduce,
    cli_sweep,
    cli_verify,
)
from .case_options import VALID_RANGES as CASE_RANGES

EXIT_USAGE = 2
EXIT_NUMERICAL = 3
SUBCOMMANDS = [
    cli_verify,
    cli_liftoff,
    cli_eigen,
    cli_sweep,
    cli_icm,
    cli_reproduce,
    cli_export,
    cli_render,
    cli_plot,
    cli_converge,
]


class _Parser(argparse.ArgumentParser):
    """ArgumentParser whose errors are one line (no usage block) and exit status 2."""

    def error(self, message: str) -> NoReturn:
        bad_type = re.fullmatch(r"argument (--[\w-]+): invalid \w+ value: (.*)", message)
        if bad_type:
            flag, got = bad_type.groups()
            valid = valid_ranges().get(flag, "a number" if "float" in message else "an integer")
            fail(f"{flag} must be {valid}, got {got}")
        fail(message)


def valid_ranges() -> dict[str, str]:
    """Valid range of every numeric flag, for one-line messages (modules add theirs)."""
    ranges = dict(CASE_RANGES)
    for module in SUBCOMMANDS:
        ranges.update(getattr(module, "VALID_RANGES", {}))
    return ranges


def fail(message: str, status: int = EXIT_USAGE) -> NoReturn:
    """Print ``twoball: error: message`` on one line and exit with ``status``."""
    sys.stderr.write(f"twoball: error: {message}\n")
    raise SystemExit(status)


def build_parser() -> argparse.ArgumentParser:
    """The ``twoball`` argument parser with every registered subcommand."""
    parser = _Parser(
        prog="twoball",
        description="Lift-off of a light body from a vibrating spherical membrane "
        "(two-ball bounce): closed-form Legendre series and finite elements.",
    )
    sub = parser.add_subparsers(dest="command", required=True, parser_class=_Parser)
    for module in SUBCOMMANDS:
        module.register(sub)
    return parser


def main(argv: Sequence[str] | None = None) -> int:
    """Entry point of the ``twoball`` console script."""
    args = build_parser().parse_args(argv)
    try:
        return int(args.run(args))
    except ParameterError as error:
        fail(str(error))
    except NumericalError as error:
        fail(f"numerical trouble: {error}", EXIT_NUMERICAL)
    except BrokenPipeError:  # output piped into a reader that stopped (e.g. `head`)
        import os

        os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())
        return 0


if __name__ == "__main__":
    raise SystemExit(main())
