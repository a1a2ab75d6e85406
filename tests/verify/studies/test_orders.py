"""Observed orders and Richardson extrapolation (verify/studies/orders.py) on exact sequences."""

import math

import numpy as np
import pytest

from twoball.verify.studies.gci import richardson
from twoball.verify.studies.orders import (
    OrderBand,
    analyse,
    error_ratios,
    least_squares_order,
    observed_order,
    step_orders,
)

H = 0.5 ** np.arange(1, 7)  # 1/2 .. 1/64, coarse to fine


@pytest.mark.parametrize("p", [1.0, 2.0, 4.0, 0.5])
def test_pure_power_law_has_exact_order(p):
    e = 3.0 * H**p
    assert step_orders(H, e) == pytest.approx(p, rel=1e-12)
    fit = least_squares_order(H, e)
    assert fit.order == pytest.approx(p, rel=1e-12)
    assert fit.constant == pytest.approx(3.0, rel=1e-10)
    assert fit.residual < 1e-12 and fit.points == H.size
    assert error_ratios(e) == pytest.approx(2.0**p)


def test_two_grid_order_and_its_arguments():
    assert observed_order(0.04, 0.01, 0.2, 0.1) == pytest.approx(2.0)
    assert observed_order(-0.04, 0.01, 0.2, 0.1) == pytest.approx(2.0)  # magnitudes
    assert math.isnan(observed_order(0.0, 0.01, 0.2, 0.1))
    with pytest.raises(ValueError):
        observed_order(0.04, 0.01, 0.1, 0.1)
    with pytest.raises(ValueError):
        observed_order(0.04, 0.01, -0.2, 0.1)


def test_richardson_removes_the_leading_term_exactly():
    f = lambda h: 1.0 + 2.0 * h**2  # noqa: E731
    assert richardson(f(0.1), f(0.2), 2.0, 2.0) == pytest.approx(1.0, abs=1e-15)
    g = lambda h: 1.0 + h**2 + h**3  # noqa: E731  (next term h^3: the extrapolate is O(h^3))
    errors = [abs(richardson(g(h), g(2 * h), 2.0, 2.0) - 1.0) for h in (0.1, 0.05, 0.025)]
    assert step_orders([0.1, 0.05, 0.025], errors) == pytest.approx(3.0, abs=0.05)
    assert richardson(5.0, 7.0, 2.0, math.inf) == 5.0
    with pytest.raises(ValueError):
        richardson(1.0, 2.0, 1.0, 2.0)
    with pytest.raises(ValueError):
        richardson(1.0, 2.0, 2.0, 0.0)


def test_order_band_fails_too_low_and_too_high():
    band = OrderBand(2.0, 0.3, 0.5)
    assert band.contains(1.8) and band.contains(2.5)
    assert not band.contains(1.6) and not band.contains(2.6) and not band.contains(math.nan)
    assert band.describe() == "2 [1.7, 2.5]"


def test_analyse_against_an_exact_value():
    values = 1.0 + 0.5 * H**2 + 0.1 * H**3
    result = analyse(H, values, reference=1.0)
    assert result.reference_kind == "exact"
    assert result.errors == pytest.approx(values - 1.0)
    assert result.orders[-1] == pytest.approx(2.0, abs=0.01)
    assert result.fit.order == pytest.approx(2.0, abs=0.1)
    assert result.gci is not None and result.gci.convergence == "monotone"
    assert result.extrapolated == pytest.approx(1.0, abs=1e-5)


def test_analyse_without_reference_uses_richardson_then_finest():
    values = 4.0 - H**4
    result = analyse(H, values)
    assert result.reference_kind == "richardson"
    assert result.reference == pytest.approx(4.0, abs=1e-14)
    assert result.finest_order == pytest.approx(4.0, abs=1e-6)
    wobbly = 4.0 + (-1.0) ** np.arange(H.size) * H**2
    result = analyse(H, wobbly)
    assert result.reference_kind == "finest" and math.isnan(result.errors[-1])
    assert result.gci is not None and result.gci.flagged


def test_analyse_needs_a_decreasing_sequence():
    with pytest.raises(ValueError):
        analyse([0.1, 0.2, 0.4], [1.0, 2.0, 3.0])
    with pytest.raises(ValueError):
        analyse([0.1], [1.0])
