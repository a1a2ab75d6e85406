"""The contact sequence of a finite-mass body: its path over the cap, events marked."""

from __future__ import annotations

from typing import Any


def contact_figure(report: Any, samples: int = 800) -> Any:
    """Body height and cap-averaged membrane (top), their velocities (bottom), in mm, m/s, ms.

    ``report`` is a :class:`~twoball.modal.contact.report.ContactReport` with a
    finite mass; impacts are marked with crosses, separations with circles.
    """
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    data = report.trajectory_si(samples)
    fig, (top, bottom) = plt.subplots(2, 1, sharex=True, figsize=(7.0, 5.6), layout="constrained")
    t = data["t_s"] * 1e3
    top.plot(t, data["cap_displacement_m"] * 1e3, color="C0", label="membrane, cap average")
    top.plot(t, data["body_height_m"] * 1e3, color="C1", ls="--", label="body")
    bottom.plot(t, data["cap_velocity_m_s"], color="C0", label="membrane, cap average")
    bottom.plot(t, data["body_velocity_m_s"], color="C1", ls="--", label="body")
    for event in report.events_si():
        style = ("x", "red") if event["kind"] == "impact" else ("o", "green")
        ms = event["t_s"] * 1e3
        top.plot([ms], [event["height_m"] * 1e3], style[0], color=style[1], ms=7)
        bottom.plot([ms], [event["velocity_m_s"]], style[0], color=style[1], ms=7)
    top.plot([], [], "x", color="red", label="impact")
    top.plot([], [], "o", color="green", label="separation")
    top.set_ylabel("height above the pole [mm]")
    bottom.set_ylabel("velocity [m/s]")
    bottom.set_xlabel("time after maximal compression [ms]")
    ratio = "-" if report.ratio is None else f"{report.ratio:.4f}"
    top.set_title(
        f"mu = {report.mass_ratio:g}, a = {report.contact_radius_m * 1e3:g} mm, "
        f"e = {report.restitution:g}: v1/|v0| = {ratio}"
    )
    for ax in (top, bottom):
        ax.grid(True, alpha=0.3)
    top.legend(fontsize=8)
    return fig
