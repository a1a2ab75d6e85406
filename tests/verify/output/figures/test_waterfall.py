"""The waterfall figure (verify/output/figures/waterfall.py), Fig. 6."""

from __future__ import annotations

import numpy as np
import pytest

from tests.helpers import drawn
from twoball._common.errors import ParameterError
from twoball.fem_membrane.options import MeshOptions
from twoball.modal.parameters import preset
from twoball.verify.output.fields import ball_model, field_mesh
from twoball.verify.output.figures import save_figure
from twoball.verify.output.figures.waterfall import waterfall_figure, waterfall_times


def test_waterfall_has_24_curves_of_each_backend(model, tmp_path):
    figure = waterfall_figure(model)
    axis = figure.axes[0]
    lines = [line for line in axis.get_lines() if len(line.get_xdata()) > 2]
    closed = [line for line in lines if line.get_linestyle() == "-"]
    nodes = [line for line in lines if line.get_marker() == "."]
    assert len(closed) == 24 and len(nodes) == 24
    # the first closed-form curve is the initial condition (3.10) in mm: flat to phi_a
    x, y = closed[0].get_data()
    flattened = np.cos(model.case.phi_a) / np.cos(x[x > 2.7]) - 1.0
    assert y[x > 2.7] == pytest.approx(flattened * model.case.radius * 1e3, abs=0.6)
    assert y[x < 2.0] == pytest.approx(0.0, abs=0.2)
    out = save_figure(figure, tmp_path / "waterfall.png")
    assert drawn(out) > 0.03


def test_waterfall_difference_stack_is_fem_minus_closed_form_at_the_nodes(model):
    from twoball.modal.legendre import displacement
    from twoball.verify.output.fields import node_polar_angles

    figure = waterfall_figure(model, 4)
    assert len(figure.axes) == 2  # the waterfall and the stacked differences beside it
    side = figure.axes[1]
    rows = [line for line in side.get_lines() if line.get_marker() == "."]
    assert len(rows) == 4
    times = waterfall_times(model, 4)
    phi = node_polar_angles(model.mesh)
    scale = model.case.scalings
    closed = displacement(model.backends["legendre"].series, times / scale.time, phi)
    expected = model.nodal("fem", times, 0) - closed * scale.length  # m
    unit = side.get_ylabel().rsplit("[", 1)[1].rstrip("]")
    factor = {"m": 1.0, "mm": 1e3, r"$\mu$m": 1e6, "nm": 1e9}[unit]
    offset = rows[1].get_ydata()[0] - expected[1, 0] * factor
    for k, row in enumerate(rows):
        np.testing.assert_allclose(row.get_ydata(), expected[k] * factor + k * offset, atol=1e-9)
    # rows line up with the waterfall: both stacks scale their limits by one factor
    (low, high), (side_low, side_high) = figure.axes[0].get_ylim(), side.get_ylim()
    assert side_low / low == pytest.approx(side_high / high)
    shift_mm = float(figure.axes[0].get_ylabel().split()[3])  # printed to 3 digits
    assert offset == pytest.approx(side_high / high * shift_mm, rel=1e-2)
    single = waterfall_figure(
        ball_model(
            preset("basketball"), field_mesh(MeshOptions(level=1, order=1)), backends=("legendre",)
        ),
        3,
    )
    assert len(single.axes) == 1


def test_waterfall_times():
    model = ball_model(
        preset("basketball"), field_mesh(MeshOptions(level=1, order=1)), backends=("legendre",)
    )
    times = waterfall_times(model)
    assert times.size == 24 and times[0] == 0 and times[-1] == pytest.approx(model.t_end_s)
    with pytest.raises(ParameterError, match="^instants must be an integer >= 2, got 1"):
        waterfall_times(model, 1)
    assert len(waterfall_figure(model, 5).axes[0].get_lines()) >= 5
