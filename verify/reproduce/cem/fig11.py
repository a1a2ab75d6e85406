"""Fig. 11: damping, lift-off and the no-lift-off threshold in D.

(a) the smallest pole acceleration against D for several N, read five ways
(:data:`~twoball.verify.reproduce.cem.tasks.CRITERIA`), each bisected for its
threshold; (b) v_l and t_l against D at N = 30 under both horizons.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

import numpy as np
from scipy.optimize import brentq

from twoball.modal.parameters import preset
from twoball.modal.scalings import STANDARD_GRAVITY as G
from twoball.verify.output.figures.style import REFERENCE_COLOUR, label, styled
from twoball.verify.reproduce.cem.tasks import (
    CRITERIA,
    ThresholdTask,
    call,
    minima_task,
    outcome_value,
    run_tasks,
    threshold_text,
)
from twoball.verify.reproduce.common import (
    Comparison,
    Context,
    Section,
    acceleration_minima,
    fmt,
    liftoff,
    markdown_table,
    new_figure,
    save,
)
from twoball.verify.sweeps.sweeps import SweepSolver, run_sweep

if TYPE_CHECKING:
    from matplotlib.figure import Figure


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
    minima = run_tasks(ctx, "Fig. 11(a): pole acceleration minima", minima_task, cases)
    table: dict[tuple[int, float], Any] = {
        (n, float(d)): outcome_value(o) for (n, d), o in zip(grid, minima, strict=True)
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
    outs = run_tasks(ctx, "Fig. 11: damping thresholds (bisection)", call, tasks, heavy=True)
    thresholds = {
        (t.criterion, t.base.modes): outcome_value(o) for t, o in zip(tasks, outs, strict=True)
    }
    fitted = _fit_damping(3.7)
    at_013 = liftoff(base)
    undamped = liftoff(base.derive(damping=0.0))

    names = [
        save(ctx, fig11a_figure(table), "fig11a_min_acceleration.png"),
        save(ctx, fig11b_figure(window, paper, at_013), "fig11b_liftoff_vs_damping.png"),
    ]
    sec = Section("fig11", "Fig. 11: damping, lift-off and the no-lift-off threshold")
    sec.figures += [
        (
            names[0],
            "(a) Smallest pole acceleration against D for several N: over the whole window "
            "(top) and only while the pole moves up (bottom); the dashed line is -g.  Left: "
            "the caption's range 0.600-0.609; right: 0-0.99 (symlog scale).",
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
            rows.append([crit, str(n), threshold_text(t, 4), CRITERIA[crit]])
    return "Damping above which no lift-off is found (bisection, relative tolerance 1e-5):\n\n" + (
        markdown_table(["criterion", "N", "D threshold", "meaning"], rows)
    )


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


@styled
def fig11a_figure(table: dict) -> Figure:
    """2 x 2 panels: whole window / moving up (rows) over the caption's and the wide D range."""
    fig, axes = new_figure(2, 2, figsize=(11.0, 7.0), sharex="col")
    ranges = (D_CAPTION, D_WIDE)
    for row, (field, what) in enumerate(
        (("overall", "over the whole window"), ("moving_up", "while the pole moves up"))
    ):
        for column, ds in enumerate(ranges):
            ax = axes[row, column]
            for k, n in enumerate(N_LIST):
                ms = [table.get((n, float(d))) for d in ds]
                values = [
                    np.nan if m is None or getattr(m, field) is None else getattr(m, field)
                    for m in ms
                ]
                ax.plot(ds, values, color=f"C{k}", linestyle="-", marker=".", label=f"$N$ = {n}")
            ax.axhline(-G, color=REFERENCE_COLOUR, lw=1.0, ls="--", label=f"$-g$ = {-G:g} m/s$^2$")
            ax.set_ylabel(label(r"min $u_{tt}(t, 0)$ " + what, "m/s$^2$"), fontsize=8)
            if column == 1:
                ax.set_yscale("symlog", linthresh=10.0)
    for column, title in enumerate(
        ("$D$ = 0.600 ... 0.609 (caption of Fig. 11(a))", "$D$ = 0 ... 0.99 (symlog scale)")
    ):
        axes[0, column].set_title(title)
        axes[1, column].set_xlabel(label("damping ratio $D$", None))
    axes[0, 1].legend(ncol=2)
    fig.suptitle("Fig. 11(a): smallest pole acceleration against the damping ratio")
    return fig


#: Legend texts of the two re-contact horizons (plain text: a figure shows no Markdown).
HORIZON_LABELS = {
    "window": "re-contact checked over the window (default)",
    "paper": r"re-contact checked for $\Delta t < t_l$ only (§3(a)(ii))",
}


@styled
def fig11b_figure(window, paper, at_013) -> Figure:
    """v_l and t_l against D under both horizons; the red dot is D = 0.13."""
    fig, axes = new_figure(2, 1, figsize=(6.4, 6.4), sharex=True)
    d = [p.case.damping for p in window]
    whole, short = HORIZON_LABELS["window"], HORIZON_LABELS["paper"]
    axes[0].plot(d, [p.v_liftoff_m_s for p in window], "-", label=whole)
    axes[0].plot(d, [p.v_liftoff_m_s for p in paper], ":", label=short)
    axes[1].plot(d, [1e3 * p.t_liftoff_s for p in window], "-", label=whole)
    axes[1].plot(d, [1e3 * p.t_liftoff_s for p in paper], ":", label=short)
    axes[0].plot([0.13], [at_013.v_liftoff_m_s], "o", color="red", label="$D$ = 0.13 (§4(b))")
    axes[1].plot([0.13], [1e3 * at_013.t_liftoff_s], "o", color="red", label="$D$ = 0.13 (§4(b))")
    axes[0].set_ylabel(label("$v_l$", "m/s"))
    axes[0].set_yscale("log")
    axes[1].set_ylabel(label("$t_l$", "ms"))
    axes[1].set_xlabel(label("damping ratio $D$", None))
    axes[0].legend()
    axes[0].set_title(
        r"$|v_0|$ = 4.1 m/s, $\varphi_a$ = 2.6 rad, $R$ = 0.12 m, $c$ = 320 1/s, $N$ = 30"
    )
    return fig
