"""Figures that show what they promise: no label cut, no legend over the data, small vector files.

References: the figure's own extent (every tick label inside it), the axes'
extents (a legend box over none of them), the written SVG's size against the
15.8 MB the waterfall took with every node a vector marker, and the texts a
reader sees (no Markdown backticks in a legend).
"""

from __future__ import annotations

from pathlib import Path

from twoball.verify.output.fields import ball_model, field_mesh

import twoball

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
    paper = twoball.sweep(dampings, recontact="paper").points
    figure = fig11b_figure(window, paper, window[1])
    texts = [
        t.get_text()
        for axis in figure.axes
        if axis.get_legend()
        for t in axis.get_legend().get_texts()
    ]
    assert texts and not any("`" in t for t in texts), texts
