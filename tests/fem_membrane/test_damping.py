"""Damping on finite elements (fem_membrane/damping.py): Rayleigh ``C = alpha M + beta K``.

Three methods for one law: the Legendre series with ratio ``zeta(omega_n)`` per
mode, finite-element modal superposition with ``zeta(omega_k)`` on the FE
eigenpairs (exact in time: C is diagonal on M-orthonormal eigenvectors), and
generalized-alpha stepping with the sparse matrix C.  They agree as h -> 0
(order 2p = 4 for P2) and dt -> 0 (order 2); the effective-ratio table and the
stepping are checked mode by mode.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

import twoball
from twoball.fem_membrane.solve import alpha_motion, fem_pole_motion, modal_model
from twoball.modal.damping import Rayleigh
from twoball.modal.filters import SpectralFilter
from twoball.modal.legendre import legendre_series
from twoball.modal.liftoff import find_liftoff
from twoball.modal.membrane import Membrane
from twoball.modal.series import ModalSeries
from twoball.modal.stiffness import Stiffness
from twoball.verify.studies.orders import OrderBand, step_orders

PHI_A, DAMPING = 2.6, 0.13


def test_rayleigh_runs_and_reports_effective_ratios():
    motion, info = fem_pole_motion(
        PHI_A,
        DAMPING,
        "lanczos",
        mesh="axisym",
        elements=60,
        order=2,
        scheme="alpha",
        damping_model="rayleigh",
    )
    rayleigh = info["rayleigh"]
    assert rayleigh["omega_low"] == pytest.approx(math.sqrt(2))
    assert rayleigh["omega_high"] == pytest.approx(math.sqrt(30 * 31))
    table = rayleigh["table"]
    assert len(table) == info["modes_used"] - 1  # all retained modes but the constant one
    omega = np.array([row["omega"] for row in table])
    zeta = np.array([row["zeta"] for row in table])
    expected = rayleigh["alpha"] / (2 * omega) + rayleigh["beta"] * omega / 2
    assert np.allclose(zeta, expected, rtol=1e-14)
    assert np.allclose([row["ratio"] for row in table], zeta / DAMPING)
    assert zeta[0] == pytest.approx(DAMPING, rel=1e-5)  # omega_1 = sqrt(2) up to FE error
    assert np.all(np.isfinite(motion.pole(motion.times).u_tt))


def test_rayleigh_stepping_equals_the_sum_of_modes_with_their_own_ratios():
    model = modal_model(PHI_A, DAMPING, "lanczos", mesh="axisym", elements=60, order=2)
    series = model.series
    fit = Rayleigh.fit(DAMPING, math.sqrt(2), model.filter.omega_n)
    keep = np.flatnonzero(series.retained)
    plain = SpectralFilter("none", 1000)
    modes = [
        ModalSeries(
            omega=series.omega[[k]],
            coefficients=(series.weights * series.coefficients)[[k]],
            pole_values=series.pole_values[[k]],
            damping=float(fit.ratios(series.omega[k])) if series.omega[k] > 1e-3 else 0.0,
            filter=plain,
        )
        for k in keep
    ]
    differences = []
    for steps in (2000, 4000):
        motion, _ = alpha_motion(model, damping_model="rayleigh", dt=4 * np.pi / steps)
        t = motion.times
        exact = sum(np.array(mode.pole(t)) for mode in modes)
        differences.append(np.abs(np.array(motion.pole(t)) - exact).max(axis=1))
    differences = np.array(differences)
    assert np.all(differences[1] < [1e-4, 1e-3, 1e-2])  # u, u_t, u_tt
    orders = np.log2(differences[0] / differences[1])
    assert np.all((orders > 1.8) & (orders < 2.2)), orders


def test_rayleigh_runs_on_modal_superposition_too():
    """Each mode with its own ratio (docs/pressurised.rst): no time stepping needed."""
    series, info = fem_pole_motion(
        PHI_A, DAMPING, mesh="axisym", elements=20, damping_model="rayleigh"
    )
    assert info["damping_model"] == "rayleigh" and info["time_scheme"] == "modal"
    assert series.damping.alpha == info["rayleigh"]["alpha"]


FILTER = SpectralFilter("lanczos", 30)


LAW = Rayleigh(0.295, 0.0363)  # units of c: ratio 0.13 at sqrt(2) and at 5.76


T = np.linspace(0.0, 4 * math.pi, 801)


def pole(motion) -> np.ndarray:
    return np.array(motion.pole(T))


def test_fe_modal_superposition_converges_to_the_closed_form_at_h4():
    exact = pole(legendre_series(PHI_A, LAW, FILTER))
    errors = []
    for elements in (50, 100, 200):
        model = modal_model(PHI_A, LAW, FILTER, mesh="axisym", elements=elements, order=2)
        assert model.series.damping == LAW
        errors.append(np.abs(pole(model.series) - exact).max(axis=1))
    errors = np.array(errors)
    for column in errors.T:  # u, u_t, u_tt
        orders = step_orders([1.0, 0.5, 0.25], column)
        assert all(OrderBand(4.0).contains(o) for o in orders), orders


@pytest.mark.parametrize("law", [LAW, Rayleigh(0.0, 0.2)], ids=["mid", "over-damped"])
def test_generalized_alpha_with_the_sparse_matrix_converges_to_fe_modal_at_dt2(law):
    model = modal_model(PHI_A, law, FILTER, mesh="axisym", elements=60, order=2)
    if law.alpha == 0.0:
        assert np.count_nonzero(model.series.ratios > 1.0) > 10  # zeta = omega / 10
    reference = pole(model.series)
    errors = []  # (over-damped modes decay at up to beta omega^2 = 186: dt resolves it)
    for steps in (2000, 4000, 8000):
        motion, _ = alpha_motion(model, dt=4 * math.pi / steps)
        errors.append(np.abs(pole(motion) - reference).max(axis=1))
    errors = np.array(errors)
    for column in errors.T:
        orders = step_orders([1.0, 0.5, 0.25], column)
        assert all(OrderBand(2.0).contains(o) for o in orders), orders


def test_generalized_alpha_meets_the_closed_form_as_h_and_dt_fall_together():
    exact = pole(legendre_series(PHI_A, LAW, FILTER))
    errors = []
    for elements, steps in ((50, 1000), (100, 2000)):
        model = modal_model(PHI_A, LAW, FILTER, mesh="axisym", elements=elements, order=2)
        motion, _ = alpha_motion(model, dt=4 * math.pi / steps)
        errors.append(np.abs(pole(motion)[0] - exact[0]).max())
    assert errors[1] < errors[0] / 3.5  # dt^2 dominates: a factor 4


def test_pressurised_ball_with_rayleigh_steps_at_dt2_through_the_shell_operator():
    ball = Stiffness(gas=19.425, membrane=Membrane("pressurised"))
    model = modal_model(PHI_A, LAW, FILTER, mesh="axisym", elements=60, order=2, stiffness=ball)
    reference = pole(model.series)
    errors = []
    for steps in (2000, 4000):
        motion, _ = alpha_motion(model, dt=4 * math.pi / steps)
        errors.append(np.abs(pole(motion) - reference).max(axis=1))
    orders = np.log2(errors[0] / errors[1])
    assert all(OrderBand(2.0).contains(o) for o in orders), orders


def test_routes_and_schemes_agree_through_fem_pole_motion():
    found = {}
    for name, options in {
        "full": {"route": "full"},
        "krylov": {"route": "krylov"},
        "alpha": {"scheme": "alpha", "dt": 4 * math.pi / 4000},
    }.items():
        motion, info = fem_pole_motion(PHI_A, LAW, FILTER, mesh="axisym", elements=100,
                                       order=2, **options)  # fmt: skip
        assert info["damping_model"] == "rayleigh"
        assert info["rayleigh"]["alpha"] == LAW.alpha
        found[name] = find_liftoff(motion, 8e-4)
    assert found["krylov"].t == pytest.approx(found["full"].t, rel=1e-9)
    assert found["alpha"].t == pytest.approx(found["full"].t, rel=1e-4)
    assert found["alpha"].velocity == pytest.approx(found["full"].velocity, rel=1e-4)


def test_fitted_rayleigh_on_the_modal_scheme_is_the_alpha_schemes_law():
    """``damping_model="rayleigh"`` with a ratio D: fitted at sqrt(2) and omega_N, any scheme."""
    _, modal = fem_pole_motion(PHI_A, 0.13, FILTER, mesh="axisym", elements=60,
                               damping_model="rayleigh")  # fmt: skip
    _, alpha = fem_pole_motion(PHI_A, 0.13, FILTER, mesh="axisym", elements=60,
                               scheme="alpha", damping_model="rayleigh")  # fmt: skip
    assert modal["rayleigh"]["alpha"] == alpha["rayleigh"]["alpha"]
    assert modal["rayleigh"]["omega_low"] == pytest.approx(math.sqrt(2), rel=1e-15)


def test_si_law_through_the_finite_elements_matches_the_closed_form():
    law = Rayleigh(100.0, 2.5e-5)  # alpha [1/s], beta [s]
    closed = twoball.liftoff(damping=law)
    solver = twoball.Superposition(twoball.MeshOptions("axisym", elements=200))
    fem = twoball.liftoff(damping=law, solver=solver)
    assert fem.t_liftoff_s == pytest.approx(closed.t_liftoff_s, rel=1e-6)
    assert fem.v_liftoff_m_s == pytest.approx(closed.v_liftoff_m_s, rel=1e-6)
    block = fem.as_dict()["rayleigh"]
    assert (block["alpha_1_s"], block["beta_s"]) == (100.0, 2.5e-5)
    assert block["alpha"] == pytest.approx(100.0 / 320.0, rel=1e-15)
