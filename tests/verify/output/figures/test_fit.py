"""verify/output/figures/fit.py: data and the fitted model, residuals below."""

from __future__ import annotations

import numpy as np

from twoball.verify.output.figures.fit import fit_figure, x_axis


def test_the_abscissa_is_the_input_that_varies():
    x, text = x_axis({"v0_m_s": np.array([3.0, 4.0]), "gap_m": np.array([0.0, 0.01])}, 2)
    assert x.tolist() == [3.0, 4.0] and "v_0" in text
    x, text = x_axis({"v0_m_s": np.array([4.1, 4.1]), "gap_m": np.array([0.0, 0.01])}, 2)
    assert x.tolist() == [0.0, 10.0] and "mm" in text
    x, text = x_axis({"v0_m_s": np.array([4.1, 4.1])}, 2)
    assert x.tolist() == [1.0, 2.0] and text == "row"


def test_a_panel_and_its_residuals_per_measured_column():
    measured = np.array([[3.7, 0.0099], [4.4, np.nan]])
    predicted = np.array([[3.6, 0.00985], [4.5, 0.0099]])
    curve = {
        "v0_m_s": np.linspace(4.0, 5.0, 5),
        "v1_m_s": np.linspace(3.6, 4.5, 5),
        "t_liftoff_s": np.full(5, 0.0099),
    }
    figure = fit_figure(
        {"v0_m_s": np.array([4.1, 4.9])},
        ("v1_m_s", "t_liftoff_s"),
        measured,
        predicted,
        np.full((2, 2), 0.05),
        curve,
        "a fit",
    )
    assert len(figure.axes) == 4
    residual_axis = figure.axes[2]  # second row, first column
    ticks = residual_axis.get_ylabel()
    assert "measured" in ticks and "v_1" in ticks
    assert figure.axes[1].get_ylabel() == "$t_l$ [ms]"
    assert figure._suptitle.get_text() == "a fit"
