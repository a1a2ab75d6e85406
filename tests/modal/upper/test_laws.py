"""A body's own contact law: the stiffness formulas, the dashpot from e, the contact times."""

from __future__ import annotations

import math

import pytest

import twoball
from twoball.modal.lumped.fitting import linear_restitution
from twoball.modal.solid.hertz import hertz_contact_time
from twoball.modal.upper.laws import ContactLaw


def test_the_three_stiffness_laws():
    pressure = ContactLaw("pressure", 0.8, radius=0.03, pressure=1e5)
    assert pressure.stiffness() == pytest.approx(2 * math.pi * 0.03 * 1e5, rel=1e-15)
    # on a ball of radius 0.12 m: 2 pi R* P with R* = r R / (r + R)
    assert pressure.stiffness(0.12) == pytest.approx(2 * math.pi * 0.024 * 1e5, rel=1e-15)
    shell = ContactLaw("reissner", 0.9, radius=0.02, youngs_modulus=2e9, poisson=0.3,
                       thickness=4e-4)  # fmt: skip
    k = 4 * 2e9 * 4e-4**2 / (0.02 * math.sqrt(3 * (1 - 0.09)))
    assert shell.stiffness() == pytest.approx(k, rel=1e-15)
    assert shell.stiffness(0.12) == shell.stiffness()  # a point load on the shell
    hertz = ContactLaw("hertz", 0.7, radius=0.01, youngs_modulus=1e7, poisson=0.5)
    assert hertz.stiffness() == pytest.approx(4 / 3 * 1e7 / 0.75 * math.sqrt(0.01), rel=1e-15)
    assert (hertz.power, hertz.damping_power, hertz.disc_factor) == (1.5, 0.25, 1.0)
    assert (pressure.power, pressure.damping_power, pressure.disc_factor) == (1.0, 0.0, 2.0)
    # the disc: a^2 = f R* delta
    assert pressure.disc_radius(1e-3) == pytest.approx(math.sqrt(2 * 0.03 * 1e-3))
    assert hertz.disc_radius(1e-3, 0.12) == pytest.approx(math.sqrt(0.12 / 13 * 1e-3))


def test_contact_times_on_a_rigid_floor():
    pressure = ContactLaw("pressure", 1.0, radius=0.03, pressure=1e5)
    m = 0.05
    assert pressure.contact_time(m) == pytest.approx(
        math.pi * math.sqrt(m / pressure.stiffness()), rel=1e-12
    )
    damped = ContactLaw("pressure", 0.8, radius=0.03, pressure=1e5)
    q = damped.reduced_damping()
    expected = linear_restitution(q, tensile=False)[1] * math.sqrt(m / damped.stiffness())
    assert damped.contact_time(m, 3.0) == pytest.approx(expected, rel=1e-12)
    hertz = ContactLaw("hertz", 1.0, radius=0.01, youngs_modulus=1e7, poisson=0.3)
    for speed in (0.5, 4.0):
        closed = hertz_contact_time(m, 0.01, 1e7 / 0.91, speed)
        assert hertz.contact_time(m, speed) == pytest.approx(closed, rel=1e-6)
        assert hertz.undamped_contact_time(m, speed) == pytest.approx(closed, rel=1e-12)


def test_the_dashpot_depends_on_the_mass_not_on_the_speed():
    law = ContactLaw("hertz", 0.6, radius=0.01, youngs_modulus=1e7, poisson=0.3)
    c = law.damping(0.01)
    assert law.damping(0.04) == pytest.approx(2 * c, rel=1e-12)  # b sqrt(m k)
    assert law.power_law(0.01, 0.1).damping == c


@pytest.mark.parametrize(
    ("fields", "name"),
    [
        ({"law": "spring", "restitution": 0.8, "radius": 0.01}, "law"),
        ({"law": "pressure", "restitution": 0.8, "radius": 0.01}, "pressure"),
        ({"law": "pressure", "restitution": 0.1, "radius": 0.01, "pressure": 1e5}, "restitution"),
        (
            {
                "law": "hertz",
                "restitution": 0.8,
                "radius": 0.01,
                "youngs_modulus": 1e6,
                "poisson": 0.3,
                "pressure": 1e5,
            },
            "pressure",
        ),  # fmt: skip
        (
            {
                "law": "reissner",
                "restitution": 0.8,
                "radius": 0.01,
                "youngs_modulus": 1e6,
                "poisson": 0.3,
                "thickness": 0.02,
            },
            "thickness",
        ),  # fmt: skip
        ({"law": "pressure", "restitution": 0.8, "radius": -1.0, "pressure": 1e5}, "radius"),
    ],
)
def test_refusals_name_the_field(fields, name):
    with pytest.raises(twoball.ParameterError) as error:
        ContactLaw(**fields)
    assert error.value.name == name
