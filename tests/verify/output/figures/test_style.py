"""The one figure style (verify/output/figures/style.py).

Every figure of plot, verify, converge and reproduce, walked.
"""

from __future__ import annotations

import re
from pathlib import Path

import numpy as np

import twoball
from tests.helpers import closed_form_series
from twoball.modal.legendre import displacement
from twoball.verify.output.fields import ball_model, coupled_model, field_mesh
from twoball.verify.output.figures.contact import contact_figure
from twoball.verify.output.figures.contact_pole import contact_pole_figure
from twoball.verify.output.figures.eigen import (
    EigenErrors,
    eigen_errors_figure,
    eigen_figure,
    eigen_table,
)
from twoball.verify.output.figures.energy import energy_figure
from twoball.verify.output.figures.pole import Trace, pole_figure, pole_motion_figure
from twoball.verify.output.figures.study import legend_name, study_figure
from twoball.verify.output.figures.style import (
    DIMENSIONLESS,
    MARK,
    MAX_CURVES,
    MIN_FONT_PT,
    STACKED,
    STYLE,
    chunks,
    curves,
    label,
)
from twoball.verify.output.figures.sweep import sweep_figure
from twoball.verify.output.figures.waterfall import waterfall_figure
from twoball.verify.reproduce import icm as icm_part
from twoball.verify.reproduce.cem import fig11, fig12
from twoball.verify.reproduce.cem.fig6 import fig6_figure
from twoball.verify.reproduce.cem.fig10 import fig10_figure
from twoball.verify.reproduce.common import acceleration_minima, liftoff
from twoball.verify.studies.modes import run_modes_study
from twoball.verify.studies.refinement import run_h_study
from twoball.verify.sweeps.sweeps import SweepSolver, make_grid, run_sweep

UNIT = re.compile(r"\[[^\[\]]+\]")
#: ASCII pseudo-math the style replaces by mathtext (outside $...$).
ASCII_MATH = re.compile(r"\^|_[a-zA-Z0-9{]|\blambda\b|\bphi\b|\bT R\b|\bmu\b|\|v0\|")


def outside_math(text: str) -> str:
    return re.sub(r"\$[^$]*\$", "", text)


def _traces(case, modes):
    out = []
    for n in modes:
        report = liftoff(case.derive(modes=n))
        scale = case.scalings
        t_l = report.t_liftoff_s / scale.time if report.t_liftoff_s is not None else None
        out.append(Trace(f"Legendre N = {n}", closed_form_series(case, n), t_l, None))
    return out


def _fig11_table(case):
    table = {}
    for n in fig11.N_LIST[:2]:
        for d in (*fig11.D_CAPTION[:3], *fig11.D_WIDE[::40]):
            table[(n, float(d))] = acceleration_minima(case.derive(damping=float(d), modes=n))
    return table


def _fig12_inputs(monkeypatch):
    small = {k: (f, v[::25], t) for k, (f, v, t) in fig12.FIG12_AXES.items()}
    monkeypatch.setattr(fig12, "FIG12_AXES", small)
    base = fig12.fig12_base()
    sweeps, optima = {}, {}
    for panel, (field, values, _) in small.items():
        for d in fig12.FIG12_DAMPING:
            cases = [base.derive(damping=d, **{field: float(x)}) for x in values]
            points = run_sweep(cases, SweepSolver("lanczos", "window"))
            sweeps[(panel, d)] = points
            ratio = fig12.main_branch(points)
            if np.isfinite(ratio).any():
                k = int(np.nanargmax(ratio))
                optima[(panel, d)] = (float(values[k]), float(ratio[k]))
    return sweeps, optima, liftoff(base)


def every_figure(case, coarse, monkeypatch):
    """(name, figure) of every builder of plot, verify, converge and reproduce."""
    scale = case.scalings
    t_end = coarse.t_end
    yield "plot waterfall", waterfall_figure(coarse, 6)
    yield "plot pole", pole_figure(coarse, 300)
    mesh = twoball.MeshOptions("sphere", level=1, order=1)
    coupled = coupled_model(case, ("fem", "legendre"), twoball.Body(0.004), mesh)
    yield "plot pole with a body", contact_pole_figure(coupled, 300)
    yield "plot eigen", eigen_figure([eigen_table(lv, od, 2) for od in (1, 2) for lv in (0, 1)])
    yield "liftoff --plot", contact_figure(twoball.liftoff(case, body=twoball.Body(0.1)))
    yield "plot precursor", _precursor(case)
    yield "fit --plot", _fit()
    # verify: pole.png (8 backends: split in columns), eigenvalues.png, energy.png
    yield "verify pole", pole_motion_figure(case, _traces(case, range(30, 70, 5)), t_end, 300)
    tables = [eigen_table(lv, 1, 2) for lv in (0, 1, 2)]
    yield (
        "verify eigen",
        eigen_errors_figure([EigenErrors(t.label, t.degrees, t.errors) for t in tables]),
    )
    t = np.linspace(0.0, t_end, 200)
    energy = [(f"N = {n}", t, closed_form_series(case, n).energy(t)) for n in (20, 30, 40)]
    yield "verify energy", energy_figure(case, energy, (t, energy[-1][2] * 1.1))
    # converge: convergence.png of a closed-form and a finite-element study
    yield "converge modes", study_figure(run_modes_study(case, modes=(30, 60, 120)))
    yield "converge h", study_figure(run_h_study(case, mesh="axisym", order=1, levels=(1, 2, 3)))
    # sweep --plot, 1-D and 2-D
    for params, values in ((["damping"], ["0:0.3:4"]), (["damping", "v0"], ["0:0.3:3", "3:5:3"])):
        grid = make_grid(params, values)
        points = run_sweep(grid.cases(case), SweepSolver(), indices=grid.indices())
        yield f"sweep {'x'.join(params)}", sweep_figure(grid, points)
    # reproduce
    dx = np.linspace(0.0, 0.15, 31)
    yield "reproduce fig3", icm_part.fig3_figure(dx, *icm_part._curves(0.1007, 0.8, 0.89, 1.0, dx))
    curves8 = {i: icm_part._curves(0.004, 0.8, 0.89, 0.92, dx) for i in (5, 6)}
    yield "reproduce fig8", icm_part.fig8_figure(dx, curves8)
    phi = np.linspace(0.0, np.pi, 91)
    t_ms = np.linspace(0.0, 11.5, 24)
    u_mm = (
        displacement(closed_form_series(case, 30), t_ms * 1e-3 / scale.time, phi)
        * case.radius
        * 1e3
    )
    yield "reproduce fig6", fig6_figure(phi, t_ms, u_mm)
    yield "reproduce fig10", fig10_figure(np.linspace(0.05, 8.0, 40), 0.12)
    yield "reproduce fig11a", fig11.fig11a_figure(_fig11_table(case))
    d_cases = [case.derive(damping=float(d)) for d in np.linspace(0.0, 0.6, 7)]
    window = run_sweep(d_cases, SweepSolver("lanczos", "window"))
    paper = run_sweep(d_cases, SweepSolver("lanczos", "paper"))
    yield "reproduce fig11b", fig11.fig11b_figure(window, paper, liftoff(case))
    yield "reproduce fig12", fig12.fig12_figure(*_fig12_inputs(monkeypatch))
    yield from _whole_bounce_figures()


def _precursor(case):
    from twoball.modal.report import t_end_dimensionless
    from twoball.verify.output.figures.precursor import law_curves, precursor_figure

    solver = twoball.ClosedForm()
    window = t_end_dimensionless(case, solver.t_end)
    curves = law_curves(case, solver.sigma, solver.recontact, window)
    return precursor_figure(case, curves, window)


def _fit():
    from twoball.verify.output.figures.fit import fit_figure

    measured = np.array([[3.7, 0.0099], [4.4, np.nan]])
    predicted = np.array([[3.6, 0.00985], [4.5, 0.0099]])
    curve = {
        "v0_m_s": np.linspace(4.0, 5.0, 5),
        "v1_m_s": np.linspace(3.6, 4.5, 5),
        "t_liftoff_s": np.full(5, 0.0099),
    }
    columns = ("v1_m_s", "t_liftoff_s")
    inputs = {"v0_m_s": np.array([4.1, 4.9])}
    errors = np.full((2, 2), 0.05)
    return fit_figure(inputs, columns, measured, predicted, errors, curve, "basketball: a fit")


def _whole_bounce_figures():
    """The drop's and the whole bounce's figures (coarse runs: N = 16)."""
    from twoball.verify.output.figures.bounce import drop_figure, gap_figure, whole_figure
    from twoball.verify.reproduce import whole as whole_part

    coarse = twoball.MoreauJean(twoball.LegendreBall(16))
    drop = twoball.bounce(solver=coarse)
    yield "plot bounce", drop_figure(drop.result, drop.case, drop.mass_kg, "legendre")
    from twoball.verify.output.figures.drop_sweep import drop_sweep_figure

    swept = twoball.sweep({"damping": [0.1, 0.2]}, drop=twoball.Drop(), solver=coarse)
    points = list(zip(swept.values, swept.reports, strict=True))
    yield "bounce sweep --plot", drop_sweep_figure(points, "damping")
    whole = twoball.bounce(solver=coarse, pair="basketball-tennis")
    icm = (1.0, 2.0)
    yield "plot whole bounce", whole_figure(whole.result, whole.case, whole.mass_kg, "x", icm)
    curves = {}
    for name in whole_part.GAP_PAIRS:
        runs = [(g, twoball.bounce(drop=twoball.Drop(gap=g), solver=coarse, pair=name).light())
                for g in (0.0, 0.005, 0.02, 0.2)]  # fmt: skip
        curves[name] = runs
    measured = {"v1": 1.8, "v2": 0.61, "dx": 0.0}
    yield "sweep gap", gap_figure(curves["basketball-tennis"], "gap", measured, "x", 0.9)
    yield "reproduce whole timing", whole_part.timing_figure(curves)
    rows = []
    for name, runs in curves.items():
        report = runs[0][1]
        base = {k: [m.get("v1_ratio"), m.get("v2_ratio")]
                for k, m in report.baselines["models"].items()}  # fmt: skip
        rows.append({"pair": name, "measured": [1.8, 0.61], "icm_printed": [2.1, 0.56],
                     "icm_2_6": [2.09, 0.49], "baselines": base, "cem_massless_v1": 0.935,
                     "whole": [report.v1_ratio, report.v2_ratio]})  # fmt: skip
    yield "reproduce whole table 1", whole_part.table1_figure(rows)


def axis_labels(axis) -> list[str]:
    labels = [axis.get_xlabel(), axis.get_ylabel()]
    if hasattr(axis, "get_zlabel"):
        labels.append(axis.get_zlabel())
    return [text for text in labels if text]


def check_fonts_and_style(name, figure):
    """Every visible text at least MIN_FONT_PT; the style's marks and rcParams on the figure."""
    from matplotlib.text import Text

    assert getattr(figure, MARK, False), f"{name}: built outside the style (styled)"
    texts = [t for t in figure.findobj(Text) if t.get_visible() and t.get_text().strip()]
    assert texts, name
    for text in texts:
        assert text.get_fontsize() >= MIN_FONT_PT, (name, text.get_text(), text.get_fontsize())
    for axis in figure.axes:
        if not axis.get_visible() or not axis.axison:
            continue
        ticks = [t for t in axis.get_xticklabels() + axis.get_yticklabels() if t.get_text()]
        assert all(t.get_fontsize() == STYLE["xtick.labelsize"] for t in ticks), name
        grid = [g for g in axis.get_xgridlines() + axis.get_ygridlines() if g.get_visible()]
        assert all(g.get_alpha() == STYLE["grid.alpha"] for g in grid), name


#: Figures whose title names what they show (the basketball preset, a pair).
NAMED = {
    "plot waterfall": "basketball",
    "plot pole": "basketball",
    "plot pole with a body": "basketball",
    "verify pole": "basketball",
    "verify energy": "basketball",
    "plot precursor": "basketball",
    "bounce sweep --plot": "basketball",
    "plot whole bounce": "x",
    "sweep gap": "x",
}


def covered_points(axis, renderer) -> int:
    """Data points (line vertices, scattered markers) of ``axis`` under its legend's frame."""
    legend = axis.get_legend()
    if legend is None:
        return 0
    box = legend.get_window_extent(renderer)
    points = [axis.transData.transform(line.get_xydata()) for line in curves(axis)]
    for collection in axis.collections:
        offsets = collection.get_offsets()
        if len(offsets) and collection.get_offset_transform() is not None:
            points.append(collection.get_offset_transform().transform(offsets))
    return sum(
        int(np.count_nonzero((p[:, 0] > box.x0) & (p[:, 0] < box.x1) & (p[:, 1] > box.y0)
                             & (p[:, 1] < box.y1)))
        for p in points
    )  # fmt: skip


def test_every_figure_labels_units_fonts_and_counts_curves(case, coarse, monkeypatch):
    seen = []
    for name, figure in every_figure(case, coarse, monkeypatch):
        seen.append(name)
        check_fonts_and_style(name, figure)
        visible = [a for a in figure.axes if a.get_visible()]
        labelled = [text for a in visible for text in axis_labels(a)]
        assert labelled, name
        for axis in visible:
            for text in axis_labels(axis):
                assert UNIT.search(text), f"{name}: axis label without a unit: {text!r}"
            texts = [axis.get_title(), *axis_labels(axis)]
            if axis.get_legend() is not None:
                texts += [t.get_text() for t in axis.get_legend().get_texts()]
            for text in texts:
                assert not ASCII_MATH.search(outside_math(text)), f"{name}: {text!r}"
            count = len(curves(axis))
            if axis.get_gid() == STACKED:
                assert name in ("plot waterfall", "reproduce fig6"), name
            else:
                assert count <= MAX_CURVES, f"{name}: {count} curves on one axis"
        title = figure.get_suptitle() if hasattr(figure, "get_suptitle") else ""
        assert not ASCII_MATH.search(outside_math(title)), f"{name}: {title!r}"
        # every title fits the figure (none cut off at the edges)
        from matplotlib.backends.backend_agg import FigureCanvasAgg

        renderer = FigureCanvasAgg(figure).get_renderer()
        figure.draw(renderer)
        width = figure.bbox.width
        texts = [a.title for a in visible] + ([figure._suptitle] if figure._suptitle else [])
        for text in texts:
            box = text.get_window_extent(renderer)
            assert box.x0 >= -1 and box.x1 <= width + 1, f"{name}: {text.get_text()!r} cut off"
        if name in NAMED:  # the title says which ball (the preset) or pair is shown
            titles = [title] + [a.get_title() for a in visible]
            assert any(NAMED[name] in t for t in titles), (name, titles)
        for axis in visible:  # legends at their best spot or beside: over no data
            assert covered_points(axis, renderer) == 0, f"{name}: {axis.get_ylabel()!r}"
    assert len(seen) == 27


def test_crowded_data_becomes_small_multiples(case, coarse):
    # 8 backends for the verify pole figure: reference + 7 others -> two columns
    traces = _traces(case, range(30, 70, 5))
    figure = pole_motion_figure(case, traces, coarse.t_end, 200)
    assert len(figure.axes) == 12  # 6 rows (3 quantities + differences) x 2 columns
    # every column repeats the reference, so each panel compares against it
    grid = np.array(figure.axes).reshape(6, 2)
    assert all(curves(a)[0].get_label() == "Legendre N = 30" for a in grid[0::2].ravel())
    assert all(len(curves(a)) <= MAX_CURVES for a in figure.axes)
    # difference rows: the others minus the reference, in the panel's unit
    t = np.linspace(0.0, coarse.t_end, 200)
    du_ref = (traces[1].motion.pole(t).u - traces[0].motion.pole(t).u) * case.radius
    shown = curves(grid[1, 0])[0]  # row 1, column 0: first other trace, Delta u
    unit = grid[1, 0].get_ylabel().split("[")[1].rstrip("]")
    factor = {"m": 1.0, "mm": 1e3, r"$\mu$m": 1e6, "nm": 1e9}[unit]
    np.testing.assert_allclose(shown.get_ydata(), du_ref * factor, rtol=1e-12, atol=1e-15)
    # eigen: 7 discretisations -> 2 panels of at most 6
    many = [eigen_table(lv, od, 2) for od in (1, 2) for lv in (0, 1, 2)] + [eigen_table(3, 1, 2)]
    assert [len(a.get_lines()) for a in eigen_figure(many).axes] == [4, 3]


def test_cycle_colours_are_the_styles_wherever_the_figure_is_saved(tmp_path):
    from matplotlib.colors import to_hex

    from twoball.verify.output.figures import new_figure
    from twoball.verify.output.figures.style import COLOURS, styled

    @styled
    def drawn():
        figure = new_figure(3.0, 2.0)
        axis = figure.subplots()
        axis.plot([0, 1, 2], [0, 1, 0], color="C1", label="x")
        axis.text(0.5, 0.5, "t", color="C2")
        return figure

    figure = drawn()
    (line,) = figure.axes[0].get_lines()
    # "C1" is looked up when drawn: outside the style it would be matplotlib's orange
    assert to_hex(line.get_color()) == COLOURS[1].lower()
    assert to_hex(figure.axes[0].texts[0].get_color()) == COLOURS[2].lower()
    figure.savefig(tmp_path / "plain.png")  # saved by hand, not by save_figure: the same
    assert to_hex(line.get_color()) == COLOURS[1].lower()


def test_label_helpers():
    assert label("$t$", "ms") == "$t$ [ms]"
    assert label("$N$", None) == f"$N$ {DIMENSIONLESS}"
    assert [len(c) for c in chunks(range(7))] == [4, 3]
    assert [len(c) for c in chunks(range(12))] == [6, 6]
    assert chunks([]) == []
    text = legend_name("E(t_end) [T R^2]")
    assert "T R" not in text and "$E(t_" in text
    assert legend_name("lambda_6 (exact 42)") == r"$\lambda_{6}$ (exact 42)"


# --- Figures that show what they promise: no label cut, no legend over the data, small vector files

CASE = twoball.Case.preset("basketball")


def _drawn(figure):
    from matplotlib.backends.backend_agg import FigureCanvasAgg

    canvas = FigureCanvasAgg(figure)
    canvas.draw()
    return canvas.get_renderer()


def test_waterfall_tick_labels_inside_and_svg_small(tmp_path: Path) -> None:
    from twoball.verify.output.figures.waterfall import waterfall_figure

    model = ball_model(CASE, field_mesh(twoball.MeshOptions("sphere", level=3)))
    figure = waterfall_figure(model)
    renderer = _drawn(figure)
    box = figure.bbox
    for axis in figure.axes:
        for text in axis.get_xticklabels() + axis.get_yticklabels():
            if not text.get_text():
                continue
            extent = text.get_window_extent(renderer)
            assert box.x0 - 0.5 <= extent.x0 and extent.x1 <= box.x1 + 0.5, text.get_text()
    result = twoball.plot("waterfall", tmp_path / "w.svg", CASE)
    size = result.file.stat().st_size
    assert size < 2_000_000, size  # was 15.8 MB: every node of 24 instants a vector marker
    assert "<image" in result.file.read_text()  # the node dots are one raster image per panel


def test_contact_pole_legend_covers_no_panel() -> None:
    from twoball.verify.output.figures.contact_pole import contact_pole_figure

    field = field_mesh(twoball.MeshOptions("sphere", level=1))
    model = ball_model(CASE, field, body=twoball.Body(0.1), route="full")
    figure = contact_pole_figure(model)
    renderer = _drawn(figure)
    legends = list(figure.legends) + [a.get_legend() for a in figure.axes if a.get_legend()]
    assert legends
    for legend in legends:
        frame = legend.get_window_extent(renderer)
        for axis in figure.axes:
            assert not frame.overlaps(axis.get_window_extent(renderer)), legend
    labels = [t.get_text() for t in figure.legends[0].get_texts()]
    assert "cap average, closed form (3.16)" in labels and "impact" in labels


def test_fig11b_legend_is_plain_text() -> None:
    from twoball.verify.reproduce.cem.fig11 import fig11b_figure

    dampings = {"damping": [0.1, 0.13, 0.3]}
    window = twoball.sweep(dampings).points
    paper = twoball.sweep(dampings, solver=twoball.ClosedForm(recontact="paper")).points
    figure = fig11b_figure(window, paper, window[1])
    texts = [
        t.get_text()
        for axis in figure.axes
        if axis.get_legend()
        for t in axis.get_legend().get_texts()
    ]
    assert texts and not any("`" in t for t in texts), texts
