"""Damping laws (modal/damping.py): the Rayleigh fit, ratios of any size per mode, SI laws."""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.integrate import solve_ivp

import twoball
from twoball import Case, ParameterError
from twoball.modal.damping import ModalRatio, Rayleigh
from twoball.modal.filters import SpectralFilter
from twoball.modal.legendre import legendre_series
from twoball.modal.series import CRITICAL_BAND, ModalSeries

DAMPING = 0.13


def test_fit_matches_the_ratio_at_both_frequencies():
    fit = Rayleigh.fit(DAMPING, math.sqrt(2), math.sqrt(30 * 31))
    assert fit.ratios(np.array([math.sqrt(2), math.sqrt(930)])) == pytest.approx(
        [DAMPING, DAMPING], rel=1e-14
    )
    inside = fit.ratios(np.array([3.0, 10.0, 20.0]))
    assert np.all(inside < DAMPING)  # below D between the fitting frequencies
    assert fit.ratios(np.array([60.0]))[0] > DAMPING
    with pytest.raises(ParameterError, match="rayleigh_frequencies"):
        Rayleigh.fit(DAMPING, 5.0, 2.0)


PLAIN = SpectralFilter("none", 1000)  # no weights: every mode as given


def single(omega: float, law, q0: float = 1.0) -> ModalSeries:
    return ModalSeries(np.array([omega]), np.array([q0]), np.array([1.0]), law, PLAIN)


def integrated(omega: np.ndarray, decay: np.ndarray, q0: np.ndarray, t: np.ndarray):
    """``q'' + d q' + w^2 q = 0`` by a Runge-Kutta integrator (second method)."""

    def rhs(_: float, y: np.ndarray) -> np.ndarray:
        q, v = y[: omega.size], y[omega.size :]
        return np.concatenate([v, -(omega**2) * q - decay * v])

    y0 = np.concatenate([q0, np.zeros_like(q0)])
    sol = solve_ivp(rhs, (0.0, t[-1]), y0, t_eval=t, method="DOP853", rtol=1e-12, atol=1e-14)
    q, v = sol.y[: omega.size], sol.y[omega.size :]
    a = -(omega**2)[:, None] * q - decay[:, None] * v
    return q.sum(axis=0), v.sum(axis=0), a.sum(axis=0)


def test_rayleigh_modes_under_critically_and_over_damped_match_an_integrator():
    omega = np.array([0.0, 0.5, 2.0, 6.0, 10.0, 30.0])
    law = Rayleigh(0.3, 0.1)  # zeta: inf, 0.325, 0.175, 0.325, 0.515, 1.505
    series = ModalSeries(omega, np.linspace(1.0, 0.4, 6), np.ones(6), law, PLAIN)
    zeta = series.ratios
    assert math.isinf(zeta[0]) and zeta[-1] > 1.0 and np.all(zeta[1:-1] < 1.0)
    t = np.linspace(0.0, 6.0, 301)
    u, u_t, u_tt = integrated(omega, law.decay(omega), np.linspace(1.0, 0.4, 6), t)
    state = series.pole(t)
    assert np.max(np.abs(state.u - u)) < 1e-10
    assert np.max(np.abs(state.u_t - u_t)) < 1e-9
    assert np.max(np.abs(state.u_tt - u_tt)) < 1e-8


def test_a_critically_damped_mode_is_1_plus_wt_times_exp_minus_wt():
    w = 3.0
    t = np.linspace(0.0, 5.0, 201)
    series = single(w, Rayleigh(2.0 * w, 0.0))  # decay 2 w: zeta = 1 exactly
    assert series.law_terms[3] is not None  # the secular term t exp(-w t)
    exact = (1 + w * t) * np.exp(-w * t)
    state = series.pole(t)
    assert np.max(np.abs(state.u - exact)) < 1e-15
    assert np.max(np.abs(state.u_t + w * w * t * np.exp(-w * t))) < 1e-14
    assert np.max(np.abs(state.u_tt - w * w * (w * t - 1) * np.exp(-w * t))) < 1e-13
    assert np.max(np.abs(series.jerk(t) - w**3 * (2 - w * t) * np.exp(-w * t))) < 1e-12
    # either side of zeta = 1 the solution is continuous: O(|zeta - 1|) away
    for delta in (1e-9, 1e-6, 1e-3):
        for side in (-1.0, 1.0):
            near = single(w, Rayleigh(2.0 * w * (1.0 + side * delta), 0.0)).pole(t).u
            assert np.max(np.abs(near - exact)) < 2 * delta
    assert CRITICAL_BAND <= 1e-10


def test_an_over_damped_mode_decays_without_oscillating_and_tends_to_its_slow_rate():
    """The limit zeta -> inf: q -> exp(-w^2 t / d), monotone, no zero crossing."""
    w = 2.0
    t = np.linspace(0.0, 50.0, 2001)
    for beta in (1.0, 10.0, 100.0):
        d = beta * w * w
        state = single(w, Rayleigh(0.0, beta)).pole(t)
        assert np.all(state.u > 0.0) and np.all(np.diff(state.u) <= 0.0)
        slow = np.exp(-w * w * t / d)
        zeta = d / (2 * w)
        # q - exp(-w^2 t/d) = O(1/zeta^2) uniformly (the fast exponential and the rate shift)
        assert np.max(np.abs(state.u - slow)) < 2.0 / zeta**2


def test_the_paper_ratio_through_a_law_object_is_bit_identical():
    f = SpectralFilter("lanczos", 30)
    a = legendre_series(2.6, 0.13, f)
    b = legendre_series(2.6, ModalRatio(0.13), f)
    t = np.linspace(0.0, 4 * math.pi, 1001)
    for x, y in zip(a.pole(t), b.pole(t), strict=True):
        assert np.array_equal(x, y)
    assert np.array_equal(a.jerk(t), b.jerk(t))
    assert b.damping == 0.13 and b.law_terms is None
    report = twoball.liftoff(damping=twoball.ModalRatio(0.13))
    base = twoball.liftoff()
    assert (report.t_liftoff_s, report.v_liftoff_m_s) == (base.t_liftoff_s, base.v_liftoff_m_s)


def test_zero_rayleigh_is_the_undamped_series_and_small_ratios_agree_with_d():
    f = SpectralFilter("lanczos", 30)
    t = np.linspace(0.0, 4 * math.pi, 801)
    undamped = legendre_series(2.6, 0.0, f).pole(t).u
    zero = legendre_series(2.6, Rayleigh(0.0, 0.0), f).pole(t).u
    assert np.max(np.abs(zero - undamped)) < 1e-13
    # pure mass damping alpha = 2 D w for one mode equals the ratio D on that mode
    w, ratio = 3.0, 0.2
    assert (
        np.max(
            np.abs(single(w, Rayleigh(2 * ratio * w, 0.0)).pole(t).u - single(w, ratio).pole(t).u)
        )
        < 1e-14
    )


def test_si_coefficients_are_scaled_by_c_at_the_api_edge():
    c = 320.0
    law = Rayleigh(100.0, 2.5e-5)  # alpha [1/s], beta [s]
    scaled = law.scaled(c)
    assert (scaled.alpha, scaled.beta) == pytest.approx((100.0 / c, 2.5e-5 * c), rel=1e-15)
    omega_si = np.array([50.0, 500.0, 5000.0])  # rad/s
    assert scaled.ratios(omega_si / c) == pytest.approx(law.ratios(omega_si), rel=1e-14)
    case = Case.preset("basketball", rayleigh=law)
    assert case.damping_law == scaled
    assert case.as_dict()["rayleigh"]["alpha_1_s"] == 100.0
    fitted = Case.preset("basketball", rayleigh=Rayleigh()).damping_law
    band = (math.sqrt(2.0), math.sqrt(30 * 31))
    assert fitted.ratios(np.array(band)) == pytest.approx([0.13, 0.13], rel=1e-14)
    pressurised = Case.from_pressure(
        77200.0, 0.567, gas="adiabatic", membrane="pressurised", rayleigh=Rayleigh()
    ).damping_law
    high = math.sqrt(29 * 32)  # (N - 1)(N + 2)
    assert pressurised.ratios(np.array([2.0, high])) == pytest.approx([0.13, 0.13], rel=1e-14)


def test_rayleigh_on_the_closed_form_through_every_entry_point():
    law = Rayleigh(100.0, 2.5e-5)
    by_case = twoball.liftoff(Case.preset("basketball", rayleigh=law))
    by_verb = twoball.liftoff(damping=law)
    assert by_case.t_liftoff_s == by_verb.t_liftoff_s
    assert by_case.as_dict()["rayleigh"]["beta_s"] == 2.5e-5
    d = by_case.as_dict()["truncation"]  # the converged reference uses the same law
    assert d["converged"] and abs(d["v_difference"]) < 0.05
    fitted = twoball.liftoff(damping=Rayleigh())
    assert fitted.as_dict()["rayleigh"]["fitted"] is True
    assert by_case.v_liftoff_m_s != twoball.liftoff().v_liftoff_m_s


@pytest.mark.parametrize(
    ("call", "name"),
    [
        (lambda: Rayleigh(-1.0, 0.0), "alpha"),
        (lambda: Rayleigh(0.1, -1e-3), "beta"),
        (lambda: Rayleigh(0.1, None), "alpha"),
        (lambda: Rayleigh(math.nan, 0.0), "alpha"),
        (lambda: Case(rayleigh=0.3), "rayleigh"),
        (lambda: ModalSeries([1.0], [1.0], [1.0], Rayleigh(), PLAIN), "damping"),
        (lambda: ModalSeries([1.0], [1.0], [1.0], "rayleigh", PLAIN), "damping"),
        # a body of finite mass: the contact model takes the modal ratio D only
        (lambda: twoball.liftoff(damping=Rayleigh(1.0, 0.0), body=twoball.Body(0.1)), "rayleigh"),
        # two laws at once
        (
            lambda: twoball.liftoff(
                Case.preset("basketball", rayleigh=Rayleigh(1.0, 0.0)), damping=ModalRatio(0.2)
            ),
            "damping",
        ),
        (
            lambda: twoball.converge(Case.preset("basketball", rayleigh=Rayleigh()), study="modes"),
            "rayleigh",
        ),
    ],
)
def test_bad_laws_and_combinations_are_refused_in_one_line(call, name):
    with pytest.raises(ParameterError) as caught:
        call()
    assert caught.value.name == name
    assert "\n" not in str(caught.value)


def test_each_law_names_its_own_field_and_states_its_range():
    with pytest.raises(ParameterError, match=r"^ratio must be in \[0, 1\), got 1.5$"):
        ModalRatio(1.5)
    # a bad value is told by its range, before the missing partner
    with pytest.raises(ParameterError, match=r"^alpha must be a finite number >= 0 \[1/s\]"):
        Rayleigh(alpha=-1.0)
    with pytest.raises(ParameterError, match=r"^beta must be given together with alpha"):
        Rayleigh(beta=0.01)
