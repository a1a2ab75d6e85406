"""The bar against a rigid obstacle: exact solutions, and the contact core's convergence to them.

Orders are observed on meshes of 40 to 320 elements with dt = h (the bands of
:data:`twoball.verify.studies.bar_drop.BAR_BANDS`, the orders docs/bounce.rst states for
the bar of Doyen, Ern & Piperno, SIAM J. Sci. Comput. 33:223, 2011); each band fails
when the order is too high too.
"""

from __future__ import annotations

import numpy as np
import pytest
import scipy.sparse.linalg as spla

from twoball.modal.nonsmooth import MoreauJean
from twoball.verify.studies.bar_drop import (
    BAR_BANDS,
    bar_model,
    bar_study,
    exact_solution,
    run_bar,
)

X = np.linspace(0.0, 1.0, 2001)


def _energy(solution, t: float) -> float:
    """``1/2 int (u_t^2 + u_x^2) dx`` with u_x from finite differences of the displacement."""
    u = solution.displacement(X, t)
    ux = np.gradient(u, X)
    ut = solution.velocity(X, t)
    return 0.5 * float(np.trapezoid(ut**2 + ux**2, X))


@pytest.mark.parametrize("t", [0.25, 0.8, 1.3, 1.7, 2.4, 2.9])
def test_clamped_exact_solution_keeps_energy_and_period(t):
    s = exact_solution("clamped")
    assert _energy(s, t) == pytest.approx(1.0 / 8.0, rel=2e-3)
    np.testing.assert_allclose(s.displacement(X, t + 3.0), s.displacement(X, t), atol=1e-14)
    assert s.displacement(np.array([1.0]), t)[0] == pytest.approx(0.0, abs=1e-14)


def test_clamped_exact_solution_is_a_contact_solution():
    """Gap >= 0, force >= 0, force x gap = 0, and the impulse 1/2 per period."""
    s = exact_solution("clamped")
    t = np.linspace(0.0, 6.0, 6001)
    gap = np.array([s.displacement(np.array([0.0]), ti)[0] for ti in t])
    force = s.force(t)
    assert gap.min() >= -1e-14 and force.min() >= 0.0
    assert np.max(np.abs(gap * force)) < 1e-14
    assert s.impulse(3.0) == pytest.approx(0.5, abs=1e-14)
    assert s.impulse(6.0) == pytest.approx(1.0, abs=1e-14)


def test_free_bar_exact_solution_reverses_momentum_without_loss():
    s = exact_solution("free", 0.7)
    assert s.impulse(5.0) == pytest.approx(2.0 * 0.7, abs=1e-14)
    np.testing.assert_allclose(s.velocity(X[1:], 2.5), 0.7, atol=1e-14)
    assert _energy(s, 1.3) == pytest.approx(0.5 * 0.7**2, rel=2e-3)


def test_free_bar_loses_the_contact_node_energy_at_the_first_impact():
    """The only impact is the end node's: loss = 1/2 v0^2 / (M^-1)_00 (e = 0)."""
    for elements in (20, 40):
        model = bar_model("free", elements)
        e0 = np.zeros(model.problem.dofs)
        e0[0] = 1.0
        inverse_00 = spla.spsolve(model.mass.tocsc(), e0)[0]
        run = run_bar("free", elements)
        assert run.energy_loss == pytest.approx(1.0 / inverse_00, rel=1e-10)
        assert run.energy_error < 1e-12


def test_bar_impulse_balance_under_gravity():
    """Sum of impulses = m (v_end - v_0) + m g t, to rounding (m = 1)."""
    model = bar_model("free", 40, gravity=0.3)
    tr = MoreauJean(model.problem, 0.01).run(model.q0, model.v0, 5.0)
    mass = float(model.mass.sum())
    momentum = float(np.ones(model.q0.size) @ (model.mass @ (tr.v_final - model.v0)))
    assert tr.impulse.sum() == pytest.approx(momentum + 0.3 * mass * tr.t[-1], rel=1e-12)


@pytest.mark.parametrize("case", ["clamped", "free"])
def test_bar_converges_at_the_stated_orders(case):
    study = bar_study(case, (40, 80, 160, 320))
    for name, band in BAR_BANDS.items():
        order = study.fitted_order(name)
        assert band.contains(order), f"{case} {name}: order {order:.3f} not in {band.describe()}"
    loss = study.fitted_order("energy_loss")
    assert 0.8 <= loss <= 1.3, loss
    assert study.errors("displacement")[-1] < 0.01
