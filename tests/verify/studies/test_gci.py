"""The grid convergence index (verify/studies/gci.py) on synthetic sequences with exact answers."""

import math

import pytest

from twoball.verify.studies.gci import classify, gci, three_grid_order


def test_gci_of_a_monotone_second_order_sequence():
    h = (0.1, 0.2, 0.4)
    values = [7.0 - 3.0 * x**2 for x in h]
    result = gci(values, h)
    assert result.convergence == "monotone" and not result.flagged
    assert result.order == pytest.approx(2.0, rel=1e-12)
    assert result.extrapolated == pytest.approx(7.0, rel=1e-14)
    assert result.approximate_error == pytest.approx(abs(values[1] - values[0]) / values[0])
    assert result.extrapolated_error == pytest.approx(abs(7.0 - values[0]) / 7.0)
    # GCI = Fs |eps21| / (r^p - 1) = 1.25 * 0.09 / 3 = 1.25 * (exact error of grid 1)
    assert result.gci_fine_absolute == pytest.approx(1.25 * 0.03, rel=1e-12)
    assert result.gci_fine == pytest.approx(1.25 * 0.03 / values[0], rel=1e-12)


def test_gci_with_unequal_ratios_iterates_to_the_exact_order():
    h = (0.1, 0.25, 0.4)  # r21 = 2.5, r32 = 1.6
    values = [2.0 + 0.7 * x**3 for x in h]
    order, converged = three_grid_order(*values, r21=2.5, r32=1.6)
    assert converged and order == pytest.approx(3.0, rel=1e-10)
    result = gci(values, h)
    assert result.order == pytest.approx(3.0, rel=1e-10)
    assert result.extrapolated == pytest.approx(2.0, rel=1e-12)


def test_gci_reproduces_the_worked_example_of_celik_2008():
    # Table 1 of Celik et al. (2008), first column: r21 = 1.5, r32 = 1.333
    result = gci([6.063, 5.972, 5.863], [1.0, 1.5, 2.0])
    assert result.order == pytest.approx(1.53, abs=0.005)
    assert result.extrapolated == pytest.approx(6.1685, abs=5e-4)
    assert result.approximate_error == pytest.approx(0.015, abs=5e-4)
    assert result.extrapolated_error == pytest.approx(0.017, abs=5e-4)
    assert result.gci_fine == pytest.approx(0.022, abs=5e-4)


def test_oscillatory_sequence_is_flagged():
    # phi_k = 1 + (-1)^k h_k^2 with h = 0.1, 0.2, 0.4: eps21/eps32 = -1/4
    h = (0.1, 0.2, 0.4)
    values = (1.0 + 0.01, 1.0 - 0.04, 1.0 + 0.16)
    assert classify(values[1] - values[0], values[2] - values[1]) == "oscillatory"
    result = gci(values, h)
    assert result.convergence == "oscillatory" and result.flagged
    assert result.order == pytest.approx(2.0, rel=1e-12)  # |eps32/eps21| = 4 = 2^2
    assert math.isfinite(result.gci_fine)


@pytest.mark.parametrize(
    "values",
    [
        (1.0 + 1 / 0.1, 1.0 + 1 / 0.2, 1.0 + 1 / 0.4),  # monotone divergence, e ~ 1/h
        (1.0 + 0.64, 1.0 - 0.16, 1.0 + 0.04),  # oscillatory divergence
        (2.0, 2.0 + 1e-3, 2.0 + 1e-3),  # the two coarse grids agree, the fine one moves
    ],
)
def test_divergent_sequences_are_flagged_and_get_no_error_band(values):
    result = gci(values, (0.1, 0.2, 0.4))
    assert result.convergence == "divergent" and result.flagged
    assert math.isinf(result.gci_fine) and result.extrapolated == values[0]
    assert result.as_dict()["gci_fine"] is None


def test_exact_and_infinitely_fast_sequences():
    exact = gci([3.0, 3.0, 3.0], [0.1, 0.2, 0.4])
    assert exact.convergence == "exact" and exact.gci_fine == 0.0 and not exact.flagged
    fast = gci([3.0, 3.0, 3.5], [0.1, 0.2, 0.4])  # two finest agree exactly
    assert fast.convergence == "monotone" and math.isinf(fast.order)
    assert fast.extrapolated == 3.0 and fast.gci_fine == 0.0


def test_gci_rejects_bad_grids():
    with pytest.raises(ValueError):
        gci([1.0, 2.0], [0.1, 0.2])
    with pytest.raises(ValueError):
        gci([1.0, 2.0, 3.0], [0.2, 0.1, 0.4])  # not finest first
    with pytest.raises(ValueError):
        gci([1.0, math.nan, 3.0], [0.1, 0.2, 0.4])
