"""Causality of the shell: a smoothed impulse at the south pole reaches the top at pi R / c_e."""

from __future__ import annotations

import math

import numpy as np
import pytest
import scipy.integrate

from twoball.modal.presets import MEASURED
from twoball.modal.shell.impulse import (
    causality_study,
    gaussian_cap_average,
    superluminal_degree,
)
from twoball.modal.shell.modes import shell_modes
from twoball.modal.shell.parameters import ShellParameters, shell_from_si

HALF = 0.5 * math.pi  # 0.5 pi R / c_e in the time unit R / c_e


def tennis(gas: str = "none") -> ShellParameters:
    """The tennis preset's wall (E = 6 MPa, h = 3.2 mm, nu = 0.5) with its R, m, P."""
    preset = MEASURED["tennis"]
    return shell_from_si(
        youngs_modulus=6e6,
        thickness=3.2e-3,
        poisson=0.5,
        radius=preset.radius,
        mass=preset.mass,
        pressure=preset.pressure,
        gas=gas,
    ).parameters


def basketball(ratio: float = 20.0, thickness: float = 4e-3) -> ShellParameters:
    """R = 0.12 m, P = 77.2 kPa, nu = 0.5; C / N0 and h assumed (the paper gives neither)."""
    return ShellParameters(0.5, bending=(thickness / 0.12) ** 2 / 12, prestress=1 / ratio)


def test_the_centre_of_mass_moves_as_j_t_over_m():
    response = causality_study(ShellParameters(0.3, prestress=0.05), 0.2, samples=201)
    assert np.allclose(response.centre, response.times, rtol=1e-14, atol=1e-15)


@pytest.mark.parametrize("seed", range(4))
def test_membrane_shell_top_is_still_until_the_in_plane_wave_arrives(seed):
    """Random nu in [0.1, 0.5], p in [0, 0.2], no bending, no gas, eps = 0.1, N = 120."""
    rng = np.random.default_rng(seed)
    shell = ShellParameters(rng.uniform(0.1, 0.5), prestress=rng.uniform(0.0, 0.2))
    width = 0.1
    response = causality_study(shell, width)
    assert response.quiet_ratio(HALF) < 1e-3  # measured ~1e-12
    assert response.sign_at_arrival() == 1.0
    assert math.pi - 4 * width < response.arrival() < math.pi


def test_arrival_converges_in_the_number_of_degrees():
    """eps = 0.1: N = 60, 120, 240 agree; N = 40 (N eps = 4) is not converged."""
    shell = ShellParameters(0.5, prestress=0.05)
    arrivals = {n: causality_study(shell, 0.1, max_degree=n).arrival() for n in (40, 60, 120, 240)}
    assert abs(arrivals[120] - arrivals[240]) < 1e-9
    assert abs(arrivals[60] - arrivals[240]) < 1e-6
    assert abs(arrivals[40] - arrivals[240]) > 0.5  # the truncated sum rings from t = 0


def test_arrival_tends_to_pi_within_three_widths():
    """(pi - t_a) / eps stays in [2.5, 3.6] as eps -> 0: t_a -> pi R / c_e linearly in eps.

    A Gaussian front reaches 1e-3 of its height sqrt(2 ln 1000) = 3.7 widths early.
    """
    shell = ShellParameters(0.5, prestress=0.05)
    early = []
    for width in (0.2, 0.1, 0.05, 0.025):
        response = causality_study(shell, width, t_end=1.2 * math.pi, samples=6001)
        early.append((math.pi - response.arrival()) / width)
        assert response.quiet_ratio(HALF) < 1e-9
    assert all(2.5 < value < 3.6 for value in early), early


def test_tennis_and_basketball_walls_are_causal_for_loads_wider_than_two_thicknesses():
    """Kirchhoff bending: eps >= 2.1 h / R keeps the superluminal flexural degrees out."""
    for shell, width in ((tennis(), 0.21), (basketball(20.0), 0.1), (basketball(200.0), 0.1)):
        assert width >= 2.1 * shell.thickness_ratio
        response = causality_study(shell, width)
        assert response.quiet_ratio(HALF) < 1e-3
        assert response.sign_at_arrival() == 1.0
        assert math.pi - 4 * width < response.arrival() < math.pi


def test_narrow_loads_show_the_flexural_precursor_of_kirchhoff_theory():
    """The limit stated in the module: eps = 0.05 on the tennis wall (h / R = 0.096) is early."""
    shell = tennis()
    degree = superluminal_degree(shell)
    assert 1.0 < degree * shell.thickness_ratio < 2.0  # about 1.3 R / h
    assert superluminal_degree(ShellParameters(0.5)) is None  # membrane shell: below c_e
    response = causality_study(shell, 0.05)
    assert response.quiet_ratio(HALF) > 1e-3


def test_the_gas_moves_the_top_at_once_by_g_t2_over_6():
    """top / centre = <cos psi>_g g t^2 / 6 + O(t^4): the breathing mode's shift by the gas."""
    shell = ShellParameters(0.3, prestress=0.05, gas=1.0)
    width = 0.1
    response = causality_study(shell, width, t_end=0.02, samples=101)

    def weight(psi):
        return math.exp(-0.5 * (psi / width) ** 2) * math.sin(psi)

    upper = 12 * width
    total = scipy.integrate.quad(weight, 0.0, upper, epsabs=0, epsrel=1e-13)[0]
    moment = scipy.integrate.quad(
        lambda psi: weight(psi) * math.cos(psi), 0.0, upper, epsabs=0, epsrel=1e-13
    )[0]
    t = response.times[1:]
    expected = (moment / total) * shell.gas * t**2 / 6
    assert np.allclose(response.ratio()[1:], expected, rtol=1e-3)


def test_gaussian_cap_average_of_the_breathing_and_translation_rows():
    modes = shell_modes(ShellParameters(0.4), 10)
    width = 0.15
    averages = gaussian_cap_average(modes.vertical, width)
    assert averages[modes.translation] == pytest.approx(1.0, abs=1e-14)

    def weight(psi):
        return math.exp(-0.5 * (psi / width) ** 2) * math.sin(psi)

    total = scipy.integrate.quad(weight, 0.0, math.pi, epsabs=0, epsrel=1e-13)[0]
    moment = scipy.integrate.quad(
        lambda psi: -weight(psi) * math.cos(psi), 0.0, math.pi, epsabs=0, epsrel=1e-13
    )[0]
    assert averages[0] == pytest.approx(moment / total, rel=1e-12)  # u_z of n = 0 is cos(phi)
    breaks = np.linspace(0, math.pi, 7)
    assert np.allclose(gaussian_cap_average(modes.vertical, width, breaks=breaks), averages)
