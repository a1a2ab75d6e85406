"""Matplotlib figures of the solution in SI: waterfall (Fig. 6), pole motion, eigenvalue errors.

Only :class:`matplotlib.figure.Figure` is used (no pyplot, no global state, Agg
canvas), so the figures never open a window and can be made from any thread.
Each ``*_figure`` function returns the figure; :func:`save_figure` writes it
atomically (scratch file beside the target, then rename).
"""

from __future__ import annotations

import math
import os
from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path

import numpy as np
from matplotlib.figure import Figure
from twoball.fem_membrane.export import staged_files
from twoball.modal.errors import ParameterError
from twoball.verify.output.fields import BallModel, node_polar_angles

DPI = 110
PLOT_KINDS: tuple[str, ...] = ("waterfall", "pole", "eigen")
WATERFALL_INSTANTS = 24  # as in Fig. 6
LABELS = {"fem": "finite elements", "legendre": "closed form (3.16)"}


# --------------------------------------------------------------------------- files
def save_figure(figure: Figure, path: str | os.PathLike[str], flag: str = "--out") -> Path:
    """Write ``figure`` as PNG to ``path``: scratch file beside it, then rename.

    Raises ParameterError naming ``flag`` if the folder is missing or not writable.
    """
    out = Path(path).expanduser()
    if out.suffix.lower() != ".png":
        raise ParameterError(flag, "a file name ending in .png", str(path))
    with staged_files(out, flag) as scratch:
        figure.savefig(scratch / out.name, dpi=DPI, format="png")
    return out


# --------------------------------------------------------------------------- waterfall
def waterfall_times(model: BallModel, instants: int = WATERFALL_INSTANTS) -> np.ndarray:
    """``instants`` evenly spaced times [s] over the modelled window [0, t_end]."""
    if isinstance(instants, bool) or not isinstance(instants, int | np.integer) or instants < 2:
        raise ParameterError("--instants", "an integer >= 2", instants)
    return np.linspace(0.0, model.t_end_s, int(instants))


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
    symmetry).  SI: u in mm, phi in rad, t in ms.

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
    figure = Figure(figsize=(7.5, 9.0), layout="constrained")
    axis = figure.subplots()
    curves: dict[str, tuple[np.ndarray, np.ndarray]] = {}
    if "legendre" in model.backends:
        from twoball.modal.legendre import displacement

        phi = np.linspace(0.0, math.pi, curve_points)
        series = model.backends["legendre"].series
        curves["legendre"] = (phi, displacement(series, times / scale.time, phi) * scale.length)
    if "fem" in model.backends:
        curves["fem"] = (node_polar_angles(model.mesh), model.nodal("fem", times, 0))
    if not curves:
        raise ParameterError("--backend", "at least one of fem, legendre")
    values = np.concatenate([u[1:].ravel() for _, u in curves.values()]) * 1e3
    if offset_mm is None:
        spread = float(np.percentile(np.abs(values), 99.5)) if values.size else 1.0
        offset_mm = 1.5 * spread if spread > 0 else 1.0
    if not (math.isfinite(offset_mm) and offset_mm > 0):
        raise ParameterError("--offset", "a number > 0 [mm]", offset_mm)
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
            fontsize=7,
        )
    axis.axvline(model.case.phi_a, color="grey", linewidth=0.7, linestyle=":")
    axis.set_xlim(0.0, math.pi)
    axis.set_xticks(np.linspace(0.0, math.pi, 5), ["0", "π/4", "π/2", "3π/4", "π"])
    axis.set_xlabel("polar angle φ [rad] (0: top, where the upper body rests)")
    axis.set_ylabel(f"u(t, φ) [mm], curves shifted by {offset_mm:.3g} mm per instant")
    axis.set_ylim(_waterfall_limits(curves, offset_mm, len(times)))
    axis.legend(loc="upper left", fontsize=8, markerscale=5)
    case = model.case
    axis.set_title(
        f"Radial displacement at {len(times)} instants (cf. Fig. 6): φa = {case.phi_a:.3g}, "
        f"R = {case.radius:g} m, c = {case.wave_speed:g} 1/s, D = {case.damping:g}",
        fontsize=9,
    )
    axis.grid(True, axis="x", alpha=0.3)
    return figure


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


# --------------------------------------------------------------------------- pole motion
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
    figure = Figure(figsize=(7.5, 8.0), layout="constrained")
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


# --------------------------------------------------------------------------- eigenvalues
@dataclass(frozen=True)
class EigenTable:
    """Finite-element eigenvalues grouped by spherical-harmonic degree l (dimensionless).

    Attributes
    ----------
    label : str
        Discretisation, e.g. ``"P1, level 3 (642 dofs)"``.
    degrees : ndarray, shape (L + 1,)
        l = 0 .. L.
    errors : ndarray, shape (L + 1,)
        Largest relative error ``|lambda_h - l (l + 1)| / (l (l + 1))`` over the
        2 l + 1 discrete eigenvalues of degree l (absolute error for l = 0).
    """

    label: str
    degrees: np.ndarray
    errors: np.ndarray


def eigen_table(level: int, order: int, max_degree: int | None = None) -> EigenTable:
    """Eigenvalues of the icosphere discretisation against ``l (l + 1)``, eq. (3.11).

    The ``(L + 1)^2`` smallest eigenvalues of ``K phi = lambda M phi`` on the unit
    sphere are grouped in clusters of ``2 l + 1`` (the multiplicity of degree l).
    ``max_degree`` defaults to the degree at which ``(L + 1)^2`` reaches half the
    number of unknowns, capped at 30.
    """
    from twoball.fem_membrane.build import build_space
    from twoball.fem_membrane.eigen import lowest_eigenpairs

    space = build_space("sphere", level=level, order=order)
    n = space.dofs
    if max_degree is None:
        max_degree = min(30, int(math.isqrt(n // 2)) - 1)
    if isinstance(max_degree, bool) or int(max_degree) != max_degree or max_degree < 1:
        raise ParameterError("--max-degree", "an integer >= 1", max_degree)
    if (max_degree + 1) ** 2 > n:
        raise ParameterError(
            "--max-degree", f"at most {math.isqrt(n) - 1} on this mesh ({n} unknowns)", max_degree
        )
    values = lowest_eigenpairs(space.stiffness, space.mass, (max_degree + 1) ** 2).values
    degrees = np.arange(max_degree + 1)
    errors = np.empty(degrees.size)
    for degree in degrees:
        cluster = values[degree * degree : (degree + 1) * (degree + 1)]
        exact = degree * (degree + 1.0)
        errors[degree] = np.abs(cluster - exact).max() / (exact if exact > 0 else 1.0)
    return EigenTable(f"P{order}, level {level} ({n} unknowns)", degrees, errors)


def eigen_figure(tables: Sequence[EigenTable]) -> Figure:
    """Relative eigenvalue error against the degree l, one line per discretisation (log scale)."""
    figure = Figure(figsize=(7.0, 4.6), layout="constrained")
    axis = figure.subplots()
    markers = "osd^v<>ph"
    for k, table in enumerate(tables):
        errors = np.where(table.errors > 0, table.errors, np.nan)
        axis.semilogy(
            table.degrees[1:],
            errors[1:],
            marker=markers[k % len(markers)],
            markersize=3,
            linewidth=1.0,
            label=table.label,
        )
    axis.set_xlabel("degree l (eigenvalue l(l+1), multiplicity 2l+1)")
    axis.set_ylabel("max |λ_h − l(l+1)| / (l(l+1))")
    axis.grid(True, which="both", alpha=0.3)
    axis.legend(fontsize=8)
    axis.set_title(
        "Finite-element eigenvalues of the unit sphere against l(l+1), eq. (3.11)", fontsize=10
    )
    return figure
