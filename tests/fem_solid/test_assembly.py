"""The factorised 3-D assembly equals scikit-fem's generic assembly of the same forms."""

from __future__ import annotations

import numpy as np
from skfem import Basis, ElementTetP2, ElementVector, asm

from twoball.fem_solid.assembly import elasticity_matrices
from twoball.fem_solid.forms import elasticity, mass
from twoball.fem_solid.mesh import ball


def test_matches_asm():
    mesh = ball(1)
    k, m, basis = elasticity_matrices(mesh, 0.7, 1.3, 1.1, chunk_size=10)
    reference = Basis(mesh, ElementVector(ElementTetP2()), intorder=4)
    k2 = asm(elasticity(0.7, 1.3), reference)
    m2 = asm(mass(1.1), reference)
    assert basis.N == reference.N
    assert abs(k - k2).max() < 1e-13 * abs(k2).max()
    assert abs(m - m2).max() < 1e-13 * abs(m2).max()
    # rigid motions have no energy: translations and a rotation
    x = basis.doflocs
    parts = basis.split_indices()
    rot = np.zeros(basis.N)
    rot[parts[0]], rot[parts[1]] = -x[1, parts[0]], x[0, parts[1]]
    shift = np.zeros(basis.N)
    shift[parts[2]] = 1.0
    for field in (rot, shift):
        assert abs(field @ (k @ field)) < 1e-12
