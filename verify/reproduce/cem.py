"""Reproduction of the continuum elastic model results: Figs. 6, 10, 11, 12 and §5 thresholds.

Each ``part_*`` function computes one group, draws its figure(s) into the output
directory and returns a :class:`~twoball.verify.reproduce.common.Section`.  Work that is
a list of independent solves goes through the context's runner, so it runs
serially, on local processes or on Dask with the same numbers.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np
from scipy.optimize import brentq, minimize_scalar
from twoball.modal.filters import SpectralFilter
from twoball.modal.initial import phi_a_from_v0, v0_dimensionless
from twoball.modal.legendre import (
    displacement,
    legendre_coefficients,
    legendre_coefficients_recurrence,
    legendre_series,
    quadrature_points,
)
from twoball.modal.parameters import STANDARD_GRAVITY, Case, preset
from twoball.verify.reproduce.common import (
    MAX_QUADRATURE_POINTS,
    Comparison,
    Context,
    Section,
    Threshold,
    acceleration_minima,
    find_threshold,
    fmt,
    liftoff,
    markdown_table,
    new_figure,
    save,
)
from twoball.verify.sweeps.parallel import Outcome
from twoball.verify.sweeps.sweeps import SweepSolver, run_sweep

G = STANDARD_GRAVITY

# --- the lift-off criteria compared in Fig. 11(a) and the thresholds ----------------

CRITERIA: dict[str, str] = {
    "overall": "criterion (i) alone: min u_tt(t, 0) over the whole window (t = 0 included) < -g",
    "moving_up": "criterion (i) while the pole moves up: min u_tt where u_t > 0 < -g",
    "main_wave": "criterion (i) on the main wave: min u_tt for t >= 5 ms < -g",
    "paper": "criteria (i) + (ii), re-contact checked for dt < t_l (`paper` horizon)",
    "window": "criteria (i) + (ii), re-contact checked to the window's end (`window`, default)",
}


@dataclass(frozen=True)
class CriterionTest:
    """Picklable yes/no: does ``case`` lift off under ``criterion`` (see CRITERIA)?"""

    criterion: str
    sigma: str = "lanczos"

    def __call__(self, case: Case) -> bool:
        if self.criterion in ("paper", "window"):
            return liftoff(case, self.criterion, self.sigma).result.lifted
        minima = acceleration_minima(case, self.sigma)
        value = getattr(minima, self.criterion)
        return value is not None and value < -case.g


@dataclass(frozen=True)
class ThresholdTask:
    """Picklable bisection of the no-lift-off boundary of one parameter (Case field)."""

    base: Case
    field: str
    criterion: str
    lo: float
    hi: float
    log: bool
    lifts_above: bool
    scan_points: int = 21
    rtol: float = 1e-5
    sigma: str = "lanczos"

    def __call__(self) -> Threshold:
        test = CriterionTest(self.criterion, self.sigma)
        return find_threshold(
            lambda x: test(self.base.derive(**{self.field: x})),
            self.lo,
            self.hi,
            lifts_above=self.lifts_above,
            log=self.log,
            scan_points=self.scan_points,
            rtol=self.rtol,
        )


def call(task: Any) -> Any:
    """Run a picklable zero-argument task (for Runner.map)."""
    return task()


def minima_task(case: Case):
    """Acceleration minima of one case (for Runner.map)."""
    return acceleration_minima(case)


def _value(outcome: Outcome) -> Any:
    return outcome.value if outcome.ok else None


def _run(ctx: Context, label: str, func, items, heavy: bool = False) -> list[Outcome]:
    """Map through the context's runner; ``heavy`` tasks (bisections) go one per message."""
    update = ctx.progress(label, len(items))
    if heavy:
        return ctx.runner.map(func, items, update, min_parallel=2, chunk=1)
    return ctx.runner.map(func, items, update)


# --- Fig. 6 -----------------------------------------------------------------------


def part_fig6(ctx: Context) -> Section:
    """Waterfall of u(phi) at 24 instants, basketball case with D = 0.1 (Fig. 6 caption)."""
    case = preset("basketball").derive(damping=0.1)
    series = legendre_series(case.phi_a, case.damping, SpectralFilter("lanczos", case.modes))
    phi = np.linspace(0.0, math.pi, 361)
    t_ms = np.linspace(0.0, 11.5, 24)
    t = t_ms * 1e-3 / case.scalings.time
    u_mm = displacement(series, t, phi) * case.radius * 1e3
    fig, ax = new_figure(figsize=(7.5, 5.5), subplot_kw={"projection": "3d"})
    for k in range(len(t)):
        ax.plot(phi, np.full_like(phi, t_ms[k]), u_mm[k], lw=0.9, color=f"C{k % 10}")
    ax.set_xlabel("polar angle phi [rad]")
    ax.set_ylabel("t [ms]")
    ax.set_zlabel("u [mm]")
    ax.view_init(elev=28, azim=-62)
    ax.set_title("Radial displacement u(t, phi): phi_a = 2.6, R = 0.12 m, c = 320 1/s, D = 0.1")
    name = save(ctx, fig, "fig06_waterfall.png")
    report = liftoff(case)
    pole = u_mm[:, 0]
    sec = Section("fig6", "Fig. 6: waterfall of the radial displacement")
    sec.figures.append(
        (name, "u(t, phi) in mm at 24 instants 0, 0.5, ..., 11.5 ms (N = 30, Lanczos filter).")
    )
    sec.paragraphs += [
        "Parameters as in the caption of Fig. 6: phi_a = 2.6, R = 0.12 m, |v0| = 4.1 m/s, "
        "c = 320 1/s, D = 0.1, N = 30.  The caption does not give the instants; we use 24 "
        "evenly spaced ones from 0 to 11.5 ms, which covers the flattened cap at t = 0, the "
        "wave running up the sphere and its arrival at the pole (phi = 0) near 10 ms.",
        f"The figure states no number to compare.  For reference, this case lifts off at "
        f"t_l = {1e3 * report.t_liftoff_s:.3f} ms with v_l = {report.v_liftoff_m_s:.3f} m/s "
        f"(default `window` horizon); the pole displacement at 11.5 ms is {pole[-1]:.2f} mm, "
        f"and its largest upward excursion over the plotted instants is {pole.max():.2f} mm.",
    ]
    sec.data = {
        "t_ms": t_ms.tolist(),
        "pole_u_mm": pole.tolist(),
        "t_liftoff_s": report.t_liftoff_s,
        "v_liftoff_m_s": report.v_liftoff_m_s,
    }
    return sec


# --- Fig. 10 ----------------------------------------------------------------------


def part_fig10(ctx: Context) -> Section:
    """phi_a against v0 from eq. (3.7) for c = 220, 320, 350 1/s, R = 0.12 m."""
    radius = 0.12
    v0 = np.linspace(0.05, 8.0, 400)
    fig, ax = new_figure(figsize=(6.4, 4.6))
    for c, style in ((220.0, "--"), (320.0, "-"), (350.0, ":")):
        phi = [phi_a_from_v0(v, radius, c) for v in v0]
        ax.plot(v0, phi, style, label=f"c = {c:g} 1/s")
    ax.plot([4.1], [2.6], "o", color="red", label="basketball: |v0| = 4.1 m/s, phi_a = 2.6")
    ax.set_xlabel("impact speed |v0| [m/s]")
    ax.set_ylabel("contact angle phi_a [rad]")
    ax.set_title("Eq. (3.7), R = 0.12 m")
    ax.grid(True, alpha=0.3)
    ax.legend()
    name = save(ctx, fig, "fig10_phi_a_vs_v0.png")

    phi_320 = phi_a_from_v0(4.1, radius, 320.0)
    c_implied = 4.1 / (radius * v0_dimensionless(2.6))
    lower = math.pi / 0.014
    upper = math.pi / 0.009
    sec = Section("fig10", "Fig. 10: contact angle against impact speed, eq. (3.7)")
    sec.figures.append((name, "phi_a(|v0|) from eq. (3.7) for c = 220, 320 and 350 1/s."))
    sec.comparisons += [
        Comparison(
            "phi_a for |v0| = 4.1 m/s, c = 320 1/s",
            2.6,
            phi_320,
            "rad",
            "§4(b), Table 2",
            "The paper's 2.6 is measured ('around 2.6'); eq. (3.7) gives 0.28 % less.",
        ),
        Comparison(
            "c that puts (4.1 m/s, 2.6) exactly on eq. (3.7)",
            320.0,
            c_implied,
            "1/s",
            "Fig. 10",
            f"The measured point lies on the curve of a {100 * abs(c_implied / 320 - 1):.1f} % "
            f"{'larger' if c_implied > 320 else 'smaller'} c.",
        ),
        Comparison(
            "lower bound of c, pi / 0.014 s",
            220.0,
            lower,
            "1/s",
            "§4(b)",
            "The wave crosses pi rad (bottom to top) in the longest measured t_l; "
            "the paper rounds.",
        ),
        Comparison(
            "upper bound of c, pi / 0.009 s",
            350.0,
            upper,
            "1/s",
            "§4(b)",
            "Same, with the shortest measured t_l.",
        ),
    ]
    sec.paragraphs.append(
        "The measured scatter of Fig. 10 is not available to us, so only the theory curves "
        "and the basketball point of Table 2 are drawn.  Reading the bounds as the time for "
        "the wave to travel from phi = pi to phi = 0 reproduces the paper's 220 and 350 1/s "
        "to within its rounding."
    )
    return sec


# --- Fig. 11 ----------------------------------------------------------------------

N_LIST = (10, 20, 30, 40, 60)
D_CAPTION = np.round(np.linspace(0.600, 0.609, 10), 3)
D_WIDE = np.round(np.linspace(0.0, 0.99, 100), 4)
D_LIFTOFF = np.round(np.linspace(0.0, 0.6, 121), 4)


def _fit_damping(target: float) -> float:
    """D at which the default lift-off velocity equals ``target`` [m/s] (N = 30)."""
    base = preset("basketball")

    def residual(d: float) -> float:
        v = liftoff(base.derive(damping=d)).v_liftoff_m_s
        return (0.0 if v is None else v) - target

    return brentq(residual, 0.10, 0.20, xtol=1e-7)


def part_fig11(ctx: Context) -> Section:
    """Minimum pole acceleration against D (a); v_l and t_l against D (b); D thresholds."""
    base = preset("basketball")
    # (a) acceleration minima for several N
    grid = [(n, d) for n in N_LIST for d in (*D_CAPTION, *D_WIDE)]
    cases = [base.derive(damping=float(d), modes=n) for n, d in grid]
    minima = _run(ctx, "Fig. 11(a): pole acceleration minima", minima_task, cases)
    table: dict[tuple[int, float], Any] = {
        (n, float(d)): _value(o) for (n, d), o in zip(grid, minima, strict=True)
    }
    # (b) lift-off against D at N = 30, both horizons
    d_cases = [base.derive(damping=float(d)) for d in D_LIFTOFF]
    window = run_sweep(
        d_cases,
        SweepSolver("lanczos", "window"),
        ctx.progress("Fig. 11(b): lift-off vs D (window)", len(d_cases)),
        runner=ctx.runner,
    )
    paper = run_sweep(
        d_cases,
        SweepSolver("lanczos", "paper"),
        ctx.progress("Fig. 11(b): lift-off vs D (paper)", len(d_cases)),
        runner=ctx.runner,
    )
    # damping thresholds
    tasks = [
        ThresholdTask(base.derive(modes=n), "damping", crit, 0.0, 0.99, False, False, 34, 1e-5)
        for crit in ("overall", "moving_up", "main_wave")
        for n in N_LIST
    ] + [
        ThresholdTask(base, "damping", crit, 0.0, 0.99, False, False, 34, 1e-5)
        for crit in ("paper", "window")
    ]
    outs = _run(ctx, "Fig. 11: damping thresholds (bisection)", call, tasks, heavy=True)
    thresholds = {(t.criterion, t.base.modes): _value(o) for t, o in zip(tasks, outs, strict=True)}
    fitted = _fit_damping(3.7)
    at_013 = liftoff(base)
    undamped = liftoff(base.derive(damping=0.0))

    names = [_plot_fig11a(ctx, table), _plot_fig11b(ctx, window, paper, at_013)]
    sec = Section("fig11", "Fig. 11: damping, lift-off and the no-lift-off threshold")
    sec.figures += [
        (
            names[0],
            "(a) Smallest pole acceleration over the window against D for several N: whole "
            "window (solid) and only while the pole moves up (dashed); the horizontal line "
            "is -g.  Left: the caption's range 0.600-0.609; right: 0-0.99 (symlog scale).",
        ),
        (
            names[1],
            "(b) v_l and t_l against D at N = 30 (default `window` horizon, solid; the "
            "`paper` horizon, dotted); the red dot is D = 0.13.",
        ),
    ]
    th = {k: (v.value if v is not None else None) for k, v in thresholds.items()}
    sec.comparisons += [
        Comparison(
            "v_l at D = 0.13 (N = 30)",
            3.7,
            at_013.v_liftoff_m_s,
            "m/s",
            "§4(b), Fig. 11(b)",
            "3.7 m/s is the measured value D was fitted to ('around').",
        ),
        Comparison(
            "t_l at D = 0.13 (N = 30)",
            0.0099,
            at_013.t_liftoff_s,
            "s",
            "§4(b)",
            "Agrees to the paper's two digits.",
        ),
        Comparison(
            "D that gives v_l = 3.7 m/s",
            0.13,
            fitted,
            "",
            "§4(b)",
            "Our curve is slightly above the paper's, so the same 3.7 m/s needs a little more "
            "damping; with N = 30 the velocity is also ~3 % below its converged value "
            "(docs/theory.rst).",
        ),
        Comparison(
            "v_l / |v0| without damping (D = 0)",
            4.5,
            undamped.ratio,
            "",
            "§6",
            "'around 4.5'; the undamped series does not converge in N (docs/theory.rst).",
            3,
        ),
    ]
    for crit, note in (
        (
            "overall",
            "No threshold: the whole-window minimum stays below -g up to D = 0.99 (see text).",
        ),
        ("moving_up", "Closest analogue of Fig. 11(a); see text."),
        ("main_wave", "The main wave alone keeps u_tt < -g to much higher damping."),
        ("paper", "Full criteria with the literal dt < t_l horizon."),
        ("window", "Full criteria, default horizon: the slow main-wave launch is re-caught."),
    ):
        sec.comparisons.append(
            Comparison(
                f"D above which no lift-off: {crit} (N = 30)",
                0.602,
                th.get((crit, 30)),
                "",
                "Fig. 11(a); §6 says 0.6066",
                note,
            )
        )
    sec.tables.append(_threshold_table_d(thresholds))
    sec.tables.append(_caption_range_table(table))
    sec.paragraphs += _fig11_text(table, thresholds, window, paper)
    sec.data = {
        "v_l_at_0.13": at_013.v_liftoff_m_s,
        "t_l_at_0.13": at_013.t_liftoff_s,
        "fitted_damping": fitted,
        "undamped_ratio": undamped.ratio,
        "damping_thresholds": {
            f"{c}/N={n}": (None if v is None else v.value) for (c, n), v in thresholds.items()
        },
        "liftoff_vs_damping": [
            {
                "damping": float(d),
                "window_v_m_s": w.v_liftoff_m_s,
                "window_t_s": w.t_liftoff_s,
                "paper_v_m_s": p.v_liftoff_m_s,
                "paper_t_s": p.t_liftoff_s,
            }
            for d, w, p in zip(D_LIFTOFF, window, paper, strict=True)
        ],
    }
    return sec


def _threshold_table_d(thresholds: dict) -> str:
    rows = []
    for crit in CRITERIA:
        for n in N_LIST:
            t = thresholds.get((crit, n))
            if t is None and (crit, n) not in thresholds:
                continue
            rows.append([crit, str(n), _threshold_text(t, 4), CRITERIA[crit]])
    return "Damping above which no lift-off is found (bisection, relative tolerance 1e-5):\n\n" + (
        markdown_table(["criterion", "N", "D threshold", "meaning"], rows)
    )


def _threshold_text(t: Threshold | None, digits: int) -> str:
    if t is None:
        return "error"
    if t.value is None:
        return "no change in range"
    text = f"{t.value:.{digits}g}"
    if len(t.transitions) > 1:
        text += f" ({len(t.transitions)} changes on the scan)"
    if t.errors:
        text += f" ({len(t.errors)} failed evaluations)"
    return text


def _caption_range_table(table: dict) -> str:
    rows = []
    for d in D_CAPTION:
        cells = [f"{d:.3f}"]
        for n in N_LIST:
            m = table.get((n, float(d)))
            cells.append("-" if m is None else f"{m.overall:.1f} / {fmt(m.moving_up, 4)}")
        rows.append(cells)
    return (
        "Smallest pole acceleration [m/s^2] in the caption's range of D, "
        "whole window / while moving up (compare with -g = -9.81):\n\n"
        + markdown_table(["D", *(f"N = {n}" for n in N_LIST)], rows)
    )


def _fig11_text(table, thresholds, window, paper) -> list[str]:
    def v(c, n=30):
        t = thresholds.get((c, n))
        return None if t is None else t.value

    initial = {n: table[(n, 0.6)].initial for n in N_LIST if table.get((n, 0.6)) is not None}
    sinking = acceleration_minima(preset("basketball").derive(damping=0.99), main_wave_from_s=1e-3)
    hops = [p for p in paper if p.report is not None and p.t_liftoff_s < 2e-3]
    main = [p for p in paper if p.report is not None and p.t_liftoff_s >= 2e-3]
    switch = min((p.case.damping for p in main), default=None)
    lo, hi = table.get((30, 0.6)), table.get((30, 0.609))
    return [
        "Fig. 11(a) plots 'the minimum acceleration' of the pole and reads off the damping "
        "above which it no longer reaches -g.  In our model the answer depends strongly on "
        "which part of the motion the minimum is taken over, so we report five readings, "
        "each found by bisection on D (tables below):",
        "1. *Whole window* (criterion (i) alone, literally): no threshold below D = 0.99 for "
        "any N.  The truncated series starts with a nonzero pole acceleration, independent "
        "of D (a truncation artefact, docs/theory.rst): "
        + ", ".join(f"{a:+.0f} m/s^2 at N = {n}" for n, a in initial.items())
        + ".  Where it is below -g (N = 20, 30, 40) it is the minimum.  Besides, at heavy "
        "damping the pole sinks towards the mean displacement a_0 < 0 as the modes die out, "
        "and that alone accelerates it downwards by more than g (N = 30, D = 0.99, after "
        f"the first millisecond: {sinking.main_wave:.1f} m/s^2 at "
        f"{1e3 * sinking.t_main_wave:.2f} ms).",
        "2. *While the pole moves up* (criterion (i) with the first half of criterion (ii), "
        "v_l > 0, but no re-contact test): "
        + ", ".join(f"D = {fmt(v('moving_up', n), 4)} at N = {n}" for n in (20, 30, 40))
        + ".  This is the reading closest to the paper's 0.602 (Fig. 11) and 0.6066 (§6), "
        f"{100 * (v('moving_up') / 0.602 - 1):.1f} % and "
        f"{100 * (v('moving_up') / 0.6066 - 1):.1f} % above them at N = 30.  At N = 10 and "
        "60 early ringing of the truncated series, moving upwards, keeps it below -g at "
        "every D.  We have not found what accounts for the remaining few per cent: the "
        "paper does not say over which times its minimum was taken, and the other filters "
        "only add ringing (docs/theory.rst).",
        f"3. *Main wave only* (t >= 5 ms): D = {fmt(v('main_wave'), 4)} at N = 30, as "
        "docs/theory.rst found.  Between readings 2 and 3 the pole's acceleration after "
        "5 ms still drops below -g, but only while the pole moves downwards, so no upward "
        "launch can result.",
        f"4. *Full criteria, `paper` horizon* (re-contact checked only for dt < t_l): "
        f"D = {fmt(v('paper'), 4)}.  For D below {fmt(switch, 3)} this horizon accepts a "
        f"micro-hop produced by the truncation ringing at ~0.5 ms ({len(hops)} of the "
        f"{len(paper)} points of Fig. 11(b) lift off before 2 ms, with v_l of order "
        "0.01 m/s), so its curve in (b) (dotted) is not the main wave's.",
        f"5. *Full criteria, default `window` horizon*: D = {fmt(v('window'), 4)}.  Above "
        "it the main wave still launches the body upwards (reading 2) but so slowly that the "
        "pole catches it again before the end of the 4 pi / c window, so the default "
        "horizon stops lifting off well below the paper's value.",
        "In the caption's range (0.600-0.609) at N = 30 the whole-window minimum is the "
        f"initial value ({fmt(None if lo is None else lo.overall, 4)} m/s^2) throughout; "
        "the minimum while moving up rises from "
        f"{fmt(None if lo is None else lo.moving_up, 4)} to "
        f"{fmt(None if hi is None else hi.moving_up, 4)} m/s^2, still below -g, and crosses "
        f"-g at D = {fmt(v('moving_up'), 4)}.",
    ]


def _plot_fig11a(ctx: Context, table: dict) -> str:
    fig, axes = new_figure(1, 2, figsize=(12.0, 4.8))
    for k, n in enumerate(N_LIST):
        for ax, ds in ((axes[0], D_CAPTION), (axes[1], D_WIDE)):
            ms = [table.get((n, float(d))) for d in ds]
            overall = [np.nan if m is None else m.overall for m in ms]
            up = [np.nan if m is None or m.moving_up is None else m.moving_up for m in ms]
            ax.plot(ds, overall, "-", color=f"C{k}", label=f"N = {n}, whole window")
            ax.plot(ds, up, "--", color=f"C{k}", label=f"N = {n}, moving up")
    for ax in axes:
        ax.axhline(-G, color="k", lw=1.2)
        ax.set_xlabel("damping ratio D")
        ax.set_ylabel("min pole acceleration [m/s^2]")
        ax.grid(True, alpha=0.3)
    axes[1].set_yscale("symlog", linthresh=10.0)
    axes[0].set_title("D = 0.600 ... 0.609 (caption of Fig. 11(a))")
    axes[1].set_title("D = 0 ... 0.99")
    axes[1].legend(fontsize=7, ncol=2)
    return save(ctx, fig, "fig11a_min_acceleration.png")


def _plot_fig11b(ctx: Context, window, paper, at_013) -> str:
    fig, axes = new_figure(2, 1, figsize=(6.4, 6.4), sharex=True)
    d = D_LIFTOFF
    axes[0].plot(d, [p.v_liftoff_m_s for p in window], "-", label="window horizon")
    axes[0].plot(d, [p.v_liftoff_m_s for p in paper], ":", label="paper horizon")
    axes[1].plot(d, [1e3 * p.t_liftoff_s for p in window], "-", label="window horizon")
    axes[1].plot(d, [1e3 * p.t_liftoff_s for p in paper], ":", label="paper horizon")
    axes[0].plot([0.13], [at_013.v_liftoff_m_s], "o", color="red", label="D = 0.13")
    axes[1].plot([0.13], [1e3 * at_013.t_liftoff_s], "o", color="red")
    axes[0].set_ylabel("v_l [m/s]")
    axes[0].set_yscale("log")
    axes[1].set_ylabel("t_l [ms]")
    axes[1].set_xlabel("damping ratio D")
    axes[0].legend()
    for ax in axes:
        ax.grid(True, alpha=0.3)
    axes[0].set_title("|v0| = 4.1 m/s, phi_a = 2.6, R = 0.12 m, c = 320 1/s, N = 30")
    return save(ctx, fig, "fig11b_liftoff_vs_damping.png")


# --- Fig. 12 ----------------------------------------------------------------------

FIG12_DAMPING = (0.0, 0.05, 0.13, 0.3)
FIG12_AXES: dict[str, tuple[str, np.ndarray, str]] = {
    "v0": ("v0", np.linspace(0.1, 20.0, 100), "impact speed |v0| [m/s]"),
    "c": ("wave_speed", np.linspace(20.0, 600.0, 100), "wave speed c [1/s]"),
    "R": ("radius", np.linspace(0.01, 0.3, 100), "radius R [m]"),
}
FIG12_PAPER_OPTIMUM = {"v0": 8.7, "c": 180.0, "R": 0.075}
FIG12_UNITS = {"v0": "m/s", "c": "1/s", "R": "m"}


@dataclass(frozen=True)
class OptimumTask:
    """Picklable refinement of the largest ``v_l/|v0|`` between two grid neighbours."""

    base: Case
    field: str
    lo: float
    hi: float

    def __call__(self) -> tuple[float, float]:
        def negative_ratio(x: float) -> float:
            report = liftoff(self.base.derive(**{self.field: x}))
            if report.ratio is None or report.result.t < EARLY:
                return 0.0
            return -report.ratio

        res = minimize_scalar(
            negative_ratio,
            bounds=(self.lo, self.hi),
            method="bounded",
            options={"xatol": 1e-6 * (self.hi - self.lo) + 1e-12},
        )
        return float(res.x), float(-res.fun)


#: Lift-offs before this dimensionless time (1/c seconds) come from the truncation's
#: ringing, not from the main wave (which needs about pi to reach the pole).
EARLY = 1.0


def _early(point) -> bool:
    return point.report is not None and point.report.result.lifted and point.report.result.t < EARLY


def main_branch(points) -> np.ndarray:
    """``v_l/|v0|`` of the points, NaN where there is no lift-off or it is an early one."""
    return np.array([np.nan if _early(p) else p.ratio for p in points])


def fig12_base() -> Case:
    """The basketball case with phi_a from eq. (3.7) (as in §5), not the measured 2.6.

    Without a preset, every case derived from it (the Fig. 12 sweeps over v0, c and
    R, the threshold searches) takes phi_a from eq. (3.7), also at 4.1 m/s, 320 1/s,
    0.12 m, where the basketball preset would take its measured angle.
    """
    return preset("basketball").derive(preset_name=None)


def fig12_sweeps(ctx: Context) -> dict[tuple[str, float], list]:
    """The 3 x 4 x 100 solves of Fig. 12, as sweep points keyed by (panel, D)."""
    base = fig12_base()
    keys, cases = [], []
    for panel, (field, values, _) in FIG12_AXES.items():
        for d in FIG12_DAMPING:
            for x in values:
                keys.append((panel, d))
                cases.append(base.derive(damping=d, **{field: float(x)}))
    points = run_sweep(
        cases,
        SweepSolver("lanczos", "window"),
        ctx.progress(f"Fig. 12: {len(cases)} solves", len(cases)),
        runner=ctx.runner,
    )
    out: dict[tuple[str, float], list] = {}
    for key, point in zip(keys, points, strict=True):
        out.setdefault(key, []).append(point)
    return out


def part_fig12(ctx: Context) -> Section:
    """``v_l/|v0|`` against v0, c and R for D = 0, 0.05, 0.13, 0.3; optimum for D = 0.13."""
    import time

    base = fig12_base()
    start = time.perf_counter()
    sweeps = fig12_sweeps(ctx)
    sweep_seconds = time.perf_counter() - start
    tasks, keys, at_end = [], [], set()
    for (panel, d), points in sweeps.items():
        field, values, _ = FIG12_AXES[panel]
        ratio = main_branch(points)
        if not np.isfinite(ratio).any():
            continue
        k = int(np.nanargmax(ratio))
        lo, hi = values[max(k - 1, 0)], values[min(k + 1, len(values) - 1)]
        tasks.append(OptimumTask(base.derive(damping=d), field, float(lo), float(hi)))
        keys.append((panel, d, float(values[k]), float(ratio[k])))
        if k in (0, len(values) - 1):
            at_end.add((panel, d))
    outs = _run(ctx, "Fig. 12: optima (bounded search)", call, tasks, heavy=True)
    optima = {}
    for (panel, d, x_grid, r_grid), o in zip(keys, outs, strict=True):
        x, r = o.value if o.ok else (x_grid, r_grid)
        if r < r_grid:  # the search stays between the neighbours; keep the better
            x, r = x_grid, r_grid
        optima[(panel, d)] = (x, r)
    dot = liftoff(base)
    name = _plot_fig12(ctx, sweeps, optima, dot)

    sec = Section("fig12", "Fig. 12: parameter dependence and the optimum")
    sec.figures.append(
        (
            name,
            "v_l/|v0| against |v0|, c and R (phi_a from eq. (3.7)) for D = 0, 0.05, 0.13, "
            "0.3; crosses mark each curve's maximum, the red dot the basketball case.",
        )
    )
    errors = sum(p.error is not None for pts in sweeps.values() for p in pts)
    early = {k: [p for p in pts if _early(p)] for k, pts in sweeps.items()}
    early = {k: v for k, v in early.items() if v}
    total = sum(len(p) for p in sweeps.values())
    sec.paragraphs.append(
        f"Ranges used (the paper's axes are not known exactly): |v0| from 0.1 to 20 m/s, c "
        f"from 20 to 600 1/s, R from 0.01 to 0.3 m, 100 evenly spaced points each; the other "
        f"parameters are the basketball's (R = 0.12 m, c = 320 1/s, |v0| = 4.1 m/s, N = 30), "
        f"with phi_a from eq. (3.7) at every point, `window` horizon.  {total} solves in "
        f"{sweep_seconds:.1f} s ({ctx.runner.describe()}); {errors} failed.  Each maximum is "
        "refined by a bounded scalar search between the grid neighbours of the best point."
    )
    if early:
        parts = []
        for (panel, d), pts in early.items():
            field = FIG12_AXES[panel][0]
            xs = [getattr(p.case, field) for p in pts]
            parts.append(
                f"{len(pts)} points of the {panel} panel at D = {d:g} "
                f"({panel} from {min(xs):.4g} to {max(xs):.4g})"
            )
        sec.paragraphs.append(
            "Early lift-offs: "
            + "; ".join(parts)
            + " accept a lift-off before t = 1/c, long before the main wave can reach the "
            "pole (t ~ pi/c).  It is the truncation's ringing that launches the body there, "
            "and with such large deformations the pole then sinks away faster than the body "
            "falls, so neither horizon rejects it.  These points are drawn as dots, left out "
            "of the curves and of the maxima."
        )
    _, r_opt_v0 = optima[("v0", 0.13)]
    sec.comparisons.append(
        Comparison(
            "largest v_l/|v0|, D = 0.13 (|v0| panel)",
            1.02,
            r_opt_v0,
            "",
            "§5",
            "'around 1.02'.  The same maximum appears in all three panels (next rows).",
            3,
        )
    )
    for panel in ("c", "R"):
        sec.comparisons.append(
            Comparison(
                f"largest v_l/|v0|, D = 0.13 ({panel} panel)",
                1.02,
                optima[(panel, 0.13)][1],
                "",
                "§5",
                "",
                3,
            )
        )
    for panel, paper_x in FIG12_PAPER_OPTIMUM.items():
        x, _ = optima[(panel, 0.13)]
        sec.comparisons.append(
            Comparison(
                f"location of the maximum in {panel}, D = 0.13",
                paper_x,
                x,
                FIG12_UNITS[panel],
                "§5",
                "The maximum is flat (see text); read off a plot by the paper.",
                3,
            )
        )
    v_opt = optima[("v0", 0.13)][0]
    c_opt = optima[("c", 0.13)][0]
    r_opt = optima[("R", 0.13)][0]
    sec.comparisons += [
        Comparison(
            "drop height for the best |v0|, v0^2 / 2g",
            3.8,
            v_opt**2 / (2 * G),
            "m",
            "§5",
            "Follows from the location in |v0|.",
            3,
        ),
        Comparison(
            "best c / measured c",
            0.5,
            c_opt / 320.0,
            "",
            "§5 ('about 1/2')",
            "",
            3,
        ),
        Comparison(
            "best R / measured R",
            2.0 / 3.0,
            r_opt / 0.12,
            "",
            "§5 ('shrinking by around a third')",
            "",
            3,
        ),
        Comparison(
            "basketball dot: v_l/|v0| at |v0| = 4.1, c = 320, R = 0.12, D = 0.13",
            0.9,
            dot.ratio,
            "",
            "Table 2 caption ('approximately 0.9')",
            "phi_a from eq. (3.7) (2.593), not the measured 2.6.",
            3,
        ),
    ]
    scaled = {
        "v0": v_opt / (0.12 * 320.0),
        "c": 4.1 / (0.12 * c_opt),
        "R": 4.1 / (r_opt * 320.0),
    }
    paper_scaled = {
        "v0": 8.7 / (0.12 * 320.0),
        "c": 4.1 / (0.12 * 180.0),
        "R": 4.1 / (0.075 * 320.0),
    }
    sec.paragraphs.append(
        "Why the three optima belong together: with phi_a from eq. (3.7) the dimensionless "
        "problem depends on |v0|, c and R only through |v0| / (R c) (which fixes phi_a) and "
        "gamma = g / (R c^2), and gamma is ~1e-3 here, so it hardly matters.  The three "
        "maxima should therefore sit at one value of |v0| / (R c).  Ours do: "
        + ", ".join(f"{k}: {v:.4f}" for k, v in scaled.items())
        + ".  The paper's three locations give "
        + ", ".join(f"{k}: {v:.3f}" for k, v in paper_scaled.items())
        + ", which differ from each other by up to 30 %, so they were read off flat curves "
        "and are uncertain by that much; all our locations lie within that spread "
        "(the paper's c, 180 1/s, agrees with ours to 1 %)."
    )
    rows = []
    for d in FIG12_DAMPING:
        cells = [f"{d:g}"]
        for panel in FIG12_AXES:
            if (panel, d) in optima:
                x, r = optima[(panel, d)]
                end = " (range end)" if (panel, d) in at_end else ""
                cells.append(f"{r:.4f} at {x:.4g} {FIG12_UNITS[panel]}{end}")
            else:
                cells.append("no lift-off")
        rows.append(cells)
    sec.tables.append(
        "Maximum of v_l/|v0| and its location, per damping ratio ('range end': the curve "
        "still rises at the edge of our range, so the true maximum lies outside it):\n\n"
        + markdown_table(["D", "|v0| panel", "c panel", "R panel"], rows)
    )
    trend = {
        panel: [optima[(panel, d)][0] for d in FIG12_DAMPING if (panel, d) in optima]
        for panel in FIG12_AXES
    }
    rising = all(b >= a for a, b in zip(trend["v0"][:-1], trend["v0"][1:], strict=True))
    falling = all(
        all(b <= a for a, b in zip(trend[p][:-1], trend[p][1:], strict=True)) for p in ("c", "R")
    )
    sec.paragraphs.append(
        "§5 states that with more damping the best c and R decrease and the best |v0| "
        f"increases.  Ours: best |v0| {'increases' if rising else 'does not increase'} "
        f"monotonically with D, best c and R {'decrease' if falling else 'do not decrease'} "
        "(table below; at D = 0 and 0.05 some maxima lie beyond our ranges)."
    )
    c_points = sweeps[("c", 0.13)]
    tc = np.array([p.t_liftoff_s * p.case.wave_speed for p in c_points])
    tc = tc[np.isfinite(tc)]
    if tc.size:
        sec.paragraphs.append(
            f"§5 also notes t_l ~ 1/c: over the c panel (D = 0.13) the product t_l c stays "
            f"between {tc.min():.3f} and {tc.max():.3f} (pi = 3.1416), i.e. the lift-off "
            "happens when the wave has travelled about half-way round and back (the pole is "
            "pi rad from the contact centre)."
        )
    sec.data = {
        "sweep_seconds": sweep_seconds,
        "solves": total,
        "failed": errors,
        "optima": {f"{p}/D={d}": {"x": x, "ratio": r} for (p, d), (x, r) in optima.items()},
        "basketball_ratio": dot.ratio,
    }
    return sec


def _plot_fig12(ctx, sweeps, optima, dot) -> str:
    fig, axes = new_figure(1, 3, figsize=(14.0, 4.4), sharey=True)
    greens = ["#00441b", "#1b7837", "#5aae61", "#a6dba0"]
    base = fig12_base()
    for ax, (panel, (field, values, label)) in zip(axes, FIG12_AXES.items(), strict=True):
        for colour, d in zip(greens, FIG12_DAMPING, strict=True):
            points = sweeps[(panel, d)]
            ax.plot(values, main_branch(points), color=colour, label=f"D = {d:g}")
            early = np.array([_early(p) for p in points])
            if early.any():
                ratio = np.array([p.ratio for p in points])
                ax.plot(values[early], ratio[early], ".", ms=3, color=colour)
            if (panel, d) in optima:
                x, r = optima[(panel, d)]
                ax.plot([x], [r], "x", color=colour)
        ax.plot([getattr(base, field)], [dot.ratio], "o", color="red")
        ax.set_xlabel(label)
        ax.set_yscale("log")
        ax.grid(True, alpha=0.3)
    axes[0].set_ylabel("v_l / |v0|")
    axes[0].legend()
    fig.suptitle("Fig. 12: phi_a from eq. (3.7); other parameters those of the basketball")
    return save(ctx, fig, "fig12_parameter_dependence.png")


# --- §5 thresholds in v0, c, R ----------------------------------------------------------

THRESHOLD_SCANS: dict[str, tuple[str, float, float, str, float]] = {
    # panel: (Case field, scan low, scan high, unit, paper value in that unit)
    "v0": ("v0", 0.01, 20.0, "m/s", 0.29),
    "c": ("wave_speed", 0.5, 600.0, "1/s", 13.3),
    "R": ("radius", 1e-6, 0.3, "mm", 0.091),
}
#: Factor from the Case field's SI unit to the unit shown (R in mm).
THRESHOLD_SHOWN = {"v0": 1.0, "c": 1.0, "R": 1e3}
THRESHOLD_CRITERIA = ("overall", "moving_up", "paper", "window")


def part_thresholds(ctx: Context) -> Section:
    """Smallest v0, c and R with lift-off for D = 0.13, under each criterion (bisection)."""
    base = fig12_base()
    tasks = [
        ThresholdTask(base, field, crit, lo, hi, True, True, 31, 1e-5)
        for (field, lo, hi, _, _) in THRESHOLD_SCANS.values()
        for crit in THRESHOLD_CRITERIA
    ]
    printed = [
        ThresholdTask(base, field, crit, lo, hi, True, True, 31, 1e-4, "printed")
        for (field, lo, hi, _, _) in THRESHOLD_SCANS.values()
        for crit in ("overall", "paper")
    ]
    outs = _run(ctx, "§5: thresholds in v0, c, R (bisection)", call, tasks + printed, heavy=True)
    results = {
        (t.field, t.criterion, t.sigma): (o.value if o.ok else None, o.error)
        for t, o in zip(tasks + printed, outs, strict=True)
    }
    sec = Section("thresholds", "§5: no-lift-off thresholds in |v0|, c and R (D = 0.13)")
    notes = {
        "overall": "criterion (i) alone, as the paper describes it",
        "moving_up": "criterion (i) while the pole moves up",
        "paper": "full criteria, dt < t_l horizon",
        "window": "full criteria, default horizon",
    }
    for panel, (field, _, _, unit, paper_value) in THRESHOLD_SCANS.items():
        for crit in THRESHOLD_CRITERIA:
            t, _ = results[(field, crit, "lanczos")]
            ours = None if t is None or t.value is None else t.value * THRESHOLD_SHOWN[panel]
            note = notes[crit]
            if t is not None and len(t.transitions) > 1:
                note += "; not monotone on the scan"
            sec.comparisons.append(
                Comparison(
                    f"smallest {panel} with lift-off: {crit}",
                    paper_value,
                    ours,
                    unit,
                    "§5",
                    note,
                    3,
                )
            )
    rows, failures = [], []
    for panel, (field, _, _, _, _) in THRESHOLD_SCANS.items():
        for crit, sigma in [(c, "lanczos") for c in THRESHOLD_CRITERIA] + [
            ("overall", "printed"),
            ("paper", "printed"),
        ]:
            t, err = results[(field, crit, sigma)]
            changes = "-" if t is None else "; ".join(f"{a:.4g}-{b:.4g}" for a, b in t.transitions)
            rows.append(
                [
                    panel,
                    crit,
                    sigma,
                    err or _threshold_text(t, 4),
                    changes,
                    "-" if t is None else str(t.evaluations),
                ]
            )
            if t is not None:
                failures += [f"{panel}, {crit}, {sigma}: {e}" for e in t.errors]
    sec.tables.append(
        "Bisection details (scan of 31 log-spaced points over the range, then bisection to a "
        "relative 1e-5, 1e-4 for the `printed` filter; 'changes' lists every lift-off / "
        "no-lift-off change on the scan):\n\n"
        + markdown_table(
            ["parameter", "criterion", "filter", "threshold", "changes", "evaluations"], rows
        )
    )
    if failures:
        sec.tables.append(
            "Evaluations that failed during the bisections (skipped; the midpoint was "
            "nudged):\n\n" + "\n".join(f"- {f}" for f in failures)
        )
    sec.paragraphs += _threshold_text_paragraphs(results, base, len(failures))
    sec.data = {
        f"{field}/{crit}/{sigma}": None if t is None else t.value
        for (field, crit, sigma), (t, _) in results.items()
    }
    return sec


def _switch_radius(base: Case) -> float:
    """Radius below which :func:`series_for` switches to the recurrence (phi_a near pi/2)."""

    def points(log_r: float) -> float:
        case = base.derive(radius=math.exp(log_r))
        return quadrature_points(case.modes, case.phi_a) - MAX_QUADRATURE_POINTS - 0.5

    return math.exp(brentq(points, math.log(1e-7), math.log(0.3), xtol=1e-6))


def _threshold_text_paragraphs(results, base: Case, failures: int) -> list[str]:
    def value(field, crit, sigma="lanczos"):
        t, _ = results[(field, crit, sigma)]
        return None if t is None else t.value

    def mm(x):
        return None if x is None else 1e3 * x

    switch = _switch_radius(base)
    checks = []
    for radius in (switch, 3e-4):
        phi = base.derive(radius=radius).phi_a
        q = legendre_coefficients(phi, base.modes)
        r = legendre_coefficients_recurrence(phi, base.modes)
        checks.append(
            f"R = {1e3 * radius:.3g} mm ({quadrature_points(base.modes, phi)} points): "
            f"{float(np.max(np.abs(q - r)) / np.max(np.abs(q))):.1e}"
        )
    return [
        "The paper attributes these thresholds to criterion (i): below them the pole "
        "acceleration never reaches -g.  We bisect each parameter (the others fixed at the "
        "basketball values, phi_a from eq. (3.7), D = 0.13, N = 30) under the same readings "
        "of the criteria as for the damping in Fig. 11; the rows above are ours beside the "
        "paper's single number.",
        "Criterion (i) taken literally gives thresholds far below the paper's: "
        f"|v0| = {fmt(value('v0', 'overall'), 3)} m/s, "
        f"c = {fmt(value('wave_speed', 'overall'), 3)} 1/s, "
        f"R = {fmt(mm(value('radius', 'overall')), 3)} mm.  Only the full criteria with the "
        f"paper's dt < t_l horizon come close, and only in |v0| "
        f"({fmt(value('v0', 'paper'), 3)} m/s against 0.29 m/s); the same reading gives "
        f"c = {fmt(value('wave_speed', 'paper'), 3)} 1/s against 13.3 1/s and "
        f"R = {fmt(mm(value('radius', 'paper')), 3)} mm against 0.091 mm.  The default `window` "
        f"horizon needs more of each: {fmt(value('v0', 'window'), 3)} m/s, "
        f"{fmt(value('wave_speed', 'window'), 3)} 1/s, "
        f"{fmt(mm(value('radius', 'window')), 3)} mm.  "
        "The filter exactly as printed in eq. (3.16) moves the criterion-(i) thresholds "
        f"further down (|v0| = {fmt(value('v0', 'overall', 'printed'), 3)} m/s, "
        f"c = {fmt(value('wave_speed', 'overall', 'printed'), 3)} 1/s, "
        f"R = {fmt(mm(value('radius', 'overall', 'printed')), 3)} mm), because its ringing at the "
        "cutoff frequency is stronger.",
        "We could not find one reading that reproduces all three of the paper's numbers.  "
        "They cannot be checked against each other either: at the paper's thresholds "
        f"|v0| / (R c) is {0.29 / (0.12 * 320):.4f}, {4.1 / (0.12 * 13.3):.3f} and "
        f"{4.1 / (0.091e-3 * 320):.0f}, and gamma = g / (R c^2) is "
        f"{G / (0.12 * 320**2):.1e}, {G / (0.12 * 13.3**2):.3f} and "
        f"{G / (0.091e-3 * 320**2):.3f}: three different dimensionless problems.",
        f"Numerics: as R or c shrinks, eq. (3.7) pushes phi_a towards pi/2 and the quadrature "
        f"of the Legendre coefficients needs ever more Gauss points (numpy's `leggauss` is a "
        f"dense eigenproblem: 0.3 s at 1000 points, 16 s at 3800).  Above "
        f"{MAX_QUADRATURE_POINTS} points (here R < {1e3 * switch:.3g} mm) we use the exact "
        f"three-term recurrence "
        f"`twoball.modal.legendre.legendre_coefficients_recurrence` instead.  "
        f"The two agree to (relative, max over a_n) " + "; ".join(checks) + ".  "
        f"Failed evaluations during the bisections: {failures}"
        + (" (listed below)." if failures else "."),
    ]
