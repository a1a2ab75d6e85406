"""One syntax for every list of values: ``v1,v2,...`` or ``START:STOP[:COUNT]``.

Every option that takes several values (sweep values, refinement levels, mode
counts, export times, plot levels and orders) reads them here, so one rule holds
everywhere:

* ``1,2,3`` -- the values as written (negative numbers allowed: ``-1,0,1``);
* ``START:STOP:COUNT`` -- ``COUNT`` evenly spaced values from START to STOP,
  both ends included (``0:0.5:6``; ``-1:1:3`` gives ``-1, 0, 1``);
* ``START:STOP`` -- for whole-number options only, every integer from START to
  STOP (``2:5`` gives ``2, 3, 4, 5``).

On the command line a value that starts with ``-`` is taken as the option's
value, not as a new option (:func:`twoball.cli.main.join_negative_values`).
"""

from __future__ import annotations

import math
from collections.abc import Sequence

from twoball._common.errors import ParameterError

__all__ = ["SYNTAX", "decimal", "parse_values", "real", "whole"]

SYNTAX = "v1,v2,... or START:STOP:COUNT"
INTEGER_SYNTAX = "v1,v2,... or START:STOP[:COUNT]"
MAX_VALUES = 1_000_000  # a list longer than this is a typo, not a study


def decimal(text: str) -> float:
    """``float(text)`` for a number as a person writes it, else :class:`ValueError`.

    Python's ``float`` also reads digit separators (``float("0_01")`` is 1.0,
    ``float("4_1")`` 41.0) and digits of other scripts (``float("\u0663")`` is
    3.0): a typo for 0.01 or 4.1 would run as another value, so both are refused.
    ``inf`` and ``nan`` are read (the ranges refuse them, naming the option).
    """
    if "_" in text or not text.isascii():
        raise ValueError(f"not a number as written: {text!r}")
    return float(text)


def whole(text: str) -> int:
    """``int(text)`` under the rules of :func:`decimal`, else :class:`ValueError`."""
    if "_" in text or not text.isascii():
        raise ValueError(f"not a whole number as written: {text!r}")
    return int(text)


def real(value: object) -> float:
    """A list item of the Python API as a float: a real number, not a string or a bool."""
    from numbers import Real

    if isinstance(value, bool) or not isinstance(value, Real):
        raise ValueError(f"not a number: {value!r}")
    return float(value)


def parse_values(
    text: str | Sequence[float],
    name: str,
    *,
    integer: bool = False,
    valid: str = "",
) -> tuple[float, ...] | tuple[int, ...]:
    """The values of ``text`` in the one list syntax (see the module docstring).

    Parameters
    ----------
    text : str or sequence of numbers
        ``"v1,v2,..."``, ``"START:STOP:COUNT"`` or (``integer``) ``"START:STOP"``;
        a sequence of numbers is taken as the list itself (Python API).
    name : str
        The parameter's name, for the error message.
    integer : bool
        Whole numbers only (levels, orders, mode counts).
    valid : str
        What else the values must satisfy, appended to the syntax in errors
        (for example ``"levels in [0, 6]"``).  The caller checks it.

    Returns
    -------
    tuple
        The values in the order written (a range ascends or descends as given);
        ``int`` when ``integer``.

    Raises
    ------
    ParameterError
        Not in the syntax, not finite, not whole when ``integer``, empty, or
        more than a million values.
    """
    syntax = INTEGER_SYNTAX if integer else SYNTAX
    expected = syntax + ("" if not valid else f" ({valid})")
    if not isinstance(text, str):
        try:
            values = [real(v) for v in text]
        except (TypeError, ValueError):
            raise ParameterError(name, expected, text) from None
        return _finish(values, name, expected, integer, text)
    parts = [p.strip() for p in text.split(":")]
    try:
        if len(parts) == 1:
            values = [decimal(p) for p in text.split(",")]
        elif len(parts) in (2, 3) and "," not in text:
            start, stop = decimal(parts[0]), decimal(parts[1])
            if len(parts) == 3:
                count = _count(parts[2])
            elif integer and start == round(start) and stop == round(stop):
                count = int(abs(stop - start)) + 1 if math.isfinite(stop - start) else 0
            else:
                raise ValueError
            if not (math.isfinite(start) and math.isfinite(stop)) or count < 1:
                raise ValueError
            if count > MAX_VALUES:
                raise ParameterError(name, f"{expected}, at most {MAX_VALUES} values", text)
            if count == 1 and start != stop:
                raise ParameterError(name, f"{expected} (COUNT 1 needs START = STOP)", text)
            step = 0.0 if count == 1 else (stop - start) / (count - 1)
            values = [start + k * step for k in range(count - 1)] + [stop]
        else:
            raise ValueError
    except ValueError:
        raise ParameterError(name, expected, text) from None
    return _finish(values, name, expected, integer, text)


def _count(text: str) -> int:
    count = decimal(text)
    if count != round(count):
        raise ValueError
    return int(count)


def _finish(
    values: list[float], name: str, expected: str, integer: bool, text: object
) -> tuple[float, ...] | tuple[int, ...]:
    if not values or len(values) > MAX_VALUES or not all(math.isfinite(v) for v in values):
        raise ParameterError(name, expected, text)
    if integer:
        if any(v != round(v) for v in values):
            raise ParameterError(name, expected + ", whole numbers", text)
        return tuple(int(round(v)) for v in values)
    return tuple(values)
