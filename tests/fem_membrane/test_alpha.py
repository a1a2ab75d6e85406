"""Generalized-alpha stepping (fem_membrane/alpha.py).

Parameters, order 2, Woodbury solve, pole functional.
"""

from __future__ import annotations

import numpy as np
import pytest
import scipy.sparse as sp

from tests.meshes import OFF_NODE_POLES
from twoball.fem_membrane.alpha import AlphaParameters, GeneralizedAlpha
from twoball.fem_membrane.damping import ModalDamping
from twoball.fem_membrane.eigen import Eigenpairs
from twoball.fem_membrane.mesh import icosphere
from twoball.fem_membrane.mesh_input import (
    load_sphere_mesh,
)
from twoball.fem_membrane.modal import filtered_displacement
from twoball.fem_membrane.space import sphere_space

DAMPING = 0.13


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


def test_woodbury_solve_equals_the_dense_effective_matrix(axisym_model):
    space, pairs = axisym_model.space, axisym_model.pairs
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


def test_initial_state_is_the_filtered_series(axisym_model):
    u0 = filtered_displacement(axisym_model.series, axisym_model.pairs)
    pole = axisym_model.series.pole(0.0)
    assert u0[axisym_model.space.pole] == pytest.approx(float(pole.u), abs=1e-12)
    stepper = GeneralizedAlpha(axisym_model.space.mass, axisym_model.space.stiffness, 0.01)
    a0 = stepper.initial_acceleration(u0, np.zeros_like(u0))
    assert a0[axisym_model.space.pole] == pytest.approx(float(pole.u_tt), abs=1e-8)


def test_time_stepping_evaluates_the_pole_functional():
    # the stepped pole history is the functional's weighted sum of the nodal histories
    space = sphere_space(load_sphere_mesh(icosphere(1), pole=OFF_NODE_POLES[1]).mesh)
    stepper = GeneralizedAlpha(space.mass, space.stiffness, 0.02, rho_inf=0.8)
    u0 = np.cos(np.arange(space.dofs))
    row = space.pole_row
    history = stepper.run(u0, np.zeros_like(u0), 0.4, row)
    nodal = [stepper.run(u0, np.zeros_like(u0), 0.4, int(i)) for i in row.indices]
    for name in ("u", "u_t", "u_tt"):
        combined = sum(w * getattr(h, name) for w, h in zip(row.data, nodal, strict=True))
        assert np.allclose(getattr(history, name), combined, rtol=0, atol=1e-13)
