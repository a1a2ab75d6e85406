"""The symmetric check of the ball body: two identical balls colliding head-on in free space.

Exact: the centre of mass at rest (no external force), the mirror symmetry
``z -> 2 - z`` (the upper ball's degree-n amplitude ``(-1)^n`` times the
lower's), the energy books at D = 0 (the scheme's identity at theta = 1/2) and,
with Newton's e = 1 at the rows, the mechanical energy itself.  Reported (the
docs quote it): the kinetic energy of the centres left after separation.
"""

from __future__ import annotations

import pytest

import twoball
from twoball.modal.balls.membrane import LegendreBall
from twoball.modal.damping import ModalRatio
from twoball.modal.floor.inputs import resolve_drop
from twoball.modal.floor.options import Drop
from twoball.modal.parameters import Case
from twoball.modal.upper.collide import free_collision


def _tennis(modes=32, damping=0.0):
    inputs = resolve_drop(Case.preset("tennis"), Drop(), ModalRatio(damping))
    return LegendreBall(modes).describe(inputs.case), inputs.v0


@pytest.mark.parametrize("restitution", [0.0, 1.0])
def test_two_undamped_balls_collide_symmetrically(restitution):
    ball, speed = _tennis()
    result = free_collision(ball, speed, restitution=restitution)
    assert result.separated
    assert result.centre_of_mass == 0.0  # +-V exactly: the impulses are equal and opposite
    assert result.mirror < 1e-12
    assert result.energy_balance < 1e-13
    assert result.velocities[0] == pytest.approx(-result.velocities[1], abs=1e-14)
    if restitution == 1.0:
        assert abs(result.impact_loss) < 1e-14  # nothing lost: the mechanical energy kept
    else:
        assert 0.0 < result.impact_loss < 0.02
    # the vibration the balls carry away: a few per cent of the energy (0.03 at N = 32)
    left = result.rigid_left + result.vibration_left + result.impact_loss
    assert left == pytest.approx(1.0, abs=1e-12)
    assert 0.01 < result.vibration_left < 0.06
    assert 0.95 < result.restitution < 1.0


def test_refusals():
    ball, _ = _tennis(16)
    with pytest.raises(twoball.ParameterError, match="speed"):
        free_collision(ball, 0.0)
