"""Bad input gives ParameterError naming the parameter and its valid range (the CLI shows flags)."""

from __future__ import annotations

import pytest
from twoball.fem_membrane import eigen_table, fem_pole_motion
from twoball.fem_membrane.axisym import axisym_space
from twoball.fem_membrane.mesh import icosphere, ring_sphere

from twoball._common.errors import ParameterError

PHI_A, DAMPING = 2.6, 0.13


@pytest.mark.parametrize(
    ("options", "flag", "valid"),
    [
        ({"mesh": "sphere", "level": -1}, "level", "an integer >= 0"),
        ({"mesh": "sphere", "level": 1.5}, "level", "an integer >= 0"),
        ({"mesh": "axisym", "order": 5}, "order", "1, 2, 3 or 4"),
        ({"mesh": "axisym", "order": 0}, "order", "1, 2, 3 or 4"),
        ({"mesh": "axisym", "elements": 1}, "elements", "an integer >= 2"),
        ({"mesh": "axisym", "scheme": "alpha", "dt": 0.0}, "dt", "a finite number > 0"),
        ({"mesh": "axisym", "scheme": "alpha", "dt": -1e-3}, "dt", "a finite number > 0"),
        ({"mesh": "axisym", "scheme": "alpha", "dt": float("nan")}, "dt", "a finite number > 0"),
        ({"mesh": "cube"}, "mesh", "one of sphere, ring, axisym"),
        ({"mesh": "axisym", "scheme": "euler"}, "scheme", "one of modal, alpha"),
        ({"mesh": "axisym", "damping_model": "viscous"}, "damping_model", "one of"),
        ({"mesh": "axisym", "scheme": "alpha", "rho_inf": 1.5}, "rho_inf", "in [0, 1]"),
        ({"mesh": "axisym", "scheme": "alpha", "t_end": -1.0}, "t_end", "a finite time > 0"),
        ({"mesh": "axisym", "initial": "exact"}, "initial", "one of projection, interpolation"),
    ],
)
def test_fem_pole_motion_rejects(options, flag, valid):
    with pytest.raises(ParameterError) as error:
        fem_pole_motion(PHI_A, DAMPING, "lanczos", **options)
    assert error.value.name == flag
    assert valid in str(error.value) and flag in str(error.value)


def test_physical_parameters_are_checked():
    with pytest.raises(ParameterError, match="phi_a"):
        fem_pole_motion(1.0, DAMPING, mesh="axisym")
    with pytest.raises(ParameterError, match="damping"):
        fem_pole_motion(PHI_A, 1.0, mesh="axisym")
    with pytest.raises(ParameterError, match="sigma"):
        fem_pole_motion(PHI_A, DAMPING, "gaussian", mesh="axisym")


def test_mesh_builders_reject():
    with pytest.raises(ParameterError, match="level must be an integer >= 0, got -1"):
        icosphere(-1)
    with pytest.raises(ParameterError, match="order must be 1, 2, 3 or 4"):
        icosphere(1, order=5)
    with pytest.raises(ParameterError, match="phi_a"):
        ring_sphere(1, 4.0)
    with pytest.raises(ParameterError, match="elements must be an integer >= 2"):
        axisym_space(1, PHI_A)


def test_eigen_table_rejects():
    with pytest.raises(ParameterError, match="level"):
        eigen_table("sphere", level=-2)
    with pytest.raises(ParameterError, match="order"):
        eigen_table("axisym", order=5)
    with pytest.raises(ParameterError, match="count"):
        eigen_table("axisym", elements=10, count=0)
