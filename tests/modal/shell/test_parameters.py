"""The shell's dimensionless parameters, their checks, and the SI conversions."""

from __future__ import annotations

import math

import pytest

from twoball._common.errors import ParameterError
from twoball.modal.shell.parameters import ShellParameters, shell_from_si
from twoball.modal.stiffness import ATMOSPHERE


@pytest.mark.parametrize(
    ("field", "value"),
    [("poisson", 0.0), ("poisson", 0.51), ("bending", -1e-9), ("prestress", -0.1), ("gas", -1.0)],
)
def test_out_of_range_values_are_refused_by_name(field, value):
    kwargs = {"poisson": 0.3, field: value}
    with pytest.raises(ParameterError) as error:
        ShellParameters(**kwargs)
    assert error.value.name == field


def test_unstable_breathing_mode_is_refused_unless_held_by_gas():
    with pytest.raises(ParameterError, match="breathing"):
        ShellParameters(0.3, prestress=1.3)
    assert ShellParameters(0.3, prestress=1.3, gas=0.1).breathing_squared == pytest.approx(0.1)


def test_from_ratios():
    shell = ShellParameters.from_ratios(0.5, thickness_ratio=0.1, wall_stiffness_ratio=20.0)
    assert shell.bending == pytest.approx(0.01 / 12)
    assert shell.prestress == pytest.approx(0.05)
    assert shell.thickness_ratio == pytest.approx(0.1)
    with pytest.raises(ParameterError):
        ShellParameters.from_ratios(0.5, wall_stiffness_ratio=0.0)


def test_tennis_ball_in_si():
    """E = 6 MPa, h = 3.2 mm, nu = 0.5, R = 33.5 mm, m = 57.7 g, P = 82.7 kPa (modal/presets.py)."""
    e, h, nu, r, m, p = 6e6, 3.2e-3, 0.5, 0.0335, 0.0577, 82700.0
    ball = shell_from_si(
        youngs_modulus=e, thickness=h, poisson=nu, radius=r, mass=m, pressure=p, gas="adiabatic"
    )
    c = e * h / (1 - nu**2)  # 25600 N/m
    rho = m / (4 * math.pi * r**2)
    assert ball.wall_stiffness == pytest.approx(25600.0)
    assert ball.parameters.prestress == pytest.approx(p * r / 2 / c)
    assert ball.parameters.gas == pytest.approx(3 * 1.4 * (p + ATMOSPHERE) * r / c)
    assert ball.extensional_speed == pytest.approx(math.sqrt(c / rho))
    assert ball.in_plane_arrival == pytest.approx(math.pi * r / math.sqrt(c / rho))
    assert ball.pressure_wave_speed == pytest.approx(math.sqrt(p * r / 2 / rho) / r)
    # one unit of Omega is c_e / R rad/s
    assert float(ball.omega_rad_s(1.0)) == pytest.approx(math.sqrt(c / rho) / r)
    assert float(ball.frequency_hz(2 * math.pi)) == pytest.approx(math.sqrt(c / rho) / r)


def test_si_inputs_are_checked():
    good = dict(youngs_modulus=1e6, thickness=1e-3, poisson=0.5, radius=0.1, mass=0.1)
    for name, bad in (("youngs_modulus", 0.0), ("thickness", -1.0), ("mass", 0.0)):
        with pytest.raises(ParameterError) as error:
            shell_from_si(**{**good, name: bad})
        assert error.value.name == name
    with pytest.raises(ParameterError):
        shell_from_si(**good, gas="steam")
