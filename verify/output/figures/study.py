"""Convergence studies: relative error against the step, with the expected slopes.

Small multiples: at most :data:`QUANTITIES_PER_PANEL` quantities (each with its
dotted expected slope) share an axis, so no panel carries more than
:data:`~twoball.verify.output.figures.style.MAX_CURVES` lines.
"""

from __future__ import annotations

import re
from typing import TYPE_CHECKING

import numpy as np

from twoball.verify.output.figures import new_figure
from twoball.verify.output.figures.style import (
    MAX_CURVES,
    chunks,
    grid_shape,
    label,
    styled,
)
from twoball.verify.studies.result import StudyResult

if TYPE_CHECKING:
    from matplotlib.figure import Figure

#: Quantities per panel: each brings its data line and its expected slope.
QUANTITIES_PER_PANEL = MAX_CURVES // 2
#: Plain-text names in quantity labels -> mathtext (for the legends).
MATH_NAMES = (
    (r"lambda_(\d+)", r"$\\lambda_{\1}$"),
    (r"\bt_l\b", "$t_l$"),
    (r"\bv_l\b", "$v_l$"),
    (r"E\(t_end\)", r"$E(t_\\mathrm{end})$"),
    (r"1/2 u0\^T K u0", r"$\\frac{1}{2}u_0^T K u_0$"),
    (r"-W \(3\.5\)", "$-W$ (3.5)"),
    (
        r"\|\|u - u_ref\|\|_L2 / \|\|u_ref\|\|",
        r"$\\|u - u_\\mathrm{ref}\\|_{L^2} / \\|u_\\mathrm{ref}\\|$",
    ),
    (r"\|pole state - modal\|", r"$|$pole state $-$ modal$|$"),
)


def legend_name(text: str) -> str:
    """A quantity label for a legend: units dropped (errors are relative), mathtext names."""
    text = re.sub(r"\s*\[[^\]]*\]", "", text)
    for pattern, replacement in MATH_NAMES:
        text = re.sub(pattern, replacement, text)
    return text


def step_axis(study: StudyResult) -> tuple[str, float]:
    """Label and factor of the step axis: SI (mm, ms) where the step has a unit.

    The studies' steps are dimensionless (length R, time 1/c); mesh sizes are
    shown in mm and time steps in ms, from the case's R and c in the settings.
    ``1/N`` and ``DOFs^(-1/2)`` are pure numbers.
    """
    radius = study.settings.get("radius_m")
    speed = study.settings.get("wave_speed_1_s")
    name = study.step_name
    if study.study == "h" and radius:
        if "triangles" in name:
            return label(r"mesh size $h = R\sqrt{4\pi/n_\triangle}$", "mm"), radius * 1e3
        return label(r"mesh size $h = \pi R / n_e$", "mm"), radius * 1e3
    if study.study == "dt" and speed:
        return label(r"time step $\Delta t$", "ms"), 1e3 / speed
    if study.study == "modes":
        return label("$h = 1/N$", None), 1.0
    if study.study == "order":
        if "1/DOFs" in name:
            return label(r"$h = 1/n_\mathrm{DOF}$", None), 1.0
        return label(r"$h = n_\mathrm{DOF}^{-1/2}$", None), 1.0
    return label(f"step {name}", None), 1.0


@styled
def study_figure(study: StudyResult) -> Figure:
    """Log-log relative errors against the step for every quantity, with expected slopes.

    The reference slope of each quantity with an expected order is drawn dotted
    in its colour, parallel to the data and a factor 3 below its finest point.
    """
    shown = [
        q
        for q in study.quantities
        if (np.isfinite(q.relative_errors) & (q.relative_errors > 0)).any()
    ]
    groups = chunks(shown, QUANTITIES_PER_PANEL) or [[]]
    rows, columns = grid_shape(len(groups), 2)
    fig = new_figure(4.6 * columns + 0.6, 3.6 * rows + 0.6)
    axes = fig.subplots(rows, columns, sharex=True, squeeze=False).ravel()
    xlabel, factor = step_axis(study)
    markers = "osd^v<"
    for axis, group in zip(axes, groups, strict=False):
        for k, q in enumerate(group):
            h = q.analysis.steps * factor
            e = q.relative_errors
            good = np.isfinite(e) & (e > 0)
            line = axis.loglog(
                h[good],
                e[good],
                marker=markers[k % len(markers)],
                linestyle="-",
                label=legend_name(q.spec.label),
            )[0]
            if q.spec.band is not None and good.sum() >= 2:
                p = q.spec.band.expected
                h0, e0 = h[good][-1], e[good][-1]
                span = np.array([h[good][0], h0])
                axis.loglog(
                    span,
                    e0 / 3.0 * (span / h0) ** p,
                    linestyle=":",
                    color=line.get_color(),
                    linewidth=1.0,
                    label=f"slope {p:g}",
                )
        axis.set_ylabel(label("relative error", None))
        if group:
            axis.legend(loc="best", fontsize=8)
    for axis in axes[len(groups) :]:
        axis.set_visible(False)
    for axis in axes[max(0, len(groups) - columns) : len(groups)]:
        axis.set_xlabel(xlabel)
        axis.xaxis.set_tick_params(labelbottom=True)
    fig.suptitle(f"Convergence study '{study.study}': {_short(study.title)}")
    return fig


def _short(text: str, width: int = 90) -> str:
    return text if len(text) <= width else text[: width - 1] + "..."
