"""Eigenvalues l (l + 1): convergence orders, clusters, completeness of the slicing solver."""

from __future__ import annotations

import math

import numpy as np
import pytest
import scipy.linalg as sl
import twoball.fem_membrane.slicing as slicing
from twoball.fem_membrane.axisym import axisym_space
from twoball.fem_membrane.eigen import eigen_table, eigenpairs, inertia, lowest_eigenpairs
from twoball.fem_membrane.mesh import icosphere
from twoball.fem_membrane.space import sphere_space

COUNT = 25  # nonzero eigenvalues checked: l = 1 .. 4 and the first of l = 5
BANDS = {1: (1.7, 2.3), 2: (3.5, 4.6)}


def sphere_exact(count: int) -> np.ndarray:
    return np.array([d * (d + 1.0) for d in range(8) for _ in range(2 * d + 1)][:count])


def sphere_errors(level: int, order: int) -> np.ndarray:
    space = sphere_space(icosphere(level), order)
    pairs = lowest_eigenpairs(space.stiffness, space.mass, 36)  # complete clusters l <= 5
    exact = sphere_exact(COUNT + 1)[1:]
    return np.abs(pairs.values[1 : COUNT + 1] / exact - 1.0)


def observed_orders(errors: list[np.ndarray], ratio: float = 2.0) -> np.ndarray:
    worst = np.array([e.max() for e in errors])
    return np.log(worst[:-1] / worst[1:]) / math.log(ratio)


@pytest.mark.parametrize("order", [1, 2])
def test_sphere_eigenvalue_order(order):
    errors = [sphere_errors(level, order) for level in (2, 3, 4)]
    low, high = BANDS[order]
    orders = observed_orders(errors)
    assert np.all((orders > low) & (orders < high)), orders
    # every one of the 25 eigenvalues converges at the rate, not only the worst
    each = np.log2(errors[-2] / errors[-1])
    assert np.all((each > low) & (each < high)), each


@pytest.mark.slow
@pytest.mark.parametrize("order", [1, 2])
def test_sphere_eigenvalue_order_levels_2_to_5(order):
    errors = [sphere_errors(level, order) for level in (2, 3, 4, 5)]
    low, high = BANDS[order]
    orders = observed_orders(errors)
    assert np.all((orders > low) & (orders < high)), orders


@pytest.mark.parametrize("order", [1, 2])
def test_axisymmetric_eigenvalue_order(order):
    n = np.arange(1, COUNT + 1)
    errors = []
    for elements in (50, 100, 200, 400):
        space = axisym_space(elements, 2.6, order)
        pairs = lowest_eigenpairs(space.stiffness, space.mass, COUNT + 1)
        errors.append(np.abs(pairs.values[1:] / (n * (n + 1.0)) - 1.0))
    low, high = BANDS[order]
    orders = observed_orders(errors)
    assert np.all((orders > low) & (orders < high)), orders


@pytest.mark.parametrize("order", [1, 2])
def test_clusters_have_2l_plus_1_members(order):
    rows = eigen_table("sphere", level=3, order=order, count=COUNT)
    assert len(rows) == COUNT + 1
    assert rows[0]["l"] == 0 and abs(rows[0]["value"]) < 1e-10
    for row in rows:
        assert row["multiplicity"] == row["expected_multiplicity"] == 2 * row["l"] + 1
        assert row["exact"] == row["l"] * (row["l"] + 1)
        assert row["relative_error"] < (0.06 if order == 1 else 1e-3)


def test_axisymmetric_table_is_simple():
    rows = eigen_table("axisym", elements=100, order=2, count=10)
    assert [row["l"] for row in rows] == list(range(11))
    assert all(row["multiplicity"] == row["expected_multiplicity"] == 1 for row in rows)


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
