"""The axisymmetric forms are the 3-D forms of the swept field (checked on a manufactured field)."""

from __future__ import annotations

import math

import numpy as np
import pytest
from skfem import Basis, ElementTriP2, ElementVector, asm

from twoball.fem_solid.forms import axisymmetric_elasticity, axisymmetric_mass, lame
from twoball.fem_solid.mesh import half_disc


def test_energy_of_a_uniform_dilatation():
    """u = (r, z) (uniform strain eps = I): energy 1/2 a(u,u) = (1/2)(9 lambda + 6 mu) V;
    mass m(u, u) = int |x|^2 dV = 4 pi / 5."""
    mesh = half_disc(3)
    basis = Basis(mesh, ElementVector(ElementTriP2()), intorder=6)
    lam, mu = lame(0.3)
    u = basis.project(lambda x: np.array([x[0], x[1]]))
    a = asm(axisymmetric_elasticity(lam, mu), basis)
    m = asm(axisymmetric_mass(1.0), basis)
    volume = 4 * math.pi / 3
    assert u @ (a @ u) == pytest.approx((9 * lam + 6 * mu) * volume, rel=1e-6)
    assert u @ (m @ u) == pytest.approx(4 * math.pi / 5, rel=1e-6)


def test_lame():
    lam, mu = lame(0.25, 2.0)
    assert lam == pytest.approx(2.0) and mu == 2.0
