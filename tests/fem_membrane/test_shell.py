"""Finite elements of the ball's operator (fem_membrane/shell.py) against the closed form.

The pressure term ``K - 2 M`` of the pressurised membrane, bending by a mixed
form and the gas as a rank-one term: spectra, orders, the breathing mode, lift-off.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
import scipy.linalg as sl

import twoball
from twoball import Case
from twoball.fem_membrane.axisym import axisym_space
from twoball.fem_membrane.eigen import eigen_table, lowest_eigenpairs
from twoball.fem_membrane.mesh import icosphere
from twoball.fem_membrane.modal import modal_series
from twoball.fem_membrane.shell import ShellOperator, shell_eigenpairs_direct, stiff_series
from twoball.fem_membrane.solve import alpha_motion, fem_pole_motion, modal_model
from twoball.fem_membrane.space import sphere_space
from twoball.modal.filters import SpectralFilter
from twoball.modal.legendre import legendre_series
from twoball.modal.liftoff import find_liftoff
from twoball.modal.membrane import Membrane
from twoball.modal.stiffness import ATMOSPHERE, Stiffness
from twoball.verify.studies.orders import OrderBand, step_orders

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
    fem = twoball.liftoff(TENNIS, solver=twoball.Superposition(mesh, route=route))
    assert fem.t_liftoff_s == pytest.approx(ref.t_liftoff_s, rel=1e-6)
    assert fem.v_liftoff_m_s == pytest.approx(ref.v_liftoff_m_s, rel=1e-6)


@pytest.mark.slow
def test_sphere_p2_liftoff_error_falls_at_the_eigenvalue_order():
    case = Case.preset("tennis", modes=12)
    ref = twoball.liftoff(case)
    errors = []
    for level in (3, 4):
        mesh = twoball.MeshOptions("sphere", level=level, order=2)
        fem = twoball.liftoff(case, solver=twoball.Superposition(mesh))
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
    fem = twoball.liftoff(TENNIS, solver=twoball.Superposition(mesh, route="krylov"))
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
    fem = twoball.liftoff(case, solver=twoball.Superposition(mesh, route="full"))
    assert fem.t_liftoff_s == pytest.approx(ref.t_liftoff_s, rel=1e-4)
    assert fem.v_liftoff_m_s == pytest.approx(ref.v_liftoff_m_s, rel=1e-4)


def test_generalized_alpha_with_bending_and_gas_is_second_order_in_dt():
    mesh = twoball.MeshOptions("axisym", elements=100, order=2)
    window = 1.5e-3
    full = twoball.Superposition(mesh, route="full", t_end=window)
    modal = twoball.liftoff(TENNIS, solver=full)
    dt = 4e-6
    errors = []
    for step in (dt, dt / 2):
        stepped = twoball.GeneralizedAlpha(mesh, dt=step, t_end=window)
        alpha = twoball.liftoff(TENNIS, solver=stepped)
        errors.append(abs(alpha.v_liftoff_m_s / modal.v_liftoff_m_s - 1.0))
    observed = orders(errors)[0]
    assert 1.6 < observed < 2.4, (errors, observed)
    assert errors[-1] < 1e-2


PRESSURISED = Membrane("pressurised")


P = 77200.0


GAS = 6 * 1.4 * (P + ATMOSPHERE) / P  # 3 kappa P_abs R / T with T = P R / 2: 19.425


BALL = Stiffness(gas=GAS, membrane=PRESSURISED)


PHI_A, DAMPING = 2.6, 0.13


FILTER = SpectralFilter("lanczos", 30)


#: (coarse, fine) element counts and the degrees n in their asymptotic range, per order
#: (the membrane's: tests/test_fem_high_order.py); K - 2 M has the same absolute errors.
AXISYM_SCHEDULE = {
    1: ((160, 320), range(2, 30)),
    2: ((160, 320), range(3, 30)),
    3: ((90, 135), range(4, 30)),
    4: ((40, 60), range(6, 30)),
}


def axisym_values(elements: int, order: int, count: int = 30) -> np.ndarray:
    """Eigenvalues of K - 2 M on the axisymmetric line, n = 0 .. count - 1."""
    rows = eigen_table("axisym", elements=elements, order=order, count=count - 1,
                       membrane=PRESSURISED)  # fmt: skip
    return np.array([r["value"] for r in rows])


@pytest.mark.parametrize("space", [axisym_space(40, PHI_A, 3), sphere_space(icosphere(1), 2)])
def test_k_minus_2m_solved_directly_has_the_mapped_spectrum(space):
    """A dense generalized eigensolve of the assembled K - 2 M (second method)."""
    operator = space.operator(PRESSURISED).toarray()
    direct = sl.eigh(operator, space.mass.toarray(), eigvals_only=True)[:25]
    mapped = PRESSURISED.eigenvalues(lowest_eigenpairs(space.stiffness, space.mass, 25).values)
    assert direct == pytest.approx(mapped, abs=1e-10 * (1 + np.abs(mapped).max()))
    assert direct[0] == pytest.approx(-2.0, abs=1e-10)  # constants: the unstable breathing


@pytest.mark.parametrize("order", [1, 2, 3, 4])
def test_axisymmetric_eigenvalues_converge_to_n_minus_1_n_plus_2_at_2p(order):
    """Every degree of the asymptotic range at 2p +- 0.3 (too high fails too); n <= p exact."""
    exact = PRESSURISED.legendre(np.arange(30))
    low = axisym_values(40, order)
    assert np.all(np.abs(low[: order + 1] - exact[: order + 1]) < 1e-11)  # P_n in the space
    assert abs(low[1]) < 1e-11  # n = 1: zero to round-off on the line (P_1 = x)
    (coarse, fine), degrees = AXISYM_SCHEDULE[order]
    band = OrderBand(2 * order)
    errors = [np.abs(axisym_values(e, order) - exact)[degrees.start :] for e in (coarse, fine)]
    for k in range(len(degrees)):
        observed = step_orders([1 / coarse, 1 / fine], [errors[0][k], errors[1][k]])[0]
        assert band.contains(observed), (order, degrees.start + k, observed, band.describe())


@pytest.mark.parametrize(("order", "levels"), [(1, (2, 3, 4)), (2, (1, 2, 3))])
def test_sphere_eigenvalues_and_the_zero_translation_converge_at_2p(order, levels):
    """Clusters l = 2 .. 4 and the n = 1 cluster (exact value 0) at the membrane's rate.

    On a sphere mesh the translation's eigenvalue is ``lambda_h(l = 1) - 2``: zero to
    the discretisation error of l = 1, not to round-off -- the tolerance of a zero mode
    is the mesh's own eigenvalue error, which falls at order 2p.
    """
    worst, translation = [], []
    for level in levels:
        rows = eigen_table("sphere", level=level, order=order, count=24, membrane=PRESSURISED)
        assert [r["exact"] for r in rows if r["l"] == 1] == [0.0, 0.0, 0.0]
        worst.append(max(r["relative_error"] for r in rows if r["l"] >= 2))
        translation.append(max(abs(r["value"]) for r in rows if r["l"] == 1))
        assert all(r["residual"] < 1e-8 for r in rows)  # residuals of K - 2 M itself
    steps = [2.0**-level for level in levels]
    band = OrderBand(2 * order)
    for observed in (*step_orders(steps, worst), *step_orders(steps, translation)):
        assert band.contains(observed), (order, observed, band.describe())


def test_the_breathing_mode_with_the_gas_is_6_kappa_p_abs_over_p_minus_2():
    expected = GAS - 2.0
    axisym = axisym_space(60, PHI_A, 2)  # 1^T M 1 = 4 pi exactly on the line
    pairs = shell_eigenpairs_direct(axisym, BALL, 6)
    volume = np.abs((axisym.mass @ np.ones(axisym.dofs)) @ pairs.vectors)
    breathing = float(pairs.values[int(np.argmax(volume))])
    assert breathing == pytest.approx(expected, rel=1e-12)
    assert np.sort(pairs.values)[0] == pytest.approx(0.0, abs=1e-10)  # the translation
    errors = []
    for level in (1, 2, 3):  # on the sphere: to the discrete area's error, which converges
        space = sphere_space(icosphere(level), 2)
        op = ShellOperator(space, BALL)
        one = np.ones(space.dofs)
        rayleigh = float(one @ op.matvec(one) / (one @ (space.mass @ one)))
        assert rayleigh == pytest.approx(GAS * op.surface_ratio - 2.0, rel=1e-12)
        errors.append(abs(rayleigh - expected))
    assert errors[2] < errors[1] < errors[0] < 5e-2


def test_shell_operator_rayleigh_quotients_are_the_mapped_spectrum():
    space = sphere_space(icosphere(1), 2)
    stiff = Stiffness(beta=0.02, gas=GAS, membrane=PRESSURISED)
    pairs = lowest_eigenpairs(space.stiffness, space.mass, 16)
    op = ShellOperator(space, stiff)
    kx = op.matmat(pairs.vectors)
    values = np.einsum("ij,ij->j", pairs.vectors, kx)
    lam = pairs.values[1:]
    assert values[1:] == pytest.approx((lam - 2) * (1 + 0.02 * lam), abs=1e-9)
    area = float(np.sum(space.mass @ np.ones(space.dofs))) / (4 * math.pi)
    assert values[0] == pytest.approx(GAS * area - 2.0, rel=1e-9)


def test_axisymmetric_liftoff_converges_to_the_closed_form_at_order_4():
    """P2 on the line: the lift-off's error falls like the eigenvalues' (h^4).

    The gas makes the body leave early (t_l ~ 0.38 / c), while the high modes still
    carry their initial energy: the constant is larger than the paper's membrane's.
    """
    reference = find_liftoff(legendre_series(PHI_A, DAMPING, FILTER, stiffness=BALL), 8e-4)
    errors = []
    for elements in (100, 200, 400):
        motion, info = fem_pole_motion(PHI_A, DAMPING, FILTER, mesh="axisym",
                                       elements=elements, order=2, route="full",
                                       stiffness=BALL)  # fmt: skip
        found = find_liftoff(motion, 8e-4)
        errors.append(
            [abs(found.t / reference.t - 1), abs(found.velocity / reference.velocity - 1)]
        )
    errors = np.array(errors)
    assert errors[-1].max() < 2e-6
    for column in errors.T:
        assert all(OrderBand(4.0).contains(o) for o in step_orders([1, 0.5, 0.25], column)), column
    krylov, _ = fem_pole_motion(PHI_A, DAMPING, FILTER, mesh="axisym", elements=400, order=2,
                                route="krylov", stiffness=BALL)  # fmt: skip
    assert find_liftoff(krylov, 8e-4).t == pytest.approx(found.t, rel=1e-9)


@pytest.mark.slow
def test_sphere_routes_agree_and_approach_the_closed_form():
    reference = find_liftoff(legendre_series(PHI_A, DAMPING, FILTER, stiffness=BALL), 8e-4)
    errors = []
    for level in (1, 2):
        found = {}
        for route in ("full", "krylov"):
            motion, _ = fem_pole_motion(PHI_A, DAMPING, FILTER, level=level, order=3,
                                        route=route, stiffness=BALL)  # fmt: skip
            found[route] = find_liftoff(motion, 8e-4)
        assert found["krylov"].t == pytest.approx(found["full"].t, rel=1e-9)
        errors.append(abs(found["full"].t / reference.t - 1))
    assert errors[1] < errors[0] and errors[1] < 3e-2  # P3 sphere, levels 1 and 2: coarse


def test_generalized_alpha_with_the_pressure_term_is_second_order_in_dt():
    model = modal_model(PHI_A, DAMPING, FILTER, mesh="axisym", elements=60, order=2,
                        stiffness=BALL)  # fmt: skip
    t = np.linspace(0.0, 2 * math.pi, 201)
    exact = np.array(model.series.pole(t))
    errors = []
    for steps in (1000, 2000):
        motion, _ = alpha_motion(model, dt=2 * math.pi / steps, t_end=2 * math.pi)
        errors.append(np.abs(np.array(motion.pole(t)) - exact).max(axis=1))
    observed = np.log2(errors[0] / errors[1])
    assert all(OrderBand(2).contains(o) for o in observed), observed
