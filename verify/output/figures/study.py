"""Convergence studies: relative error against the step, with the expected slopes."""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np
from twoball.verify.output.figures import new_figure
from twoball.verify.studies.result import StudyResult

if TYPE_CHECKING:
    from matplotlib.figure import Figure


def study_figure(study: StudyResult) -> Figure:
    """Log-log errors against the step h for every quantity, with its expected slope.

    The reference slope of each quantity with an expected order is drawn dotted,
    parallel to the data and a factor 3 below its finest point.
    """
    from matplotlib import colormaps

    fig = new_figure(7.5, 5.5)
    axis = fig.subplots()
    if len(study.quantities) > 10:
        axis.set_prop_cycle(color=colormaps["tab20"].colors)
    markers = "osd^v<>phx*"
    for k, q in enumerate(study.quantities):
        h = q.analysis.steps
        e = q.relative_errors
        good = np.isfinite(e) & (e > 0)
        if good.sum() < 1:
            continue
        line = axis.loglog(
            h[good], e[good], marker=markers[k % len(markers)], markersize=4, label=q.spec.label
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
            )
    slopes = sorted({q.spec.band.expected for q in study.quantities if q.spec.band})
    if slopes:
        text = ", ".join(f"{s:g}" for s in slopes)
        axis.plot([], [], "k:", label=f"expected slope ({text})")
    axis.set_xlabel(study.step_name)
    axis.set_ylabel("relative error")
    axis.grid(True, which="both", alpha=0.3)
    axis.legend(fontsize=7, loc="best")
    axis.set_title(f"Convergence study '{study.study}': {_short(study.title)}", fontsize=9)
    return fig


def _short(text: str, width: int = 70) -> str:
    return text if len(text) <= width else text[: width - 1] + "..."
