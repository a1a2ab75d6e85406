"""verify/output/figures/drop_sweep.py: drops of the ball alone against the damping."""

from __future__ import annotations

import numpy as np

import twoball
from twoball.verify.output.figures.drop_sweep import drop_sweep_figure, sweep_axis_label


def test_three_panels_against_the_swept_value():
    solver = twoball.MoreauJean(twoball.LegendreBall(8))
    result = twoball.sweep({"damping": [0.1, 0.2]}, drop=twoball.Drop(), solver=solver)
    figure = drop_sweep_figure(list(zip(result.values, result.reports, strict=True)), "damping")
    labels = [ax.get_ylabel() for ax in figure.axes]
    assert labels[0].startswith("$e_2") and "ms" in labels[1] and "phi_{a,max}" in labels[2]
    assert figure.axes[2].get_xlabel() == sweep_axis_label("damping") == "damping ratio $D$ [–]"
    e2 = figure.axes[0].get_lines()[0].get_ydata()
    assert np.allclose(e2, [r.e2 for r in result.reports])
