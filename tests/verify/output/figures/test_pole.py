"""The pole-motion figure (verify/output/figures/pole.py): lift-off marked, FE minus closed form."""

from __future__ import annotations

import numpy as np
import pytest

from tests.helpers import drawn
from twoball.fem_membrane.options import MeshOptions
from twoball.modal.parameters import preset
from twoball.verify.output.fields import ball_model, field_mesh
from twoball.verify.output.figures import save_figure
from twoball.verify.output.figures.pole import pole_figure
from twoball.verify.output.figures.style import curves


def test_pole_plot_marks_liftoff(model, tmp_path):
    figure = pole_figure(model)
    assert len(figure.axes) == 6  # u, u_t, u_tt, each with its difference panel below
    top, middle, bottom = figure.axes[0:6:2]
    for name in ("fem", "legendre"):
        t_ms = model.backends[name].report.t_liftoff_s * 1e3
        marked = [
            line
            for line in top.get_lines()
            if line.get_marker() == "o" and line.get_xdata()[0] == pytest.approx(t_ms)
        ]
        assert marked, name
    assert any(np.allclose(line.get_ydata(), -9.81) for line in bottom.get_lines())
    assert "lift-off" in [t.get_text() for t in bottom.get_legend().get_texts()]
    out = save_figure(figure, tmp_path / "pole.png")
    assert drawn(out) > 0.03


def test_pole_difference_panel_is_fem_minus_closed_form(model):
    figure = pole_figure(model, samples=400)
    below_u = figure.axes[1]
    (line,) = curves(below_u)
    t_ms, shown = line.get_data()
    # the same difference evaluated here from the two series, in m
    t = np.asarray(t_ms) * 1e-3 / model.case.scalings.time
    fem = model.backends["fem"].series.pole(t).u
    closed = model.backends["legendre"].series.pole(t).u
    expected_m = (fem - closed) * model.case.radius
    unit = below_u.get_ylabel().split("[")[1].rstrip("]")
    factor = {"m": 1.0, "mm": 1e3, r"$\mu$m": 1e6, "nm": 1e9}[unit]
    np.testing.assert_allclose(shown, expected_m * factor, rtol=1e-12, atol=1e-12)
    # level 1 P1 against the closed form differs by about a millimetre somewhere
    assert 1e-4 < np.abs(expected_m).max() < 1e-2
    single = pole_figure(
        ball_model(
            preset("basketball"), field_mesh(MeshOptions(level=1, order=1)), backends=("legendre",)
        ),
        200,
    )
    assert len(single.axes) == 3  # nothing to compare: no difference panels
