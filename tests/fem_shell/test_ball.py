"""The shell on the meridian's finite elements as a lower ball (twoball.fem_shell.ball)."""

from __future__ import annotations

import math

import numpy as np
import pytest

import twoball
from twoball.fem_shell.ball import FEShellBall, exact_translation, fe_shell_ball
from twoball.fem_shell.modes import fem_shell_modes
from twoball.modal.balls.shell import ShellBall, Wall
from twoball.modal.shell import ShellParameters


def test_the_translation_is_made_exact():
    parameters = ShellParameters.from_ratios(0.5, 0.05, 20.0, gas=0.3)
    raw = fem_shell_modes(parameters, 16)
    clean = exact_translation(raw)
    k = raw.translation
    # the eigensolver's translation was exact to rounding; the cleaning moves nothing more
    assert abs(raw.omega[k]) < 1e-7 and clean.omega[k] == 0.0
    assert np.abs(raw.vectors[:, k]).max() < 1e-12
    assert np.abs(np.delete(raw.translation_amplitude, k)).max() < 1e-12
    np.testing.assert_allclose(clean.vertical(np.linspace(0, math.pi, 7))[k], 1.0, atol=3e-16)
    np.testing.assert_allclose(np.delete(clean.centre_of_mass(), k), 0.0, atol=1e-14)
    assert clean.centre_of_mass()[k] == 1.0


def test_the_ball_has_its_floor_at_the_lower_nodes():
    parameters = ShellParameters.from_ratios(0.5, 0.03, 3.0, gas=2.0)
    ball = fe_shell_ball(parameters, 24, 2, twoball.ModalRatio(0.13))
    nodes = np.linspace(0.0, math.pi, 25)
    np.testing.assert_allclose(ball.phi, nodes[nodes > math.pi / 2], atol=1e-15)
    assert ball.modes == FEShellBall(elements=24).size()[0]
    assert ball.points == FEShellBall(elements=24).size()[1]
    k = ball.centre
    assert np.all(ball.floor_rows[:, k] == 1.0) and ball.top[k] == 1.0
    assert ball.decay[k] == 0.0 and ball.omega_squared[k] == 0.0
    # the gas's share on the breathing mode (degree 0), g / p in units of c^2
    breathing = int(np.argmax(ball.gas_squared))
    assert ball.gas_squared[breathing] == pytest.approx(2.0 / parameters.prestress)
    assert np.count_nonzero(ball.gas_squared) == 1


@pytest.mark.parametrize("order", [1, 2, 3])
def test_every_order_runs_a_drop(order):
    ball = FEShellBall(elements=12, order=order)
    assert ball.size()[0] == 2 * 12 + order * 12 - 1
    report = twoball.bounce(twoball.Case.preset("tennis"), solver=twoball.MoreauJean(ball))
    assert report.left_floor and report.backend == "fem"
    assert report.model["resolution"] == f"shell meridian 12 P{order}"


def test_the_summary_is_the_closed_forms():
    case = twoball.Case.preset("tennis")
    wall = Wall(wall_stiffness_ratio=12.0, thickness_ratio=0.05)
    assert FEShellBall(wall).summary(case) == ShellBall(wall).summary(case)
    assert FEShellBall(wall).as_dict()["wall"] == wall.as_dict()
    assert FEShellBall().dense and FEShellBall().label == "shell meridian 64 P2"
