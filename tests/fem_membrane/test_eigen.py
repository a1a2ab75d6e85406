"""Eigenpairs and the eigenvalue table (fem_membrane/eigen.py) against l (l + 1), eq. (3.11)."""

from __future__ import annotations

import math

import numpy as np
import pytest
import scipy.linalg as sl

from tests.fem_membrane.helpers import force_slicing, model
from twoball._common.errors import ParameterError
from twoball.fem_membrane.axisym import axisym_space
from twoball.fem_membrane.build import build_space
from twoball.fem_membrane.eigen import (
    eigen_table,
    lowest_eigenpairs,
    sphere_degree,
)
from twoball.fem_membrane.mesh import icosphere
from twoball.fem_membrane.space import sphere_space
from twoball.modal.filters import SpectralFilter

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


FILTER = SpectralFilter("lanczos", 30)


def test_dense_path_keeps_small_eigenvalues_accurate(monkeypatch):
    """M x = nu (K + M) x: the lowest eigenvalues as accurate as shift-invert Lanczos.

    Axisymmetric P4 on 160 elements has lambda_max ~ 1e8; the direct dense
    K x = lambda M x loses about eps lambda_max / lambda (1e-11 at lambda ~ 300).
    """
    space = build_space("axisym", elements=160, order=4)
    K, M = space.stiffness, space.mass
    dense = lowest_eigenpairs(K, M, 200)  # 641 unknowns, 200 pairs: dense
    assert dense.method == "dense"
    force_slicing(monkeypatch)
    lanczos = lowest_eigenpairs(K, M, 30)
    assert lanczos.method == "slicing"
    values = dense.values[1:30]
    assert np.abs(values / lanczos.values[1:30] - 1.0).max() < 1e-12
    direct = sl.eigh(K.toarray(), M.toarray(), subset_by_index=[0, 29], eigvals_only=True)
    assert np.abs(direct[1:30] / lanczos.values[1:30] - 1.0).max() > 1e-12  # what it avoids


def test_eigen_table_reports_residuals_and_refuses_too_many():
    space_dofs = 42  # sphere level 1, P1
    rows = eigen_table("sphere", level=1, order=1, count=space_dofs)
    assert len(rows) == space_dofs
    assert all(row["residual"] < 1e-9 for row in rows)
    assert rows[0]["orthonormality"] < 1e-12
    with pytest.raises(ParameterError) as error:
        eigen_table("sphere", level=1, order=1, count=space_dofs + 1)
    assert error.value.name == "count"


def test_eigen_table_rejects():
    with pytest.raises(ParameterError, match="level"):
        eigen_table("sphere", level=-2)
    with pytest.raises(ParameterError, match="order"):
        eigen_table("axisym", order=5)
    with pytest.raises(ParameterError, match="count"):
        eigen_table("axisym", elements=10, count=0)


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


@pytest.mark.slow
def test_lowest_eigenpairs_with_a_tie_across_the_cut():
    """P3 level 2, 676 pairs (plot eigen's default there): a multiple eigenvalue straddles the
    cut, which deflation used to chase for ever; against the dense generalized solver."""
    from scipy.linalg import eigh

    space = sphere_space(icosphere(2, 3))
    values = lowest_eigenpairs(space.stiffness, space.mass, 676).values
    dense = eigh(space.stiffness.toarray(), space.mass.toarray(), eigvals_only=True)[:676]
    assert np.allclose(values, dense, rtol=1e-9, atol=1e-9)


@pytest.mark.slow
def test_sphere_clusters_up_to_the_cutoff():
    pairs = model("sphere", 2, 3).pairs
    counts = np.bincount(sphere_degree(pairs.values))
    assert np.array_equal(counts[:16], 2 * np.arange(16) + 1)
    assert pairs.values.max() <= FILTER.omega_cut**2 < pairs.next_value
