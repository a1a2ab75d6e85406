"""Stiffer balls in closed form: bending (beta) and the enclosed gas (omega_0), presets, CLI."""

from __future__ import annotations

import math
from dataclasses import replace

import numpy as np
import pytest
from numpy.polynomial import legendre as npleg

import twoball
from twoball import Case
from twoball._common.errors import ParameterError
from twoball.modal.filters import SpectralFilter
from twoball.modal.legendre import legendre_series
from twoball.modal.parameters import PRESETS, wave_speed_from_pressure
from twoball.modal.stiffness import (
    ATMOSPHERE,
    Stiffness,
    flexural_rigidity,
    stiffen,
    stiffness_from_si,
)

# today's results (main at d34289e, `twoball liftoff --json ...`), bit for bit
MAIN = {
    (): (0.009882475691423885, 3.8321572905988326),
    ("--v0", "3.0"): (0.009878799082480655, 2.628216966275543),
    ("--pressure", "60000", "--mass", "0.6"): (0.01152225258566044, 4.1002966852973985),
}


def _laplacian_eigenvalue(n: int) -> float:
    """-Delta_s P_n / P_n by polynomial algebra: Delta = d/dx (1 - x^2) d/dx."""
    c = np.zeros(n + 1)
    c[n] = 1.0
    p = npleg.leg2poly(c)
    d = np.polynomial.polynomial.polyder(p)
    lap = np.polynomial.polynomial.polyder(np.polynomial.polynomial.polymul([1, 0, -1], d))
    return -lap[n] / p[n] if n else 0.0


def test_zero_bending_and_no_gas_leave_the_series_unchanged():
    base = Case.preset("basketball")
    same = Case(bending=0.0, gas="none", pressure=77200.0)
    assert same == replace(base, pressure=77200.0)
    assert not same.stiff and not same.stiffness.active
    a = legendre_series(base.phi_a, base.damping, SpectralFilter("lanczos", 30))
    b = legendre_series(
        same.phi_a, same.damping, SpectralFilter("lanczos", 30), stiffness=same.stiffness
    )
    t = np.linspace(0.0, 4 * np.pi, 3001)
    assert np.array_equal(a.omega, b.omega) and b.filter_omega is None
    assert np.array_equal(a.pole(t).u_tt, b.pole(t).u_tt)
    assert twoball.liftoff(same).as_dict()["t_liftoff_s"] == MAIN[()][0]


def test_bending_operator_on_legendre_polynomials_matches_the_dispersion():
    # apply T Delta - B/R^2 Delta (Delta + 2) to P_n independently (coefficient algebra)
    beta = 0.037
    series = legendre_series(2.5, 0.1, SpectralFilter("none", 12), stiffness=Stiffness(beta))
    for n in range(1, 13):
        lam = _laplacian_eigenvalue(n)
        assert lam == pytest.approx(n * (n + 1), rel=1e-12)
        assert series.omega[n] ** 2 == pytest.approx(lam + beta * lam * (lam - 2), rel=1e-12)


@pytest.mark.parametrize("beta, gas", [(0.0, 8.4), (0.014, 0.0), (0.02, 18.7), (0.5, 6.0)])
def test_closed_form_spectra_match_their_formulas(beta, gas):
    n = np.arange(61)
    stiff = Stiffness(beta, gas)
    series = legendre_series(2.4, 0.13, SpectralFilter("lanczos", 60), stiffness=stiff)
    lam = n * (n + 1.0)
    expected = lam * (1.0 + beta * (lam - 2.0))
    expected[0] = gas
    assert np.allclose(series.omega**2, expected, rtol=1e-13, atol=0.0)
    # the filter keeps weighing by the degree: same weights as the membrane series
    membrane = legendre_series(2.4, 0.13, SpectralFilter("lanczos", 60))
    assert np.array_equal(series.weights, membrane.weights)
    assert np.array_equal(series.coefficients, membrane.coefficients)


def test_si_to_dimensionless_by_an_independent_route():
    # tennis: omega_0 = sqrt(3 kappa P_abs / (rho R)) [1/s], c from P, m, R (eq. (3.8))
    P, m, R, B = 82700.0, 0.0577, 0.0335, 0.02
    c = wave_speed_from_pressure(P, m, R)
    rho = m / (4 * math.pi * R**2)
    T = rho * (c * R) ** 2  # = P R / 2
    for gas, kappa in (("isothermal", 1.0), ("adiabatic", 1.4)):
        s = stiffness_from_si(radius=R, pressure=P, bending=B, gas=gas)
        omega0 = math.sqrt(3 * kappa * (P + ATMOSPHERE) / (rho * R))
        assert s.gas == pytest.approx((omega0 / c) ** 2, rel=1e-13)
        assert s.beta == pytest.approx(B / (T * R**2), rel=1e-13)
    assert flexural_rigidity(2.0e6, 0.003, 0.3) == pytest.approx(
        2.0e6 * 0.003**3 / (12 * 0.91), rel=1e-15
    )


def test_inverse_dispersion_and_stiffen_agree_with_the_legendre_series():
    s = Stiffness(0.03, 12.0)
    lam = np.arange(1, 40) * np.arange(2, 41.0)
    assert np.allclose(s.membrane_value(s.omega_squared(lam)), lam, rtol=1e-13)
    membrane = legendre_series(2.5, 0.1, SpectralFilter("lanczos", 30))
    direct = legendre_series(2.5, 0.1, SpectralFilter("lanczos", 30), stiffness=s)
    mapped = stiffen(membrane, s)
    assert np.allclose(mapped.omega, direct.omega, rtol=1e-14)
    assert np.array_equal(mapped.weights, direct.weights)


def test_small_stiffness_tends_to_the_membrane_liftoff():
    base = Case.preset("basketball")
    ref = twoball.liftoff(base)
    for beta_scale in (1e-8,):
        tiny = Case(bending=beta_scale, pressure=77200.0)
        assert tiny.stiffness.beta < 1e-7
        out = twoball.liftoff(tiny)
        assert out.t_liftoff_s == pytest.approx(ref.t_liftoff_s, rel=1e-6)
        assert out.v_liftoff_m_s == pytest.approx(ref.v_liftoff_m_s, rel=1e-6)


def test_gas_mode_oscillates_at_omega_0():
    # undamped, unfiltered n = 0 coordinate: a_0 cos(omega_0 t) (the membrane keeps a_0)
    s = Stiffness(0.0, 9.0)
    series = legendre_series(2.6, 0.0, SpectralFilter("none", 4), stiffness=s)
    t = np.linspace(0.0, 5.0, 11)
    q0 = series.modal_coordinates(t)[:, 0]
    assert np.allclose(q0, series.coefficients[0] * np.cos(3.0 * t), rtol=0, atol=1e-15)


def test_presets_and_floor_time():
    tennis, volley = PRESETS["tennis"], PRESETS["volleyball"]
    assert tennis.wave_speed == wave_speed_from_pressure(82700.0, 0.0577, 0.0335)
    assert tennis.phi_a_source == "eq. (3.7)" and tennis.gas == "adiabatic"
    assert tennis.bending == pytest.approx(6e6 * 3.2e-3**3 / 9.0, rel=1e-14)
    assert volley.bending == 0.0 and volley.stiff
    # pi/(2c) = half period of the spring k = 2 pi R P on the mass m
    for case, m, P in ((PRESETS["basketball"], 0.567, 77200.0), (tennis, 0.0577, 82700.0)):
        k = 2 * math.pi * case.radius * P
        half = 0.5 * math.pi * math.sqrt(m / k)
        assert case.floor_time == pytest.approx(half, rel=2e-3 if m == 0.567 else 1e-12)
    report = twoball.liftoff(Case.preset("tennis"))
    data = report.as_dict()
    assert data["floor_time_s"] == tennis.floor_time
    assert data["beta"] == tennis.stiffness.beta and data["gas"] == "adiabatic"
    assert report.before_floor_departure is (report.t_liftoff_s < tennis.floor_time) is True
    assert data["before_floor_departure"] is True
    assert twoball.liftoff().as_dict()["before_floor_departure"] is False  # 9.9 ms > 4.9 ms


@pytest.mark.parametrize(
    "changes, name",
    [
        ({"bending": -1.0}, "bending"),
        ({"bending": float("nan")}, "bending"),
        ({"gas": "argon"}, "gas"),
        ({"gas": "adiabatic", "pressure": None}, "pressure"),
        ({"bending": 0.1, "pressure": -5.0}, "pressure"),
        ({"atmosphere": -1.0}, "atmosphere"),
    ],
)
def test_bad_stiffness_raises_parameter_error(changes, name):
    with pytest.raises(ParameterError) as info:
        Case(**changes)
    assert info.value.name == name


def test_pressure_comes_with_the_mass_or_a_stiff_measurement():
    with pytest.raises(ParameterError) as info:
        Case.preset("tennis", pressure=6e4)  # c would not follow: use from_pressure
    assert info.value.name == "pressure"
    soft = Case.from_pressure(6e4, 0.0577, preset="tennis")
    assert soft.pressure == 6e4 and soft.wave_speed == wave_speed_from_pressure(6e4, 0.0577, 0.0335)
    own = Case.from_measurements(
        radius=0.0335, v0=4.1, wave_speed=549.0, pressure=8e4, gas="isothermal"
    )
    assert own.stiffness.gas == pytest.approx(6 * (8e4 + ATMOSPHERE) / 8e4, rel=1e-14)


def test_gas_energy_enters_the_contact_angle_of_eq_3_7():
    # kinetic energy 2 pi v0^2 = membrane strain energy (3.5) + gas 2 pi omega_0^2 a_0^2
    from twoball.modal.initial import deformation_work
    from twoball.modal.legendre import legendre_coefficients

    case = Case.preset("volleyball")
    assert case.phi_a_source == "eq. (3.7)" and case.stiffness.gas > 0
    v0 = case.v0 / (case.radius * case.wave_speed)
    a0 = legendre_coefficients(case.phi_a, 1)[0]  # quadrature of eq. (3.12), not (3.13)
    energy = -deformation_work(case.phi_a) + 2 * math.pi * case.stiffness.gas * a0**2
    assert 2 * math.pi * v0**2 == pytest.approx(energy, rel=1e-12)
    membrane = case.derive(gas="none")  # the rule applies again: less energy stored, deeper
    assert membrane.phi_a < case.phi_a


def test_a_preset_without_stiffness_takes_its_own_pressure_for_bending() -> None:
    """The basketball keeps no pressure (it acts on nothing), though Table 2 gives one:
    bending or a gas given to it take P = 77200 Pa, so T = P R / 2 and beta = B / (T R^2)."""
    bent = Case.preset("basketball", bending=1.0)
    assert bent.pressure == 77200.0
    assert bent.stiffness.beta == pytest.approx(1.0 / (77200.0 * 0.12 / 2.0 * 0.12**2), rel=1e-14)
    assert Case.preset("basketball", gas="isothermal").pressure == 77200.0
    assert Case.preset("basketball").pressure is None  # nothing stiff: no pressure kept
    assert Case.preset("tennis", bending=0.02).pressure == Case.preset("tennis").pressure
    with pytest.raises(ParameterError) as info:  # no preset: no pressure to take
        Case(preset_name=None, bending=1.0)
    assert info.value.name == "pressure"
