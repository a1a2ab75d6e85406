"""PNG plots of the verification report and of the convergence studies (SI units).

Only :class:`matplotlib.figure.Figure` is used (no pyplot, no global state), so
the plots can be drawn from any thread and never open a window.  matplotlib is
imported on first use, keeping ``twoball`` quick to start.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path

import numpy as np
from twoball.modal.liftoff import PoleMotion
from twoball.modal.parameters import Case
from twoball.verify.studies.result import StudyResult

DPI = 120


def _figure(width: float, height: float):
    """A constrained-layout matplotlib Figure (imported lazily)."""
    from matplotlib.figure import Figure

    return Figure(figsize=(width, height), layout="constrained")


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


def plot_pole_motion(
    path: Path, case: Case, traces: Sequence[Trace], t_end: float, samples: int = 3000
) -> None:
    """Pole displacement, velocity and acceleration against time, every backend overlaid.

    Lift-off is marked by a dot on each curve and a dashed vertical line; the
    acceleration panel shows ``-g`` (criterion (i) of §3(a)).
    """
    scale = case.scalings
    t = np.linspace(0.0, t_end, samples)
    fig = _figure(8.0, 8.5)
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
    fig.savefig(path, dpi=DPI)


@dataclass(frozen=True)
class EigenErrors:
    """Relative eigenvalue errors of one discretisation against ``l (l + 1)``.

    ``degrees`` are the l of each entry, ``errors`` the largest relative error
    over the 2l + 1 discrete eigenvalues of that degree (one on the axisymmetric line).
    """

    label: str
    degrees: np.ndarray
    errors: np.ndarray


def plot_eigen_errors(path: Path, tables: Sequence[EigenErrors]) -> None:
    """Relative eigenvalue error against the degree l for each discretisation (log scale)."""
    fig = _figure(7.0, 4.5)
    axis = fig.subplots()
    for table in tables:
        errors = np.where(table.errors > 0, table.errors, np.nan)
        axis.semilogy(table.degrees, errors, marker="o", markersize=3, label=table.label)
    axis.set_xlabel("degree l")
    axis.set_ylabel("max |lambda_h - l(l+1)| / (l(l+1))")
    axis.grid(True, which="both", alpha=0.3)
    if tables:
        axis.legend(fontsize=8)
    axis.set_title("Eigenvalue error of the finite elements against l(l+1)")
    fig.savefig(path, dpi=DPI)


def plot_energy(
    path: Path,
    case: Case,
    curves: Sequence[tuple[str, np.ndarray, np.ndarray]],
    bound: tuple[np.ndarray, np.ndarray] | None = None,
) -> None:
    """Energy (unit T R^2) against time [ms] on a log scale, with the modal decay bound."""
    fig = _figure(7.0, 4.5)
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
    fig.savefig(path, dpi=DPI)


def plot_study(path: Path, study: StudyResult) -> None:
    """Log-log errors against the step h for every quantity, with its expected slope.

    The reference slope of each quantity with an expected order is drawn dotted,
    parallel to the data and a factor 3 below its finest point.
    """
    from matplotlib import colormaps

    fig = _figure(7.5, 5.5)
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
    fig.savefig(path, dpi=DPI)


def _short(text: str, width: int = 70) -> str:
    return text if len(text) <= width else text[: width - 1] + "..."
