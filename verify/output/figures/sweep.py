"""Lift-off sweeps: ``v_l / |v0|`` and ``t_l`` against one parameter, or heat maps over two."""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np
from twoball.verify.output.figures import new_figure
from twoball.verify.sweeps.sweeps import PARAMETER_LABELS, SweepGrid, SweepPoint

if TYPE_CHECKING:
    from matplotlib.figure import Figure


def sweep_figure(grid: SweepGrid, points: list[SweepPoint]) -> Figure:
    """``v_l/|v0|`` and t_l [ms] against the parameter (1-D) or as heat maps (2-D)."""
    from matplotlib import colormaps

    ratio = np.array([p.ratio for p in points]).reshape(grid.shape)
    t_ms = np.array([p.t_liftoff_s for p in points]).reshape(grid.shape) * 1e3
    if len(grid.shape) == 1:
        fig = new_figure(6.4, 6.0)
        axes = fig.subplots(2, 1, sharex=True)
        x = grid.values[0]
        axes[0].plot(x, ratio, ".-")
        axes[0].set_ylabel("v_l / |v0|")
        axes[1].plot(x, t_ms, ".-")
        axes[1].set_ylabel("t_l [ms]")
        axes[1].set_xlabel(PARAMETER_LABELS[grid.parameters[0]])
        for ax in axes:
            ax.grid(True, alpha=0.3)
    else:
        fig = new_figure(11.0, 4.4)
        axes = fig.subplots(1, 2)
        y, x = grid.values  # first parameter on the vertical axis (rows)
        for ax, data, label in ((axes[0], ratio, "v_l / |v0|"), (axes[1], t_ms, "t_l [ms]")):
            cmap = colormaps["viridis"].with_extremes(bad="0.85")
            mesh = ax.pcolormesh(x, y, np.ma.masked_invalid(data), cmap=cmap, shading="nearest")
            fig.colorbar(mesh, ax=ax, label=label)
            ax.set_xlabel(PARAMETER_LABELS[grid.parameters[1]])
            ax.set_ylabel(PARAMETER_LABELS[grid.parameters[0]])
            ax.set_title(f"{label} (grey: no lift-off or error)")
    errors = sum(p.error is not None for p in points)
    title = "Closed-form lift-off sweep" + (f" ({errors} points failed)" if errors else "")
    fig.suptitle(title)
    return fig
