"""Measured rows from a CSV file (or a mapping of columns), read and refused by name.

A measured file is comma-separated text with one header line naming its
columns (:data:`~twoball._common.choices.MEASURED_COLUMNS`, SI with the unit in
the name: ``v0_m_s``, ``phi_a_rad``, ``gap_m``, ``v1_m_s``, ``v2_m_s``,
``t_liftoff_s``), optional uncertainty columns ``sigma_<column>`` (same unit)
and one row per measurement.  Lines starting with ``#`` are comments; a blank
cell is a value not measured (an input then takes the case's).  Anything else
is refused with one line naming the file, the row (and its line) and the
column: :class:`MeasurementError`, a :class:`~twoball.ParameterError`.

Examples
--------
>>> data = Measurements.from_columns({"v0_m_s": [4.1], "v1_m_s": [3.7]})
>>> data.columns, data.rows, float(data.column("v1_m_s")[0])
(('v0_m_s', 'v1_m_s'), 1, 3.7)
"""

from __future__ import annotations

import csv
import math
import os
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np

from twoball._common.choices import MEASURED_COLUMNS, SIGMA_PREFIX
from twoball._common.errors import ParameterError

__all__ = [
    "MeasurementError",
    "Measurements",
    "as_measurements",
    "measured_columns",
    "read_measurements",
]

#: Units of the columns, for messages and headers.
UNITS: dict[str, str] = {
    "v0_m_s": "m/s",
    "phi_a_rad": "rad",
    "gap_m": "m",
    "v1_m_s": "m/s",
    "v2_m_s": "m/s",
    "t_liftoff_s": "s",
}
#: Plausible largest values (SI): beyond them a value is probably in another unit.
PLAUSIBLE: dict[str, tuple[float, str]] = {
    "t_liftoff_s": (1.0, "milliseconds? the column is in seconds"),
    "gap_m": (1.0, "millimetres? the column is in metres"),
    "v0_m_s": (100.0, "the column is in m/s"),
    "v1_m_s": (100.0, "the column is in m/s"),
    "v2_m_s": (100.0, "the column is in m/s"),
}


def measured_columns() -> tuple[str, ...]:
    """Every column a measured file may hold: the values, then their ``sigma_`` columns."""
    return (*MEASURED_COLUMNS, *(SIGMA_PREFIX + name for name in MEASURED_COLUMNS))


class MeasurementError(ParameterError):
    """A measured file (or mapping) refused: one line naming the source, row and column.

    ``name`` is the argument that gave the data (``data``, ``measured``); the
    message reads ``data runs.csv: row 3 (line 4), column v1_m_s: must be a
    finite number [m/s], got 'abc'`` (the command line prints the flag for the
    name: ``--data runs.csv: ...``).

    Examples
    --------
    >>> error = MeasurementError("data", "runs.csv", "a finite number", "abc", row=3, line=4,
    ...                          column="v1_m_s")
    >>> str(error)
    "data runs.csv: row 3 (line 4), column v1_m_s: must be a finite number, got 'abc'"
    """

    def __init__(
        self,
        name: str,
        source: str,
        valid: str,
        got: object = None,
        *,
        row: int | None = None,
        line: int | None = None,
        column: str | None = None,
    ) -> None:
        ParameterError.__init__(self, name, valid, got)
        self.source, self.row, self.line, self.column = source, row, line, column
        where = []
        if row is not None:
            where.append(f"row {row}" + (f" (line {line})" if line is not None else ""))
        elif line is not None:
            where.append(f"line {line}")
        if column is not None:
            where.append(f"column {column}")
        text = f"{name} {source}: " + ("".join(f"{w}, " for w in where[:-1]))
        text += f"{where[-1]}: " if where else ""
        text += f"must be {valid}"
        if got is not None:
            text += f", got {got!r}"
        ValueError.__init__(self, text)

    def __reduce__(self) -> Any:
        """Pickled with every field (process pools send errors back)."""
        fields = {"row": self.row, "line": self.line, "column": self.column}
        return (_rebuild, (self.name, self.source, self.valid, self.got, fields))


def _rebuild(name: str, source: str, valid: str, got: object, fields: dict) -> MeasurementError:
    return MeasurementError(name, source, valid, got, **fields)


@dataclass(frozen=True)
class Measurements:
    """Measured rows: the columns given, their values (NaN where blank), where they came from.

    Attributes
    ----------
    source : str
        The file as given (or ``"rows"`` for a mapping).
    columns : tuple of str
        The columns in their order (values and ``sigma_`` columns).
    values : dict of str to ndarray
        Each column's values, SI, NaN where the cell was blank.
    lines : tuple of int
        The line of each row in the file (1 is the first line).
    name : str
        The argument that gave the data (for messages): ``data``, ``measured``.

    Examples
    --------
    >>> data = Measurements.from_columns({"v0_m_s": [3.0, 4.1], "v1_m_s": [2.6, None]})
    >>> data.rows, data.measured("v1_m_s").tolist()
    (2, [True, False])
    """

    source: str
    columns: tuple[str, ...]
    values: dict[str, np.ndarray]
    lines: tuple[int, ...]
    name: str = "data"

    @property
    def rows(self) -> int:
        """The number of rows."""
        return len(self.lines)

    def has(self, column: str) -> bool:
        """Whether the file has ``column``."""
        return column in self.values

    def column(self, column: str) -> np.ndarray:
        """The values of ``column`` (NaN where blank; all NaN when the file has none)."""
        if column in self.values:
            return self.values[column]
        return np.full(self.rows, np.nan)

    def measured(self, column: str) -> np.ndarray:
        """Where ``column`` holds a value (a boolean per row)."""
        return np.isfinite(self.column(column))

    def sigma(self, column: str) -> np.ndarray | None:
        """The uncertainties of ``column`` (None without a ``sigma_`` column)."""
        key = SIGMA_PREFIX + column
        return self.values[key] if key in self.values else None

    def error(
        self, valid: str, got: object = None, *, row: int | None = None, column: str | None = None
    ) -> MeasurementError:
        """A refusal naming this source, the row (from 0 here, from 1 in the message)."""
        line = None if row is None else (self.lines[row] or None)
        return MeasurementError(
            self.name,
            self.source,
            valid,
            got,
            row=None if row is None else row + 1,
            line=line,
            column=column,
        )

    def refuse_columns(
        self, usable: Sequence[str], why: str, hints: Mapping[str, str] | None = None
    ) -> None:
        """Refuse, by name, the first column (or its ``sigma_``) that is not in ``usable``;
        ``hints`` says where a refused column belongs."""
        for column in self.columns:
            base = column.removeprefix(SIGMA_PREFIX)
            if base not in usable:
                valid = f"a column {why} can use ({', '.join(usable)})"
                hint = (hints or {}).get(base)
                raise self.error(valid + (f"; {hint}" if hint else ""), column=column)

    def as_dict(self) -> dict[str, Any]:
        """JSON-ready: the source, the columns and the rows (None where blank)."""
        return {
            "source": self.source,
            "columns": list(self.columns),
            "rows": [{c: _cell(self.values[c][k]) for c in self.columns} for k in range(self.rows)],
            "lines": list(self.lines),
        }

    @classmethod
    def from_columns(
        cls, columns: Mapping[str, Sequence[Any]], name: str = "data", source: str = "rows"
    ) -> Measurements:
        """Measurements from ``{"v0_m_s": [...], "v1_m_s": [...]}`` (None or NaN: not measured).

        Refused as a file is: unknown columns, lists of different lengths, cells
        that are not finite numbers.
        """
        if not isinstance(columns, Mapping) or not columns:
            valid = "a CSV file, or a mapping of columns (" + ", ".join(MEASURED_COLUMNS) + ")"
            got = columns if columns is None else type(columns).__name__
            raise ParameterError(name, valid, got)
        names = [str(key) for key in columns]
        lengths = set()
        for key, items in columns.items():
            if isinstance(items, (str, bytes)) or not isinstance(items, Sequence | np.ndarray):
                raise MeasurementError(name, source, "a list of numbers", items, column=str(key))
            lengths.add(len(items))
        rows = max(lengths)
        if len(lengths) != 1:
            raise MeasurementError(name, source, "columns of one length", sorted(lengths))
        cells = [[columns[key][k] for key in columns] for k in range(rows)]
        return _build(name, source, names, cells, [0] * rows, text=False)


def _cell(value: float) -> float | None:
    return None if not math.isfinite(value) else float(value)


def read_measurements(path: str | os.PathLike[str], name: str = "data") -> Measurements:
    """Read a measured CSV file (module docstring); refuse it in one line naming the cell.

    Parameters
    ----------
    path : path-like
        The file: a header line naming the columns, then one row per measurement.
    name : str
        The argument that gave it (``data``, ``measured``), named in refusals.

    Raises
    ------
    MeasurementError
        A missing or unreadable file, no header, an unknown or repeated column,
        a row of another length, a cell that is not a finite number, no rows.
    """
    if isinstance(path, bool) or not isinstance(path, str | os.PathLike):
        valid = "a CSV file path (str or os.PathLike), or a mapping of columns"
        raise ParameterError(name, valid, type(path).__name__)
    shown = os.fspath(path)
    if not shown:
        raise MeasurementError(name, repr(shown), "a CSV file path, not empty")
    target = Path(shown).expanduser()
    try:
        text = target.read_text(encoding="utf-8-sig")
    except FileNotFoundError:
        raise MeasurementError(name, shown, "an existing CSV file (no such file)") from None
    except IsADirectoryError:
        raise MeasurementError(name, shown, "a CSV file, not a folder") from None
    except NotADirectoryError:
        valid = "an existing CSV file (a folder on its path is a file)"
        raise MeasurementError(name, shown, valid) from None
    except PermissionError:
        raise MeasurementError(name, shown, "a readable CSV file (permission denied)") from None
    except UnicodeDecodeError:
        raise MeasurementError(name, shown, "a text file (UTF-8), not binary") from None
    except OSError as error:
        raise MeasurementError(name, shown, f"a readable CSV file ({error.strerror})") from None
    lines = text.splitlines()
    numbered = [
        (k + 1, line)
        for k, line in enumerate(lines)
        if line.strip() and not line.lstrip().startswith("#")
    ]
    if not numbered:
        valid = "a CSV file with a header line naming its columns ("
        valid += ", ".join(MEASURED_COLUMNS) + ")"
        raise MeasurementError(name, shown, valid, "an empty file")
    delimiter = _delimiter(numbered[0][1])
    try:
        parsed = [
            (number, next(csv.reader([line], delimiter=delimiter, skipinitialspace=True)))
            for number, line in numbered
        ]
    except csv.Error as error:
        raise MeasurementError(name, shown, f"CSV text ({error})") from None
    header_line, header = parsed[0]
    names = [cell.strip() for cell in header]
    if all(_is_number(cell) for cell in names if cell):
        valid = "a header line naming the columns (" + ", ".join(MEASURED_COLUMNS) + ")"
        raise MeasurementError(name, shown, valid, delimiter.join(names), line=header_line)
    body = parsed[1:]
    return _build(
        name,
        shown,
        names,
        [cells for _, cells in body],
        [n for n, _ in body],
        header_line=header_line,
    )


def as_measurements(data: Any, name: str = "data") -> Measurements:
    """Measured rows from a CSV path, a mapping of columns or rows already read.

    ``name`` is the argument (``data``, ``measured``) the refusals name.
    """
    if isinstance(data, Measurements):
        return data
    if isinstance(data, Mapping):
        return Measurements.from_columns(data, name=name)
    return read_measurements(data, name)


def _delimiter(header: str) -> str:
    """A comma, unless the header has none and holds semicolons or tabs (spreadsheet exports)."""
    if "," in header:
        return ","
    for other in (";", "\t"):
        if other in header:
            return other
    return ","


def _is_number(text: str) -> bool:
    try:
        float(text)
    except ValueError:
        return False
    return True


def _build(
    name: str,
    source: str,
    names: list[str],
    cells: list[list[Any]],
    lines: list[int],
    *,
    text: bool = True,
    header_line: int = 1,
) -> Measurements:
    """Check the header and every cell; the columns as float arrays (NaN where blank)."""
    known = measured_columns()
    for k, column in enumerate(names):
        if not column:
            raise MeasurementError(
                name,
                source,
                "a named column (the header has an empty name)",
                line=header_line,
                column=str(k + 1),
            )
        if column not in known:
            valid = "one of " + ", ".join(MEASURED_COLUMNS) + " (or sigma_ and one of them)"
            raise MeasurementError(name, source, valid, line=header_line, column=column)
        if names.count(column) > 1:
            raise MeasurementError(
                name, source, "named once in the header", "twice", line=header_line, column=column
            )
    for column in names:
        if column.startswith(SIGMA_PREFIX) and column.removeprefix(SIGMA_PREFIX) not in names:
            valid = f"given with its column {column.removeprefix(SIGMA_PREFIX)}"
            raise MeasurementError(name, source, valid, line=header_line, column=column)
    if not cells:
        raise MeasurementError(
            name, source, "a file with at least one row of values below the header", "a header only"
        )
    values = {column: np.full(len(cells), np.nan) for column in names}
    for k, row in enumerate(cells):
        if len(row) != len(names):
            raise MeasurementError(
                name,
                source,
                f"{len(names)} cells, as the header has",
                len(row),
                row=k + 1,
                line=lines[k] or None,
            )
        for column, cell in zip(names, row, strict=True):
            values[column][k] = _value(name, source, column, cell, k, lines[k], text)
    for column in names:  # an uncertainty beside every measured value
        if column.startswith(SIGMA_PREFIX):
            measured = np.isfinite(values[column.removeprefix(SIGMA_PREFIX)])
            blank = measured & ~np.isfinite(values[column])
            if blank.any():
                k = int(np.flatnonzero(blank)[0])
                raise MeasurementError(
                    name,
                    source,
                    "given where its column holds a value",
                    "a blank cell",
                    row=k + 1,
                    line=lines[k] or None,
                    column=column,
                )
    return Measurements(source, tuple(names), values, tuple(lines), name)


def _value(name: str, source: str, column: str, cell: Any, k: int, line: int, text: bool) -> float:
    """One cell as a finite float (NaN: blank); a sigma must be > 0, a time > 0."""
    base = column.removeprefix(SIGMA_PREFIX)
    unit = UNITS[base]
    valid = f"a finite number [{unit}] or a blank cell"

    def refuse(what: str = valid) -> MeasurementError:
        return MeasurementError(
            name, source, what, cell, row=k + 1, line=line or None, column=column
        )

    if cell is None or (text and isinstance(cell, str) and not cell.strip()):
        return math.nan
    if isinstance(cell, str):
        if not text:
            raise refuse()
        stripped = cell.strip()
        if "_" in stripped:  # float("4_1") is 41.0: a digit separator is not a decimal point
            raise refuse()
        try:
            value = float(stripped)
        except ValueError:
            raise refuse() from None
    elif isinstance(cell, bool) or not isinstance(cell, int | float | np.integer | np.floating):
        raise refuse()
    else:
        value = float(cell)
        if math.isnan(value) and not text:
            return math.nan  # a mapping's NaN: not measured
    if not math.isfinite(value):
        raise refuse()
    if column.startswith(SIGMA_PREFIX) and value <= 0.0:
        raise refuse(f"an uncertainty > 0 [{unit}]")
    if base in ("t_liftoff_s", "gap_m") and value < 0.0:
        what = "a time >= 0 [s]" if base == "t_liftoff_s" else "a gap >= 0 [m]"
        raise refuse(what)
    return value


def plausibility_warnings(data: Measurements) -> list[str]:
    """Values far beyond what the column's unit allows for a ball: probably a unit slip."""
    out = []
    for column, (limit, hint) in PLAUSIBLE.items():
        if not data.has(column):
            continue
        values = np.abs(data.column(column))
        big = np.flatnonzero(np.isfinite(values) & (values > limit))
        if big.size:
            k = int(big[0])
            out.append(
                f"{data.source}: row {k + 1}, column {column} = "
                f"{data.column(column)[k]:g} {UNITS[column]} ({hint}); {big.size} such row(s)"
            )
    return out
