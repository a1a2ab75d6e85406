"""The modal description a ball hands the contact core (modal/balls/description.py).

Independent values: the energy of a state summed by hand (the reach of a floor
point is a Cauchy-Schwarz bound, attained by the state proportional to the row
over the stiffness), the membrane's own reach formula ``|cos phi| sqrt(sum S^2 /
(m omega^2))``, pickling, and the assembled contact problem of a ball whose
centre is held (no weight, no Z).
"""

from __future__ import annotations

import math
import pickle

import numpy as np
import pytest

from twoball._common.errors import NumericalError
from twoball.modal.balls.description import ModalBall
from twoball.modal.balls.membrane import legendre_ball, membrane_rows
from twoball.modal.damping import ModalRatio
from twoball.modal.floor.system import floor_system
from twoball.modal.stiffness import Stiffness

GAS = 6.0 * 1.4 * (77.2e3 + 101325.0) / 77.2e3
PRESSURISED = Stiffness(gas=GAS, membrane="pressurised")
GAMMA = 9.81 / (0.12 * 320.0**2)


def _ball(**changes) -> ModalBall:
    """Two vibrating coordinates and a translation (coordinate 1), two floor points."""
    fields = {
        "masses": np.array([0.5, 1.0, 0.25]),
        "omega_squared": np.array([4.0, 0.0, 9.0]),
        "gas_squared": np.zeros(3),
        "decay": np.array([0.1, 0.0, 0.2]),
        "centre": 1,
        "phi": np.array([2.0, math.pi]),
        "floor_rows": np.array([[0.3, 1.0, -0.2], [-1.0, 1.0, 0.5]]),
        "top": np.array([1.0, 1.0, 1.0]),
    }
    return ModalBall(**(fields | changes))


def test_the_reach_is_the_largest_vertical_motion_at_a_given_energy():
    """|rows_i[deformation] . q| <= r_i sqrt(2 E) for every state, with equality at
    q_k = rows_ik / (m_k omega_k^2) (Cauchy-Schwarz); the translation is no deformation."""
    ball = _ball()
    assert ball.deformation.tolist() == [0, 2] and ball.stable
    reach = ball.floor_reach()
    rng = np.random.default_rng(3)
    for i, row in enumerate(ball.floor_rows):
        best = np.zeros(3)
        best[[0, 2]] = row[[0, 2]] / (ball.masses[[0, 2]] * ball.omega_squared[[0, 2]])
        best[1] = 7.0  # any height of the centre: it moves the point, it is not a vibration
        for q in [best, *rng.normal(size=(50, 3))]:
            energy = 0.5 * sum(ball.masses[k] * ball.omega_squared[k] * q[k] ** 2 for k in (0, 2))
            motion = abs(row[0] * q[0] + row[2] * q[2])
            assert motion <= reach[i] * math.sqrt(2.0 * energy) * (1 + 1e-14)
        energy = 0.5 * sum(ball.masses[k] * ball.omega_squared[k] * best[k] ** 2 for k in (0, 2))
        assert abs(row[0] * best[0] + row[2] * best[2]) == pytest.approx(
            reach[i] * math.sqrt(2.0 * energy), rel=1e-14
        )
    # a free motion of the shape (omega^2 = 0 off the translation) has no bound
    free = _ball(omega_squared=np.array([0.0, 0.0, 9.0]), decay=np.array([0.0, 0.0, 0.2]))
    assert not free.stable and np.all(np.isinf(free.floor_reach()))


def test_the_membranes_reach_is_the_description_bound():
    """membrane_rows' own formula and ModalBall.bound of the assembled rows agree."""
    ball = legendre_ball(24, PRESSURISED, ModalRatio(0.1))
    x = np.cos(ball.phi)
    degrees = np.array([0, *range(2, 25)])
    shapes = np.polynomial.legendre.legvander(x, 24)[:, degrees]
    masses, w2 = 1.0 / (2.0 * degrees + 1.0), ball.omega_squared[1:]
    rows, reach = membrane_rows(ball.phi, shapes, masses, w2)
    np.testing.assert_array_equal(rows, ball.floor_rows)
    np.testing.assert_allclose(ball.bound(ball.floor_rows), reach, rtol=1e-13)
    by_hand = np.abs(x) * np.sqrt((shapes**2) @ (1.0 / (masses * w2)))
    np.testing.assert_allclose(reach, by_hand, rtol=1e-13)
    assert reach[-1] > 0.0 and ball.floor_reach() is ball.reach


def test_a_held_centre_carries_no_weight_and_has_no_height():
    """The paper's model (degree 1 a mode about a centre that does not move): no load on
    any coordinate, the rows the modes' alone, and no coordinate Z to ask for."""
    held = legendre_ball(12, PRESSURISED, ModalRatio(0.1), anchored=True)
    system = floor_system(held, GAMMA)
    assert held.centre is None and np.all(system.problem.load == 0.0)
    np.testing.assert_array_equal(system.problem.constraints, held.floor_rows)
    with pytest.raises(NumericalError, match="held"):
        _ = system.centre
    free = floor_system(legendre_ball(12, PRESSURISED, ModalRatio(0.1)), GAMMA)
    assert free.problem.load[0] == -GAMMA and np.all(free.problem.load[1:] == 0.0)
    alone = floor_system(legendre_ball(12, PRESSURISED, ModalRatio(0.1)), GAMMA, floor=False)
    assert alone.problem.count == 0 and np.all(alone.problem.load == 0.0)  # §3, eq. (3.10)


@pytest.mark.parametrize(
    ("changes", "words"),
    [
        ({"masses": np.array([0.5, 2.0, 0.25])}, "free translation of unit mass"),
        ({"omega_squared": np.array([4.0, 1.0, 9.0])}, "free translation of unit mass"),
        ({"decay": np.array([0.1, 0.3, 0.2])}, "free translation of unit mass"),
        ({"centre": 3}, "not a coordinate"),
        ({"phi": np.array([math.pi, 2.0])}, "ascend"),
        ({"phi": np.array([1.0, math.pi])}, "ascend"),
        ({"floor_rows": np.ones((2, 2))}, "floor_rows"),
        ({"top": np.ones(2)}, "top"),
        ({"masses": np.array([0.0, 1.0, 0.25])}, "masses must be > 0"),
    ],
)
def test_a_description_out_of_shape_is_refused(changes, words):
    with pytest.raises(NumericalError, match=words):
        _ball(**changes)


def test_a_description_without_its_closures_pickles_and_keeps_its_numbers():
    ball = legendre_ball(16, PRESSURISED, ModalRatio(0.1))
    light = pickle.loads(pickle.dumps(ball.without_samplers()))
    np.testing.assert_array_equal(light.floor_rows, ball.floor_rows)
    np.testing.assert_array_equal(light.floor_reach(), ball.floor_reach())
    assert light.centre == 0 and light.label == "legendre N = 16"
    with pytest.raises(NumericalError, match="no sampler"):
        light.modes_at(np.array([1.0]))
    with pytest.raises(NumericalError, match="no cap averages"):
        light.cap_average(0.2)
