"""Sweeps of the drop on the floor and of the whole bounce: one run per value (SI).

:func:`bounce_points` turns a base case, drop and body and one swept parameter
into the (case, drop, body) triples the face runs one by one (``twoball.sweep(...,
drop=Drop())``) on the process pool or Dask
(:class:`~twoball.verify.sweeps.parallel.Runner`): the impact speed ``v0``
[m/s], the drop height ``drop-height`` [m], the gap ``gap`` [m] (Fig. 3, Fig. 8)
and the mass ratio ``mass-ratio`` of the upper body.  The figures are
:func:`twoball.verify.output.figures.bounce.speeds_figure` and
:func:`~twoball.verify.output.figures.bounce.gap_figure`.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import replace
from typing import Any

import numpy as np
from twoball.modal.floor.options import Drop
from twoball.modal.parameters import Case
from twoball.verify.sweeps.sweeps import parse_range

from twoball._common.errors import ParameterError

__all__ = ["BOUNCE_PARAMETERS", "bounce_points", "bounce_values"]

#: Parameters of a drop sweep (CLI names) and the field each sets.
BOUNCE_PARAMETERS: dict[str, str] = {
    "v0": "v0",
    "drop-height": "drop_height",
    "gap": "gap",
    "mass-ratio": "mass_ratio",
}


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
    case: Case, drop: Drop, parameter: str, values: np.ndarray, body: Any = None
) -> list[tuple[Case, Drop, Any]]:
    """One (case, drop, body) per value of ``parameter`` (validated by the options' classes).

    ``gap`` needs a body (or a pair, which the face resolves: ``body`` is then
    None and the gap is the drop's); ``mass-ratio`` replaces the body's mu (a
    body of that mu with the default contact radius and no restitution when
    none is given).
    """
    if parameter == "v0":
        if drop.drop_height is not None:
            raise ParameterError("drop_height", "left out when v0 is swept", drop.drop_height)
        return [(case.derive(v0=float(v)), drop, body) for v in values]
    if parameter == "drop-height":
        from twoball.modal.floor.model import check_drop_height

        points = [(case, replace(drop, drop_height=float(v)), body) for v in values]
        for _, point, _ in points:  # a height below the case's radius: before the first run
            check_drop_height(case, point.drop_height)
        return points
    if parameter == "gap":
        if drop.gap != 0.0:
            raise ParameterError("gap", "left out when the gap is swept", drop.gap)
        return [(case, replace(drop, gap=float(v)), body) for v in values]
    from twoball.modal.contact.body import Body

    if body is not None and body.mass_ratio != 0.0:
        raise ParameterError("mass_ratio", "left out when the mass ratio is swept", body.mass_ratio)
    base = Body(0.0) if body is None else body
    return [(case, drop, replace(base, mass_ratio=float(v))) for v in values]
