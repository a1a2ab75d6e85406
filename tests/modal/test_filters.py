"""Spectral filters as functions of frequency (eq. (3.16))."""

import math

import numpy as np
import pytest

from twoball._common.errors import ParameterError
from twoball.modal.filters import SpectralFilter, legendre_frequency


def test_lanczos_is_sinc_with_pi_and_zero_at_cutoff():
    f = SpectralFilter("lanczos", 30)
    w = legendre_frequency(np.arange(31))
    expected = np.ones(31)
    expected[1:] = np.sin(math.pi * w[1:] / w[30]) / (math.pi * w[1:] / w[30])
    np.testing.assert_allclose(f(w), expected, atol=1e-15)
    assert f(w[30]) == pytest.approx(0.0, abs=1e-15)


def test_printed_is_eq_3_16_without_pi():
    f = SpectralFilter("printed", 30)
    w = legendre_frequency(np.arange(1, 31))
    np.testing.assert_allclose(f(w), np.sin(w / w[-1]) / (w / w[-1]), rtol=1e-15)
    assert f(w[-1]) == pytest.approx(math.sin(1.0))


@pytest.mark.parametrize("kind", ["lanczos", "printed", "none"])
def test_every_filter_truncates_between_n_and_n_plus_1(kind):
    f = SpectralFilter(kind, 10)
    w = legendre_frequency(np.arange(0, 20))
    weights = f(w)
    assert np.all(weights[11:] == 0)
    assert weights[0] == 1.0
    if kind != "lanczos":
        assert np.all(weights[:11] > 0)
    # a finite-element frequency slightly above omega_N still belongs to degree N
    assert (f(np.array([w[10] * 1.01]))[0] != 0) == (kind != "lanczos")


def test_bad_filter_inputs():
    with pytest.raises(ParameterError, match="sigma"):
        SpectralFilter("hamming", 30)
    with pytest.raises(ParameterError, match="modes"):
        SpectralFilter("lanczos", 0)
