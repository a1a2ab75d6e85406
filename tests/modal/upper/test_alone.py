"""A lumped body alone on a rigid floor: the closed forms of its laws through the whole path.

Hertz's contact time 2.8683 (m^2 / (R E*^2 v))^(1/5) at low speed
(:func:`twoball.modal.solid.hertz.hertz_contact_time`), ``pi sqrt(m / k)`` for a
linear law, the damped laws' restitution and durations, the peak compression
``(5 m v^2 / (4 k))^(2/5)`` (Hertz) and ``v sqrt(m / k)`` (linear), and the
books.
"""

from __future__ import annotations

import math

import pytest

import twoball
from twoball.modal.solid.hertz import hertz_contact_time, hertz_max_compression
from twoball.modal.upper.alone import lumped_alone
from twoball.modal.upper.laws import ContactLaw
from twoball.modal.upper.options import LumpedBody


@pytest.mark.parametrize("speed", [0.05, 0.5])
def test_hertz_contact_time_at_low_speed(speed):
    law = ContactLaw("hertz", 1.0, radius=0.01, youngs_modulus=5e7, poisson=0.3)
    alone = lumped_alone(LumpedBody(0.01, law), 0.004, speed, g=0.0, steps=400)
    modulus = 5e7 / (1 - 0.09)
    assert alone.contact_time == pytest.approx(
        hertz_contact_time(0.004, 0.01, modulus, speed), rel=1e-4
    )
    assert alone.peak_compression == pytest.approx(
        hertz_max_compression(0.004, 0.01, modulus, speed), rel=1e-5
    )
    assert alone.restitution == pytest.approx(1.0, abs=1e-12)


def test_linear_law_half_period():
    law = ContactLaw("pressure", 1.0, radius=0.03, pressure=5e4)
    k = law.stiffness()
    alone = lumped_alone(LumpedBody(0.1, law), 0.05, 3.0, g=0.0)
    assert alone.contact_time == pytest.approx(math.pi * math.sqrt(0.05 / k), rel=1e-4)
    assert alone.peak_compression == pytest.approx(3.0 * math.sqrt(0.05 / k), rel=1e-5)
    assert alone.restitution == pytest.approx(1.0, abs=1e-12)
    assert alone.energy["balance"] < 1e-14 * alone.energy["initial"]


@pytest.mark.parametrize("law_name", ["pressure", "reissner", "hertz"])
def test_damped_laws_give_their_restitution_at_any_speed(law_name):
    fields = {
        "pressure": {"radius": 0.03, "pressure": 5e4},
        "reissner": {"radius": 0.02, "youngs_modulus": 2e9, "poisson": 0.35, "thickness": 4e-4},
        "hertz": {"radius": 0.01, "youngs_modulus": 5e7, "poisson": 0.3},
    }[law_name]
    body = LumpedBody(0.1, ContactLaw(law_name, 0.7, **fields))
    for speed in (1.0, 6.0):
        alone = lumped_alone(body, 0.03, speed, g=0.0)
        assert alone.restitution == pytest.approx(0.7, abs=1e-4)
        assert alone.contact_time == pytest.approx(alone.stated_contact_time, rel=1e-3)
        dissipated = 0.5 * 0.03 * speed**2 * (1 - alone.restitution**2)
        assert alone.energy["dissipated"] == pytest.approx(dissipated, rel=1e-9)


def test_refusals():
    with pytest.raises(twoball.ParameterError, match="body"):
        lumped_alone(twoball.Body(0.1), 0.01, 1.0)
    law = ContactLaw("pressure", 0.8, radius=0.03, pressure=5e4)
    with pytest.raises(twoball.ParameterError, match="speed"):
        lumped_alone(LumpedBody(0.1, law), 0.01, -1.0)
