"""Solved balls shared by the tests of files, pictures and figures (SI, basketball preset)."""

import pytest

import twoball
from twoball.fem_membrane.options import MeshOptions
from twoball.modal.parameters import preset
from twoball.verify.output.fields import (
    ball_model,
    coupled_model,
    field_mesh,
    field_series,
    frame_times,
)

#: The contact case: few Legendre modes keep the coupled solves short.
CONTACT_CASE = preset("basketball").derive(modes=10)


@pytest.fixture(scope="package")
def case():
    return preset("basketball")


@pytest.fixture(scope="package")
def model(case):
    """Both backends on the level-2 P1 icosphere."""
    return ball_model(case, field_mesh(MeshOptions(level=2, order=1)))


@pytest.fixture(scope="package")
def coarse(case):
    """Both backends on the level-1 P1 icosphere."""
    return ball_model(case, field_mesh(MeshOptions("sphere", level=1, order=1)))


@pytest.fixture(scope="package", params=[(2, 1), (1, 2)], ids=["P1-level2", "P2-level1"])
def sphere(request, case):
    """Both backends on the level-2 P1 and the level-1 P2 icosphere."""
    level, order = request.param
    return ball_model(case, field_mesh(MeshOptions(level=level, order=order)))


@pytest.fixture(scope="package")
def sphere_series(sphere):
    """Five evenly spaced frames of ``sphere`` and its lift-off."""
    return field_series(sphere, frame_times(sphere, frames=5))


@pytest.fixture(scope="package")
def coupled():
    """A body of mass ratio 0.004 on the level-1 P2 icosphere, both backends coupled to it."""
    mesh = twoball.MeshOptions("sphere", level=1, order=2)
    return coupled_model(CONTACT_CASE, ("fem", "legendre"), twoball.Body(0.004), mesh)
