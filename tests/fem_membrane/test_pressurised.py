"""The pressurised membrane in finite elements: K - 2 M, its orders, n = 1, the gas, lift-off."""

from __future__ import annotations

import json
import math
import subprocess
import sys

import numpy as np
import pytest
import scipy.linalg as sl
from twoball.fem_membrane.axisym import axisym_space
from twoball.fem_membrane.eigen import eigen_table, lowest_eigenpairs
from twoball.fem_membrane.mesh import icosphere
from twoball.fem_membrane.shell import ShellOperator, shell_eigenpairs_direct
from twoball.fem_membrane.solve import alpha_motion, fem_pole_motion, modal_model
from twoball.fem_membrane.space import sphere_space
from twoball.modal.filters import SpectralFilter
from twoball.modal.legendre import legendre_series
from twoball.modal.liftoff import find_liftoff
from twoball.modal.membrane import Membrane
from twoball.modal.stiffness import ATMOSPHERE, Stiffness
from twoball.verify.studies.orders import OrderBand, step_orders

import twoball

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


def _cli(*args: str) -> subprocess.CompletedProcess[str]:
    return subprocess.run([sys.executable, "-m", "twoball", "--quiet", *args],
                          capture_output=True, text=True, timeout=300)  # fmt: skip


def test_eigen_command_lists_n_minus_1_n_plus_2():
    done = _cli("eigen", "--mesh", "axisym", "--elements", "50", "--order", "3", "--count", "5",
                "--membrane", "pressurised", "--json")  # fmt: skip
    assert done.returncode == 0, done.stderr
    rows = json.loads(done.stdout)["results"]
    assert [r["exact"] for r in rows] == [-2.0, 0.0, 4.0, 10.0, 18.0, 28.0]
    assert abs(rows[1]["value"]) < 1e-11


def test_liftoff_command_runs_the_pressurised_ball_on_both_backends():
    ball = ["--membrane", "pressurised", "--gas", "adiabatic", "--pressure", "77200",
            "--mass", "0.567", "--json"]  # fmt: skip
    closed = _cli("liftoff", *ball)
    fem = _cli("liftoff", *ball, "--backend", "fem", "--mesh", "axisym", "--elements", "200")
    assert closed.returncode == fem.returncode == 0, closed.stderr + fem.stderr
    a, b = json.loads(closed.stdout), json.loads(fem.stdout)
    assert a["membrane"] == b["membrane"] == "pressurised"
    assert b["t_liftoff_s"] == pytest.approx(a["t_liftoff_s"], rel=1e-4)  # E = 200, P2
    api = twoball.liftoff(twoball.Case.from_pressure(77200, 0.567, gas="adiabatic",
                                                     membrane="pressurised"))  # fmt: skip
    assert api.t_liftoff_s == a["t_liftoff_s"]


@pytest.mark.parametrize(
    ("args", "flag"),
    [
        (["liftoff", "--membrane", "pressurised"], "--gas"),
        (["liftoff", "--membrane", "flat"], "--membrane"),
        (["eigen", "--membrane", "flat"], "--membrane"),
        (["converge", "modes", "--membrane", "pressurised", "--gas", "adiabatic", "--pressure",
          "77200", "--mass", "0.567", "--phi-a", "2.6", "--out", "/tmp/twoball-never-written"],
         "--membrane"),
        (["liftoff", "--membrane", "pressurised", "--gas", "adiabatic", "--pressure", "77200",
          "--mass", "0.567", "--mass-ratio", "0.1"], "--mass-ratio"),
    ],
)  # fmt: skip
def test_the_command_line_refuses_what_does_not_apply_in_one_line(args, flag):
    done = _cli(*args)
    assert done.returncode == 2
    lines = done.stderr.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith(f"twoball: error: {flag} "), done.stderr
