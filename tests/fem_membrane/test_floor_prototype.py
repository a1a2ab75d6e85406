"""The ball dropped on the floor on axisymmetric P2 elements (fem_membrane/floor_prototype.py)."""

import pytest
from twoball.modal.floor_prototype import FloorModel, drop


def test_finite_elements_agree_with_modes():
    """Axisymmetric P2 (E = 20) against Legendre modes (N = 40): same node spacing pi/40."""
    from twoball.fem_membrane.floor_prototype import AxisymFloorModel, axisym_drop

    fe = axisym_drop(AxisymFloorModel(elements=20, damping=0.13), 0.02)
    modal = drop(FloorModel(modes=40, points=20, damping=0.13), 0.02)
    assert fe.impulse_balance < 1e-10 and fe.energy_error < 1e-10
    assert fe.e2 == pytest.approx(modal.e2, rel=1e-3)
    assert fe.contact_time == pytest.approx(modal.contact_time, rel=3e-3)
    assert fe.flattening_max == pytest.approx(modal.flattening_max, rel=2e-3)
