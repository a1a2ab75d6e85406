"""Check results (verify/checks/results.py): bounded checks fail on missing or NaN values."""

import math

from twoball.verify.checks.results import Check, bounded


def test_bounded_fails_on_missing_or_nan_values():
    assert bounded("a", "", 1e-3, 1e-2).passed
    assert not bounded("a", "", 2e-2, 1e-2).passed
    assert not bounded("a", "", None, 1e-2).passed
    assert not bounded("a", "", math.nan, 1e-2).passed
    assert Check("a", "", 1.0, None, False).verdict == "FAIL"
