"""The converged limit N -> infinity of the Legendre series (modal/converged.py)."""

import math

import numpy as np
import pytest

from twoball._costs import check_series
from twoball.modal.converged import converged_legendre, filtered_liftoff, unfiltered_series
from twoball.modal.cost import decaying_work, reference_estimate
from twoball.modal.decay import DecayingSeries
from twoball.modal.filters import SpectralFilter
from twoball.modal.guards import Truncation, truncation_warnings
from twoball.modal.legendre import legendre_series
from twoball.modal.liftoff import DEFAULT_T_END, find_liftoff
from twoball.modal.parameters import preset
from twoball.modal.report import legendre_liftoff


def test_converged_reference_settles_to_1e7():
    case = preset("basketball")
    limit = converged_legendre(case)
    assert limit.converged and limit.clear
    (_, t0, v0), (_, t1, v1) = limit.history[-2:]
    assert abs(v1 - v0) <= 1e-7 * abs(v1) and abs(t1 - t0) <= 1e-7 * t1
    assert limit.velocity * case.scalings.velocity == pytest.approx(3.94537, abs=1e-5)


# --- The truncation guard's converged reference is converged, and the warning follows it


def _ms(case, t: float) -> float:
    return t * case.scalings.time * 1e3


def test_tennis_reference_is_the_root_the_series_converges_to() -> None:
    """N = 30 lifts off on a neighbouring root; the reference must not follow it there."""
    case = preset("tennis")
    limit = converged_legendre(case, flight=False)
    assert limit.converged
    # the plain unfiltered series at N = 60 (no filter, no mode dropped): 0.51832 ms
    plain = find_liftoff(unfiltered_series(case, 60), case.gamma)
    assert limit.t == pytest.approx(plain.t, rel=1e-6)
    assert limit.velocity == pytest.approx(plain.velocity, rel=1e-5)
    # the plain Lanczos series settles there too (N = 240: 0.51826 ms, v_l -0.3 %)
    lanczos = find_liftoff(
        legendre_series(
            case.phi_a, case.damping, SpectralFilter("lanczos", 240), stiffness=case.stiffness
        ),
        case.gamma,
    )
    assert lanczos.t == pytest.approx(limit.t, rel=2e-4)
    assert lanczos.velocity == pytest.approx(limit.velocity, rel=5e-3)
    assert _ms(case, limit.t) == pytest.approx(0.5183, abs=1e-4)


@pytest.mark.parametrize("modes", [60, 240])
def test_tennis_warning_goes_away_once_converged(modes: int) -> None:
    report = legendre_liftoff(preset("tennis").derive(modes=modes))
    block = report.extra["truncation"]
    assert block["converged"] and block["converged_modes"] > modes  # never below the N asked
    assert block["t_liftoff_s"] == pytest.approx(0.5183e-3, rel=1e-3)
    assert block["v_liftoff_m_s"] == pytest.approx(1.4576, rel=1e-3)
    assert not [w for w in report.warnings if "truncation" in w]


def test_tennis_n30_is_warned_against_the_converged_numbers() -> None:
    report = legendre_liftoff(preset("tennis"))
    block = report.extra["truncation"]
    assert block["t_difference"] == pytest.approx(0.5826 / 0.5183 - 1, abs=2e-3)  # +12.4 %
    (text,) = [w for w in report.warnings if "truncation" in w]
    assert "0.5183 ms" in text and "1.458 m/s" in text


def test_volleyball_reference_converges() -> None:
    """Its lift-off (0.24 / c) is early: the unfiltered tail still counts at small N."""
    report = legendre_liftoff(preset("volleyball"))
    block = report.extra["truncation"]
    assert block["converged"] and block["t_liftoff_s"] is not None
    assert block["t_liftoff_s"] == pytest.approx(report.t_liftoff_s, rel=0.01)
    plain = find_liftoff(
        legendre_series(
            report.case.phi_a,
            report.case.damping,
            SpectralFilter("lanczos", 240),
            stiffness=report.case.stiffness,
        ),
        report.case.gamma,
    )
    assert block["t_liftoff_s"] == pytest.approx(plain.t * report.case.scalings.time, rel=1e-3)


def test_an_unknown_reference_is_said() -> None:
    unknown = Truncation(30, 60, False, None, None, None, None, True, "reason given")
    (text,) = truncation_warnings(unknown)
    assert "not known" in text and "reason given" in text
    only_result = Truncation(30, 240, True, None, None, None, None, True)
    (text,) = truncation_warnings(only_result)
    assert "does not within the window" in text
    neither = Truncation(30, 240, True, None, None, None, None, False)
    assert truncation_warnings(neither) == []


def test_a_spurious_early_liftoff_is_warned() -> None:
    """The paper horizon lets N = 30 lift off on a Gibbs precursor at 0.48 ms (limit: 9.96 ms)."""
    report = legendre_liftoff(preset("basketball").derive(damping=0.2), recontact="paper")
    block = report.extra["truncation"]
    assert report.t_liftoff_s < 1e-3 and block["t_liftoff_s"] == pytest.approx(9.956e-3, rel=1e-3)
    assert any(w.startswith("N = 30 truncation: t_l -95") for w in report.warnings)


@pytest.mark.parametrize("name", ["basketball", "tennis", "volleyball"])
def test_blockwise_evaluation_matches_the_plain_series(name: str) -> None:
    case = preset(name)
    series = legendre_series(
        case.phi_a, case.damping, SpectralFilter("lanczos", 120), stiffness=case.stiffness
    )
    plain = find_liftoff(series, case.gamma)
    fast = filtered_liftoff(case, 120)
    assert fast.t == pytest.approx(plain.t, rel=1e-11)
    assert fast.velocity == pytest.approx(plain.velocity, rel=1e-9)
    times = np.linspace(0.05, DEFAULT_T_END, 777)
    blockwise = DecayingSeries(series, DEFAULT_T_END).pole(times).u_tt
    np.testing.assert_allclose(blockwise, series.pole(times).u_tt, rtol=0, atol=1e-11)


def test_reference_cost_is_estimated_with_the_modes_it_sums() -> None:
    """The estimate counts the terms DecayingSeries sums (within 25 %), and bending's omega."""
    case = preset("tennis")
    n = np.arange(1921)
    measured = DecayingSeries(
        legendre_series(
            case.phi_a, case.damping, SpectralFilter("lanczos", 1920), stiffness=case.stiffness
        ),
        DEFAULT_T_END,
    ).work
    _, estimated = decaying_work(case.stiffness.legendre_omega(n), case.damping, DEFAULT_T_END)
    assert estimated == pytest.approx(measured, rel=0.25)
    # linear, not quadratic, in N: N = 960 costs < 1 s where the plain series took 147 s
    assert reference_estimate(4 * math.pi, 960, case.damping, case.stiffness).seconds < 2.0
    membrane = check_series(960, 4 * math.pi).seconds
    assert (
        check_series(960, 4 * math.pi, None, case.damping, case.stiffness).seconds > 30 * membrane
    )
