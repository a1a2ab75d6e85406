"""Bracketed roots (modal/roots.py): vectorised bisection and Newton to 1e-12."""

import math

import numpy as np
import pytest

from twoball._common.errors import NumericalError
from twoball.modal.roots import bracketed_roots


def test_bracketed_roots_vectorised_to_1e_12():
    k = np.arange(1, 40)
    lower, upper = k * math.pi - 0.5, k * math.pi + 0.7

    def f(x, i):
        return np.sin(x) * (1 + 0.1 * i)  # each bracket its own function

    roots = bracketed_roots(f, lower, upper, xtol=1e-12)
    np.testing.assert_allclose(roots, k * math.pi, atol=1e-12, rtol=0)
    with pytest.raises(NumericalError):
        bracketed_roots(f, np.array([0.5]), np.array([1.0]))


def test_newton_bracketed_converges_quadratically_to_1e_12():
    from twoball.modal.roots import newton_bracketed

    calls = []

    def f(x, i):
        calls.append(x.size)
        return np.cos(x) - x * (1 + 0.1 * i), -np.sin(x) - (1 + 0.1 * i)

    lower, upper = np.zeros(5), np.ones(5)
    roots = newton_bracketed(f, lower, upper, xtol=1e-12)
    value, _ = f(roots, np.arange(5))
    assert np.all(np.abs(value) < 1e-14)
    assert len(calls) <= 2 + 7  # two end evaluations, then a few Newton steps, no bisection tail
