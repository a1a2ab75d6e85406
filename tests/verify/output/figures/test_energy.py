"""The energy figure (verify/output/figures/energy.py)."""

from __future__ import annotations

import numpy as np
import pytest

from tests.helpers import closed_form_series
from twoball.modal.filters import SpectralFilter
from twoball.modal.legendre import legendre_series
from twoball.modal.parameters import preset
from twoball.verify.output.figures.energy import energy_figure
from twoball.verify.output.figures.style import (
    DIMENSIONLESS,
    curves,
)


def test_energy_per_kilogram_starts_at_the_impact_energy():
    # E/m = e (R c)^2 / (4 pi) [J/kg]; at t = 0 the stored energy of the unfiltered
    # series tends to the kinetic energy per kilogram before impact, |v0|^2 / 2
    # (eqs. (3.5)-(3.6), phi_a from eq. (3.7)), with an error falling like 1/N
    case = preset("basketball").derive(preset_name=None)
    t = np.array([0.0, 1.0])
    gaps = []
    for n in (400, 1600):
        series = legendre_series(case.phi_a, 0.0, SpectralFilter("none", n))
        figure = energy_figure(case, [(f"N = {n}", t, series.energy(t))])
        (line,) = figure.axes[0].get_lines()
        assert figure.axes[0].get_ylabel() == "$E/m$ [J/kg]"
        assert line.get_ydata()[1] == pytest.approx(line.get_ydata()[0], rel=1e-9)  # D = 0
        gaps.append(1.0 - line.get_ydata()[0] / (case.v0**2 / 2))
    assert 0.003 < gaps[0] < 0.01
    assert 3.5 < gaps[0] / gaps[1] < 4.5  # first order in 1/N


def test_energy_pairs_get_a_relative_difference_panel(case):
    t = np.linspace(0.0, 10.0, 50)
    e30, e60 = closed_form_series(case, 30).energy(t), closed_form_series(case, 60).energy(t)
    figure = energy_figure(case, [("N = 30", t, e30), ("N = 60", t, e60)])
    top, below = figure.axes
    assert len(curves(top)) == 2
    (line,) = curves(below)
    np.testing.assert_allclose(line.get_ydata(), e30 / e60 - 1.0, rtol=1e-12)
    assert below.get_ylabel() == f"relative difference {DIMENSIONLESS}"
