"""Terminal output shared by the subcommands: rich tables without markup surprises.

rich is imported when something is drawn: ``print_json`` and ``number`` need none
of it, so the ``--json`` paths start without it.  Subcommands import
:func:`Table` from here rather than from rich for the same reason.
"""

from __future__ import annotations

import json
import sys
from collections.abc import Sequence
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from rich.console import Console
    from rich.table import Table as RichTable


#: Columns of a table written to a file or a pipe: wide enough that no cell is cut
#: ("9.556799796e…"); a reader of a log or a script gets every value whole.
PIPE_WIDTH = 1000


def console(wide: bool = False) -> Console:
    """A console that prints brackets literally (units like ``[m/s]`` are not markup).

    On a terminal, tables fit its width (``wide`` is kept for the callers' intent:
    their tables have many columns).  Written to a file or a pipe, tables take the
    width their cells need (up to :data:`PIPE_WIDTH` columns): no value is cut.
    """
    from rich.console import Console

    width = None if sys.stdout.isatty() else PIPE_WIDTH
    return Console(markup=False, highlight=False, width=width)


def number(value: float | None, scale: float = 1.0, digits: int = 4) -> str:
    """``value * scale`` with fixed digits, or ``-`` for None."""
    return "-" if value is None else f"{value * scale:.{digits}f}"


def print_json(data: Any) -> None:
    """Print JSON (two-space indent) to standard output."""
    print(json.dumps(data, indent=2))


def Table(*columns: Any, **options: Any) -> RichTable:  # named like the class it makes
    """A :class:`rich.table.Table` (same arguments); rich is imported on the first call."""
    from rich.table import Table as RichTable

    return RichTable(*columns, **options)


def key_value_table(title: str, rows: list[tuple[str, str]]) -> RichTable:
    """A two-column table of quantities and values."""
    table = Table(title=title)
    table.add_column("quantity")
    table.add_column("value", justify="right")
    for name, value in rows:
        table.add_row(name, value)
    return table


def print_notes(notes: list[str]) -> None:
    """Print each note on standard error (``twoball: note: ...``), apart from the results."""
    for note in notes:
        sys.stderr.write(f"twoball: note: {note}\n")


def print_warnings(warnings: Sequence[str]) -> None:
    """Print each accuracy warning on standard error (``twoball: warning: ...``).

    The same texts are in the result's JSON ``warnings`` list; the run goes on.
    """
    for text in warnings:
        sys.stderr.write(f"twoball: warning: {text}\n")
