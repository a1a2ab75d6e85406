"""A ball is an object: a test ball of its own runs through ``twoball.bounce`` unchanged.

:class:`SpringBall` lives in this module only: a rigid shell (the part that meets
the floor and the body) on a spring around a rigid core.  It is neither a
membrane nor radial: its translation is a motion of its material (both masses),
its one vibration moves the shell *and* the core, and its contact rows are the
shell's vertical motion.  Nothing in the contact core, the measures or the
report knows it; the drop and the whole bounce run it as they run the membrane.

Closed form of its drop on a plastic floor without gravity: the shell stops at
the impact (Newton's e = 0 at the one floor point, the south pole), the core
(mass ``(1 - alpha) M``) swings on the spring with ``omega_c = sqrt(k / m_c)``
and pulls the shell off again when the spring turns from pushing to pulling,
half a period later, ``t_c = pi / omega_c``; the core then moves up at ``|v0|``
and the shell at rest, so the centre of mass leaves at ``(1 - alpha) |v0|``:
``e2 = 1 - alpha``.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np
import pytest

import twoball
from twoball.modal.balls.description import ModalBall


@dataclass(frozen=True)
class SpringBall:
    """A rigid shell of mass ``alpha M`` on a spring around a rigid core (dimensionless omega).

    Coordinates: the centre of mass Z (mass 1 in units of M) and the spring's
    extension r (modal mass ``alpha (1 - alpha)``: the shell sits at ``Z + (1 -
    alpha) r``, the core at ``Z - alpha r``), frequency ``omega`` in units of the
    case's c.
    """

    alpha: float = 0.4
    omega: float = 2.0
    damping: float = 0.0
    mass_kg: float = 0.5

    kind = "spring ball"
    backend = "toy"

    @property
    def label(self) -> str:
        return f"shell {self.alpha:g} on a spring, omega {self.omega:g}"

    def mass(self, case: Any) -> float:
        return self.mass_kg

    def size(self, case: Any) -> tuple[int, int]:
        return 2, 1

    def describe(self, case: Any, monitor: Any = None) -> ModalBall:
        a = self.alpha
        shell = np.array([1.0, 1.0 - a])  # the shell's vertical motion per coordinate
        w2 = self.omega**2
        return ModalBall(
            masses=np.array([1.0, a * (1.0 - a)]),
            omega_squared=np.array([0.0, w2]),
            gas_squared=np.zeros(2),
            decay=np.array([0.0, 2.0 * self.damping * self.omega]),
            centre=0,
            phi=np.array([math.pi]),  # a rigid sphere meets a floor at one point
            floor_rows=shell[None, :],
            top=shell,
            label=self.label,
            sampler=lambda phi: np.zeros((np.size(phi), 2)),
            averager=lambda theta: shell,
        )

    def as_dict(self) -> dict[str, Any]:
        return {"ball": self.kind, "alpha": self.alpha, "omega": self.omega}


def _case(**changes: Any) -> twoball.Case:
    return twoball.Case.preset("basketball", **changes)


def test_the_spring_ball_is_a_ball():
    assert isinstance(SpringBall(), twoball.Ball)
    with pytest.raises(twoball.ParameterError, match="solver|ball"):
        twoball.MoreauJean(ball=object())


@pytest.mark.parametrize("alpha", [0.25, 0.6])
def test_its_drop_follows_the_closed_form(alpha):
    """Plastic floor, no weight: contact time pi / omega_c and e2 = 1 - alpha."""
    ball = SpringBall(alpha=alpha, omega=2.0)
    case = _case(g=1e-6)
    dt = 1e-3
    solver = twoball.MoreauJean(ball, dt=dt / case.wave_speed)
    report = twoball.bounce(case, solver=solver)
    omega_c = ball.omega * math.sqrt(alpha)  # k / m_c with k = omega^2 alpha (1 - alpha)
    assert report.left_floor
    assert report.contact_time_s * case.wave_speed == pytest.approx(math.pi / omega_c, rel=2e-3)
    assert report.e2 == pytest.approx(1.0 - alpha, abs=2e-3)
    # the floor's impulse is the centre of mass's momentum change and the weight's
    weight = report.mass_kg * case.g * report.contact_time_s
    change = report.mass_kg * (report.v2_m_s + case.v0)
    assert report.floor_impulse_N_s == pytest.approx(change + weight, rel=1e-12)
    assert report.model["resolution"] == ball.label and report.backend == "toy"
    data = report.as_dict()
    assert data["energy_J"]["balance_error"] < 1e-12 * data["energy_J"]["initial_kinetic"]


def test_the_whole_bounce_runs_it_and_keeps_its_books():
    """A body on the spring ball, every contact elastic, no damping: both books close."""
    ball = SpringBall(alpha=0.5, omega=3.0)
    case = _case(g=1e-6)
    solver = twoball.MoreauJean(ball, dt=5e-4 / case.wave_speed)
    body = twoball.Body(0.2, contact_radius=0.01, restitution=1.0)
    drop = twoball.Drop(gap=0.01, floor_restitution=1.0)
    report = twoball.bounce(case, drop, solver=solver, body=body)
    assert report.has_body
    data = report.as_dict()
    assert data["body_contacts"] >= 1 and data["v1_m_s"] is not None
    assert report.result.impulse_balance < 1e-10  # floor impulse = both momenta + weights
    books = data["energy_J"]
    assert abs(books["lost_impacts"]) < 1e-12 * books["initial_kinetic"]
    final = (
        books["final_rigid_kinetic"]
        + books["final_membrane_kinetic"]
        + books["final_membrane_elastic"]
        + books["final_body_kinetic"]
        + books["gravity_gained"]
        + books["body_gravity_gained"]
    )
    assert final == pytest.approx(books["initial_kinetic"], rel=1e-10)
    assert data["body"]["mass_kg"] == pytest.approx(0.2 * ball.mass_kg)
