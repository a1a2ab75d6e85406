"""Fields from the Krylov Ritz basis; the full eigen route by dense LAPACK or slicing (issue 16)."""

from __future__ import annotations

import numpy as np
import pytest
import scipy.linalg as sl
import twoball.fem_membrane.slicing as slicing
from twoball.fem_membrane.build import build_space
from twoball.fem_membrane.eigen import eigen_table, eigenpairs, lowest_eigenpairs
from twoball.fem_membrane.initial import initial_moments
from twoball.fem_membrane.krylov import krylov_modal_series
from twoball.fem_membrane.mesh import icosphere
from twoball.fem_membrane.modal import modal_series
from twoball.fem_membrane.ritz_field import field_times
from twoball.fem_membrane.space import sphere_space
from twoball.modal.filters import SpectralFilter

from twoball._common.errors import ParameterError

PHI_A = 2.6
DAMPING = 0.13
FILTER = SpectralFilter("lanczos", 30)


def _m_norm(M, fields: np.ndarray) -> np.ndarray:
    """M-norm of each row (one field per row)."""
    return np.sqrt(np.einsum("ti,ti->t", fields @ M, fields))


def test_ritz_fields_agree_with_full_route_at_level_3():
    """u, u_t, u_tt on every node: Ritz basis vs all eigenpairs, 1e-8 in the M-norm."""
    space = build_space("sphere", level=3, order=2, phi_a=PHI_A)  # 2562 unknowns
    moments = initial_moments(space, PHI_A)
    pairs = eigenpairs(space.stiffness, space.mass, FILTER.omega_cut**2)
    full = modal_series(pairs, moments, space.pole_row, DAMPING, FILTER)
    t_end = 4 * np.pi
    fast, info = krylov_modal_series(
        space,
        moments,
        DAMPING,
        FILTER,
        t_end=t_end,
        vectors=True,
        field_times=field_times(t_end, FILTER.omega_cut),
    )
    assert info.pairs is not None and info.converged
    assert len(info.pairs) < len(pairs)  # fewer modes than the full route (817)
    times = np.linspace(0.0, t_end, 37)  # not the criterion's sample instants
    M = space.mass
    for derivative in range(3):
        reference = full.field(times, pairs.vectors.T, derivative)
        ritz = fast.field(times, info.pairs.vectors.T, derivative)
        error = _m_norm(M, ritz - reference).max() / _m_norm(M, reference).max()
        assert error < 1e-8, (derivative, error)
    # the pole-only rule stops earlier: the field rule is what makes the fields converge
    _, pole_only = krylov_modal_series(space, moments, DAMPING, FILTER, t_end=t_end)
    assert pole_only.basis_size < info.basis_size


def _forced_slicing(monkeypatch):
    monkeypatch.setattr(slicing, "DENSE_ALWAYS", 0)
    monkeypatch.setattr(slicing, "DENSE_COUNT", 10**9)


@pytest.mark.parametrize("path", ["dense", "slicing"])
def test_lowest_pairs_for_counts_across_cluster_boundaries(path, monkeypatch):
    """Any count 1..n: values vs LAPACK on the dense matrices, residuals, M-orthonormality."""
    if path == "slicing":
        _forced_slicing(monkeypatch)
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
    _forced_slicing(monkeypatch)
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


def test_dense_path_keeps_small_eigenvalues_accurate(monkeypatch):
    """M x = nu (K + M) x: the lowest eigenvalues as accurate as shift-invert Lanczos.

    Axisymmetric P4 on 160 elements has lambda_max ~ 1e8; the direct dense
    K x = lambda M x loses about eps lambda_max / lambda (1e-11 at lambda ~ 300).
    """
    space = build_space("axisym", elements=160, order=4)
    K, M = space.stiffness, space.mass
    dense = lowest_eigenpairs(K, M, 200)  # 641 unknowns, 200 pairs: dense
    assert dense.method == "dense"
    _forced_slicing(monkeypatch)
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


@pytest.mark.parametrize(
    "argv",
    [
        ["export", "--out", "{tmp}/f.vtu", "--route", "bogus"],
        ["render", "--out", "{tmp}/f.png", "--route", "eigen"],
        ["plot", "pole", "--out", "{tmp}/f.png", "--route", "dense"],
        ["plot", "eigen", "--out", "{tmp}/f.png", "--route", "full"],
        ["eigen", "--level", "1", "--order", "1", "--count", "43"],
    ],
)
def test_bad_route_or_count_is_one_line_exit_2(argv, tmp_path, capsys):
    from twoball.cli.main import main

    with pytest.raises(SystemExit) as stop:
        main([a.format(tmp=tmp_path) for a in argv])
    err = capsys.readouterr().err.strip().splitlines()
    assert stop.value.code == 2 and len(err) == 1, err
    flag = "--count" if "--count" in argv else "--route"
    assert err[0].startswith("twoball: error: " + flag), err
    assert not any(tmp_path.iterdir())  # no partial output
