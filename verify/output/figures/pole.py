"""Pole motion u, u_t, u_tt against time with lift-off marked (§3(a)), in SI.

:func:`pole_figure` draws a :class:`~twoball.verify.output.fields.BallModel`'s
backends (``twoball plot pole``); :func:`pole_motion_figure` overlays any
:class:`Trace` of dimensionless pole motion (the ``verify`` report).  Both put a
difference panel under each quantity when a solution is compared with a
reference (finite elements against the closed form).
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

import numpy as np

from twoball.modal.liftoff import PoleMotion
from twoball.modal.parameters import Case
from twoball.verify.output.fields import BallModel
from twoball.verify.output.figures import LABELS, new_figure
from twoball.verify.output.figures.style import (
    LIFTOFF_MARKER,
    LINE_STYLES,
    MAX_CURVES,
    REFERENCE_COLOUR,
    chunks,
    difference_limits,
    difference_unit,
    label,
    styled,
    subject,
    time_label,
)

if TYPE_CHECKING:
    from matplotlib.figure import Figure

#: Quantity symbol, SI unit and factor from SI of the three pole panels.
QUANTITIES = (
    ("$u(t, 0)$", "mm", 1e3),
    (r"$u_t(t, 0)$", "m/s", 1.0),
    (r"$u_{tt}(t, 0)$", "m/s$^2$", 1.0),
)


def _si_units(case: Case) -> tuple[float, float, float]:
    """Dimensionless -> SI factors of u [m], u_t [m/s], u_tt [m/s^2]."""
    scale = case.scalings
    return scale.length, scale.velocity, scale.acceleration


def _quantity_axes(figure: Any, compare: bool, columns: int = 1) -> np.ndarray:
    """Axes of the three quantities (rows 0, 2, 4 with a difference row below each)."""
    if not compare:
        return figure.subplots(3, columns, sharex=True, squeeze=False)
    return figure.subplots(
        6, columns, sharex=True, squeeze=False, gridspec_kw={"height_ratios": [3, 1.4] * 3}
    )


def _liftoff_legend(axis: Any) -> None:
    """Explain the markers: a proxy entry for the lift-off dot and line."""
    axis.plot([], [], LIFTOFF_MARKER, linestyle="--", color="0.4", linewidth=0.7, label="lift-off")


def clip_acceleration(axis: Any, values: np.ndarray, g: float) -> None:
    """Zoom past the first samples of a filtered series, keeping -g in view."""
    finite = np.abs(values[np.isfinite(values)])
    spread = float(np.percentile(finite, 99.0)) if finite.size else 0.0
    if spread > 0:
        axis.set_ylim(-1.3 * max(spread, g), 1.3 * max(spread, g))


def draw_differences(
    axes: Sequence[Any], t_ms: np.ndarray, diffs: list[tuple[str, Any, list[np.ndarray]]]
) -> None:
    """Fill the difference rows: ``diffs`` = (label, colour/style, [du, du_t, du_tt] SI)."""
    for row, (symbol, unit, _) in enumerate(QUANTITIES):
        axis = axes[row]
        base = "m" if unit == "mm" else unit
        si = np.concatenate([d[2][row] for d in diffs]) if diffs else np.zeros(0)
        scale, shown = difference_unit(si, base)
        for name, style, values in diffs:
            axis.plot(t_ms, values[row] * scale, label=name, **style)
        axis.axhline(0.0, color=REFERENCE_COLOUR, linewidth=0.6)
        # the whole difference of u and u_t; u_tt past the first samples of a filter
        limits = difference_limits(si * scale, 99.5 if row == 2 else 100.0)
        if limits is not None:
            axis.set_ylim(*limits)
        axis.set_ylabel(label(r"$\Delta " + symbol[1:].split("(")[0] + "$", shown), fontsize=8)


@styled
def pole_figure(model: BallModel, samples: int = 2500) -> Figure:
    """Pole displacement [mm], velocity [m/s] and acceleration [m/s^2] against time [ms].

    One line per backend (eq. (3.16) in closed form for both); each backend's
    lift-off (§3(a), criteria (i)-(ii)) is marked by a dot and a dashed line, and
    the acceleration panel shows ``-g``, the lift-off threshold of criterion (i).
    After lift-off the velocity panel also shows the body's free flight
    ``v_l - g (t - t_l)``.  With both backends, a panel under each quantity
    shows the difference finite elements minus closed form (6 axes, else 3).
    """
    case = model.case
    scale = case.scalings
    t = np.linspace(0.0, model.t_end, samples)
    ms = t * scale.time * 1e3
    compare = "fem" in model.backends and "legendre" in model.backends
    figure = new_figure(7.5, 10.0 if compare else 8.0)
    grid = _quantity_axes(figure, compare)[:, 0]
    axes = grid[::2] if compare else grid
    si = _si_units(case)
    states = {name: b.series.pole(t) for name, b in model.backends.items()}
    styles = {"legendre": "-", "fem": "--"}
    for name, backend in model.backends.items():
        state = states[name]
        report = backend.report
        lines = []
        for axis, values, unit, (_, _, factor) in zip(axes, state, si, QUANTITIES, strict=True):
            lines.append(
                axis.plot(
                    ms, values * unit * factor, styles.get(name, ":"), label=LABELS.get(name, name)
                )[0]
            )
        if report.result.lifted:
            t_l = report.result.t
            t_l_ms = t_l * scale.time * 1e3
            mark = backend.series.pole(np.array([t_l]))
            for axis, values, unit, line, (_, _, factor) in zip(
                axes, mark, si, lines, QUANTITIES, strict=True
            ):
                axis.plot(t_l_ms, values[0] * unit * factor, LIFTOFF_MARKER, color=line.get_color())
                axis.axvline(t_l_ms, color=line.get_color(), linewidth=0.7, linestyle="--")
            after = t >= t_l
            flight = report.v_liftoff_m_s - case.g * (t[after] - t_l) * scale.time
            axes[1].plot(
                ms[after],
                flight,
                ":",
                linewidth=0.9,
                color=lines[1].get_color(),
                label=f"body in flight ({LABELS.get(name, name)})",
            )
            axes[0].annotate(
                f"lift-off {report.t_liftoff_s * 1e3:.2f} ms, {report.v_liftoff_m_s:.3f} m/s",
                xy=(t_l_ms, mark.u[0] * si[0] * 1e3),
                xytext=(8, 8 if name == "legendre" else -14),
                textcoords="offset points",
                fontsize=8,
                color=lines[0].get_color(),
            )
    axes[2].axhline(-case.g, color=REFERENCE_COLOUR, linewidth=0.8, linestyle=":", label="$-g$")
    clip_acceleration(axes[2], np.concatenate([s.u_tt * si[2] for s in states.values()]), case.g)
    for axis, (symbol, unit, _) in zip(axes, QUANTITIES, strict=True):
        axis.set_ylabel(label(symbol, unit))
    _liftoff_legend(axes[2])
    axes[1].legend(loc="best")
    axes[2].legend(loc="best")
    if compare:
        fem, ref = states["fem"], states["legendre"]
        diff = [
            (np.asarray(a) - np.asarray(b)) * unit for a, b, unit in zip(fem, ref, si, strict=True)
        ]
        style = {"color": "0.15", "linestyle": "-", "linewidth": 0.9}
        draw_differences(grid[1::2], ms, [("finite elements − closed form", style, diff)])
        grid[1].legend(loc="upper right")
    grid[-1].set_xlabel(time_label("after maximal compression"))
    figure.suptitle(
        f"{subject(model.case)}: "
        + r"motion of the pole ($\varphi = 0$)"
        + (", finite elements − closed form below each" if compare else ""),
    )
    return figure


@dataclass(frozen=True)
class Trace:
    """One backend's pole motion for the overlay plot (dimensionless motion).

    Attributes
    ----------
    label : str
        Legend entry.
    motion : PoleMotion
        Anything with ``pole(t)``.
    t_l, v_l : float or None
        Its lift-off time and velocity (dimensionless), marked on the curves.
    """

    label: str
    motion: PoleMotion
    t_l: float | None
    v_l: float | None


@styled
def pole_motion_figure(
    case: Case, traces: Sequence[Trace], t_end: float, samples: int = 3000
) -> Figure:
    """Pole displacement, velocity and acceleration of every backend, and differences.

    The first trace is the reference: under each quantity a panel shows every
    other trace minus it.  With more than :data:`MAX_CURVES` traces the others
    are split over several columns (the reference repeated in each).  Lift-off
    is marked by a dot on each curve; the acceleration panel shows ``-g``
    (criterion (i) of §3(a)).
    """
    scale = case.scalings
    t = np.linspace(0.0, t_end, samples)
    ms = t * scale.time * 1e3
    si = _si_units(case)
    reference, others = (traces[0], list(traces[1:])) if traces else (None, [])
    groups = chunks(others, MAX_CURVES - 1) or [[]]
    compare = bool(others)
    fig = new_figure(7.0 * len(groups) + 1.0, 10.5 if compare else 8.0)
    grid = _quantity_axes(fig, compare, len(groups))
    ref_state = None if reference is None else reference.motion.pole(t)
    for column, group in enumerate(groups):
        rows = grid[:, column]
        axes = rows[::2] if compare else rows
        members = ([reference] if reference is not None else []) + group
        diffs = []
        for k, trace in enumerate(members):
            colour = f"C{k}"
            state = ref_state if k == 0 else trace.motion.pole(t)
            mark = None if trace.t_l is None else trace.motion.pole(np.array([trace.t_l]))
            style = {
                "color": colour,
                "linestyle": LINE_STYLES[k % len(LINE_STYLES)],
            }
            for axis, values, unit, (_, _, factor), field in zip(
                axes, state, si, QUANTITIES, ("u", "u_t", "u_tt"), strict=True
            ):
                axis.plot(ms, values * unit * factor, label=_pretty(trace.label), **style)
                if mark is not None:
                    axis.plot(
                        trace.t_l * scale.time * 1e3,
                        getattr(mark, field)[0] * unit * factor,
                        LIFTOFF_MARKER,
                        color=colour,
                    )
            if k > 0 and ref_state is not None:
                diffs.append(
                    (
                        _pretty(trace.label),
                        {**style, "linewidth": 0.9},
                        [
                            (np.asarray(a) - np.asarray(b)) * unit
                            for a, b, unit in zip(state, ref_state, si, strict=True)
                        ],
                    )
                )
        for axis, (symbol, unit, _) in zip(axes, QUANTITIES, strict=True):
            axis.set_ylabel(label(symbol, unit))
        axes[2].axhline(-case.g, color=REFERENCE_COLOUR, linewidth=0.8, linestyle=":", label="$-g$")
        if ref_state is not None:
            clip_acceleration(axes[2], ref_state.u_tt * si[2], case.g)
        if reference is not None and reference.t_l is not None:
            for axis in axes:
                axis.axvline(
                    reference.t_l * scale.time * 1e3, color="0.5", linewidth=0.7, linestyle="--"
                )
        if compare:
            draw_differences(rows[1::2], ms, diffs)
        axes[0].legend(loc="best", fontsize=8)
        if column == len(groups) - 1:  # the same two entries in every column: once, beside
            _liftoff_legend(axes[2])
            axes[2].legend(loc="upper left", bbox_to_anchor=(1.01, 1.0), fontsize=8)
        rows[-1].set_xlabel(time_label("after maximal compression"))
    title = f"{subject(case)}: pole motion of every backend; dots and dashed line: lift-off"
    if compare and reference is not None:
        title += f"; below each: difference to {_pretty(reference.label)}"
    fig.suptitle(title)
    return fig


def _pretty(text: str) -> str:
    """A backend label for a legend: arrows as arrows."""
    return text.replace("->", "→")
