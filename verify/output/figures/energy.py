"""Energy decay of direct time stepping against the modal closed form."""

from __future__ import annotations

from collections.abc import Sequence
from typing import TYPE_CHECKING

import numpy as np
from twoball.modal.parameters import Case
from twoball.verify.output.figures import new_figure

if TYPE_CHECKING:
    from matplotlib.figure import Figure


def energy_figure(
    case: Case,
    curves: Sequence[tuple[str, np.ndarray, np.ndarray]],
    bound: tuple[np.ndarray, np.ndarray] | None = None,
) -> Figure:
    """Energy (unit T R^2) against time [ms] on a log scale, with the modal decay bound."""
    fig = new_figure(7.0, 4.5)
    axis = fig.subplots()
    ms = case.scalings.time * 1e3
    for k, (label, t, energy) in enumerate(curves):
        style = "-" if k % 2 == 0 else "--"
        axis.semilogy(t * ms, energy, linestyle=style, linewidth=1.2, label=label)
    if bound is not None:
        axis.semilogy(bound[0] * ms, bound[1], "k:", linewidth=1.0, label="per-mode bound")
    axis.set_xlabel("t [ms]")
    axis.set_ylabel("E(t) [T R^2]")
    axis.grid(True, which="both", alpha=0.3)
    if curves or bound is not None:
        axis.legend(fontsize=8)
    axis.set_title("Energy decay: direct time stepping against the modal closed form")
    return fig
