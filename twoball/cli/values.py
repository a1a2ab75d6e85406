"""Argument types of the command line that leave every range check to the API.

``--radius abc`` or ``--level 2.5`` reach the public function as they were
typed (a string, a float), and the option object or model that owns the
parameter refuses them with its one message naming the valid range; so no
range is written twice.  A number with a digit separator (``--gap 0_01``, which
Python's ``float`` reads as 1.0) stays text, so it is refused as not a number
(:func:`twoball._common.ranges.decimal`).
"""

from __future__ import annotations

from twoball._common.ranges import decimal, whole

__all__ = ["integer", "number"]


def number(text: str) -> float | str:
    """``text`` as a float if it reads as one, else the text itself."""
    try:
        return decimal(text)
    except ValueError:
        return text


def integer(text: str) -> int | float | str:
    """``text`` as an int if it reads as one, else as :func:`number`."""
    try:
        return whole(text)
    except ValueError:
        return number(text)
