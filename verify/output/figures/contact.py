"""The contact sequence of a finite-mass body: its path over the cap, events marked."""

from __future__ import annotations

from typing import Any

from twoball.verify.output.figures import new_figure
from twoball.verify.output.figures.style import COLOURS, label, styled, time_label

#: Markers and colours of the events: impacts (crosses) and separations (circles).
EVENT_MARKS = {"impact": ("x", COLOURS[1]), "separation": ("o", COLOURS[2])}


@styled
def contact_figure(report: Any, samples: int = 800) -> Any:
    """Body height and cap-averaged membrane (top), their velocities (bottom), in mm, m/s, ms.

    ``report`` is a :class:`~twoball.modal.contact.report.ContactReport` with a
    finite mass; impacts are marked with crosses, separations with circles.
    """
    data = report.trajectory_si(samples)
    fig = new_figure(7.0, 5.6)
    top, bottom = fig.subplots(2, 1, sharex=True)
    t = data["t_s"] * 1e3
    top.plot(t, data["cap_displacement_m"] * 1e3, color="C0", label="membrane, cap average")
    top.plot(t, data["body_height_m"] * 1e3, color="C1", ls="--", label="body")
    bottom.plot(t, data["cap_velocity_m_s"], color="C0", label="membrane, cap average")
    bottom.plot(t, data["body_velocity_m_s"], color="C1", ls="--", label="body")
    for event in report.events_si():
        marker, colour = EVENT_MARKS["impact" if event["kind"] == "impact" else "separation"]
        ms = event["t_s"] * 1e3
        top.plot([ms], [event["height_m"] * 1e3], marker, color=colour, ms=7, ls="none")
        bottom.plot([ms], [event["velocity_m_s"]], marker, color=colour, ms=7, ls="none")
    for kind, (marker, colour) in EVENT_MARKS.items():
        top.plot([], [], marker, color=colour, ls="none", label=kind)
    top.set_ylabel(label("height above the pole", "mm"))
    bottom.set_ylabel(label("velocity", "m/s"))
    bottom.set_xlabel(time_label("after maximal compression"))
    ratio = "–" if report.ratio is None else f"{report.ratio:.4f}"
    top.set_title(
        f"μ = {report.mass_ratio:g}, a = {report.contact_radius_m * 1e3:g} mm, "
        f"e = {report.restitution:g}: v₁/|v₀| = {ratio}"
    )
    top.legend(loc="best")
    bottom.legend(loc="best")
    return fig
