"""Energy decay of direct time stepping against the modal closed form."""

from __future__ import annotations

import math
from collections.abc import Sequence
from typing import TYPE_CHECKING

import numpy as np
from twoball.modal.parameters import Case
from twoball.verify.output.figures import new_figure
from twoball.verify.output.figures.style import REFERENCE_COLOUR, chunks, label, styled, time_label

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
    and dashed; more than :data:`~.style.MAX_CURVES` are split over panels.
    """
    fig_groups = chunks(list(curves)) or [[]]
    fig = new_figure(min(6.5 * len(fig_groups), 16.0), 4.5)
    axes = fig.subplots(1, len(fig_groups), sharey=True, squeeze=False)[0]
    ms = case.scalings.time * 1e3
    per_kg = case.scalings.velocity**2 / (4.0 * math.pi)
    for axis, group in zip(axes, fig_groups, strict=True):
        for k, (name, t, energy) in enumerate(group):
            style = "-" if k % 2 == 0 else "--"
            axis.semilogy(
                t * ms, np.asarray(energy) * per_kg, linestyle=style, color=f"C{k // 2}", label=name
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
        axis.set_xlabel(time_label())
        if group or bound is not None:
            axis.legend()
    axes[0].set_ylabel(label("$E/m$", "J/kg"))
    fig.suptitle("Energy per kilogram of membrane: time stepping against the modal closed form")
    return fig
