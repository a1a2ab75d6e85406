"""Pole motion u, u_t, u_tt against time with lift-off marked (§3(a)), in SI.

:func:`pole_figure` draws a :class:`~twoball.verify.output.fields.BallModel`'s
backends (``twoball plot pole``); :func:`pole_motion_figure` overlays any
:class:`Trace` of dimensionless pole motion (the ``verify`` report).
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np
from twoball.modal.liftoff import PoleMotion
from twoball.modal.parameters import Case
from twoball.verify.output.fields import BallModel
from twoball.verify.output.figures import LABELS, new_figure

if TYPE_CHECKING:
    from matplotlib.figure import Figure


def pole_figure(model: BallModel, samples: int = 2500) -> Figure:
    """Pole displacement [mm], velocity [m/s] and acceleration [m/s^2] against time [ms].

    One line per backend (eq. (3.16) in closed form for both); each backend's
    lift-off (§3(a), criteria (i)-(ii)) is marked by a dot and a dashed line, and
    the acceleration panel shows ``-g``, the lift-off threshold of criterion (i).
    After lift-off the velocity panel also shows the body's free flight
    ``v_l - g (t - t_l)``.
    """
    scale = model.case.scalings
    t = np.linspace(0.0, model.t_end, samples)
    ms = t * scale.time * 1e3
    figure = new_figure(7.5, 8.0)
    axes = figure.subplots(3, 1, sharex=True)
    units = (1e3 * scale.length, scale.velocity, scale.acceleration)
    names = ("u(t, 0) [mm]", "u_t(t, 0) [m/s]", "u_tt(t, 0) [m/s²]")
    styles = {"legendre": "-", "fem": "--"}
    for name, backend in model.backends.items():
        state = backend.series.pole(t)
        report = backend.report
        lines = []
        for axis, values, unit in zip(axes, state, units, strict=True):
            lines.append(
                axis.plot(
                    ms,
                    values * unit,
                    styles.get(name, ":"),
                    linewidth=1.0,
                    label=LABELS.get(name, name),
                )[0]
            )
        if report.result.lifted:
            t_l = report.result.t
            mark = backend.series.pole(np.array([t_l]))
            for axis, values, unit, line in zip(axes, mark, units, lines, strict=True):
                axis.plot(
                    t_l * scale.time * 1e3,
                    values[0] * unit,
                    "o",
                    markersize=5,
                    color=line.get_color(),
                )
                axis.axvline(
                    t_l * scale.time * 1e3, color=line.get_color(), linewidth=0.7, linestyle="--"
                )
            after = t >= t_l
            flight = report.v_liftoff_m_s - model.case.g * (t[after] - t_l) * scale.time
            axes[1].plot(
                ms[after],
                flight,
                ":",
                linewidth=0.8,
                color=lines[1].get_color(),
                label=f"body in flight ({LABELS.get(name, name)})",
            )
            axes[0].annotate(
                f"lift-off {report.t_liftoff_s * 1e3:.2f} ms, {report.v_liftoff_m_s:.3f} m/s",
                xy=(t_l * scale.time * 1e3, mark.u[0] * units[0]),
                xytext=(8, 8 if name == "legendre" else -14),
                textcoords="offset points",
                fontsize=7,
                color=lines[0].get_color(),
            )
    axes[2].axhline(-model.case.g, color="black", linewidth=0.8, linestyle=":", label="-g")
    accelerations = np.concatenate(
        [b.series.pole(t).u_tt * scale.acceleration for b in model.backends.values()]
    )
    spread = float(np.percentile(np.abs(accelerations), 99.0))
    if spread > 0:  # a few early samples of a filtered series can dwarf the rest
        axes[2].set_ylim(-1.3 * max(spread, model.case.g), 1.3 * spread)
    for axis, name in zip(axes, names, strict=True):
        axis.set_ylabel(name)
        axis.grid(True, alpha=0.3)
    axes[1].legend(fontsize=7, loc="best")
    axes[2].legend(fontsize=7, loc="lower right")
    axes[2].set_xlabel("t [ms] after maximal compression")
    figure.suptitle("Motion of the pole (φ = 0); dots and dashed lines: lift-off", fontsize=10)
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


def pole_motion_figure(
    case: Case, traces: Sequence[Trace], t_end: float, samples: int = 3000
) -> Figure:
    """Pole displacement, velocity and acceleration against time, every backend overlaid.

    Lift-off is marked by a dot on each curve and a dashed vertical line; the
    acceleration panel shows ``-g`` (criterion (i) of §3(a)).
    """
    scale = case.scalings
    t = np.linspace(0.0, t_end, samples)
    fig = new_figure(8.0, 8.5)
    axes = fig.subplots(3, 1, sharex=True)
    units = [
        ("u(t, 0) [mm]", 1e3 * scale.length),
        ("u_t(t, 0) [m/s]", scale.velocity),
        ("u_tt(t, 0) [m/s^2]", scale.acceleration),
    ]
    styles = ["-", "--", "-.", ":", (0, (5, 1)), (0, (3, 1, 1, 1))]
    for k, trace in enumerate(traces):
        state = trace.motion.pole(t)
        mark = None if trace.t_l is None else trace.motion.pole(np.array([trace.t_l]))
        for axis, values, (_, factor), field in zip(
            axes, state, units, ("u", "u_t", "u_tt"), strict=True
        ):
            line = axis.plot(
                t * scale.time * 1e3,
                values * factor,
                linestyle=styles[k % len(styles)],
                linewidth=1.0,
                label=trace.label,
            )[0]
            if mark is not None:
                axis.plot(
                    trace.t_l * scale.time * 1e3,
                    getattr(mark, field)[0] * factor,
                    "o",
                    color=line.get_color(),
                    markersize=4,
                )
    for axis, (label, _) in zip(axes, units, strict=True):
        axis.set_ylabel(label)
        axis.grid(True, alpha=0.3)
    axes[2].axhline(-case.g, color="black", linewidth=0.8, linestyle=":", label="-g")
    accel = [tr.motion.pole(t).u_tt * scale.acceleration for tr in traces[:1]]
    if accel:  # the first few samples of a filtered series are huge; zoom on the rest
        spread = np.percentile(np.abs(accel[0]), 99.5)
        axes[2].set_ylim(-1.2 * spread, 1.2 * spread)
    lifted = [tr.t_l for tr in traces if tr.t_l is not None]
    if lifted:
        for axis in axes:
            axis.axvline(lifted[0] * scale.time * 1e3, color="grey", linewidth=0.8, linestyle="--")
    axes[2].set_xlabel("t [ms] after maximal compression")
    axes[0].legend(fontsize=7, loc="best")
    fig.suptitle("Pole motion of every backend; dots and dashed line: lift-off")
    return fig
