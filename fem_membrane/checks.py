"""Input validation shared by the finite-element entry points.

Every check raises :class:`twoball._common.errors.ParameterError` naming the command-line
flag the value comes from, so the CLI can print the message unchanged.
"""

from __future__ import annotations

import math
from numbers import Integral, Real

from twoball._common.errors import ParameterError

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
    if not _is_real(dt) or not math.isfinite(float(dt)) or float(dt) <= 0.0:
        raise ParameterError("dt", "a finite number > 0", dt)
    return float(dt)


DT_MIN = 1e-9  # dimensionless (time unit 1/c): below it the step count overflows any budget


def check_dt_in_window(dt: object, time_unit_s: float, t_end: float) -> float:
    """A time step ``dt`` [s] as a dimensionless step in [1e-9, ``t_end``] (``--dt``).

    ``time_unit_s`` is 1/c [s]; ``t_end`` the dimensionless window.  A step
    longer than the window takes no step at all.
    """
    low, high = DT_MIN * time_unit_s, t_end * time_unit_s
    valid = f"a time step in [{low:.3g}, {high:.3g}] s (at most the modelled window)"
    if not _is_real(dt) or not (low <= float(dt) <= high):
        raise ParameterError("dt", valid, dt)
    return float(dt) / time_unit_s


def _is_real(value: object) -> bool:
    return isinstance(value, Real) and not isinstance(value, bool)


def check_rho_inf(rho_inf: object) -> float:
    """Spectral radius at infinite frequency of generalized-alpha: in [0, 1] (``--rho-inf``)."""
    if not _is_real(rho_inf) or not (0.0 <= float(rho_inf) <= 1.0):
        raise ParameterError("rho_inf", "in [0, 1]", rho_inf)
    return float(rho_inf)


def check_t_end(t_end: object) -> float:
    """End of the integration window (dimensionless): a finite number > 0 (``--t-end``)."""
    if not _is_real(t_end) or not math.isfinite(float(t_end)) or float(t_end) <= 0.0:
        raise ParameterError("t_end", "a finite time > 0", t_end)
    return float(t_end)


def check_choice(flag: str, value: object, choices: tuple[str, ...]) -> str:
    """``value`` must be one of ``choices`` (named by ``flag``)."""
    if value not in choices:
        raise ParameterError(flag, "one of " + ", ".join(choices), value)
    return str(value)
