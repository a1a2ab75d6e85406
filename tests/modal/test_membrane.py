"""The pressurised membrane operator in closed form: spectrum, gas, n = 1, eq. (3.7), refusals."""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.integrate import quad

import twoball
from twoball import Case, ParameterError
from twoball.modal.damping import ModalRatio, Rayleigh
from twoball.modal.filters import SpectralFilter
from twoball.modal.initial import phi_a_from_v0
from twoball.modal.legendre import legendre_coefficients_recurrence, legendre_series
from twoball.modal.membrane import Membrane, square_integral
from twoball.modal.stiffness import ATMOSPHERE, Stiffness, stiffness_from_si

PRESSURISED = Membrane("pressurised")
P, M, R = 77200.0, 0.567, 0.12  # the paper's basketball (Table 2)


def pressurised_case(gas: str = "adiabatic", **changes: object) -> Case:
    return Case.from_pressure(P, M, gas=gas, membrane="pressurised", **changes)


def test_legendre_spectrum_is_exactly_n_minus_1_times_n_plus_2():
    n = np.arange(0, 2001)
    exact = np.array([(k - 1) * (k + 2) for k in range(2001)], dtype=float)  # integers
    assert np.array_equal(PRESSURISED.legendre(n), exact)
    assert np.array_equal(Membrane().legendre(n), n * (n + 1.0))
    assert np.array_equal(PRESSURISED.eigenvalues(n * (n + 1.0)), exact)
    # the ratios to the paper's frequencies quoted in the sources: 0, 0.816, 0.913, 0.949, 0.966
    ratio = np.sqrt(exact[1:6] / (n[1:6] * (n[1:6] + 1.0)))
    assert np.round(ratio, 3).tolist() == [0.0, 0.816, 0.913, 0.949, 0.966]


@pytest.mark.parametrize("beta", [0.0, 0.02, 0.5])
def test_stiffened_spectrum_keeps_the_helfrich_bending_factor(beta):
    gas = 19.425
    stiff = Stiffness(beta=beta, gas=gas, membrane=PRESSURISED)
    n = np.arange(0, 61, dtype=float)
    omega2 = stiff.legendre_omega(n) ** 2
    membrane = (n - 1) * (n + 2)
    bending = beta * (n - 1) * n * (n + 1) * (n + 2)  # Helfrich 1973, unchanged
    assert omega2[0] == pytest.approx(gas - 2.0, rel=1e-15)
    assert omega2[1] == 0.0  # the free translation, exactly
    assert omega2[2:] == pytest.approx((membrane + bending)[2:], rel=1e-14)
    # the paper's operator: n (n + 1) + the same bending term
    paper = Stiffness(beta=beta, gas=gas).legendre_omega(n) ** 2
    assert paper[1:] == pytest.approx((n * (n + 1) + bending)[1:], rel=1e-14)
    assert stiff.membrane_value(stiff.omega_squared(n[1:] * (n[1:] + 1))) == pytest.approx(
        n[1:] * (n[1:] + 1), rel=1e-12, abs=1e-12
    )


@pytest.mark.parametrize(("gas", "kappa"), [("isothermal", 1.0), ("adiabatic", 1.4)])
def test_breathing_mode_is_6_kappa_p_abs_over_p_minus_2(gas, kappa):
    case = pressurised_case(gas)
    expected = 6.0 * kappa * (P + ATMOSPHERE) / P - 2.0  # the sources' formula, by hand
    omega = legendre_series(case.phi_a, case.damping_law, stiffness=case.stiffness).omega
    assert omega[0] ** 2 == pytest.approx(expected, rel=1e-13, abs=0)
    assert case.as_dict()["omega0_squared"] == pytest.approx(expected, rel=1e-13, abs=0)
    if gas == "adiabatic":  # the check value of the notes: 17.43, omega_0 = 4.17
        assert expected == pytest.approx(17.425, abs=1e-12)
        assert math.sqrt(expected) == pytest.approx(4.17, abs=5e-3)


def _energy(n: int, eps: float, tension: float = 1.0, radius: float = 1.0) -> float:
    """``T A - P V`` of the surface ``r = R + eps P_n(cos phi)``, P = 2 T / R, by quadrature."""
    from numpy.polynomial.legendre import Legendre

    p = Legendre.basis(n)
    dp = p.deriv()

    def radius_at(phi: float) -> tuple[float, float]:
        x = math.cos(phi)
        return radius + eps * p(x), -eps * dp(x) * math.sin(phi)

    def area(phi: float) -> float:
        r, dr = radius_at(phi)
        return 2 * math.pi * r * math.sqrt(r * r + dr * dr) * math.sin(phi)

    def volume(phi: float) -> float:
        r, _ = radius_at(phi)
        return 2 * math.pi / 3 * r**3 * math.sin(phi)

    options = {"epsabs": 0.0, "epsrel": 1e-13, "limit": 200}
    a = quad(area, 0, math.pi, **options)[0]
    v = quad(volume, 0, math.pi, **options)[0]
    return tension * a - (2 * tension / radius) * v


@pytest.mark.parametrize("n", [0, 1, 2, 3, 5])
def test_second_variation_of_area_and_volume_gives_the_operator(n):
    """The derivation itself: ``T dA - P dV`` of an exact surface, second order in eps.

    Independent of the model code: area and volume of ``r = 1 + eps P_n`` by quadrature;
    their second-order part must be ``(T/2) (n - 1)(n + 2) int P_n^2 dOmega``.
    """
    eps = 1e-3
    second = (_energy(n, eps) + _energy(n, -eps) - 2 * _energy(n, 0.0)) / (2 * eps * eps)
    expected = 0.5 * float(PRESSURISED.legendre(n)) * 4 * math.pi / (2 * n + 1)
    assert second == pytest.approx(expected, rel=2e-5, abs=2e-5)
    first = (_energy(n, eps) - _energy(n, -eps)) / (2 * eps)
    assert abs(first) < 20 * eps * eps  # P = 2 T / R: an equilibrium (O(eps^2) is third order)


@pytest.mark.parametrize("law", [ModalRatio(0.13), Rayleigh(0.3, 0.04)])
def test_n_equal_1_is_a_free_translation_its_amplitude_stays_constant(law):
    case = pressurised_case()
    series = legendre_series(
        case.phi_a, law, SpectralFilter("lanczos", 30), stiffness=case.stiffness
    )
    assert series.omega[1] == 0.0
    t = np.linspace(0.0, 4 * math.pi, 97)
    q1 = series.modal_coordinates(t)[:, 1]
    start = series.weights[1] * series.coefficients[1]
    assert start != 0.0  # the initial condition (3.10) has a translation part a_1
    assert np.all(q1 == start)
    assert np.all(series.modal_coordinates(t, 1)[:, 1] == 0.0)
    # the paper's operator makes the same amplitude oscillate at sqrt(2)
    paper = legendre_series(case.phi_a, law, SpectralFilter("lanczos", 30))
    assert paper.modal_coordinates(np.array([math.pi]))[0, 1] != start


@pytest.mark.parametrize("phi_a", [1.6, 2.0, 2.6, 3.1, math.pi - 1e-3])
def test_square_integral_of_f_three_ways(phi_a):
    """``int F^2 dOmega / 2 pi``: the formula, adaptive quadrature, and Parseval on a_n."""
    import mpmath

    with mpmath.workdps(40):
        xa = mpmath.cos(mpmath.mpf(phi_a))
        direct = float(mpmath.quad(lambda x: (xa / x - 1) ** 2, [-1, xa]))
    assert square_integral(phi_a) == pytest.approx(direct, rel=1e-11)
    if phi_a < 3.0:  # Parseval: sum a_n^2 2 / (2n + 1); F is continuous, a_n ~ n^-2
        a = legendre_coefficients_recurrence(phi_a, 4000)
        n = np.arange(a.size)
        assert float(np.sum(a * a * 2 / (2 * n + 1))) == pytest.approx(direct, rel=1e-8)


def test_eq_3_7_balances_the_kinetic_energy_with_the_pressurised_energies():
    """phi_a from |v0| with the gas and the -2 u^2 term: the shape equals (v0 / R c)^2."""
    from twoball.modal.initial import _energy_shape, gas_energy_shape

    case = pressurised_case()
    gas = case.stiffness.gas
    xa = math.cos(case.phi_a)
    f2 = quad(lambda x: (xa / x - 1.0) ** 2, -1.0, xa, epsabs=0.0, epsrel=1e-13)[0]
    shape = _energy_shape(case.phi_a) + gas_energy_shape(case.phi_a, gas) - f2
    assert shape == pytest.approx((case.v0 / (case.radius * case.wave_speed)) ** 2, rel=1e-12)
    paper = Case.from_pressure(P, M, gas="adiabatic")
    assert case.phi_a < paper.phi_a  # less energy per flattening: a flatter ball
    assert case.phi_a_source == "eq. (3.7)"
    # at the preset's own measured point phi_a stays the measured one
    given = Case(pressure=P, gas="adiabatic", membrane="pressurised")
    assert given.phi_a == 2.6
    assert phi_a_from_v0(4.1, R, 320.0, 0.0, Membrane()) == phi_a_from_v0(4.1, R, 320.0)


def test_paper_default_is_unchanged_bit_for_bit():
    base = twoball.liftoff()
    same = twoball.liftoff(Case.preset("basketball", membrane="paper"))
    assert (same.t_liftoff_s, same.v_liftoff_m_s) == (base.t_liftoff_s, base.v_liftoff_m_s)
    assert Case().membrane == Membrane("paper") and not Case().stiff
    assert base.as_dict()["membrane"] == "paper"


def test_pressurised_liftoff_of_the_basketball_moves_by_the_operator():
    """Same phi_a, c, gas: only the operator differs (docs/pressurised.rst, the table)."""
    fixed = {"phi_a": 2.6, "pressure": P, "gas": "adiabatic"}
    paper = twoball.liftoff(Case(**fixed))
    pressurised = twoball.liftoff(Case(**fixed, membrane="pressurised"))
    assert paper.lifted and pressurised.lifted
    assert pressurised.t_liftoff_s > paper.t_liftoff_s  # the lower frequencies: later
    assert pressurised.as_dict()["membrane"] == "pressurised"
    assert pressurised.as_dict()["omega0_squared"] == pytest.approx(
        paper.as_dict()["omega0_squared"] - 2.0, rel=1e-14
    )


@pytest.mark.parametrize(
    ("call", "name"),
    [
        (lambda: Membrane("flat"), "membrane"),
        (lambda: Membrane(2), "membrane"),
        (lambda: Case(membrane="flat"), "membrane"),
        (lambda: Case(membrane="pressurised"), "gas"),  # no gas: omega_0^2 = -2
        (lambda: Case.from_pressure(P, M, membrane="pressurised"), "gas"),
        (lambda: Stiffness(gas=1.5, membrane=PRESSURISED), "gas"),
        (lambda: stiffness_from_si(radius=R, pressure=P, membrane="pressurised"), "gas"),
        (lambda: twoball.fem.eigen(membrane="flat"), "membrane"),
    ],
)
def test_bad_membranes_are_refused_in_one_line(call, name):
    with pytest.raises(ParameterError) as caught:
        call()
    assert caught.value.name == name
    assert "\n" not in str(caught.value)
