"""Generalized-alpha stepping against modal superposition: order 2 in dt, Woodbury solve."""

from __future__ import annotations

import numpy as np
import pytest
import scipy.sparse as sp
from twoball.fem_membrane.alpha import AlphaParameters, GeneralizedAlpha, automatic_step
from twoball.fem_membrane.damping import ModalDamping
from twoball.fem_membrane.eigen import Eigenpairs
from twoball.fem_membrane.modal import filtered_displacement
from twoball.fem_membrane.solve import alpha_motion, fem_pole_motion, modal_model
from twoball.modal.liftoff import SampledPoleMotion, find_liftoff
from twoball.modal.parameters import Case

PHI_A, DAMPING = 2.6, 0.13
GAMMA = Case().gamma


@pytest.fixture(scope="module")
def model():
    return modal_model(PHI_A, DAMPING, "lanczos", mesh="axisym", elements=100, order=2)


def pole_difference(model, motion) -> np.ndarray:
    exact = model.series.pole(motion.times)
    sampled = motion.pole(motion.times)
    return np.array([np.abs(a - b).max() for a, b in zip(sampled, exact, strict=True)])


def test_parameters():
    trapezoidal = AlphaParameters(1.0)
    assert (trapezoidal.alpha_m, trapezoidal.alpha_f) == (0.5, 0.5)
    assert (trapezoidal.gamma, trapezoidal.beta) == (0.5, 0.25)
    damped = AlphaParameters(0.0)
    assert damped.alpha_m == -1.0 and damped.alpha_f == 0.0
    assert damped.gamma == 1.5 and damped.beta == 1.0


@pytest.mark.parametrize("rho_inf", [1.0, 0.8, 0.0])
def test_single_damped_oscillator_is_second_order(rho_inf):
    omega, ratio = 5.0, DAMPING
    root = omega * np.sqrt(1 - ratio**2)

    def exact(t):
        return np.exp(-ratio * omega * t) * (
            np.cos(root * t) + ratio * omega / root * np.sin(root * t)
        )

    M = sp.identity(1, format="csr")
    K = sp.csr_matrix([[omega**2]])
    C = ModalDamping.from_modes(M, Eigenpairs(np.array([omega**2]), np.ones((1, 1))), ratio)
    errors = []
    for steps in (200, 400, 800):
        history = GeneralizedAlpha(M, K, 4.0 / steps, C, rho_inf).run(
            np.array([1.0]), np.array([0.0]), 4.0, 0
        )
        errors.append(np.abs(history.u - exact(history.t)).max())
    orders = np.log2(np.array(errors[:-1]) / np.array(errors[1:]))
    assert np.all((orders > 1.9) & (orders < 2.1)), orders


def test_woodbury_solve_equals_the_dense_effective_matrix(model):
    space, pairs = model.space, model.pairs
    damping = ModalDamping.from_modes(space.mass, pairs, DAMPING)
    stepper = GeneralizedAlpha(space.mass, space.stiffness, 0.01, damping, rho_inf=0.7)
    p = stepper.parameters
    dense_c = damping.basis @ np.diag(damping.rates) @ damping.basis.T
    effective = (
        (1 - p.alpha_m) * space.mass.toarray()
        + (1 - p.alpha_f) * p.gamma * 0.01 * dense_c
        + (1 - p.alpha_f) * p.beta * 1e-4 * space.stiffness.toarray()
    )
    rhs = np.random.default_rng(1).standard_normal(space.dofs)
    assert np.allclose(stepper.solve(rhs), np.linalg.solve(effective, rhs), rtol=1e-10, atol=1e-12)
    v = np.random.default_rng(2).standard_normal(space.dofs)
    assert np.allclose(damping @ v, dense_c @ v)


def test_initial_state_is_the_filtered_series(model):
    u0 = filtered_displacement(model.series, model.pairs)
    pole = model.series.pole(0.0)
    assert u0[model.space.pole] == pytest.approx(float(pole.u), abs=1e-12)
    stepper = GeneralizedAlpha(model.space.mass, model.space.stiffness, 0.01)
    a0 = stepper.initial_acceleration(u0, np.zeros_like(u0))
    assert a0[model.space.pole] == pytest.approx(float(pole.u_tt), abs=1e-8)


@pytest.mark.parametrize("rho_inf", [1.0, 0.5])
def test_alpha_matches_modal_at_order_2(model, rho_inf):
    differences = []
    for steps in (1000, 2000, 4000):
        motion, info = alpha_motion(model, dt=4 * np.pi / steps, rho_inf=rho_inf)
        assert isinstance(motion, SampledPoleMotion) and info["steps"] == steps
        differences.append(pole_difference(model, motion))
    differences = np.array(differences)  # rows: dt; columns: u, u_t, u_tt
    orders = np.log2(differences[:-1] / differences[1:])
    assert np.all((orders > 1.8) & (orders < 2.2)), orders


def test_alpha_liftoff_converges_to_modal_liftoff_at_order_2(model):
    # the step samples go through per-field splines, so t_l and v_l inherit O(dt^2)
    reference = find_liftoff(model.series, GAMMA)
    gaps = []
    for steps in (1000, 2000, 4000):
        motion, _ = alpha_motion(model, dt=4 * np.pi / steps)
        result = find_liftoff(motion, GAMMA)
        gaps.append(
            [abs(result.t / reference.t - 1), abs(result.velocity / reference.velocity - 1)]
        )
    gaps = np.array(gaps)
    orders = np.log2(gaps[:-1] / gaps[1:])
    assert np.all((orders > 1.8) & (orders < 2.2)), orders
    assert np.all(gaps[-1] < 1e-4)


def test_fem_pole_motion_alpha_with_automatic_step():
    motion, info = fem_pole_motion(
        PHI_A, DAMPING, "lanczos", mesh="axisym", elements=40, order=2, scheme="alpha"
    )
    assert info["time_scheme"] == "alpha" and info["rho_inf"] == 1.0
    assert info["dt"] * info["omega_cut"] <= 0.2 + 1e-12
    assert info["steps"] * info["dt"] == pytest.approx(4 * np.pi)
    assert motion.times[-1] >= 4 * np.pi
    assert automatic_step(31.0, 4 * np.pi) * 31.0 <= 0.2
