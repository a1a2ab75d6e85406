"""Rayleigh damping on finite elements (fem_membrane/damping.py).

Effective ratios, stepping mode by mode.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from twoball.fem_membrane.solve import alpha_motion, fem_pole_motion, modal_model
from twoball.modal.damping import Rayleigh
from twoball.modal.filters import SpectralFilter
from twoball.modal.series import ModalSeries

from twoball._common.errors import ParameterError

PHI_A, DAMPING = 2.6, 0.13


def test_rayleigh_runs_and_reports_effective_ratios():
    motion, info = fem_pole_motion(
        PHI_A,
        DAMPING,
        "lanczos",
        mesh="axisym",
        elements=60,
        order=2,
        scheme="alpha",
        damping_model="rayleigh",
    )
    rayleigh = info["rayleigh"]
    assert rayleigh["omega_low"] == pytest.approx(math.sqrt(2))
    assert rayleigh["omega_high"] == pytest.approx(math.sqrt(30 * 31))
    table = rayleigh["table"]
    assert len(table) == info["modes_used"] - 1  # all retained modes but the constant one
    omega = np.array([row["omega"] for row in table])
    zeta = np.array([row["zeta"] for row in table])
    expected = rayleigh["alpha"] / (2 * omega) + rayleigh["beta"] * omega / 2
    assert np.allclose(zeta, expected, rtol=1e-14)
    assert np.allclose([row["ratio"] for row in table], zeta / DAMPING)
    assert zeta[0] == pytest.approx(DAMPING, rel=1e-5)  # omega_1 = sqrt(2) up to FE error
    assert np.all(np.isfinite(motion.pole(motion.times).u_tt))


def test_rayleigh_stepping_equals_the_sum_of_modes_with_their_own_ratios():
    model = modal_model(PHI_A, DAMPING, "lanczos", mesh="axisym", elements=60, order=2)
    series = model.series
    fit = Rayleigh.fit(DAMPING, math.sqrt(2), model.filter.omega_n)
    keep = np.flatnonzero(series.retained)
    plain = SpectralFilter("none", 1000)
    modes = [
        ModalSeries(
            omega=series.omega[[k]],
            coefficients=(series.weights * series.coefficients)[[k]],
            pole_values=series.pole_values[[k]],
            damping=float(fit.ratios(series.omega[k])) if series.omega[k] > 1e-3 else 0.0,
            filter=plain,
        )
        for k in keep
    ]
    differences = []
    for steps in (2000, 4000):
        motion, _ = alpha_motion(model, damping_model="rayleigh", dt=4 * np.pi / steps)
        t = motion.times
        exact = sum(np.array(mode.pole(t)) for mode in modes)
        differences.append(np.abs(np.array(motion.pole(t)) - exact).max(axis=1))
    differences = np.array(differences)
    assert np.all(differences[1] < [1e-4, 1e-3, 1e-2])  # u, u_t, u_tt
    orders = np.log2(differences[0] / differences[1])
    assert np.all((orders > 1.8) & (orders < 2.2)), orders


def test_rayleigh_needs_time_stepping():
    with pytest.raises(ParameterError, match="damping_model"):
        fem_pole_motion(PHI_A, DAMPING, mesh="axisym", elements=20, damping_model="rayleigh")
