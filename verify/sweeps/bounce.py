"""Sweeps of the drop on the floor: one drop per impact speed or drop height (SI).

:func:`bounce_points` turns a base case and drop and one swept parameter into
the (case, drop) pairs the face drops one by one (``twoball.sweep(...,
drop=Drop())``); the figure is :func:`twoball.verify.output.figures.bounce.speeds_figure`.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import replace

import numpy as np
from twoball.modal.floor.options import Drop
from twoball.modal.parameters import Case
from twoball.verify.sweeps.sweeps import parse_range

from twoball._common.errors import ParameterError

__all__ = ["BOUNCE_PARAMETERS", "bounce_points", "bounce_values"]

#: Parameters of a drop sweep (CLI names) and the field each sets.
BOUNCE_PARAMETERS: dict[str, str] = {"v0": "v0", "drop-height": "drop_height"}


def bounce_values(parameters: Sequence[str], values: Sequence[object]) -> tuple[str, np.ndarray]:
    """The one swept parameter of a drop sweep and its values (``START:STOP:COUNT`` or a list)."""
    parameters = [p.replace("_", "-") for p in parameters]
    if len(parameters) != 1 or parameters[0] not in BOUNCE_PARAMETERS:
        valid = "one of " + ", ".join(BOUNCE_PARAMETERS) + " (a drop sweep has one axis)"
        raise ParameterError("param", valid, ",".join(parameters))
    if len(values) != 1:
        raise ParameterError("values", "given once, for the one parameter", list(values))
    items = values[0]
    array = parse_range(items) if isinstance(items, str) else np.asarray(items, dtype=float)
    array = np.atleast_1d(array).astype(float)
    if array.ndim != 1 or array.size < 1 or not np.all(np.isfinite(array)):
        raise ParameterError("values", "a non-empty list of finite numbers", items)
    return parameters[0], array


def bounce_points(
    case: Case, drop: Drop, parameter: str, values: np.ndarray
) -> list[tuple[Case, Drop]]:
    """One (case, drop) per value: the impact speed (|v0| [m/s]) or the drop height H [m]."""
    if parameter == "v0":
        if drop.drop_height is not None:
            raise ParameterError("drop_height", "left out when v0 is swept", drop.drop_height)
        return [(case.derive(v0=float(v)), drop) for v in values]
    return [(case, replace(drop, drop_height=float(v))) for v in values]
