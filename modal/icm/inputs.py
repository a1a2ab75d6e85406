"""Input checks of the independent collision model: one line naming the flag and its range.

Every check returns the value as a float or raises
:class:`~twoball.modal.errors.ParameterError` with the command-line flag
(``--mu``, ``--e2``, ``--e12``, ``--dx``, ``--drop-height``, ``--g``).
"""

from __future__ import annotations

import math

from ..errors import ParameterError


def _as_float(name: str, valid: str, value: object) -> float:
    try:
        out = float(value)  # type: ignore[arg-type]
    except (TypeError, ValueError):
        raise ParameterError(name, valid, value) from None
    if not math.isfinite(out):
        raise ParameterError(name, valid, value)
    return out


def _bounded_below(name: str, value: object, unit: str, strict: bool) -> float:
    """A finite float ``> 0`` (``strict``) or ``>= 0``; ``unit`` is named in the message."""
    valid = f"a finite number {'>' if strict else '>='} 0" + (f" [{unit}]" if unit else "")
    out = _as_float(name, valid, value)
    if not (out > 0.0 if strict else out >= 0.0):
        raise ParameterError(name, valid, out)
    return out


def check_mu(mu: float) -> float:
    """Mass ratio ``m1 / m2``: a finite number >= 0."""
    return _bounded_below("mu", mu, "", strict=False)


def check_restitution(name: str, value: float) -> float:
    """A restitution coefficient in [0, 1]; ``name`` is its flag (``--e2``, ``--e12``)."""
    valid = "in [0, 1]"
    value = _as_float(name, valid, value)
    if not 0.0 <= value <= 1.0:
        raise ParameterError(name, valid, value)
    return value


def check_dx(dx: float) -> float:
    """Initial gap between the balls [m]: a finite number >= 0."""
    return _bounded_below("dx", dx, "m", strict=False)


def check_drop_height(drop_height: float) -> float:
    """Fall height H [m]: a finite number > 0."""
    return _bounded_below("drop_height", drop_height, "m", strict=True)


def check_g(g: float) -> float:
    """Gravitational acceleration [m/s^2]: a finite number > 0."""
    return _bounded_below("g", g, "m/s^2", strict=True)
