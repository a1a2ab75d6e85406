"""The full eigen route by dense LAPACK or spectrum slicing (fem_membrane/slicing.py)."""

from __future__ import annotations

import numpy as np
import pytest
import scipy.linalg as sl

import twoball.fem_membrane.slicing as slicing
from tests.fem_membrane.helpers import force_slicing
from twoball.fem_membrane.eigen import eigenpairs, inertia, lowest_eigenpairs
from twoball.fem_membrane.mesh import icosphere
from twoball.fem_membrane.space import sphere_space


@pytest.mark.parametrize("path", ["dense", "slicing"])
def test_lowest_pairs_for_counts_across_cluster_boundaries(path, monkeypatch):
    """Any count 1..n: values vs LAPACK on the dense matrices, residuals, M-orthonormality."""
    if path == "slicing":
        force_slicing(monkeypatch)
    space = sphere_space(icosphere(2), 1)  # 162 unknowns, exact icosahedral multiplicities
    K, M = space.stiffness, space.mass
    n = K.shape[0]
    reference = sl.eigh(K.toarray(), M.toarray(), eigvals_only=True)
    for count in (1, 3, 4, 8, 9, 10, 35, 36, 37, 64, n - 1, n):
        pairs = lowest_eigenpairs(K, M, count)
        assert len(pairs) == count
        assert np.allclose(pairs.values, reference[:count], rtol=1e-9, atol=1e-10), count
        gram = pairs.vectors.T @ (M @ pairs.vectors)
        assert np.abs(gram - np.eye(count)).max() == pytest.approx(pairs.orthonormality)
        assert pairs.orthonormality < 1e-10
        residual = K @ pairs.vectors - (M @ pairs.vectors) * pairs.values
        scale = np.maximum(
            np.linalg.norm(K @ pairs.vectors, axis=0), np.linalg.norm(M @ pairs.vectors, axis=0)
        )
        assert (np.linalg.norm(residual, axis=0) / scale).max() == pytest.approx(
            pairs.max_residual, rel=1e-6, abs=1e-15
        )
        assert pairs.max_residual < 1e-8
        expected = "dense" if count > slicing.DENSE_FRACTION * n or path == "dense" else path
        assert pairs.method == expected


def test_all_pairs_below_cutoff_by_slicing_match_dense(monkeypatch):
    """Slicing over several slices: same values as dense, complete by the inertia."""
    force_slicing(monkeypatch)
    space = sphere_space(icosphere(3), 1)  # 642 unknowns
    K, M = space.stiffness, space.mass
    reference = sl.eigh(K.toarray(), M.toarray(), eigvals_only=True)
    upper = 200.0  # l <= 13: about 196 pairs in about 5 slices of 40
    pairs = eigenpairs(K, M, upper)
    assert pairs.method == "slicing"
    assert len(pairs) == np.count_nonzero(reference <= upper)
    assert np.allclose(pairs.values, reference[: len(pairs)], rtol=1e-9, atol=1e-10)
    assert pairs.next_value == pytest.approx(reference[len(pairs)], rel=1e-9)
    assert pairs.max_residual < 1e-8 and pairs.orthonormality < 1e-10


def test_slicing_solver_matches_dense_and_inertia(monkeypatch):
    monkeypatch.setattr(slicing, "DENSE_DOFS", 100)  # force the sliced Lanczos path
    space = sphere_space(icosphere(2), 1)  # 162 unknowns, exact icosahedral multiplicities
    K, M = space.stiffness, space.mass
    dense = sl.eigh(K.toarray(), M.toarray(), eigvals_only=True)
    upper = 60.0
    pairs = eigenpairs(K, M, upper, window=10)
    assert len(pairs) == np.count_nonzero(dense <= upper) == inertia(K, M, upper) == 49
    assert np.allclose(pairs.values, dense[: len(pairs)], rtol=1e-9, atol=1e-10)
    assert pairs.next_value == pytest.approx(dense[len(pairs)], rel=1e-9)
    gram = pairs.vectors.T @ (M @ pairs.vectors)
    assert np.abs(gram - np.eye(len(pairs))).max() < 1e-9
    residual = K @ pairs.vectors - (M @ pairs.vectors) * pairs.values
    assert np.abs(residual).max() < 1e-8
    for shift in (-0.5, 1.0, 45.0, 59.5):
        assert inertia(K, M, shift) == np.count_nonzero(dense < shift)
    lowest = lowest_eigenpairs(K, M, 30)
    assert np.allclose(lowest.values, dense[:30], rtol=1e-9, atol=1e-10)
