"""The figure of a fit: each measured column and the fitted model, residuals below.

One column of panels per measured quantity (``v1_m_s``, ``v2_m_s``,
``t_liftoff_s``): the measured values (with their uncertainties when the file
gives them) and the model at every row against the input the rows vary
(``|v0|``, else the gap, else the row number), the model's curve between them
where it is cheap (the closed form along ``|v0|``), and the residual
``measured - model`` in the panel below.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from typing import TYPE_CHECKING

import numpy as np

from twoball.verify.output.figures import new_figure
from twoball.verify.output.figures.measured import MARKER, MEASURED_COLOUR
from twoball.verify.output.figures.style import REFERENCE_COLOUR, label, styled

if TYPE_CHECKING:
    from matplotlib.figure import Figure

__all__ = ["QUANTITIES", "fit_figure", "x_axis"]

#: Each measured column: its symbol (mathtext), SI unit and the factor it is drawn with.
QUANTITIES: dict[str, tuple[str, str, float]] = {
    "v1_m_s": ("$v_1$", "m/s", 1.0),
    "v2_m_s": ("$v_2$", "m/s", 1.0),
    "t_liftoff_s": ("$t_l$", "ms", 1e3),
    "phi_a_rad": (r"$\varphi_a$", "rad", 1.0),
}
#: The inputs a figure may draw against, in order of preference.
INPUTS: dict[str, tuple[str, str, float]] = {
    "v0_m_s": (r"impact speed $|v_0|$", "m/s", 1.0),
    "gap_m": (r"gap $\Delta x$", "mm", 1e3),
}


def x_axis(inputs: Mapping[str, np.ndarray], rows: int) -> tuple[np.ndarray, str]:
    """The abscissa of every row and its label: the first input that varies, else the row."""
    for column, (text, unit, scale) in INPUTS.items():
        values = inputs.get(column)
        if values is not None and np.ptp(values) > 1e-9 * max(
            float(np.max(np.abs(values))), 1e-300
        ):
            return np.asarray(values, dtype=float) * scale, label(text, unit)
    return np.arange(1, rows + 1, dtype=float), "row"


@styled
def fit_figure(
    inputs: Mapping[str, np.ndarray],
    columns: Sequence[str],
    measured: np.ndarray,
    predicted: np.ndarray,
    sigma: np.ndarray | None,
    curve: Mapping[str, np.ndarray] | None,
    title: str,
) -> Figure:
    """Data and model (top row) and residuals (bottom row), one column per quantity.

    Parameters
    ----------
    inputs : mapping
        The inputs of every row (``v0_m_s``, ``gap_m``, ...), SI.
    columns : sequence of str
        The measured columns.
    measured, predicted : ndarray
        Rows x columns, SI (NaN: not measured).
    sigma : ndarray, optional
        The uncertainties (rows x columns), drawn as error bars.
    curve : mapping, optional
        The model between the rows: ``v0_m_s`` and each column, SI.
    title : str
        The figure's title (the fitted values).
    """
    rows = measured.shape[0]
    x, xlabel = x_axis(inputs, rows)
    order = np.argsort(x, kind="stable")
    count = len(columns)
    fig = new_figure(3.6 * count + 1.0, 5.4)
    axes = fig.subplots(2, count, sharex="col", squeeze=False, height_ratios=(2.2, 1.0))
    for j, column in enumerate(columns):
        symbol, unit, scale = QUANTITIES[column]
        top, bottom = axes[0, j], axes[1, j]
        seen = np.isfinite(measured[:, j])
        if curve is not None and column in curve:
            top.plot(curve["v0_m_s"], curve[column] * scale, "-", color="C0", label="model")
            top.plot(
                x[order],
                predicted[order, j] * scale,
                "o",
                color="C0",
                mfc="none",
                label="model at the rows",
            )
        else:
            top.plot(
                x[order],
                predicted[order, j] * scale,
                "o-",
                color="C0",
                mfc="none",
                label="model at the rows",
            )
        errors = None if sigma is None else sigma[seen, j] * scale
        top.errorbar(
            x[seen],
            measured[seen, j] * scale,
            yerr=errors,
            fmt=MARKER,
            color=MEASURED_COLOUR,
            ms=6,
            capsize=2,
            label="measured",
        )
        top.set_ylabel(label(symbol, unit))
        top.legend(loc="best")
        residual = (measured[:, j] - predicted[:, j]) * scale
        bottom.axhline(0.0, color=REFERENCE_COLOUR, lw=0.8)
        bottom.errorbar(
            x[seen], residual[seen], yerr=errors, fmt=MARKER, color=MEASURED_COLOUR, ms=5, capsize=2
        )
        bottom.set_ylabel(label(f"measured $-$ model, {symbol}", unit))
        bottom.set_xlabel(xlabel)
        if xlabel == "row":
            bottom.set_xticks(np.arange(1, rows + 1))
    fig.suptitle(title)
    return fig
