"""The elastic bodies in the drop's contact problem: rows, books and the two backends.

Independent values: the lower ball's vertical rows against its floor rows;
momentum (floor impulse = change of both momenta + weights) to 1e-10; the
energy books (every part, the bodies' own energy and dissipation) to
rounding, also at D = 0 with every contact elastic (nothing lost); the ICM's
algebra (2.5) with the run's own e2 and e12_effective at a large gap without
gravity; Legendre against finite elements (slow, at the defaults).
"""

from __future__ import annotations

from dataclasses import replace

import numpy as np
import pytest

import twoball
from twoball.modal.balls.membrane import legendre_ball
from twoball.modal.damping import ModalRatio
from twoball.modal.stiffness import Stiffness
from twoball.modal.upper.system import lower_rows

COARSE = {
    "legendre": lambda: twoball.LegendreBall(24),
    "fem": lambda: twoball.FEBall(twoball.MeshOptions("axisym", elements=12)),
}


def _body(kind, elastic=False):
    body = twoball.body_preset("basketball-tennis", kind)
    if not elastic:
        return body
    if kind == "lumped":
        return twoball.body_preset("basketball-tennis", "lumped", restitution=1.0)
    coarse = twoball.LegendreBall(24)  # undamped, a coarse body rattles less
    return replace(body, ball=coarse, damping=ModalRatio(0.0), restitution=None)


def _books(report) -> tuple[float, float]:
    """(initial, the sum of every final part and loss) [J]."""
    e = report.as_dict()["energy_J"]
    parts = (
        "final_rigid_kinetic", "final_membrane_kinetic", "final_membrane_elastic", "final_gas",
        "gravity_gained", "final_body_kinetic", "body_gravity_gained", "final_body_internal",
        "dissipated_damping", "body_dissipated", "lost_impacts", "held_arrivals",
    )  # fmt: skip
    return e["initial_kinetic"], sum(e[p] for p in parts)


def test_lower_rows_are_the_floor_rows_at_the_floor_points():
    ball = legendre_ball(24, Stiffness(gas=17.4, membrane="pressurised"), ModalRatio(0.1))
    np.testing.assert_allclose(lower_rows(ball, ball.phi), ball.floor_rows, atol=1e-14)
    np.testing.assert_allclose(lower_rows(ball, np.array([0.0]))[0], ball.top, atol=1e-14)
    from twoball.modal.floor.inputs import resolve_drop

    case = resolve_drop(twoball.Case.preset("basketball"), twoball.Drop()).case
    described = twoball.FEBall(twoball.MeshOptions("axisym", elements=12)).describe(case)
    np.testing.assert_allclose(
        lower_rows(described, described.phi), described.floor_rows, atol=1e-12
    )


@pytest.mark.parametrize("backend", sorted(COARSE))
@pytest.mark.parametrize("kind", ["lumped", "ball"])
def test_books_close_with_each_body_on_each_backend(kind, backend):
    solver = twoball.MoreauJean(COARSE[backend]())
    report = twoball.bounce(pair="basketball-tennis", body=_body(kind), solver=solver)
    assert report.result.impulse_balance < 1e-10
    initial, final = _books(report)
    assert final == pytest.approx(initial, rel=1e-12)
    data = report.as_dict()
    assert data["body"]["kind"] == kind and data["energy_J"]["body_dissipated"] > 0.0
    assert data["body_contact"]["peak_force_N"] > 0.0
    assert 0.0 < data["body_contact"]["disc_max_radius_m"] < 0.06
    assert 1.5 < data["v1_ratio"] < 2.5  # far above the rigid body's 1.4


@pytest.mark.parametrize("backend", sorted(COARSE))
@pytest.mark.parametrize("kind", ["lumped", "ball"])
def test_nothing_is_lost_when_every_contact_is_elastic(kind, backend):
    """D = 0 on both balls; the lumped body elastic (e = 1) with e = 1 at the floor's points
    too (nothing lost at all); the ball body's rows and the floor keep Newton's e = 0 (their
    points' touches are booked as impacts, the model's, not the scheme's)."""
    solver = twoball.MoreauJean(COARSE[backend]())
    elastic = 1.0 if kind == "lumped" else 0.0  # e = 1 makes the ball body's points rattle
    drop = twoball.Drop(gap=0.02, floor_restitution=elastic)
    body = _body(kind, elastic=True)
    report = twoball.bounce(drop=drop, pair="basketball-tennis", body=body, solver=solver,
                            damping=ModalRatio(0.0))  # fmt: skip
    e = report.as_dict()["energy_J"]
    assert e["dissipated_damping"] == 0.0 and abs(e["body_dissipated"]) < 1e-12
    assert abs(e["balance_error"]) < 1e-12 * e["initial_kinetic"]
    initial, final = _books(report)
    assert final == pytest.approx(initial, rel=1e-12)
    if kind == "lumped":
        assert abs(e["lost_impacts"]) < 1e-12 * initial  # the floor's points kept it all


def test_a_large_gap_without_gravity_is_the_icm_of_its_own_coefficients():
    case = twoball.Case.preset("basketball", g=1e-6)
    solver = twoball.MoreauJean(twoball.LegendreBall(24))
    body = twoball.body_preset("basketball-tennis", "lumped")
    report = twoball.bounce(case, twoball.Drop(gap=0.2), body=body, solver=solver)
    icm = report.icm_solver
    assert report.as_dict()["sequence"] == "independent"
    assert 0.5 < report.e12_effective < 0.95
    assert report.v1_ratio == pytest.approx(icm["v1_ratio"], abs=1e-8)
    assert report.v2_ratio == pytest.approx(icm["v2_ratio"], abs=1e-8)


@pytest.mark.slow
@pytest.mark.parametrize("gap", [0.0, 0.05])
@pytest.mark.parametrize("kind", ["lumped", "ball"])
def test_legendre_and_finite_elements_agree(kind, gap):
    """Basketball and tennis ball at the defaults (N = 192 against 96 P2): v1, v2, t_l."""
    runs = [
        twoball.bounce(
            drop=twoball.Drop(gap=gap), pair="basketball-tennis", body=kind,
            solver=twoball.MoreauJean(ball),
        )
        for ball in (twoball.LegendreBall(), twoball.FEBall())
    ]  # fmt: skip
    a, b = runs
    assert b.v1_ratio == pytest.approx(a.v1_ratio, rel=1e-3)
    assert b.v2_ratio == pytest.approx(a.v2_ratio, rel=1e-3)
    assert b.t_liftoff_s == pytest.approx(a.t_liftoff_s, rel=1e-3)
