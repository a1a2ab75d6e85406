"""A sweep's table as CSV: one row per point, SI columns with the unit in the name.

:func:`liftoff_table` is the table of a lift-off sweep (the swept parameters
first, then the case of the point and its lift-off), :func:`bounce_table` that
of a sweep of the drop or the whole bounce (the swept value first, then the
drop's and the body's numbers); :func:`write_table` writes either atomically
(:func:`twoball._common.staging.staged_file`).  Blank cells are values the
point does not have (no lift-off, a failed point); ``error`` says why a point
failed, ``warnings`` joins a point's warnings with `` | ``.

Examples
--------
>>> header, rows = liftoff_table([], ("damping",))
>>> header[:4]
['damping', 'v0_m_s', 'radius_m', 'wave_speed_1_s']
"""

from __future__ import annotations

import csv
import io
import math
import os
from collections.abc import Sequence
from pathlib import Path
from typing import Any

__all__ = ["BOUNCE_COLUMNS", "LIFTOFF_COLUMNS", "bounce_table", "liftoff_table", "write_table"]

#: The column of each swept parameter (CLI name) in the table.
SWEPT_COLUMNS: dict[str, str] = {
    "damping": "damping",
    "v0": "v0_m_s",
    "wave-speed": "wave_speed_1_s",
    "radius": "radius_m",
    "modes": "modes",
    "mass-ratio": "mass_ratio",
    "bending": "bending_N_m",
    "drop-height": "drop_height_m",
    "gap": "gap_m",
}
#: The columns of a lift-off sweep after the swept ones (keys of the point's JSON).
LIFTOFF_COLUMNS: tuple[str, ...] = (
    "v0_m_s",
    "radius_m",
    "wave_speed_1_s",
    "damping",
    "modes",
    "phi_a_rad",
    "phi_a_source",
    "lifted",
    "t_liftoff_s",
    "v_liftoff_m_s",
    "ratio",
    "warnings",
    "error",
)
#: The columns of a sweep of the drop (and, with a body, of the whole bounce).
BOUNCE_COLUMNS: tuple[str, ...] = (
    "v0_m_s",
    "drop_height_m",
    "left_floor",
    "contact_time_s",
    "v2_m_s",
    "e2",
    "phi_a_max_rad",
    "flattening_max_m",
    "t_max_compression_s",
)
BODY_COLUMNS: tuple[str, ...] = (
    "gap_m",
    "mass_ratio",
    "v1_m_s",
    "v1_ratio",
    "v2_ratio",
    "t_liftoff_s",
    "t_liftoff_from_max_compression_s",
    "body_left_first",
    "sequence",
    "e12_effective",
    "caveats",
)


def _cell(value: Any) -> str:
    """A cell: repr of a float (round-trips), blank for None/NaN, true/false for a bool."""
    if value is None:
        return ""
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, float):
        return "" if not math.isfinite(value) else repr(value)
    if isinstance(value, (list, tuple)):
        return " | ".join(str(v) for v in value)
    return str(value)


def liftoff_table(points: Sequence[Any], parameters: Sequence[str]) -> tuple[list[str], list]:
    """Header and rows of a lift-off sweep (``points``: its :class:`SweepPoint` list).

    The swept parameters' columns come first (``mass_ratio`` from the point's body).
    """
    swept = [SWEPT_COLUMNS[p] for p in parameters]
    header = swept + [c for c in LIFTOFF_COLUMNS if c not in swept]
    rows = []
    for point in points:
        data = point.as_dict()
        case = point.case
        values = {
            "mass_ratio": getattr(case, "mass_ratio", None),
            "bending_N_m": getattr(case, "bending", None),
            **data,
        }
        if "mass_ratio" not in data and getattr(point, "report", None) is not None:
            body = getattr(point.report, "body", None)
            if body is not None:
                values["mass_ratio"] = body.mass_ratio
        rows.append([_cell(values.get(c)) for c in header])
    return header, rows


def bounce_table(
    parameter: str, values: Sequence[float], reports: Sequence[Any], errors: Sequence[str | None]
) -> tuple[list[str], list]:
    """Header and rows of a sweep of the drop or the whole bounce (one row per value)."""
    swept = SWEPT_COLUMNS[parameter]
    body = any(r is not None and r.has_body for r in reports)
    columns = [*BOUNCE_COLUMNS, *(BODY_COLUMNS if body else ()), "warnings", "error"]
    header = [swept, *(c for c in columns if c != swept)]
    rows = []
    for value, report, error in zip(values, reports, errors, strict=True):
        data: dict[str, Any] = {swept: value, "error": error}
        if report is not None:
            data |= {k: v for k, v in report.as_dict().items() if k in header and k != swept}
            if report.has_body:
                data["gap_m"] = report.drop.gap
                data["mass_ratio"] = report.whole.body.mass_ratio
            if parameter == "damping":
                data["damping"] = report.case.damping
        rows.append([_cell(data.get(c)) for c in header])
    return header, rows


def write_table(
    header: Sequence[str],
    rows: Sequence[Sequence[str]],
    path: str | os.PathLike[str],
    name: str = "csv",
) -> Path:
    """Write the table as CSV to ``path`` (replaced whole or not at all); ``name`` names it
    in refusals (``csv``)."""
    from twoball._common.staging import check_path_type, staged_file

    check_path_type(path, name)
    buffer = io.StringIO()
    writer = csv.writer(buffer, lineterminator="\n")
    writer.writerow(header)
    writer.writerows(rows)
    out = Path(path).expanduser()
    with staged_file(out, name) as scratch:
        scratch.write_text(buffer.getvalue(), encoding="utf-8")
    return out
