"""Input validation shared by the finite-element entry points.

Every check raises :class:`twoball.modal.errors.ParameterError` naming the command-line
flag the value comes from, so the CLI can print the message unchanged.
"""

from __future__ import annotations

import math
from numbers import Integral, Real

from twoball.modal.errors import ParameterError

ORDERS: tuple[int, ...] = (1, 2, 3, 4)
ORDER_RANGE = "1, 2, 3 or 4"
MESH_KINDS: tuple[str, ...] = ("sphere", "ring", "axisym")
GEOMETRIES: tuple[str, ...] = ("isoparametric", "exact")
TIME_SCHEMES: tuple[str, ...] = ("modal", "alpha")
DAMPING_MODELS: tuple[str, ...] = ("modal", "rayleigh")
INITIAL_METHODS: tuple[str, ...] = ("projection", "interpolation")


def _is_int(value: object) -> bool:
    return isinstance(value, Integral) and not isinstance(value, bool)


def check_level(level: object) -> int:
    """Refinement level of a sphere mesh: an integer >= 0 (``--level``)."""
    if not _is_int(level) or int(level) < 0:
        raise ParameterError("level", "an integer >= 0", level)
    return int(level)


def check_order(order: object) -> int:
    """Polynomial order of elements and geometry: 1, 2, 3 or 4 (``--order``)."""
    if not _is_int(order) or int(order) not in ORDERS:
        raise ParameterError("order", ORDER_RANGE, order)
    return int(order)


def check_elements(elements: object) -> int:
    """Number of elements of the axisymmetric mesh: an integer >= 2 (``--elements``)."""
    if not _is_int(elements) or int(elements) < 2:
        raise ParameterError("elements", "an integer >= 2", elements)
    return int(elements)


def check_dt(dt: object) -> float | None:
    """Time step of the direct integrator: None (automatic) or a finite number > 0 (``--dt``)."""
    if dt is None:
        return None
    if not isinstance(dt, Real) or not math.isfinite(float(dt)) or float(dt) <= 0.0:
        raise ParameterError("dt", "a finite number > 0", dt)
    return float(dt)


def check_rho_inf(rho_inf: object) -> float:
    """Spectral radius at infinite frequency of generalized-alpha: in [0, 1] (``--rho-inf``)."""
    if not isinstance(rho_inf, Real) or not (0.0 <= float(rho_inf) <= 1.0):
        raise ParameterError("rho_inf", "in [0, 1]", rho_inf)
    return float(rho_inf)


def check_t_end(t_end: object) -> float:
    """End of the integration window (dimensionless): a finite number > 0 (``--t-end``)."""
    if not isinstance(t_end, Real) or not math.isfinite(float(t_end)) or float(t_end) <= 0.0:
        raise ParameterError("t_end", "a finite time > 0", t_end)
    return float(t_end)


def check_choice(flag: str, value: object, choices: tuple[str, ...]) -> str:
    """``value`` must be one of ``choices`` (named by ``flag``)."""
    if value not in choices:
        raise ParameterError(flag, "one of " + ", ".join(choices), value)
    return str(value)
