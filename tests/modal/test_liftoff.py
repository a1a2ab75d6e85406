"""Lift-off criteria (i)-(ii) of §3(a) against closed forms, brute force and the paper."""

import math

import numpy as np
import pytest

from twoball._common.errors import NumericalError, ParameterError
from twoball.modal.filters import SpectralFilter
from twoball.modal.legendre import legendre_series
from twoball.modal.liftoff import SampledPoleMotion, find_liftoff
from twoball.modal.parameters import preset
from twoball.modal.series import ModalSeries


def single_mode(amplitude: float, omega: float) -> ModalSeries:
    """u(t) = amplitude cos(omega t) at the pole: one undamped mode, no filter weight."""
    filt = SpectralFilter("none", 1000)
    return ModalSeries([omega], [amplitude], [1.0], 0.0, filt)


def brute_force_gap(series, gamma, candidate, end, count=200001):
    t = np.linspace(candidate.t, end, count)[1:]
    dt = t - candidate.t
    s = candidate.displacement + candidate.velocity * dt - 0.5 * gamma * dt**2
    return s - series.pole(t).u


def test_single_mode_liftoff_time_and_velocity_in_closed_form():
    # u = A cos(w t), A < 0: u_tt + gamma = -A w^2 cos(w t) + gamma crosses zero from above
    # where cos(w t) = -gamma/(|A| w^2) for the first time, moving up with u_t = |A| w sin(w t).
    a, w, gamma = -0.01, 5.0, 0.05
    phase = math.acos(gamma / (a * w * w))
    result = find_liftoff(single_mode(a, w), gamma, t_end=2.0, horizon="window")
    assert result.lifted
    assert result.t == pytest.approx(phase / w, abs=1e-12)
    assert result.velocity == pytest.approx(-a * w * math.sin(phase), abs=1e-12)
    assert result.rejected == ()


def test_single_mode_recontact_depends_on_the_horizon():
    # The body flies about 2 v_l / gamma ~ 2 time units and lands on the pole again.
    # Over a window of 12 every candidate is caught again except the last one, whose
    # landing falls after the window; with the paper's horizon dt < t_l the first is kept.
    a, w, gamma = -0.01, 5.0, 0.05
    long = find_liftoff(single_mode(a, w), gamma, t_end=12.0, horizon="window")
    assert long.lifted and long.t > 12.0 - 2.5
    assert len(long.rejected) >= 5
    assert all(c.reason == "re-contact" and c.t < c.recontact <= 12.0 for c in long.rejected)
    period = 2 * math.pi / w
    np.testing.assert_allclose(np.diff([c.t for c in long.candidates]), period, atol=1e-11)
    paper = find_liftoff(single_mode(a, w), gamma, t_end=12.0, horizon="paper")
    assert paper.lifted and paper.t == pytest.approx(long.candidates[0].t, abs=1e-12)
    short = find_liftoff(single_mode(a, w), gamma, t_end=1.0, horizon="window")
    assert short.lifted and short.t == pytest.approx(paper.t, abs=1e-12)


def test_no_crossing_means_no_liftoff():
    result = find_liftoff(single_mode(-1e-6, 3.0), gamma=0.05)  # |u_tt| never reaches gamma
    assert not result.lifted and result.candidates == ()


@pytest.mark.parametrize(
    ("damping", "kind"), [(0.13, "lanczos"), (0.0, "lanczos"), (0.3, "lanczos"), (0.13, "none")]
)
def test_every_verdict_against_brute_force(damping, kind):
    gamma = preset("basketball").gamma
    series = legendre_series(2.6, damping, SpectralFilter(kind, 30))
    result = find_liftoff(series, gamma)
    assert result.candidates
    for c in result.candidates:
        state = series.pole(np.array([c.t - 1e-7, c.t, c.t + 1e-7]))
        assert abs(state.u_tt[1] + gamma) < 1e-9  # criterion (i): contact force zero ...
        assert state.u_tt[0] + gamma > 0 > state.u_tt[2] + gamma  # ... crossed from above
        if c.reason.startswith("moving down"):
            assert c.velocity <= 0
        elif c.reason == "re-contact":
            assert c.velocity > 0
            gap = brute_force_gap(series, gamma, c, 4 * math.pi)
            assert gap.min() < 0
            dt = c.recontact - c.t
            s = c.displacement + c.velocity * dt - 0.5 * gamma * dt**2
            assert abs(s - series.pole(c.recontact).u) < 1e-12
            t = np.linspace(c.t, c.recontact, 20001)[1:-1]
            dt = t - c.t
            inside = c.displacement + c.velocity * dt - 0.5 * gamma * dt**2 - series.pole(t).u
            assert np.all(inside[t > c.t + 1e-3] > 0)  # the first re-contact, not a later one
        else:
            assert c.accepted and c is result.candidates[-1]
            assert c.velocity > 0
            assert brute_force_gap(series, gamma, c, 4 * math.pi)[100:].min() > 0


def test_sampled_motion_gives_the_same_liftoff():
    gamma = preset("basketball").gamma
    series = legendre_series(2.6, 0.13, SpectralFilter("lanczos", 30))
    exact = find_liftoff(series, gamma)
    t = np.linspace(0.0, 4 * math.pi, 4001)
    u, u_t, u_tt = series.pole(t)
    sampled = find_liftoff(SampledPoleMotion(t, u, u_t, u_tt), gamma)
    assert sampled.lifted
    assert sampled.t == pytest.approx(exact.t, rel=1e-6)
    assert sampled.velocity == pytest.approx(exact.velocity, rel=1e-6)
    assert len(sampled.candidates) == len(exact.candidates)


@pytest.mark.parametrize(
    ("kwargs", "flag"),
    [
        ({"gamma": 0.0}, "gamma"),
        ({"gamma": 1e-3, "t_end": 0.0}, "t_end"),
        ({"gamma": 1e-3, "horizon": "forever"}, "recontact"),
        ({"gamma": 1e-3, "samples_per_period": 8}, "samples_per_period"),
    ],
)
def test_invalid_liftoff_options(kwargs, flag):
    series = legendre_series(2.6, 0.13, SpectralFilter("lanczos", 30))
    with pytest.raises(ParameterError) as error:
        find_liftoff(series, **kwargs)
    assert error.value.name == flag


def test_sampled_motion_rejects_nan():
    t = np.linspace(0, 1, 5)
    with pytest.raises(NumericalError):
        SampledPoleMotion(t, np.full(5, np.nan), t, t)


def test_flight_clearance_agrees_with_the_verdicts_and_brute_force():
    from twoball.modal.liftoff import flight_clearance

    gamma = preset("basketball").gamma
    series = legendre_series(2.6, 0.13, SpectralFilter("lanczos", 30))
    result = find_liftoff(series, gamma)
    for c in result.candidates:
        if c.velocity <= 0:
            continue
        clearance = flight_clearance(series, gamma, c.t, 4 * math.pi)
        brute = brute_force_gap(series, gamma, c, 4 * math.pi)[100:].min()
        assert (clearance > 0) == c.accepted == (brute > 0)
    assert flight_clearance(series, gamma, 5.0, 4.0) == math.inf
