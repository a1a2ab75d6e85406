"""Waterfall of the radial displacement u(phi) at many instants (cf. Fig. 6), in SI."""

from __future__ import annotations

import math
from typing import TYPE_CHECKING, Any

import numpy as np

from twoball._common.choices import WATERFALL_INSTANTS
from twoball._common.errors import ParameterError
from twoball.verify.output.fields import BallModel, node_polar_angles
from twoball.verify.output.figures import LABELS, new_figure
from twoball.verify.output.figures.style import STACKED, difference_unit, label, styled, subject

if TYPE_CHECKING:
    from matplotlib.figure import Figure


def waterfall_times(model: BallModel, instants: int = WATERFALL_INSTANTS) -> np.ndarray:
    """``instants`` evenly spaced times [s] over the modelled window [0, t_end]."""
    if isinstance(instants, bool) or not isinstance(instants, int | np.integer) or instants < 2:
        raise ParameterError("instants", "an integer >= 2", instants)
    return np.linspace(0.0, model.t_end_s, int(instants))


@styled
def waterfall_figure(
    model: BallModel,
    instants: int = WATERFALL_INSTANTS,
    offset_mm: float | None = None,
    curve_points: int = 721,
) -> Figure:
    """Waterfall of the radial displacement u(phi) [mm] at ``instants`` times (cf. Fig. 6).

    Each instant is one curve, shifted up by ``offset_mm`` per step, labelled by
    its time [ms].  Lines: the closed form, eq. (3.16), on a fine grid of polar
    angles.  Dots: the finite-element nodal values against the polar angle of
    each node (all azimuths; their spread shows the departure from axial
    symmetry).  SI: u in mm, phi in rad, t in ms.  With both backends a
    narrower panel on the right stacks the difference finite elements minus
    closed form at the nodes, row by row beside its instant.  The axis is a stack of
    shifted curves that never overlap, tagged :data:`~.style.STACKED` (the one
    kind of axis allowed more than six curves).

    Parameters
    ----------
    model : BallModel
        Case and backends (any of ``legendre``, ``fem``).
    instants : int
        Number of curves (24 as in Fig. 6), evenly spaced over [0, t_end].
    offset_mm : float, optional
        Vertical shift between curves [mm]; default: from the largest wave after t = 0.
    curve_points : int
        Polar angles of each closed-form curve.
    """
    times = waterfall_times(model, instants)
    scale = model.case.scalings
    compare = "fem" in model.backends and "legendre" in model.backends
    figure = new_figure(10.5 if compare else 7.5, 9.0)
    if compare:
        axis, side = figure.subplots(1, 2, gridspec_kw={"width_ratios": [3.0, 1.25]})
    else:
        axis, side = figure.subplots(), None
    curves: dict[str, tuple[np.ndarray, np.ndarray]] = {}
    if "legendre" in model.backends:
        from twoball.modal.legendre import displacement

        phi = np.linspace(0.0, math.pi, curve_points)
        series = model.backends["legendre"].series
        curves["legendre"] = (phi, displacement(series, times / scale.time, phi) * scale.length)
    if "fem" in model.backends:
        curves["fem"] = (node_polar_angles(model.mesh), model.nodal("fem", times, 0))
    if not curves:
        raise ParameterError("backends", "at least one of fem, legendre")
    values = np.concatenate([u[1:].ravel() for _, u in curves.values()]) * 1e3
    if offset_mm is None:
        spread = float(np.percentile(np.abs(values), 99.5)) if values.size else 1.0
        offset_mm = 1.5 * spread if spread > 0 else 1.0
    if not (math.isfinite(offset_mm) and offset_mm > 0):
        raise ParameterError("offset", "a number > 0 [mm]", offset_mm)
    colours = _colours(len(times))
    for k, t in enumerate(times):
        shift = k * offset_mm
        if "fem" in curves:
            phi, u = curves["fem"]
            axis.plot(
                phi,
                u[k] * 1e3 + shift,
                ".",
                markersize=1.6,
                color=colours[k],
                alpha=0.55,
                label=LABELS["fem"] + " (nodes)" if k == 0 else None,
                rasterized=True,  # every node of every instant: vector files stay small
            )
        if "legendre" in curves:
            phi, u = curves["legendre"]
            axis.plot(
                phi,
                u[k] * 1e3 + shift,
                "-",
                linewidth=0.9,
                color=colours[k],
                label=LABELS["legendre"] if k == 0 else None,
            )
        axis.annotate(
            f"{t * 1e3:.1f} ms",
            xy=(1.0, shift),
            xycoords=("axes fraction", "data"),
            xytext=(4, 0),
            textcoords="offset points",
            va="center",
            fontsize=8,
        )
    axis.axvline(
        model.case.phi_a,
        color="grey",
        linewidth=0.7,
        linestyle=":",
        label=r"edge of the contact at $t = 0$, $\varphi_a$",
    )
    axis.set_xlim(0.0, math.pi)
    axis.set_xticks(
        np.linspace(0.0, math.pi, 5), ["0", r"$\pi/4$", r"$\pi/2$", r"$3\pi/4$", r"$\pi$"]
    )
    axis.set_xlabel(label(r"polar angle $\varphi$ (0: top, where the upper body rests)", "rad"))
    axis.set_ylabel(
        label(rf"$u(t, \varphi)$ + {offset_mm:.3g} mm per instant (time at the right)", "mm")
    )
    axis.set_gid(STACKED)
    axis.set_ylim(_waterfall_limits(curves, offset_mm, len(times)))
    # the stacked curves fill the panel: the legend goes below the figure, covering none
    handles, names = axis.get_legend_handles_labels()
    figure.legend(handles, names, loc="outside lower center", ncols=3, markerscale=5)
    case = model.case
    axis.set_title(
        f"{subject(case)}: radial displacement at {len(times)} instants (cf. Fig. 6), "
        rf"$\varphi_a$ = {case.phi_a:.3g} rad, $R$ = {case.radius:g} m, "
        f"$c$ = {case.wave_speed:g} 1/s, $D$ = {case.damping:g}"
    )
    axis.grid(False, axis="y")
    if side is not None:
        _difference_stack(side, model, times, curves["fem"], axis.get_ylim(), offset_mm, colours)
    return figure


def _difference_stack(
    axis: Any,
    model: BallModel,
    times: np.ndarray,
    fem: tuple[np.ndarray, np.ndarray],
    limits: tuple[float, float],
    offset_mm: float,
    colours: np.ndarray,
) -> None:
    """Finite elements minus closed form at the nodes, stacked like the waterfall beside it.

    Instant k sits at the same height as in the waterfall: the stack's offset and
    limits are the waterfall's scaled by one factor, so the rows line up.
    """
    from twoball.modal.legendre import displacement

    phi, u_fem = fem
    scale = model.case.scalings
    series = model.backends["legendre"].series
    closed = displacement(series, times / scale.time, phi) * scale.length
    diff = u_fem - closed  # m
    factor, unit = difference_unit(diff[1:].ravel() if len(times) > 1 else diff.ravel(), "m")
    spread = float(np.percentile(np.abs(diff[1:] * factor), 99.5)) if len(times) > 1 else 0.0
    offset = 1.5 * spread if spread > 0 else 1.0
    ratio = offset / offset_mm
    for k in range(len(times)):
        axis.plot(
            phi,
            diff[k] * factor + k * offset,
            ".",
            markersize=1.6,
            color=colours[k],
            rasterized=True,
        )
    axis.axvline(model.case.phi_a, color="grey", linewidth=0.7, linestyle=":")
    axis.set_xlim(0.0, math.pi)
    axis.set_xticks(np.linspace(0.0, math.pi, 3), ["0", r"$\pi/2$", r"$\pi$"])
    for text, align in zip(axis.get_xticklabels(), ("left", "center", "right"), strict=True):
        text.set_horizontalalignment(align)  # the end labels stay inside the narrow panel
    axis.set_ylim(limits[0] * ratio, limits[1] * ratio)
    axis.set_xlabel(label(r"$\varphi$", "rad"))
    shift = rf"finite elements $-$ closed form + {offset:.3g} {unit} per instant"
    axis.set_ylabel(label(shift, unit))
    axis.set_title("difference at the nodes")
    axis.grid(False, axis="y")
    axis.set_gid(STACKED)


def _colours(count: int) -> np.ndarray:
    from matplotlib import colormaps

    return colormaps["viridis"](np.linspace(0.0, 0.9, count))


def _waterfall_limits(
    curves: dict[str, tuple[np.ndarray, np.ndarray]], offset: float, count: int
) -> tuple[float, float]:
    low = min(float(u[0].min()) for _, u in curves.values()) * 1e3
    high = max(
        float((u * 1e3 + offset * np.arange(count)[:, None]).max()) for _, u in curves.values()
    )
    return min(low, -offset) - 0.3 * offset, high + 0.6 * offset
