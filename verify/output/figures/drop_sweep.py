"""A sweep of the drop of the ball alone against a parameter that is not its speed (damping).

``e2 = v2/|v0|``, the contact time and the largest contact angle of every drop
against the swept value; the sweeps against ``|v0|`` or the drop height have
:func:`~twoball.verify.output.figures.bounce.speeds_figure`, those of the
whole bounce :func:`~twoball.verify.output.figures.bounce.gap_figure`.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import TYPE_CHECKING, Any

import numpy as np

from twoball.verify.output.figures import new_figure
from twoball.verify.output.figures.style import label, styled

if TYPE_CHECKING:
    from matplotlib.figure import Figure

__all__ = ["AXIS_LABELS", "drop_sweep_figure", "sweep_axis_label"]

#: The x labels of the sweeps of the drop and the whole bounce (CLI names of the parameter).
AXIS_LABELS: dict[str, str] = {
    "damping": label("damping ratio $D$", None),
    "v0": label(r"impact speed $|v_0|$", "m/s"),
    "drop-height": label("drop height $H$", "m"),
    "gap": label(r"gap $\Delta x$", "mm"),
    "mass-ratio": label(r"mass ratio $\mu$", None),
}


def sweep_axis_label(parameter: str) -> str:
    """The x label of a sweep against ``parameter`` (the name itself if unknown)."""
    return AXIS_LABELS.get(parameter, parameter)


def _values(reports: Sequence[Any], name: str, scale: float = 1.0) -> np.ndarray:
    values = [getattr(r, name) for r in reports]
    return np.array([np.nan if v is None else v * scale for v in values], dtype=float)


@styled
def drop_sweep_figure(points: Sequence[tuple[float, Any]], parameter: str) -> Figure:
    """e2, the contact time [ms] and phi_a,max [rad] of the drops against ``parameter``.

    ``points`` are (value, report) of drops of the ball alone
    (:class:`twoball.BounceReport`, light or not).
    """
    if not points:
        raise ValueError("no drops to draw")
    x = np.array([v for v, _ in points], dtype=float)
    reports = [r for _, r in points]
    fig = new_figure(6.4, 7.2)
    axes = fig.subplots(3, 1, sharex=True)
    axes[0].plot(x, _values(reports, "e2"), "o-", label="the drop")
    axes[0].set_ylabel(label(r"$e_2 = v_2/|v_0|$", None))
    axes[1].plot(x, _values(reports, "contact_time_s", 1e3), "o-", label="the drop")
    axes[1].set_ylabel(label("contact time", "ms"))
    axes[2].plot(x, _values(reports, "phi_a_max_rad"), "o-", label="the drop")
    axes[2].set_ylabel(label(r"$\phi_{a,max}$", "rad"))
    axes[2].set_xlabel(sweep_axis_label(parameter))
    case = reports[0].case
    fig.suptitle(f"Drops of the {case.preset_name or 'ball'} at $|v_0|$ = {case.v0:g} m/s")
    return fig
