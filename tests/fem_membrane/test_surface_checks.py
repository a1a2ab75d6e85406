"""Sphere fit of a user's mesh (fem_membrane/surface_checks.py)."""

from __future__ import annotations

import numpy as np
import pytest
from twoball.fem_membrane.mesh import ring_sphere
from twoball.fem_membrane.surface_checks import sphere_fit

from tests.meshes import CENTER, RADIUS, on_ball

PHI_A = 2.6


def test_sphere_fit_is_exact_for_unevenly_spread_points():
    # a ring sphere crowds vertices near phi_a: their mean is off the centre, the fit is not
    points = on_ball(ring_sphere(2, PHI_A))
    center, radius = sphere_fit(points)
    assert np.linalg.norm(points.mean(axis=0) - CENTER) > 1e-3 * RADIUS
    assert np.allclose(center, CENTER, atol=1e-15) and radius == pytest.approx(RADIUS, rel=1e-14)
