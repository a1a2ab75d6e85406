"""Input checks of the independent collision model: one line naming the parameter and its range.

Every check returns the value as a float or raises
:class:`~twoball._common.errors.ParameterError` naming the parameter (``mu``,
``e2``, ``e12``, ``dx``, ``drop_height``, ``g``).
"""

from __future__ import annotations

from twoball._common.errors import ParameterError, real_number


def _as_float(name: str, valid: str, value: object) -> float:
    """A finite real number (not a string, not a boolean), as a float."""
    return real_number(name, valid=valid, value=value)


#: Largest mass ratio, gap and drop height: physically meaningful and far from the
#: overflow of eqs. (2.1)-(2.6) (a velocity sqrt(2 g H) or a ratio mu u / (mu + 1)).
UPPER: dict[str, float] = {"mu": 1e6, "dx": 1e6, "drop_height": 1e6, "g": 1e6}


def _bounded_below(name: str, value: object, unit: str, strict: bool) -> float:
    """A finite float in ``(0, UPPER]`` (``strict``) or ``[0, UPPER]``; ``unit`` in the message."""
    high = UPPER[name]
    valid = f"a number in {'(' if strict else '['}0, {high:g}]" + (f" [{unit}]" if unit else "")
    out = _as_float(name, valid, value)
    if not ((out > 0.0 if strict else out >= 0.0) and out <= high):
        raise ParameterError(name, valid, out)
    return out


def check_mu(mu: float) -> float:
    """Mass ratio ``m1 / m2``: a finite number >= 0."""
    return _bounded_below("mu", mu, "", strict=False)


def check_restitution(name: str, value: float) -> float:
    """A restitution coefficient in [0, 1]; ``name`` is its parameter (``e2``, ``e12``)."""
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
