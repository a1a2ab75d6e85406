"""Finite elements of the stiffened ball (mixed bending, rank-one gas) against the closed form."""

from __future__ import annotations

import math

import numpy as np
import pytest
import scipy.linalg as sl
from twoball.fem_membrane.axisym import axisym_space
from twoball.fem_membrane.eigen import lowest_eigenpairs
from twoball.fem_membrane.mesh import icosphere
from twoball.fem_membrane.modal import modal_series
from twoball.fem_membrane.shell import ShellOperator, shell_eigenpairs_direct, stiff_series
from twoball.fem_membrane.space import sphere_space
from twoball.modal.filters import SpectralFilter
from twoball.modal.stiffness import Stiffness

import twoball
from twoball import Case

STIFF = Stiffness(beta=0.02, gas=18.7)  # about the tennis preset's
BANDS = {1: (1.7, 2.3), 2: (3.5, 4.6)}  # h^(2p), as the membrane's (tests/test_fem_eigen.py)


DEGREES = 8  # axisymmetric: n = 1 .. 8


def exact_axisym(count: int) -> np.ndarray:
    n = np.arange(count)
    return STIFF.legendre_omega(n) ** 2


def split_gas(space, pairs) -> tuple[float, np.ndarray]:
    """The breathing mode's eigenvalue (the one the volume functional sees) and the rest."""
    volume = np.abs((space.mass @ np.ones(space.dofs)) @ pairs.vectors)
    k = int(np.argmax(volume))
    others = np.delete(volume, k)
    assert others.max() < 1e-8 * volume[k]  # every other mode keeps the volume
    return float(pairs.values[k]), np.delete(pairs.values, k)


def orders(worst: list[float], ratio: float = 2.0) -> np.ndarray:
    w = np.array(worst)
    return np.log(w[:-1] / w[1:]) / math.log(ratio)


def _sphere_exact(count: int) -> np.ndarray:
    degrees = np.array([d for d in range(8) for _ in range(2 * d + 1)][:count])
    return STIFF.legendre_omega(degrees) ** 2


def _rayleigh(space, vectors: np.ndarray) -> np.ndarray:
    """Rayleigh quotients of the shell operator (saddle-point products, no spectral map)."""
    op = ShellOperator(space, STIFF)
    kx = op.matmat(vectors)
    values = np.einsum("ij,ij->j", vectors, kx) / np.einsum(
        "ij,ij->j", vectors, space.mass @ vectors
    )
    residual = kx - (space.mass @ vectors) * values
    assert np.abs(residual).max() < 1e-8 * values.max()  # they are eigenpairs of K_s
    return values


TENNIS = Case.preset("tennis")


@pytest.mark.parametrize("order", [1, 2])
def test_axisymmetric_stiff_eigenvalues_converge_at_order_2p(order):
    exact = exact_axisym(DEGREES + 1)[1:]
    worst = []
    for elements in (40, 80, 160):
        space = axisym_space(elements, 2.6, order)
        gas, values = split_gas(space, shell_eigenpairs_direct(space, STIFF, DEGREES + 1))
        assert gas == pytest.approx(STIFF.gas, rel=1e-12)  # 1^T M 1 = 4 pi exactly
        worst.append(np.max(np.abs(values / exact - 1.0)))
    low, high = BANDS[order]
    observed = orders(worst)
    assert np.all((observed > low) & (observed < high)), observed


@pytest.mark.parametrize("order", [1, 2])
def test_sphere_stiff_eigenvalues_converge_at_order_2p(order):
    # the vectors from the membrane's certified solver (inertia-checked, multiplicities
    # complete); their eigenvalues for K_s from the operator itself
    count = 25  # l = 0 .. 4
    exact = _sphere_exact(count)
    worst, gas_errors = [], []
    for level in (2, 3, 4):
        space = sphere_space(icosphere(level), order)
        pairs = lowest_eigenpairs(space.stiffness, space.mass, count)
        values = _rayleigh(space, pairs.vectors)
        area = float(np.sum(space.mass @ np.ones(space.dofs))) / (4 * math.pi)
        assert values[0] == pytest.approx(STIFF.gas * area, rel=1e-9)
        gas_errors.append(abs(values[0] / STIFF.gas - 1.0))
        worst.append(np.max(np.abs(np.sort(values[1:]) / exact[1:] - 1.0)))
    low, high = BANDS[order]
    observed = orders(worst)
    assert np.all((observed > low) & (observed < high)), observed
    assert gas_errors[-1] < gas_errors[0]  # the discrete area converges too


@pytest.mark.parametrize("space", [axisym_space(60, 2.5, 2), sphere_space(icosphere(1), 2)])
def test_dense_mixed_matrix_has_the_mapped_membrane_spectrum(space):
    # K_s = (1 - 2 beta) K + beta K M^-1 K + gas/(4 pi) m m^T, formed densely (small only)
    K, M = space.stiffness.toarray(), space.mass.toarray()
    m = M @ np.ones(space.dofs)
    Ks = (1 - 2 * STIFF.beta) * K + STIFF.beta * K @ np.linalg.solve(M, K)
    Ks += STIFF.gas / (4 * math.pi) * np.outer(m, m)
    dense = sl.eigh(Ks, M, eigvals_only=True)
    pairs = lowest_eigenpairs(space.stiffness, space.mass, space.dofs)
    membrane = modal_series(pairs, np.ones(space.dofs), 0, 0.1, SpectralFilter("none", 30))
    mapped = np.sort(stiff_series(membrane, space, STIFF).omega ** 2)
    assert np.allclose(mapped, dense, rtol=1e-8, atol=1e-8)
    if space.kind == "axisym":  # ARPACK on the saddle-point solve: the lowest ones
        direct = shell_eigenpairs_direct(space, STIFF, 12).values
        assert np.allclose(direct, dense[:12], rtol=1e-9, atol=0.0)


@pytest.mark.parametrize("route", ["full", "krylov"])
def test_axisymmetric_p2_liftoff_agrees_with_the_closed_form(route):
    ref = twoball.liftoff(TENNIS)
    mesh = twoball.MeshOptions("axisym", elements=800, order=2)
    fem = twoball.liftoff(TENNIS, backend="fem", mesh=mesh, stepping=twoball.Stepping(route=route))
    assert fem.t_liftoff_s == pytest.approx(ref.t_liftoff_s, rel=1e-6)
    assert fem.v_liftoff_m_s == pytest.approx(ref.v_liftoff_m_s, rel=1e-6)


def test_sphere_p2_liftoff_error_falls_at_the_eigenvalue_order():
    case = Case.preset("tennis", modes=12)
    ref = twoball.liftoff(case)
    errors = []
    for level in (3, 4):
        mesh = twoball.MeshOptions("sphere", level=level, order=2)
        fem = twoball.liftoff(case, backend="fem", mesh=mesh)
        errors.append(
            max(
                abs(fem.t_liftoff_s / ref.t_liftoff_s - 1.0),
                abs(fem.v_liftoff_m_s / ref.v_liftoff_m_s - 1.0),
            )
        )
    observed = orders(errors)[0]
    assert 3.0 < observed < 5.0, (errors, observed)


@pytest.mark.slow
def test_sphere_p2_liftoff_agrees_with_the_closed_form_krylov():
    # the tennis preset as it is (N = 30): the filtered top modes carry a bending
    # acceleration beta n^4 times the membrane's, so 1e-4 needs level 6 (163 842 DOFs;
    # measured 32 s wall, 2.4 GB): t_l -4.8e-5, v_l +1.5e-5 (level 5: -7.4e-4, +2.3e-4)
    ref = twoball.liftoff(TENNIS)
    mesh = twoball.MeshOptions("sphere", level=6, order=2)
    krylov = twoball.Stepping(route="krylov")
    fem = twoball.liftoff(TENNIS, backend="fem", mesh=mesh, stepping=krylov)
    assert fem.t_liftoff_s == pytest.approx(ref.t_liftoff_s, rel=1e-4)
    assert fem.v_liftoff_m_s == pytest.approx(ref.v_liftoff_m_s, rel=1e-4)
    assert abs(fem.t_liftoff_s / ref.t_liftoff_s - 1.0) > 1e-6  # a discretisation error remains


@pytest.mark.slow
def test_sphere_p2_liftoff_agrees_with_the_closed_form_full():
    # the full route (every eigenpair below the cutoff) at N = 12, where level 5 suffices
    # (its 1000 pairs at level 6 would take minutes); measured 36 s CPU
    case = Case.preset("tennis", modes=12)
    ref = twoball.liftoff(case)
    mesh = twoball.MeshOptions("sphere", level=5, order=2)
    fem = twoball.liftoff(case, backend="fem", mesh=mesh, stepping=twoball.Stepping(route="full"))
    assert fem.t_liftoff_s == pytest.approx(ref.t_liftoff_s, rel=1e-4)
    assert fem.v_liftoff_m_s == pytest.approx(ref.v_liftoff_m_s, rel=1e-4)


def test_generalized_alpha_with_bending_and_gas_is_second_order_in_dt():
    mesh = twoball.MeshOptions("axisym", elements=100, order=2)
    window = 1.5e-3
    full = twoball.Stepping(t_end=window, route="full")
    modal = twoball.liftoff(TENNIS, backend="fem", mesh=mesh, stepping=full)
    dt = 4e-6
    errors = []
    for step in (dt, dt / 2):
        alpha = twoball.Stepping(t_end=window, scheme="alpha", dt=step)
        alpha = twoball.liftoff(TENNIS, backend="fem", mesh=mesh, stepping=alpha)
        errors.append(abs(alpha.v_liftoff_m_s / modal.v_liftoff_m_s - 1.0))
    observed = orders(errors)[0]
    assert 1.6 < observed < 2.4, (errors, observed)
    assert errors[-1] < 1e-2
