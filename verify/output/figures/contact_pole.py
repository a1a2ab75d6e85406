"""``twoball plot pole --mass-ratio MU``: the cap's motion with the body's path, events marked.

The pole panels of :func:`~twoball.verify.output.figures.pole.pole_figure`, for
the membrane coupled to an upper body of finite mass (docs/contact.rst): the
cap-averaged displacement, velocity and acceleration of each backend's contact
solution, with the body's height ``s(t)`` and velocity ``s'(t)`` drawn over
them, every impact and separation marked and the final lift-off ringed.  With
both backends a panel under each quantity shows finite elements minus closed
form, for the cap and for the body.  SI: mm, m/s, m/s^2 against ms.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

import numpy as np

from twoball.verify.output.fields import CoupledModel
from twoball.verify.output.figures import LABELS, new_figure
from twoball.verify.output.figures.pole import clip_acceleration, draw_differences
from twoball.verify.output.figures.style import (
    LIFTOFF_MARKER,
    REFERENCE_COLOUR,
    label,
    styled,
    subject,
    time_label,
)

if TYPE_CHECKING:
    from matplotlib.figure import Figure

#: Symbol, SI unit and factor from SI of the three panels (cap average and body).
QUANTITIES = (
    (r"$\bar u(t)$, $s(t)$", "mm", 1e3),
    (r"$\bar u_t(t)$, $s_t(t)$", "m/s", 1.0),
    (r"$\bar u_{tt}(t)$", "m/s$^2$", 1.0),
)
#: Marker of each event kind (the lift-off keeps :data:`LIFTOFF_MARKER`).
EVENT_MARKERS = {"impact": "v", "separation": "^"}
#: ``gid`` prefix of the marker series of the events (one point per event).
EVENT_GID = "contact-events"
#: ``gid`` prefix of the body's path.
BODY_GID = "body-path"
_CAP_STYLE = {"legendre": "-", "fem": "--"}
_BODY_STYLE = {"legendre": "-.", "fem": ":"}


@styled
def contact_pole_figure(model: CoupledModel, samples: int = 2500) -> Figure:
    """Cap motion of the coupled membrane and the body's path against time, in SI.

    Parameters
    ----------
    model : CoupledModel
        The contact solution of one or both backends
        (:func:`twoball.verify.output.fields.coupled_model`).
    samples : int
        Times over the window.

    Rows: the cap average ``b . q`` (eq. (C3)) and the body's height ``s`` [mm];
    their velocities [m/s]; the cap's acceleration [m/s^2] with ``-g``.  Every
    event of :meth:`~twoball.modal.contact.report.ContactReport.events_si` is one
    marker on the first two rows (impacts and separations apart, one series per
    backend with ``gid`` ``contact-events-<kind>-<backend>``); the final
    separation (the lift-off of the window) is ringed and a dashed line.
    """
    case = model.case
    times = np.linspace(0.0, model.t_end_s, samples)
    ms = times * 1e3
    compare = "fem" in model.backends and "legendre" in model.backends
    figure = new_figure(7.5, 10.0 if compare else 8.0)
    rows = 6 if compare else 3
    ratios = {"height_ratios": [3, 1.4] * 3} if compare else None
    grid = figure.subplots(rows, 1, sharex=True, squeeze=False, gridspec_kw=ratios)[:, 0]
    axes = grid[::2] if compare else grid
    motions = {name: model.motion(name, times) for name in model.backends}
    for k, (name, motion) in enumerate(motions.items()):
        _draw_backend(axes, ms, name, motion, model.contact(name), f"C{k}", k)
    axes[2].axhline(-case.g, color=REFERENCE_COLOUR, linewidth=0.8, linestyle=":", label="$-g$")
    clip_acceleration(axes[2], np.concatenate([m["cap_tt_m_s2"] for m in motions.values()]), case.g)
    for axis, (symbol, unit, _) in zip(axes, QUANTITIES, strict=True):
        axis.set_ylabel(label(symbol, unit))
    _event_legend(axes[1])
    if compare:
        fem, ref = motions["fem"], motions["legendre"]
        cap = [fem[k] - ref[k] for k in ("cap_m", "cap_t_m_s", "cap_tt_m_s2")]
        body = [fem[k] - ref[k] for k in ("s_m", "s_t_m_s", "s_tt_m_s2")]
        draw_differences(
            grid[1::2],
            ms,
            [
                ("cap: finite elements − closed form", {"color": "0.15", "linewidth": 0.9}, cap),
                ("body: finite elements − closed form", {"color": "C3", "linewidth": 0.9}, body),
            ],
        )
    grid[-1].set_xlabel(time_label("after maximal compression"))
    _figure_legend(figure, grid)
    report = next(iter(model.backends.values())).report
    figure.suptitle(
        f"{subject(model.case)}: "
        rf"cap ($a$ = {report.contact_radius_m * 1e3:.3g} mm) and body of mass ratio "
        rf"$\mu$ = {report.mass_ratio:g}, $e$ = {report.restitution:g}"
        + ("\nfinite elements − closed form below each" if compare else "")
    )
    return figure


def _draw_backend(
    axes: Any, ms: np.ndarray, name: str, motion: dict, report: Any, colour: str, k: int
) -> None:
    """One backend: cap and body curves, its events, its lift-off."""
    short = LABELS.get(name, name)
    keys = (("cap_m", "s_m"), ("cap_t_m_s", "s_t_m_s"), ("cap_tt_m_s2", None))
    for axis, (cap, body), (_, _, factor) in zip(axes, keys, QUANTITIES, strict=True):
        axis.plot(
            ms,
            motion[cap] * factor,
            _CAP_STYLE.get(name, "-"),
            color=colour,
            label=f"cap average, {short}",
        )
        if body is not None:
            axis.plot(
                ms,
                motion[body] * factor,
                _BODY_STYLE.get(name, ":"),
                color=colour,
                linewidth=1.5,
                label=f"body, {short}",
                gid=f"{BODY_GID}-{name}",
            )
    events = report.events_si()
    for kind, marker in EVENT_MARKERS.items():
        chosen = [e for e in events if e["kind"] == kind]
        t = np.array([e["t_s"] * 1e3 for e in chosen])
        for axis, key, factor in ((axes[0], "height_m", 1e3), (axes[1], "velocity_m_s", 1.0)):
            values = np.array([e[key] * factor for e in chosen])
            axis.plot(
                t,
                values,
                marker,
                linestyle="none",
                color=colour,
                markersize=6,
                markeredgecolor="black",
                markeredgewidth=0.5,
                gid=f"{EVENT_GID}-{kind}-{name}",
            )
    if report.lifted:
        t_l = report.t_liftoff_s * 1e3
        final = report.history.displacement * report.case.scalings.length
        for axis, value in ((axes[0], final * 1e3), (axes[1], report.v_liftoff_m_s)):
            axis.plot(
                t_l,
                value,
                LIFTOFF_MARKER,
                markersize=10,
                markerfacecolor="none",
                markeredgecolor=colour,
                markeredgewidth=1.2,
            )
        for axis in axes:
            axis.axvline(t_l, color=colour, linewidth=0.7, linestyle="--")
        axes[0].annotate(
            f"lift-off {t_l:.2f} ms, {report.v_liftoff_m_s:.3f} m/s",
            xy=(t_l, final * 1e3),
            xytext=(8, 8 if k == 0 else -14),
            textcoords="offset points",
            fontsize=8,
            color=colour,
        )


def _figure_legend(figure: Any, axes: Any) -> None:
    """One legend for every panel, below them: no legend box covers a curve or a peak."""
    entries: dict[str, Any] = {}
    for axis in axes:
        handles, names = axis.get_legend_handles_labels()
        for handle, name in zip(handles, names, strict=True):
            entries.setdefault(name, handle)
        if axis.get_legend() is not None:
            axis.get_legend().remove()
    figure.legend(
        list(entries.values()),
        list(entries),
        loc="outside lower center",
        ncol=3,
        fontsize=8,
        frameon=False,
    )


def _event_legend(axis: Any) -> None:
    """Proxy entries explaining the event markers and the lift-off ring."""
    for kind, marker in EVENT_MARKERS.items():
        axis.plot([], [], marker, ls="none", color="0.5", markeredgecolor="black", label=kind)
    axis.plot(
        [],
        [],
        LIFTOFF_MARKER,
        markerfacecolor="none",
        markeredgecolor="0.3",
        markersize=8,
        linestyle="--",
        color="0.4",
        linewidth=0.7,
        label="lift-off (final separation)",
    )
