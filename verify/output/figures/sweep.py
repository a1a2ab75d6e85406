"""Lift-off sweeps: ``v_l / |v0|`` and ``t_l`` against one parameter, or heat maps over two."""

from __future__ import annotations

import os
from pathlib import Path
from typing import TYPE_CHECKING

import numpy as np

from twoball.verify.output.figures import new_figure
from twoball.verify.output.figures.style import label, styled
from twoball.verify.sweeps.sweeps import PARAMETER_LABELS, SweepGrid, SweepPoint, phi_a_rule

if TYPE_CHECKING:
    from matplotlib.figure import Figure

#: Axis labels of the swept parameters (CLI names), mathtext with SI units.
AXIS_LABELS: dict[str, str] = {
    "damping": label("damping ratio $D$", None),
    "v0": label(r"impact speed $|v_0|$", "m/s"),
    "wave-speed": label("wave speed $c$", "1/s"),
    "radius": label("radius $R$", "m"),
    "modes": label("modes $N$", None),
}
RATIO = label(r"$v_l\,/\,|v_0|$", None)
TIME = label("$t_l$", "ms")


def axis_label(parameter: str) -> str:
    """The axis label of a swept parameter (its plain label if not in :data:`AXIS_LABELS`)."""
    return AXIS_LABELS.get(parameter, PARAMETER_LABELS.get(parameter, parameter))


@styled
def sweep_figure(grid: SweepGrid, points: list[SweepPoint]) -> Figure:
    """``v_l/|v0|`` and t_l [ms] against the parameter (1-D) or as heat maps (2-D)."""
    from matplotlib import colormaps

    ratio = np.array([p.ratio for p in points], dtype=float).reshape(grid.shape)
    t_ms = np.array([p.t_liftoff_s for p in points], dtype=float).reshape(grid.shape) * 1e3
    if len(grid.shape) == 1:
        fig = new_figure(6.4, 6.0)
        axes = fig.subplots(2, 1, sharex=True)
        x = grid.values[0]
        axes[0].plot(x, ratio, ".-")
        axes[0].set_ylabel(RATIO)
        axes[1].plot(x, t_ms, ".-")
        axes[1].set_ylabel(TIME)
        axes[1].set_xlabel(axis_label(grid.parameters[0]))
    else:
        fig = new_figure(11.0, 4.4)
        axes = fig.subplots(1, 2)
        y, x = grid.values  # first parameter on the vertical axis (rows)
        for ax, data, name in ((axes[0], ratio, RATIO), (axes[1], t_ms, TIME)):
            cmap = colormaps["viridis"].with_extremes(bad="0.85")
            mesh = ax.pcolormesh(x, y, np.ma.masked_invalid(data), cmap=cmap, shading="nearest")
            fig.colorbar(mesh, ax=ax, label=name)
            ax.set_xlabel(axis_label(grid.parameters[1]))
            ax.set_ylabel(axis_label(grid.parameters[0]))
            ax.set_title(f"{name.split(' [')[0]} (grey: no lift-off or error)")
            ax.grid(False)
    errors = sum(p.error is not None for p in points)
    title = "Closed-form lift-off sweep" + (f" ({errors} points failed)" if errors else "")
    rule = phi_a_rule([p.case for p in points]).replace("|v0|", "$|v_0|$")
    fig.suptitle(f"{title}\n" + r"$\varphi_a$: " + rule)
    return fig


def plot_sweep(grid: SweepGrid, points: list[SweepPoint], target: str | os.PathLike[str]) -> Path:
    """Write :func:`sweep_figure` to ``target`` (checked before the sweep).

    The format follows the suffix (``.png``, ``.pdf``, ``.svg``, ...); the file
    is replaced whole or not at all (:func:`twoball._common.staging.staged_file`).
    """
    from twoball.verify.output.figures import REPORT_DPI, save_figure

    return save_figure(sweep_figure(grid, points), target, "plot", dpi=REPORT_DPI)
