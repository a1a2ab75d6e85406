"""The drop on the floor: its history, and the contact against the impact speed (SI).

``drop_figure``: floor force, contact angle, the centre's height and the energy
books against time.  ``whole_figure``: the whole two-ball bounce (a body on the
ball): heights of the floor contact, the ball's top and the body, both contact
forces, both velocities with the ICM's, and the energy books with the body's
share, every event marked.  ``speeds_figure``: the largest contact angle and the
flattening against ``|v0|`` beside eq. (3.7), pressure x area (Cross 1999) and
the measurements (Table 2's phi_a = 2.6 at 4.1 m/s; 3.07 mm of compression per
m/s, Dowell & Krebs 1991).
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from typing import TYPE_CHECKING, Any

import numpy as np

from twoball._common.errors import ParameterError
from twoball.modal.floor.drop import DropResult
from twoball.modal.floor.references import MEASURED_COMPRESSION, pressure_area
from twoball.modal.parameters import Case
from twoball.verify.output.figures import new_figure
from twoball.verify.output.figures.style import (
    COLOURS,
    DIMENSIONLESS,
    REFERENCE_COLOUR,
    label,
    styled,
    time_label,
)
from twoball.verify.output.forces import contact_forces

if TYPE_CHECKING:
    from matplotlib.figure import Figure

__all__ = ["TABLE2", "drop_figure", "speeds_figure", "whole_figure"]

#: Table 2 of the paper: the basketball's measured contact angle at 4.1 m/s.
TABLE2 = (4.1, 2.6)
#: Lines marking events (touches, separations, the contact's end): thin, light and
#: behind the data (zorder below the curves' 2 and the stacks' 1), so they cover none.
EVENT_LINE = {"lw": 0.4, "alpha": 0.35, "zorder": 0.5}
#: A run of events closer together than this share of the time axis (a chatter) is
#: drawn as one band from its first to its last event instead of a line each.
EVENT_CLUSTER = 0.01
EVENT_BAND = {"lw": 0.0, "alpha": 0.12, "zorder": 0.5}


def event_clusters(times: Sequence[float], gap: float) -> list[tuple[float, float]]:
    """``times`` grouped into runs whose neighbours lie closer than ``gap``: (first, last).

    >>> event_clusters([0.0, 5.0, 5.1, 5.15, 9.0], 0.2)
    [(0.0, 0.0), (5.0, 5.15), (9.0, 9.0)]
    """
    runs: list[tuple[float, float]] = []
    for t in sorted(times):
        if runs and t - runs[-1][1] < gap:
            runs[-1] = (runs[-1][0], t)
        else:
            runs.append((t, t))
    return runs


def force_label(window_s: float) -> str:
    """The force axis label: the mean over windows of ``window_s`` seconds, in N."""
    return label(rf"$\bar F$, impulse per {window_s * 1e3:.2g} ms window", "N")


@styled
def drop_figure(r: DropResult, case: Case, mass: float, title: str = "") -> Figure:
    """Four panels against time [ms]: floor force, contact angle, centre height, energy.

    ``r`` is the dimensionless drop of ``case``, ``mass`` the ball's mass m2 [kg].
    """
    to_ms = 1e3 / case.wave_speed
    force_unit = mass * case.radius * case.wave_speed**2  # m2 R c^2 [N]
    energy_unit = mass * case.scalings.velocity**2
    tr, system = r.trajectory, r.system
    fig = new_figure(8.0, 8.0)
    axes = fig.subplots(4, 1, sharex=True)
    window, forces = contact_forces(r, case)
    mid, force = forces["floor"]
    axes[0].plot(mid * to_ms, force * force_unit, label="floor force")
    weight = mass * case.g
    axes[0].axhline(weight, color=REFERENCE_COLOUR, lw=0.8, ls=":", label="weight $m_2 g$")
    axes[0].set_ylabel(force_label(window))
    axes[0].legend(loc="upper right")
    _contact_angle_panel(axes[1], r, case, to_ms)
    height = (tr.q[:, r.system.centre] - 1.0) * case.radius * 1e3
    axes[2].plot(tr.t * to_ms, height, label="centre $Z - R$")
    axes[2].axhline(0.0, color=REFERENCE_COLOUR, lw=0.6)
    if r.contact_time is not None:
        for ax in axes:
            ax.axvline(r.contact_time * to_ms, **EVENT_LINE, color=REFERENCE_COLOUR, ls="-.")
    axes[2].set_ylabel(label("$Z - R$", "mm"))
    axes[2].legend(loc="lower right")
    parts = system.energies(tr.q, tr.v)
    membrane = parts["membrane_kinetic"] + parts["membrane_elastic"] + parts["gas"]
    gravity = parts["gravity"] - parts["gravity"][0]
    stacks = [
        (parts["rigid_kinetic"], "rigid kinetic"),
        (membrane, "membrane and gas"),
        (-tr.damping_work, "damped"),
        (-tr.impact_work - tr.contact_work, "lost at impacts"),
    ]
    t_ms = tr.t * to_ms
    axes[3].stackplot(
        t_ms,
        *[s * energy_unit for s, _ in stacks],
        labels=[name for _, name in stacks],
        alpha=0.8,
    )
    axes[3].plot(t_ms, gravity * energy_unit, color="k", lw=0.8, label="gravity $m_2 g (Z - R)$")
    axes[3].set_ylabel(label("$E$", "J"))
    axes[3].set_xlabel(time_label("after the first touch"))
    axes[3].legend(loc="upper left", bbox_to_anchor=(1.01, 1.0))  # beside the stack
    e2 = "–" if r.e2 is None else f"{r.e2:.4f}"
    fig.suptitle(
        f"Drop on the floor{': ' + title if title else ''}\n$|v_0|$ = {case.v0:g} m/s, $e_2$ = {e2}"
    )
    return fig


def _contact_angle_panel(ax: Any, r: DropResult, case: Case, to_ms: float) -> None:
    """The contact edge phi_a(t) [rad], its largest contact phi_a,max and, for the drop's
    |v0|, the contact angles of eq. (3.7) and of pressure x area as reference levels."""
    from twoball.modal.initial import phi_a_from_v0

    ax.plot(r.edge_t * to_ms, r.edge, ".", ms=2, label=r"contact edge $\phi_a(t)$")
    ax.axhline(r.phi_a_max, color="C1", lw=0.9, label=rf"$\phi_{{a,max}}$ = {r.phi_a_max:.4f} rad")
    levels = [r.phi_a_max]
    try:
        eq37 = phi_a_from_v0(case.v0, case.radius, case.wave_speed)
    except ParameterError:  # beyond the largest speed eq. (3.7) can store
        eq37 = None
    if eq37 is not None:
        ax.axhline(
            eq37, color=REFERENCE_COLOUR, lw=0.9, ls="--", label=f"eq. (3.7): {eq37:.4f} rad"
        )
        levels.append(eq37)
    pa = pressure_area(case.v0, case.radius, case.wave_speed)["phi_a_max_rad"]
    ax.axhline(pa, color=REFERENCE_COLOUR, lw=0.9, ls=":", label=f"pressure x area: {pa:.4f} rad")
    levels.append(pa)
    low = min(levels)
    # the edge starts and ends at the pole (pi) and stays above phi_a,max, the reference
    # levels lie below it: the legend takes the free band under the lowest level
    span = math.pi - low
    ax.set_ylim(low - 0.9 * span, math.pi + 0.05 * span)
    ax.set_ylabel(label(r"$\phi_a$", "rad"))
    ax.legend(loc="lower center", ncols=2)


@styled
def speeds_figure(rows: Sequence[tuple[float, float, float]], case: Case) -> Figure:
    """phi_a,max [rad] and the largest flattening [m] against ``|v0|`` [m/s] (rows), with
    eq. (3.7), pressure x area and the measurements for the ball of ``case``."""
    from twoball.modal.initial import phi_a_from_v0

    if not rows:
        raise ValueError("no drops to draw")
    v0 = np.array([row[0] for row in rows])
    phi = np.array([row[1] for row in rows])
    flat = np.array([row[2] for row in rows]) * 1e3
    grid = np.linspace(max(0.2, 0.5 * v0.min()), 1.1 * v0.max(), 200)
    fig = new_figure(6.4, 6.4)
    axes = fig.subplots(2, 1, sharex=True)
    axes[0].plot(v0, phi, "o-", label=r"the drop: $\phi_{a,max}$")
    eq37 = [phi_a_from_v0(v, case.radius, case.wave_speed) for v in grid]
    axes[0].plot(grid, eq37, color=REFERENCE_COLOUR, ls="--", label="eq. (3.7)")
    area = [pressure_area(v, case.radius, case.wave_speed)["phi_a_max_rad"] for v in grid]
    axes[0].plot(grid, area, color=REFERENCE_COLOUR, ls=":", label="pressure x area")
    if case.preset_name == "basketball":
        axes[0].plot(*TABLE2, "s", color="C3", label="Table 2 (measured)")
    axes[0].set_ylabel(label(r"$\phi_{a,max}$", "rad"))
    axes[0].legend()
    axes[1].plot(v0, flat, "o-", label="the drop: largest flattening")
    axes[1].plot(
        grid, grid / case.wave_speed * 1e3, color=REFERENCE_COLOUR, ls=":", label="$|v_0|/c$"
    )
    axes[1].plot(
        grid,
        MEASURED_COMPRESSION * grid * 1e3,
        color="C3",
        ls="-.",
        label="3.07 mm per m/s (measured)",
    )
    axes[1].set_ylabel(label("flattening", "mm"))
    axes[1].set_xlabel(label(r"impact speed $|v_0|$", "m/s"))
    axes[1].legend()
    axes[1].set_xlim(0.0, 1.1 * v0.max())
    if math.isfinite(phi.min()):
        axes[0].set_ylim(min(phi.min(), min(eq37)) - 0.02, math.pi)
    return fig


@styled
def whole_figure(
    r: DropResult,
    case: Case,
    mass: float,
    title: str = "",
    icm: tuple[float, float] | None = None,
) -> Figure:
    """Five panels against time [ms] for the whole bounce (``r.body`` set).

    Heights above the floor of the ball's lowest point, centre and top (the
    cap's mean) and of the body's lowest point; the gap between the body and
    the top (eq. (B2): the degree-1 precursor opens it at once when they start
    touching); the floor's and the body's contact forces, each the impulse per
    window of :data:`FORCE_WINDOW_S` (:func:`mean_force`, impacts included);
    the centre's and the body's velocities (with ``icm`` = (v1, v2) [m/s] of
    eq. (2.5) as dashed lines); the energy books, the body's kinetic energy
    among them.  Touches and separations of both contacts are marked behind
    the data: floor (grey) and body (orange), thin lines, a chatter of them as
    one light band (:func:`event_clusters`).  Legends stand beside the panels.
    """
    system = r.system
    if system.body is None or r.body is None:
        raise ValueError("whole_figure needs a run with a body on the ball")
    to_ms = 1e3 / case.wave_speed
    R = case.radius
    speed = case.scalings.velocity
    force_unit = mass * R * case.wave_speed**2
    energy_unit = mass * speed**2
    tr = r.trajectory
    t_ms = tr.t * to_ms
    fig = new_figure(8.2, 10.4)
    axes = fig.subplots(5, 1, sharex=True, height_ratios=(1.2, 0.8, 1.0, 1.0, 1.2))
    beside = {"loc": "upper left", "bbox_to_anchor": (1.01, 1.0)}
    cap = system.body.cap  # one average per coordinate of the ball, the translation's too
    z = tr.q[:, system.centre]
    top = 1.0 + tr.q[:, : system.ball.modes] @ cap  # the cap's vertical rows include Z
    lowest = np.min(system.floor_gaps(tr.q), axis=1)  # the ball's lowest floor point
    s = tr.q[:, system.body_coordinate]
    axes[0].plot(t_ms, s * R * 1e3, color="C1", label="body, lowest point")
    axes[0].plot(t_ms, top * R * 1e3, color="C0", label="ball's top (cap mean)")
    axes[0].plot(t_ms, z * R * 1e3, color="C0", ls="--", lw=0.8, label="ball's centre")
    axes[0].plot(t_ms, lowest * R * 1e3, color="C2", lw=0.8, label="ball's lowest point")
    axes[0].axhline(0.0, color=REFERENCE_COLOUR, lw=0.8)
    axes[0].set_ylabel(label("height", "mm"))
    axes[0].legend(**beside)
    axes[1].plot(t_ms, system.body_gap(tr.q) * R * 1e3, color="C1", label="body above the top")
    axes[1].axhline(0.0, color=REFERENCE_COLOUR, lw=0.8)
    axes[1].set_ylabel(label("gap", "mm"))
    axes[1].legend(**beside)
    window, forces = contact_forces(r, case)
    for name, colour, text in (
        ("floor", "C2", "floor on the ball"),
        ("body", "C1", "ball on the body"),
    ):
        mid, force = forces[name]
        axes[2].plot(mid * to_ms, force * force_unit, color=colour, label=text)
    axes[2].set_ylabel(force_label(window))
    axes[2].legend(**beside)
    axes[3].plot(t_ms, tr.v[:, system.centre] * speed, color="C0", label="ball's centre $Z'$")
    axes[3].plot(t_ms, tr.v[:, system.body_coordinate] * speed, color="C1", label="body $s'$")
    if icm is not None:
        axes[3].axhline(icm[0], color="C1", ls="--", lw=0.8, label="ICM (2.5): $v_1$")
        axes[3].axhline(icm[1], color="C0", ls="--", lw=0.8, label="ICM (2.5): $v_2$")
    axes[3].set_ylabel(label("velocity", "m/s"))
    axes[3].legend(**beside)
    parts = system.energies(tr.q, tr.v)
    membrane = parts["membrane_kinetic"] + parts["membrane_elastic"] + parts["gas"]
    stacks = [
        (parts["rigid_kinetic"], "ball, rigid kinetic"),
        (parts["body_kinetic"], "body, kinetic"),
        (membrane, "membrane and gas"),
        (-tr.damping_work, "damped"),
        (-tr.impact_work - tr.contact_work, "lost at impacts"),
    ]
    axes[4].stackplot(
        t_ms, *[x * energy_unit for x, _ in stacks], labels=[n for _, n in stacks], alpha=0.8
    )
    gravity = parts["gravity"] + parts["body_gravity"]
    gravity = gravity - gravity[0]
    axes[4].plot(t_ms, gravity * energy_unit, color="k", lw=0.8, label="gravity gained")
    axes[4].set_ylabel(label("$E$", "J"))
    axes[4].set_xlabel(time_label("after the first floor touch"))
    axes[4].legend(**beside)
    span = float(t_ms[-1] - t_ms[0]) if t_ms.size > 1 else 1.0
    for contact, colour in (("floor", REFERENCE_COLOUR), ("body", "C1")):
        events = [e for e in r.body.events if e.contact == contact]
        for first, last in event_clusters([e.t * to_ms for e in events], EVENT_CLUSTER * span):
            for ax in axes:
                if first == last:
                    ax.axvline(first, **EVENT_LINE, color=colour)
                else:  # a chatter of touches and separations: one light band
                    ax.axvspan(first, last, **EVENT_BAND, color=colour)
    b = r.body
    v1 = "–" if b.v1 is None else f"{b.v1 / r.settings.v0:.3f}"
    v2 = "–" if b.v2 is None else f"{b.v2 / r.settings.v0:.3f}"
    fig.suptitle(
        f"Whole bounce{': ' + title if title else ''}\n$|v_0|$ = {case.v0:g} m/s, "
        f"$v_1/|v_0|$ = {v1}, $v_2/|v_0|$ = {v2}"
    )
    return fig


#: Colour, line style, marker and name of each lumped baseline in :func:`gap_figure`:
#: distinct in colour, dash and marker (also in greyscale print).
BASELINE_STYLES = {
    "icm": ("k", "-", None, "ICM (2.5)"),
    "two-spring-dashpot": (COLOURS[3], "--", "v", "two spring-dashpots"),
    "bartz2020": (COLOURS[4], "-.", "^", "Bartz 2020"),
    "hertz-viscoelastic": (COLOURS[5], ":", "D", "Hertz, viscoelastic"),
}
#: Colours of the whole bounce's v1 and v2, the paper's CEM and the measurements.
WHOLE_V1, WHOLE_V2, CEM_COLOUR = COLOURS[1], COLOURS[0], COLOURS[2]
MEASURED_COLOUR = "#882255"


def _baseline(reports: Sequence[object], name: str, key: str) -> np.ndarray:
    """One baseline's value ``key`` in every report (nan where it has none)."""
    rows = [((r.baselines or {}).get("models", {}).get(name) or {}) for r in reports]
    return np.array([row.get(key, np.nan) for row in rows], dtype=float)


#: The marks of the whole bounce's caveats (:data:`twoball.modal.floor.bounce.CAVEATS`)
#: on its v1 and v2 curves: marker, size, legend text.
CAVEAT_MARKS: dict[str, tuple[str, float, str]] = {
    "artefact": ("X", 8.0, "depends on the degree-1 artefact"),
    "e12_low": ("v", 8.0, "$e_{12,eff}$ < 0.5 Newton's $e_{12}$"),
}


@styled
def gap_figure(
    points: Sequence[tuple[float, object]],
    parameter: str = "gap",
    measured: dict[str, float] | None = None,
    title: str = "",
    cem: float | None = None,
) -> Figure:
    """v1/|v0|, v2/|v0| and the lift-off times against the gap Delta x [mm] or mu.

    ``points`` are (value, report) of the whole bounce (:class:`twoball.BounceReport`
    with a body, light or not).  Upper two panels, v1 and v2: the whole bounce,
    each report's lumped baselines (the ICM (2.5) solid black, the others
    dashed, dash-dotted and dotted with their own markers),
    :attr:`~twoball.BounceReport.icm_solver` (the ICM with the run's own e2 and
    e12_effective) as open circles where the collisions do not overlap,
    ``cem`` (the paper's massless CEM, v1 only) and ``measured``
    (``{"v1": .., "v2": .., "dx": ..}``, Table 1's ratios) as markers.  Lower
    panel: the body's lift-off after the floor touch and after the largest
    compression (Fig. 9's t_l), the ball's floor release and the ICM's eq.
    (2.2).  The legends stand beside the panels, clear of the data.
    """
    if not points:
        raise ValueError("no whole bounces to draw")
    scale = 1e3 if parameter == "gap" else 1.0
    x = np.array([v for v, _ in points]) * scale
    reports = [r for _, r in points]
    fig = new_figure(8.4, 8.6)
    axes = fig.subplots(3, 1, sharex=True)
    beside = {"loc": "upper left", "bbox_to_anchor": (1.01, 1.0)}
    icm = [r.icm_solver for r in reports]
    for k, (key, ax, colour, marker) in enumerate(
        (("v1_ratio", axes[0], WHOLE_V1, "o"), ("v2_ratio", axes[1], WHOLE_V2, "s"))
    ):
        which = f"$v_{k + 1}/|v_0|$"
        whole = [getattr(r, key) for r in reports]
        whole = np.array([np.nan if v is None else v for v in whole], dtype=float)
        ax.plot(x, whole, color=colour, ls="-", marker=marker, ms=4, label="whole bounce")
        for tag, (mark, size, text) in CAVEAT_MARKS.items():  # the answers that say what they are
            flagged = np.array([tag in getattr(r, "caveats", ()) for r in reports])
            if flagged.any():
                ax.plot(x[flagged], whole[flagged], mark, color="crimson", ms=size, mfc="none",
                        ls="none", label=text)  # fmt: skip
        for name, (c, style, mark, text) in BASELINE_STYLES.items():
            values = _baseline(reports, name, key)
            if np.all(np.isnan(values)):
                continue
            ax.plot(x, values, color=c, ls=style, lw=1.0, marker=mark, ms=3.5, mfc="none",
                    label=text)  # fmt: skip
        if any(i is not None for i in icm):
            solver = np.array([np.nan if i is None else i[key] for i in icm])
            ax.plot(x, solver, "o", mfc="none", color="k", ms=7, ls="none",
                    label="ICM, $e_2$ and $e_{12,eff}$ of the run")  # fmt: skip
        if cem is not None and k == 0:
            ax.plot([0.0], [cem], "D", color=CEM_COLOUR, ms=7, ls="none",
                    label="CEM (massless), the paper")  # fmt: skip
        if measured:
            at = measured.get("dx", 0.0) * scale
            ax.plot([at], [measured[f"v{k + 1}"]], "s", color=MEASURED_COLOUR, ms=8, ls="none",
                    label="measured (Table 1)")  # fmt: skip
        ax.set_ylabel(which + " " + DIMENSIONLESS)
        ax.legend(**beside)
    to_ms = 1e3
    t_lift = np.array([np.nan if r.t_liftoff_s is None else r.t_liftoff_s for r in reports])
    t_l = np.array(
        [
            np.nan
            if r.t_liftoff_from_max_compression_s is None
            else r.t_liftoff_from_max_compression_s
            for r in reports
        ]
    )
    floor = np.array(
        [
            np.nan
            if r.result.body is None or r.result.body.t_floor_release is None
            else r.result.body.t_floor_release / r.case.wave_speed
            for r in reports
        ]
    )
    axes[2].plot(x, t_lift * to_ms, "o-", color="C1", ms=3, label="lift-off after the floor touch")
    axes[2].plot(
        x, t_l * to_ms, "^-", color="C2", ms=3, label="$t_l$: after the largest compression"
    )
    axes[2].plot(x, floor * to_ms, "--", color="C0", label="the ball leaves the floor")
    icm_t = _baseline(reports, "icm", "t_liftoff_s")
    if not np.all(np.isnan(icm_t)):
        axes[2].plot(x, icm_t * to_ms, "k-", lw=1.0, label="ICM, eq. (2.2)")
    axes[2].set_ylabel(label("time", "ms"))
    axes[2].set_xlabel(
        label(r"gap $\Delta x$", "mm") if parameter == "gap" else r"mass ratio $\mu$ [–]"
    )
    axes[2].legend(**beside)
    case = reports[0].case
    fig.suptitle(f"Whole bounce{': ' + title if title else ''} ($|v_0|$ = {case.v0:g} m/s)")
    from twoball.modal.floor.bounce import CAVEATS

    seen = [t for t in CAVEAT_MARKS if any(t in getattr(r, "caveats", ()) for r in reports)]
    if seen:  # what the marked points mean, and where the docs measure it
        import textwrap

        lines = [textwrap.fill(f"{CAVEAT_MARKS[t][2]}: {CAVEATS[t]}", 120) for t in seen]
        fig.supxlabel("\n".join(lines), fontsize=8, x=0.01, ha="left")
    return fig
