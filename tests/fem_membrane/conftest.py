"""The axisymmetric P2 model of the paper's case shared by the time-stepping tests."""

import pytest

from twoball.fem_membrane.solve import modal_model

PHI_A, DAMPING = 2.6, 0.13


@pytest.fixture(scope="package")
def axisym_model():
    return modal_model(PHI_A, DAMPING, "lanczos", mesh="axisym", elements=100, order=2)
