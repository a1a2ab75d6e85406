"""The whole bounce with each lower ball and each upper body, beside the measurements.

Two parts of ``twoball reproduce`` (docs: shell, bodies):

``kinds_table1``
    Table 1, rows 1-6 at Delta x = 0, with the lower ball a radial membrane
    (:class:`~twoball.modal.balls.membrane.LegendreBall`) or a thin shell
    (:class:`~twoball.modal.balls.shell.ShellBall`) and the upper body rigid
    (Newton's e12), lumped (its own contact law) or a second ball (where the
    pair's body has one: the tennis ball), beside the measured values, the
    ICM (2.6) and the lumped baselines of §1(b).  Each row says whether its
    numbers are predictions or hang on the membrane's degree-1 artefact.
``kinds_gap``
    Figs. 3, 8 and 9 with the same balls and bodies: v1/|v0|, v2/|v0| and the
    body's lift-off after the largest compression (t_l) against Delta x for
    the three basketball pairs, with the ICM (2.5), eq. (2.2), the lumped
    baselines and Table 1's point at Delta x -> 0.

The runs are coarser than ``whole_*``'s (Legendre N = :data:`MODES` for both
lower balls, :data:`GAPS`), so that the parts stay cheap; the membrane's rigid
body at N = 192 is ``whole_table1``'s and ``whole_gap``'s.  Nothing is fitted:
the pairs are :data:`twoball.modal.pairs.PAIRS`, the bodies the presets of
:mod:`twoball.modal.bodies`, the shells' walls the presets'
(:data:`twoball.modal.balls.shell.WALLS`).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

from twoball.modal.floor.bounce import ARTEFACT_SECTION
from twoball.modal.icm.table1 import TABLE1
from twoball.modal.pairs import PAIRS
from twoball.verify.reproduce.common import Comparison, Context, Section, markdown_table, save

__all__ = [
    "BALLS",
    "GAPS",
    "GAP_PAIRS",
    "KINDS",
    "MODES",
    "kinds_of",
    "part_kinds_gap",
    "part_kinds_table1",
    "reading",
]

#: The lower balls, in the tables' order.
BALLS = ("membrane", "shell")
#: The upper bodies' kinds, in the tables' order (docs/bodies.rst).
KINDS = ("rigid", "lumped", "ball")
#: Legendre degree of both lower balls (the shell: 2 N + 1 modes of both branches).
MODES = 64
#: The gaps of the curves [m] (Figs. 3, 8 and 9: 0 to 250 mm, denser at small gaps; seven,
#: to keep the part's whole bounces few).
GAPS = (0.0, 0.005, 0.01, 0.025, 0.05, 0.1, 0.25)
#: The pairs of Figs. 3 and 8.
GAP_PAIRS = ("basketball-tennis", "basketball-tissue", "basketball-table-tennis")
#: Where the docs say what the shell changes in Table 1, and what the bodies do.
SHELL_SECTION = "docs/shell.rst, 'Table 1 with the shell'"
BODIES_SECTION = "docs/bodies.rst, 'Table 1 at Δx = 0, and row 4'"

#: The columns of ``kinds_gap``'s table: (lower ball, body kind).
COLUMNS = (("membrane", "lumped"), ("membrane", "ball"), *(("shell", k) for k in KINDS))

_RUNS: dict[str, dict[tuple[str, str, str, float], Any]] = {}


@dataclass(frozen=True)
class Steps:
    """The Moreau-Jean steps of the parts' runs: the lower ball, the drop's default step
    (0.005 / c) and window (what :class:`~twoball.verify.sweeps.bounce.BounceTask` reads)."""

    ball: Any
    dt: float | None = None
    t_end: float | None = None


def kinds_of(pair: str) -> tuple[str, ...]:
    """The body kinds of a pair: rigid and lumped always, ball where its body is a tennis
    ball (:func:`twoball.body_preset` has a ball body only there)."""
    ball = pair.endswith("-tennis") and not pair.endswith("table-tennis")
    return KINDS if ball else KINDS[:2]


def lower_ball(name: str) -> Any:
    """The lower ball ``membrane`` or ``shell`` at :data:`MODES`."""
    from twoball.modal.balls.membrane import LegendreBall
    from twoball.modal.balls.shell import ShellBall

    return LegendreBall(MODES) if name == "membrane" else ShellBall(modes=MODES)


def reading(ball: str, pair: str) -> str:
    """What a row's numbers are: predictions, or values that hang on the degree-1 artefact.

    The radial membrane's body is first struck by the top's degree-1 precursor
    at small gaps; that moves the tennis ball's rows (rows 1-3, the tennis
    ball as lower ball) and the tennis ball on the basketball (row 4) by up to
    0.25 |v0|, the light bodies' v1 and v2 on the basketball by under 1 %, their
    lift-off time more: the returning top throws them (docs/whole_bounce.rst, 'The
    degree-1 artefact, and what depends on it'; docs/bodies.rst).
    The shell carries its translation as the wall's motion: no precursor.
    """
    p = PAIRS[pair]
    if ball == "membrane" and (p.lower == "tennis" or p.row == 4):
        return "hangs on the degree-1 artefact"
    if ball == "membrane":  # the light bodies: v1, v2 hardly; t_l is the precursor's throw
        return "v1, v2 predictions (the artefact moves them < 1 %); t_l hangs on it"
    return "prediction"


@dataclass(frozen=True)
class KindTask:
    """One whole bounce ``(ball, pair, kind, gap)`` on :func:`lower_ball`, picklable for the
    runner (:class:`~twoball.verify.sweeps.bounce.BounceTask` with the ball's steps)."""

    monitor: Any = None

    def __call__(self, item: tuple[str, str, str, float]) -> Any:
        from twoball.modal.floor.options import Drop
        from twoball.verify.sweeps.bounce import BounceTask

        ball, pair, kind, gap = item
        task = BounceTask(solver=Steps(lower_ball(ball)), monitor=self.monitor)
        return task((None, Drop(gap=gap), kind, pair))


def _cost(item: tuple[str, str, str, float]) -> int:
    """The runs' order: the costliest first, so that two workers end together (a lumped
    body on the tennis ball steps its stiff law for long; a ball body steps two balls)."""
    _, pair, kind, _ = item
    if kind == "lumped" and PAIRS[pair].lower == "tennis":
        return 0
    return 1 if kind == "ball" else 2


def _runs(ctx: Context, items: list[tuple[str, str, str, float]], label: str) -> None:
    """Whole bounces ``(ball, pair, kind, gap)`` on the context's runner, kept for both parts."""
    from twoball._common.errors import NumericalError

    key = str(ctx.directory)
    if key not in _RUNS:
        _RUNS.clear()
        _RUNS[key] = {}
    done = _RUNS[key]
    todo = sorted((item for item in dict.fromkeys(items) if item not in done), key=_cost)
    update = ctx.progress(label, len(todo))
    task = KindTask(monitor=ctx.monitor)
    outcomes = ctx.runner.map(task, todo, progress=update, min_parallel=2, chunk=1)
    bad = [o.error for o in outcomes if not o.ok]
    if bad:
        raise NumericalError(f"whole bounce failed: {bad[0]}")
    done.update(zip(todo, (o.value for o in outcomes), strict=True))


def curve_kinds(ball: str, pair: str) -> tuple[str, ...]:
    """The body kinds of ``kinds_gap``'s curves: every kind on the shell, the elastic ones on
    the membrane (its rigid body's curves are ``whole_gap``'s, at N = 192)."""
    kinds = kinds_of(pair)
    return kinds if ball == "shell" else kinds[1:]


def _get(ctx: Context, ball: str, pair: str, kind: str, gap: float) -> Any:
    return _RUNS[str(ctx.directory)][(ball, pair, kind, gap)]


def _pair_text(report: Any) -> str:
    v1, v2 = report.v1_ratio, report.v2_ratio
    text = "-" if v1 is None or v2 is None else f"{v1:.3f} / {v2:.3f}"
    return text + (" *" if "artefact" in report.caveats else "")


def part_kinds_table1(ctx: Context) -> Section:
    """Table 1 at Delta x = 0 with the membrane and the shell, each body kind."""
    from twoball.modal.icm.limits import touching_ratios

    items = [(b, p, k, 0.0) for b in BALLS for p in PAIRS for k in kinds_of(p)]
    _runs(ctx, items, "Table 1 with each ball and body")
    sec = Section(
        "kinds_table1", "Table 1 with the shell and the elastic bodies: every row at Delta x = 0"
    )
    rows, data = [], []
    lumped = ("two-spring-dashpot", "bartz2020", "hertz-viscoelastic")
    for name, pair in PAIRS.items():
        row = TABLE1[pair.row - 1]
        icm1, icm2 = touching_ratios(pair.mu, pair.e2, pair.e12)
        for ball in BALLS:
            reports = {k: _get(ctx, ball, name, k, 0.0) for k in kinds_of(name)}
            models = reports["rigid"].baselines["models"]
            base = {k: [models[k].get("v1_ratio"), models[k].get("v2_ratio")] for k in lumped}
            cells = [_pair_text(reports[k]) if k in reports else "-" for k in KINDS]
            t_l = [getattr(reports.get(k), "t_liftoff_from_max_compression_s", None) for k in KINDS]
            rows.append(
                [
                    str(pair.row),
                    name,
                    ball,
                    f"{row.measured_v1:g} / {row.measured_v2:g}",
                    f"{icm1:.3f} / {icm2:.3f}",
                    " / ".join(f"{base[k][0]:.2f}" for k in lumped),
                    *cells,
                    " / ".join("-" if t is None else f"{t * 1e3:.2f}" for t in t_l),
                    reading(ball, name),
                ]
            )
            for kind, report in reports.items():
                what = f"{ball}, {kind} body, N = {MODES}: {reading(ball, name)}"
                for col, measured, ours in (
                    ("v1", row.measured_v1, report.v1_ratio),
                    ("v2", row.measured_v2, report.v2_ratio),
                ):
                    sec.comparisons.append(
                        Comparison(
                            f"row {pair.row} ({name}), {col}/|v0|, {ball}, {kind} body",
                            measured,
                            ours,
                            "",
                            "Table 1 (measured)",
                            what,
                            3,
                        )
                    )
                data.append(
                    {
                        "pair": name,
                        "row": pair.row,
                        "ball": ball,
                        "kind": kind,
                        "measured": [row.measured_v1, row.measured_v2],
                        "icm_2_6": [icm1, icm2],
                        "baselines": base,
                        "whole": [report.v1_ratio, report.v2_ratio],
                        "t_l_s": report.t_liftoff_from_max_compression_s,
                        "body_left_first": report.body_left_first,
                        "caveats": list(report.caveats),
                        "reading": reading(ball, name),
                    }
                )
    sec.tables.append(
        f"Table 1 with each lower ball and body (v1/|v0| / v2/|v0|, Delta x = 0, "
        f"|v0| = 4.1 m/s, Legendre N = {MODES}; * the run's own tag: the body was first "
        "struck before the wave could reach the top, pi/c):\n\n"
        + markdown_table(
            [
                "row",
                "pair",
                "lower ball",
                "measured",
                "ICM (2.6)",
                "v1: TSD / Bartz / Hertz",
                "rigid",
                "lumped",
                "ball",
                "t_l rigid / lumped / ball [ms]",
                "reads as",
            ],
            rows,
        )
    )
    sec.paragraphs += [
        "Each Table 1 pair dropped touching (Delta x = 0) at 4.1 m/s on the floor with its "
        "lower ball a radial membrane (the paper's, the centre a coordinate of its own) or a "
        "thin shell (radial and meridional displacement, the preset's wall: its translation "
        "is the wall's motion), and its body rigid (Newton's e12 of Table 1 on a cap), "
        "lumped (a point mass with its own contact law and restitution on a rigid floor) or "
        "a second modal ball (the tennis ball, row 4 only).  Nothing is fitted: the bodies' "
        "inputs are fixed before Table 1 (docs/bodies.rst), the walls are the presets'.",
        "Which numbers are predictions: every shell row, and v1 and v2 of the membrane's "
        "light bodies on the basketball (rows 5, 6; the artefact moves them by under 1 %, "
        "their t_l more: the returning top throws the lumped tissue ball after 2 ms).  The "
        "membrane's "
        "tennis-ball rows (1-3) and its row 4 hang on the degree-1 artefact: the top drops "
        "away at the first floor force and strikes the body back before any wave could "
        f"reach it, by up to 0.25 |v0| ({ARTEFACT_SECTION}).  What the shell changes is in "
        f"{SHELL_SECTION}; what the bodies change in {BODIES_SECTION}.",
        "The ICM (2.6) and the lumped baselines (two spring-dashpots, Bartz 2020, Hertz "
        "with a viscoelastic dashpot; their v2 in whole_table1) take Table 1's mu, e2 and e12; "
        f"the membrane's rigid row at N = 192 is whole_table1's (this part's N = {MODES} is "
        "within about 0.01 of it).",
    ]
    sec.data = {"modes": MODES, "rows": data}
    sec.figures.append(
        (
            save(ctx, table1_figure(data), "kinds_table1.png"),
            "Table 1 at Delta x = 0 with the membrane (open markers; its rows 1-4 hang on the "
            "degree-1 artefact) and the shell (filled; predictions), each body kind, beside "
            "the measurements and the ICM (2.6)",
        )
    )
    return sec


#: Colour and marker of each body kind in the figures.
KIND_MARKS = {"rigid": ("#0072B2", "o"), "lumped": ("#D55E00", "s"), "ball": ("#009E73", "^")}
MEASURED_COLOUR = "#882255"


def table1_figure(rows: list[dict[str, Any]]) -> Any:
    """v1/|v0| and v2/|v0| of every Table 1 row at Delta x = 0: measured, the ICM (2.6), and
    each (lower ball, body kind) as a marker (the membrane open, the shell filled).

    ``rows``: the data of :func:`part_kinds_table1`.
    """
    from twoball.verify.output.figures import new_figure
    from twoball.verify.output.figures.style import DIMENSIONLESS, styled

    pairs = list(dict.fromkeys(r["pair"] for r in rows))

    @styled
    def draw() -> Any:
        fig = new_figure(7.6, 6.4)
        axes = fig.subplots(2, 1, sharex=True)
        x = np.arange(len(pairs))
        columns = [(b, k) for b in BALLS for k in KINDS]
        spread = np.linspace(-0.3, 0.3, len(columns) + 2)
        for j, ax in enumerate(axes):
            first = [next(r for r in rows if r["pair"] == p) for p in pairs]
            ax.plot(x + spread[0], [r["measured"][j] for r in first], "s", color=MEASURED_COLOUR,
                    ms=7, ls="none", label="measured (Table 1)")  # fmt: skip
            ax.plot(x + spread[1], [r["icm_2_6"][j] for r in first], "+", color="k", ms=8,
                    ls="none", label="ICM, eq. (2.6)")  # fmt: skip
            for (ball, kind), dx in zip(columns, spread[2:], strict=True):
                colour, marker = KIND_MARKS[kind]
                values = []
                for p in pairs:
                    mine = [r for r in rows if (r["pair"], r["ball"], r["kind"]) == (p, ball, kind)]
                    value = mine[0]["whole"][j] if mine else None
                    values.append(np.nan if value is None else value)
                face = colour if ball == "shell" else "none"
                ax.plot(x + dx, values, marker=marker, ls="none", color=colour, mfc=face, ms=6,
                        label=f"{ball}, {kind} body")  # fmt: skip
            ax.set_ylabel(f"$v_{j + 1}/|v_0|$ at $\\Delta x$ = 0 {DIMENSIONLESS}")
            for edge in x[:-1] + 0.5:
                ax.axvline(edge, color="0.85", lw=0.6)
        axes[1].set_xticks(x, [p.replace("-", "\n", 1) for p in pairs])
        axes[1].set_xlim(-0.5, len(pairs) - 0.5)
        handles, labels = axes[0].get_legend_handles_labels()
        fig.legend(handles, labels, loc="outside lower center", ncols=4)
        fig.suptitle("Table 1 with each lower ball and body: $\\Delta x$ = 0, "
                     "$|v_0|$ = 4.1 m/s")  # fmt: skip
        return fig

    return draw()


def gap_figure(ctx: Context, pair: str) -> Any:
    """v1/|v0|, v2/|v0| and t_l against Delta x [mm] for one pair: each (ball, kind) a line
    (the membrane dashed, the shell solid), the ICM (2.5) and eq. (2.2), the lumped
    baselines at Delta x = 0 and Table 1's point."""
    from twoball.verify.output.figures import new_figure
    from twoball.verify.output.figures.style import DIMENSIONLESS, label, styled

    row = TABLE1[PAIRS[pair].row - 1]
    gaps = np.array(GAPS)

    @styled
    def draw() -> Any:
        fig = new_figure(8.4, 8.6)
        axes = fig.subplots(3, 1, sharex=True)
        reference = [_get(ctx, "shell", pair, "rigid", g) for g in GAPS]
        icm = [r.baselines["models"]["icm"] for r in reference]
        for j, key in enumerate(("v1_ratio", "v2_ratio")):
            ax = axes[j]
            ax.plot(gaps * 1e3, [m[key] for m in icm], color="k", lw=1.0,
                    label="ICM, eq. (2.5), Table 1's e2, e12")  # fmt: skip
            models = reference[0].baselines["models"]
            for name, marker in (("two-spring-dashpot", "v"), ("bartz2020", "<"),
                                 ("hertz-viscoelastic", "D")):  # fmt: skip
                value = models[name].get(key)
                if value is not None:
                    ax.plot([0.0], [value], marker=marker, color="0.4", mfc="none", ls="none",
                            ms=6, label=f"{name} (lumped, touching)")  # fmt: skip
            measured = row.measured_v1 if j == 0 else row.measured_v2
            ax.plot([0.0], [measured], "s", color=MEASURED_COLOUR, ms=8, ls="none",
                    label=r"measured, Table 1 ($\Delta x \to 0$)")  # fmt: skip
            ax.set_ylabel(f"$v_{j + 1}/|v_0|$ {DIMENSIONLESS}")
        ax = axes[2]
        ax.plot(gaps * 1e3, [m["t_liftoff_s"] * 1e3 for m in icm], color="k", lw=1.0,
                label="ICM, eq. (2.2)")  # fmt: skip
        ax.fill_between([0.0, 10.0], 9.0, 14.0, color=MEASURED_COLOUR, alpha=0.15, lw=0.0,
                        label=r"measured $t_l$, small $\Delta x$ (Fig. 9)")  # fmt: skip
        for ball in BALLS:
            style = "-" if ball == "shell" else (0, (4, 2))
            for kind in curve_kinds(ball, pair):
                colour, marker = KIND_MARKS[kind]
                reports = [_get(ctx, ball, pair, kind, g) for g in GAPS]
                face = colour if ball == "shell" else "none"
                for j, values in enumerate(
                    (
                        [r.v1_ratio for r in reports],
                        [r.v2_ratio for r in reports],
                        [
                            None if t is None else t * 1e3
                            for t in (r.t_liftoff_from_max_compression_s for r in reports)
                        ],
                    )
                ):
                    y = np.array([np.nan if v is None else v for v in values], dtype=float)
                    axes[j].plot(gaps * 1e3, y, ls=style, marker=marker, ms=3.5, color=colour,
                                 mfc=face, label=f"{ball}, {kind} body")  # fmt: skip
        ax.set_ylabel(label("$t_l$ after the largest compression", "ms"))
        ax.set_xlabel(label(r"gap $\Delta x$", "mm"))
        for a in (axes[0], axes[2]):  # v2's markers and lines are v1's
            a.legend(loc="upper left", bbox_to_anchor=(1.01, 1.0), fontsize="small")
        fig.suptitle(f"{pair}: the whole bounce against the gap, N = {MODES}")
        return fig

    return draw()


def part_kinds_gap(ctx: Context) -> Section:
    """v1, v2 and t_l against Delta x for the basketball pairs with each ball and body kind."""
    items = [
        (b, p, k, g) for b in BALLS for p in GAP_PAIRS for k in curve_kinds(b, p) for g in GAPS
    ]
    _runs(ctx, items, "the gap with each ball and body")
    sec = Section(
        "kinds_gap", "Figs. 3, 8 and 9 with the shell and the elastic bodies: against the gap"
    )
    rows, data = [], {}
    for pair in GAP_PAIRS:
        kinds = kinds_of(pair)
        row = TABLE1[PAIRS[pair].row - 1]
        file = save(ctx, gap_figure(ctx, pair), f"kinds_gap_{pair}.png")
        sec.figures.append(
            (
                file,
                f"{pair}: v1/|v0|, v2/|v0| and t_l against Delta x, the shell (solid, filled) "
                "with each body kind and the membrane (dashed, open) with the elastic ones",
            )
        )
        data[pair] = []
        for gap in GAPS:
            icm = _get(ctx, "shell", pair, "rigid", gap).baselines["models"]["icm"]
            cells = []
            for ball, kind in COLUMNS:
                if kind not in curve_kinds(ball, pair):
                    cells.append("-")
                    continue
                r = _get(ctx, ball, pair, kind, gap)
                t_l = r.t_liftoff_from_max_compression_s
                cells.append(_pair_text(r) + ("" if t_l is None else f" ({t_l * 1e3:.1f})"))
                data[pair].append(
                    {
                        "ball": ball,
                        "kind": kind,
                        "gap_m": gap,
                        "v1_ratio": r.v1_ratio,
                        "v2_ratio": r.v2_ratio,
                        "t_l_s": t_l,
                        "e12_effective": r.e12_effective,
                        "body_left_first": r.body_left_first,
                        "caveats": list(r.caveats),
                    }
                )
            rows.append(
                [
                    pair,
                    f"{gap * 1e3:g}",
                    f"{icm['v1_ratio']:.3f} / {icm['v2_ratio']:.3f} "
                    f"({icm['t_liftoff_s'] * 1e3:.1f})",
                    *cells,
                ]
            )
        for kind in kinds:
            first = _get(ctx, "shell", pair, kind, 0.0)
            far = _get(ctx, "shell", pair, kind, GAPS[-1])
            far_icm = far.baselines["models"]["icm"]["v1_ratio"]
            sec.comparisons += [
                Comparison(
                    f"{pair}: v1/|v0| at Delta x -> 0, shell, {kind} body",
                    row.measured_v1,
                    first.v1_ratio,
                    "",
                    "Table 1",
                    f"shell, N = {MODES}: prediction",
                    3,
                ),
                Comparison(
                    f"{pair}: v1/|v0| at Delta x = {GAPS[-1] * 1e3:g} mm, shell, {kind} body",
                    far_icm,
                    far.v1_ratio,
                    "",
                    "eq. (2.5), Table 1's e2 and e12",
                    "the paper measures the ICM's value at large gaps",
                    3,
                ),
            ]
            if first.t_liftoff_from_max_compression_s is not None:
                sec.comparisons.append(
                    Comparison(
                        f"{pair}: t_l at Delta x = 0, shell, {kind} body (measured 9-14 ms)",
                        0.0099,
                        first.t_liftoff_from_max_compression_s,
                        "s",
                        "Fig. 9, §4(b) (the paper's CEM)",
                        "after the ball's largest compression",
                        3,
                    )
                )
    columns = [f"{b} {k}" for b, k in COLUMNS]
    sec.tables.append(
        f"The whole bounce against the gap with each ball and body (v1/|v0| / v2/|v0| (t_l "
        f"[ms]); Legendre N = {MODES}; * the run's artefact tag):\n\n"
        + markdown_table(["pair", "Delta x [mm]", "ICM v1 / v2 (t (2.2))", *columns], rows)
    )
    sec.paragraphs += [
        "The three basketball pairs of Figs. 3 and 8 against the gap, with the shell (solid "
        "lines, filled markers) and each body kind, and the membrane (dashed, open) with the "
        "elastic bodies (its rigid body's curves are whole_gap's, at N = 192); the ICM "
        "(2.5) and eq. (2.2) with Table 1's coefficients, the lumped baselines (touching) and "
        "Table 1's point at Delta x -> 0.  The measured scatter of Figs. 3 and 8 is not in "
        "the paper's text; its t_l window 9-14 ms at small gaps (Fig. 9) is drawn.",
        "At small gaps (the runs marked *) the membrane's elastic bodies are first struck by "
        "the top's degree-1 precursor: the tennis ball's v1 and v2 hang on it, and the light "
        f"bodies' t_l (the top throws them after 2-3 ms) ({ARTEFACT_SECTION}); the shell's "
        "values are predictions.  At large gaps both balls stay below the ICM with the rigid "
        "body (e12_effective below Table 1's e12: docs/whole_bounce.rst, 'What the whole "
        "bounce reproduces, and what it does not'); the elastic bodies carry their own "
        "restitution (docs/bodies.rst).",
    ]
    sec.data = {"modes": MODES, "gaps_m": list(GAPS), "curves": data}
    return sec
