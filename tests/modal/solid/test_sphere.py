"""The SI sphere: derived moduli and speeds, and Lamb's frequencies in rad/s."""

from __future__ import annotations

import math

import pytest

from twoball._common.errors import ParameterError
from twoball.modal.solid.sphere import ElasticSphere


def test_derived_quantities():
    s = ElasticSphere(radius=0.025, density=1100.0, youngs_modulus=5e6, poisson=0.25)
    mu, lam = s.shear_modulus, s.lame_lambda
    assert mu == pytest.approx(2e6) and lam == pytest.approx(2e6)  # nu = 1/4: lambda = mu
    assert s.pressure_speed == pytest.approx(math.sqrt((lam + 2 * mu) / 1100.0))
    assert s.pressure_speed / s.shear_speed == pytest.approx(math.sqrt(3))
    assert s.mass == pytest.approx(4 / 3 * math.pi * 0.025**3 * 1100)
    # n = 2: eta = 2.6399 (reference) -> omega = eta c_s / R
    omega = s.angular_frequencies(2, 1)[0]
    assert omega * s.radius / s.shear_speed == pytest.approx(2.6399, abs=6e-5)


@pytest.mark.parametrize("field", ["radius", "density", "youngs_modulus"])
def test_invalid(field):
    values = dict(radius=0.025, density=1100.0, youngs_modulus=5e6, poisson=0.25)
    values[field] = -1.0
    with pytest.raises(ParameterError):
        ElasticSphere(**values)
    with pytest.raises(ParameterError):
        ElasticSphere(0.025, 1100.0, 5e6, 0.5)
