"""Energy decay of direct time stepping against the modal closed form."""

from __future__ import annotations

import math
from collections.abc import Sequence
from typing import TYPE_CHECKING

import numpy as np

from twoball.modal.parameters import Case
from twoball.verify.output.figures import new_figure
from twoball.verify.output.figures.style import (
    MAX_CURVES,
    REFERENCE_COLOUR,
    chunks,
    label,
    styled,
    subject,
    time_label,
)

if TYPE_CHECKING:
    from matplotlib.figure import Figure


@styled
def energy_figure(
    case: Case,
    curves: Sequence[tuple[str, np.ndarray, np.ndarray]],
    bound: tuple[np.ndarray, np.ndarray] | None = None,
) -> Figure:
    """Energy per unit membrane mass [J/kg] against time [ms], log scale, with the decay bound.

    ``curves`` hold dimensionless times (unit 1/c) and energies (unit T R^2);
    with the tension ``T = rho R^2 c^2`` and the membrane mass
    ``m = 4 pi R^2 rho`` the energy is ``E = (T R^2) e = m (R c)^2 e / (4 pi)``,
    so ``E / m = e (R c)^2 / (4 pi)`` [J/kg] needs no mass (cf. eqs. (3.5)-(3.6):
    at t = 0 it is ``|v0|^2 / 2``, the impact's kinetic energy per kilogram).
    Pairs of curves (time stepping, its modal closed form) share a colour, solid
    and dashed; a lower panel shows the relative difference of each pair, first
    minus second over second.  More than three pairs are split over columns.
    """
    pairs = [list(curves[k : k + 2]) for k in range(0, len(curves), 2)]
    groups = chunks(pairs, MAX_CURVES // 2) or [[]]
    compare = any(len(pair) == 2 for pair in pairs)
    fig = new_figure(min(6.5 * len(groups), 16.0), 6.0 if compare else 4.5)
    grid = fig.subplots(
        2 if compare else 1,
        len(groups),
        sharex=True,
        squeeze=False,
        gridspec_kw={"height_ratios": [3, 1.4]} if compare else None,
    )
    ms = case.scalings.time * 1e3
    per_kg = case.scalings.velocity**2 / (4.0 * math.pi)
    for column, group in enumerate(groups):
        axis = grid[0, column]
        for k, pair in enumerate(group):
            for j, (name, t, energy) in enumerate(pair):
                axis.semilogy(
                    t * ms,
                    np.asarray(energy) * per_kg,
                    linestyle="-" if j == 0 else "--",
                    color=f"C{k}",
                    label=name,
                )
            if compare and len(pair) == 2:
                (first, t1, e1), (second, t2, e2) = pair
                e2_at = np.interp(t1, t2, e2)
                with np.errstate(divide="ignore", invalid="ignore"):
                    relative = (np.asarray(e1) - e2_at) / e2_at
                grid[1, column].plot(
                    t1 * ms, relative, color=f"C{k}", label=f"{first} vs {second}".strip()
                )
        if bound is not None:
            axis.semilogy(
                bound[0] * ms,
                np.asarray(bound[1]) * per_kg,
                ":",
                color=REFERENCE_COLOUR,
                linewidth=1.0,
                label="per-mode decay bound",
            )
        if group or bound is not None:
            axis.legend(title="below: solid minus dashed, relative" if compare else None)
        if compare:
            below = grid[1, column]
            below.axhline(0.0, color=REFERENCE_COLOUR, linewidth=0.6)
            below.set_ylabel(label("relative difference", None), fontsize=8)
            below.ticklabel_format(axis="y", style="sci", scilimits=(-2, 3))
        grid[-1, column].set_xlabel(time_label())
    grid[0, 0].set_ylabel(label("$E/m$", "J/kg"))
    fig.suptitle(
        f"{subject(case)}: energy per kilogram of membrane,\n"
        "time stepping against the modal closed form"
    )
    return fig
