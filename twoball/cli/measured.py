"""The options that bring the user's measurements to a figure and a sweep's table to a file.

``--measured FILE.csv`` (``sweep --plot`` and ``bounce --plot``): the rows of a
measured file, in the columns of ``twoball fit`` (``v0_m_s``, ``gap_m``,
``phi_a_rad``, ``v1_m_s``, ``v2_m_s``, ``t_liftoff_s``, ``sigma_v1_m_s``, ...), drawn
over the model's curves; ``--csv FILE`` (``sweep``): the table as CSV, one row
per point.  Both are checked before any work: the measured file is read (and
refused by file, row and column), the table's path must be writable.
"""

from __future__ import annotations

import argparse
from pathlib import Path
from typing import Any

from twoball._common.errors import ParameterError

__all__ = [
    "add_csv_option",
    "add_measured_option",
    "check_paths",
    "csv_target",
    "measured_rows",
    "print_overlay",
]


def add_measured_option(parser: argparse.ArgumentParser, what: str) -> None:
    """``--measured FILE``: the user's points drawn on ``--plot`` (``what`` says where)."""
    parser.add_argument(
        "--measured",
        metavar="FILE",
        help="with --plot: a CSV of measured rows (the columns of twoball fit: v0_m_s, gap_m, "
        f"phi_a_rad, v1_m_s, v2_m_s, t_liftoff_s, sigma_v1_m_s, ...) drawn {what}",
    )


def add_csv_option(parser: argparse.ArgumentParser) -> None:
    """``--csv FILE``: the sweep's table as CSV."""
    parser.add_argument(
        "--csv",
        metavar="FILE",
        help="also write the table as CSV: one row per point, SI columns with the unit in "
        "the name (v0_m_s, t_liftoff_s, ...; blank: no value)",
    )


def measured_rows(args: argparse.Namespace) -> Any:
    """The rows of ``--measured``, read and checked before any work (None without it).

    Refused without ``--plot`` (nothing to draw them on), and, for a file, in one
    line naming it, the row and the column.
    """
    path = getattr(args, "measured", None)
    if path is None:
        return None
    if getattr(args, "plot", None) is None:
        raise ParameterError("measured", "given with --plot (the figure it is drawn on)", path)
    from twoball._fit import read_measured

    return read_measured(path, "measured")


def csv_target(args: argparse.Namespace) -> Path | None:
    """The path of ``--csv``, checked before any work (a file in a writable folder)."""
    path = getattr(args, "csv", None)
    if path is None:
        return None
    from twoball._common.staging import check_file, check_path_type

    check_path_type(path, "csv")
    return check_file(path, "csv")


def print_overlay(result: Any, rows: Any) -> None:
    """Say on standard error what the figure left out of the measured rows (notes)."""
    if rows is None:
        return
    from twoball._fit import overlay_notes
    from twoball.cli.console import print_notes

    print_notes(overlay_notes(result, rows))


def check_paths(args: argparse.Namespace, outputs: dict[str, Any]) -> None:
    """Refuse, before any work, two outputs with one path or an output onto ``--measured``."""
    from twoball._common.staging import check_distinct

    given = getattr(args, "measured", None)
    inputs = {"the measured file (--measured)": given} if given is not None else None
    check_distinct(outputs, inputs=inputs, labels={name: f"--{name}" for name in outputs})
