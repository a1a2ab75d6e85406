"""The lower ball on a rigid floor as one contact problem for the nonsmooth core.

Dimensionless (R, 1/c, m2).  Coordinates ``q = (Z, a_1, ..., a_K)``: Z the
height of the ball's centre of mass above the floor, a_k the membrane's modal
amplitudes (:class:`~twoball.modal.floor.ball.ModalBall`), u measured from the
centre so that a translation is carried by Z alone.

Equations (the contact core's (N1)-(N3), :mod:`twoball.modal.nonsmooth`)::

    Z'' = -gamma + sum_i lambda_i                                          (F1)
    m_k (a_k'' + d_k a_k' + omega_k^2 a_k) = sum_i lambda_i x_i S_ik       (F2)
    g_i = Z + (1 + u(phi_i)) x_i >= 0,  lambda_i >= 0,  lambda_i g_i = 0   (F3)

with ``x_i = cos(phi_i) < 0`` and ``u(phi_i) = sum_k S_ik a_k``.  (F3) is exact:
the material point of polar angle phi_i sits at distance ``R (1 + u)`` from the
centre along its radius, so its height is ``Z + (1 + u) cos(phi_i)``, linear in q.
Gravity, uniform over the membrane, acts on the centre of mass only (its load
on u, ``-gamma cos(phi)``, is pure degree 1).  At an impact Newton's law (N3)
with restitution e holds at each floor point (default e = 0: the floor stops
the arriving membrane).

An upper body plugs in as one more coordinate (its height s, mass mu) and one
more row (the gap ``s - Z - (1 + u(0))`` above the ball's top, restitution
e12): :func:`floor_system` keeps the layout in :class:`FloorSystem`.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from twoball.modal.floor.ball import ModalBall
from twoball.modal.nonsmooth import ContactProblem

__all__ = ["FloorSystem", "floor_system"]


@dataclass(frozen=True, eq=False)
class FloorSystem:
    """The contact problem of a ball on the floor and where each part sits in q.

    Attributes
    ----------
    ball : ModalBall
    problem : ContactProblem
        M, C, K diagonal; rows of G: the floor points (ascending phi).
    gamma : float
        ``g / (R c^2)``.
    """

    ball: ModalBall
    problem: ContactProblem
    gamma: float

    #: Index of Z in q.
    centre = 0

    @property
    def membrane(self) -> slice:
        """Indices of the modal amplitudes in q."""
        return slice(1, 1 + self.ball.modes)

    @property
    def floor(self) -> slice:
        """Rows of the floor constraints in G."""
        return slice(0, self.ball.points)

    def falling(self, v0: float, height: float = 1.0) -> tuple[np.ndarray, np.ndarray]:
        """Undeformed state, the centre at ``height`` (1: the pole touching), falling at v0."""
        q = np.zeros(self.problem.dofs)
        v = np.zeros(self.problem.dofs)
        q[self.centre] = height
        v[self.centre] = -abs(v0)
        return q, v

    def floor_gaps(self, q: np.ndarray) -> np.ndarray:
        """Gaps (F3) of the floor points for states q (last axis), dimensionless."""
        G = self.problem.constraints[self.floor]
        return q @ G.T + self.problem.offset[self.floor]

    def energies(self, q: np.ndarray, v: np.ndarray) -> dict[str, np.ndarray]:
        """Energy parts of states (rows of q, v), in units of ``m2 (R c)^2``.

        ``rigid_kinetic`` 1/2 Z'^2, ``membrane_kinetic`` 1/2 sum m_k a_k'^2,
        ``membrane_elastic`` 1/2 sum m_k (omega_k^2 - gas_k) a_k^2 (negative
        parts: the pressurised breathing mode without its gas), ``gas``
        1/2 sum m_k gas_k a_k^2 and ``gravity`` gamma Z (from the floor level).
        """
        q = np.atleast_2d(q)
        v = np.atleast_2d(v)
        b = self.ball
        a, da = q[:, self.membrane], v[:, self.membrane]
        return {
            "rigid_kinetic": 0.5 * v[:, self.centre] ** 2,
            "membrane_kinetic": 0.5 * (da**2) @ b.masses,
            "membrane_elastic": 0.5 * (a**2) @ (b.masses * (b.omega_squared - b.gas_squared)),
            "gas": 0.5 * (a**2) @ (b.masses * b.gas_squared),
            "gravity": self.gamma * q[:, self.centre],
        }


def floor_system(ball: ModalBall, gamma: float, restitution: float = 0.0) -> FloorSystem:
    """Assemble (F1)-(F3) for ``ball`` under gravity ``gamma`` (dimensionless).

    Parameters
    ----------
    ball : ModalBall
    gamma : float
        ``g / (R c^2)`` >= 0.
    restitution : float
        Newton's e at every floor point, in [0, 1].
    """
    x = np.cos(ball.phi)
    masses = np.concatenate([[1.0], ball.masses])
    stiffness = np.concatenate([[0.0], ball.masses * ball.omega_squared])
    damping = np.concatenate([[0.0], ball.masses * ball.decay])
    load = np.zeros(masses.size)
    load[0] = -float(gamma)
    G = np.column_stack([np.ones_like(x), x[:, None] * ball.shapes])
    problem = ContactProblem.create(masses, damping, stiffness, load, G, x, restitution)
    return FloorSystem(ball, problem, float(gamma))
