"""The membrane as a lower ball: its Legendre modes and the ball object that builds them.

Dimensionless: length R, time 1/c, mass m2 = 4 pi rho R^2.  The membrane moves
radially only: ``u = sum_k a_k phi_k`` over modes of mass ``m_k = int phi_k^2 dS /
(4 pi)``, stiffness ``m_k omega_k^2`` and damping ``m_k d_k`` (the decay ``d_k = 2
zeta_k omega_k`` of the damping law).  It cannot translate by a motion of its
material (its degree-1 part is the centre's), so the centre's height Z is a
coordinate of its own, the first, and the degree-1 content of u (``int u
cos(phi) dS``, the centre of mass's offset) is left out: a translation is
carried once.  A material point at polar angle phi stands at ``Z + (1 + u)
cos(phi)``, so its vertical row is ``(1, cos(phi) phi_k(phi))``
(:class:`~twoball.modal.balls.description.ModalBall`).

* Legendre modes (:func:`legendre_ball`, the ball :class:`LegendreBall`):
  ``phi_k = P_n(cos phi)``, ``m_n = 1 / (2n + 1)``, the floor points at the
  Gauss-Radau nodes of degree N + 1 on the lower hemisphere
  (:func:`floor_angles`; the south pole is one).
* Finite elements (:func:`twoball.fem_membrane.floor.axisym_ball`, the ball
  :class:`twoball.fem_membrane.ball.FEBall`): the M-orthonormal eigenvectors of
  the whole finite-element space (``m_k = 1``), the floor points at the nodes of
  the lower hemisphere.  A change of coordinates, exact to rounding: the contact
  core integrates the finite-element equations.

:func:`mode_spectrum` reads each mode's frequency from the ball's
:class:`~twoball.modal.stiffness.Stiffness` (membrane operator, bending, enclosed
gas) by its Laplace-Beltrami eigenvalue, and :func:`mode_decay` its damping from
the law.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

import numpy as np
from numpy.polynomial.legendre import legvander

from twoball._common.errors import ParameterError
from twoball._common.keywords import checked
from twoball.modal.balls.description import ModalBall
from twoball.modal.contact.caps import legendre_cap_averages
from twoball.modal.damping import ModalRatio, Rayleigh
from twoball.modal.stiffness import Stiffness

if TYPE_CHECKING:
    from twoball.modal.parameters import Case

__all__ = [
    "DEFAULT_MODES",
    "LegendreBall",
    "floor_angles",
    "legendre_ball",
    "membrane_rows",
    "mode_decay",
    "summary",
    "mode_spectrum",
]

#: Legendre degree N of the drop on the closed-form modes (floor points at its ~N/2
#: Gauss-Radau nodes on the lower hemisphere).
DEFAULT_MODES = 192
#: Degrees N a Legendre ball takes.
MODES_RANGE = (8, 2000)

#: Laplace-Beltrami eigenvalue below which a mode is the constant one (n = 0).
CONSTANT_MODE = 1e-6


def mode_spectrum(stiffness: Stiffness, laplace: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """omega^2 of modes of Laplace-Beltrami eigenvalues ``laplace``, and the gas's share.

    Read from the ball's :class:`~twoball.modal.stiffness.Stiffness` (membrane
    operator, bending, gas): :meth:`~twoball.modal.stiffness.Stiffness.omega_squared`
    for the vibrating modes, :attr:`~twoball.modal.stiffness.Stiffness.breathing`
    (``gas - s``) for the constant one, whose gas share is ``gas``.
    """
    lam = np.asarray(laplace, dtype=float)
    constant = np.abs(lam) < CONSTANT_MODE
    w2 = np.where(constant, stiffness.breathing, stiffness.omega_squared(lam))
    return w2, np.where(constant, stiffness.gas, 0.0)


def mode_decay(law: ModalRatio | Rayleigh, omega_squared: np.ndarray) -> np.ndarray:
    """``d_k = 2 zeta_k omega_k`` of each mode: the law's :meth:`decay` (units c).

    :class:`~twoball.modal.damping.Rayleigh`'s ``alpha + beta omega^2`` is ``C =
    alpha M + beta K`` exactly in the modes of K.  A mode of ``omega^2 <= 0`` (a
    free motion) has ``2 D omega = 0`` under the modal ratio.
    """
    if not isinstance(law, (ModalRatio, Rayleigh)):
        raise ParameterError("damping", "a ModalRatio or Rayleigh", law)
    w2 = np.asarray(omega_squared, dtype=float)
    return np.asarray(law.decay(np.sqrt(np.clip(w2, 0.0, None))), dtype=float)


def floor_angles(modes: int) -> np.ndarray:
    """Polar angles [rad] of the floor points of N Legendre modes: Gauss-Radau nodes, ascending.

    The N + 1 nodes of the Gauss-Radau rule on [-1, 1] with the node x = -1 (the
    south pole) are exact for polynomials of degree 2N, so the modes are
    discretely orthogonal on them: ``sum_k w_k P_m(x_k) P_n(x_k) = 2 delta_mn /
    (2n + 1)`` for m, n <= N.  The floor's Delassus matrix ``G M^-1 G^T`` is then
    diagonal, ``2 x_k^2 / w_k``, up to the smooth rank-two terms of the centre
    (+1) and of the missing degree 1 (``-3 x_i^2 x_j^2``): each point carries the
    mass of its own quadrature cell, and an impulse at one point does not pull
    its neighbours onto the floor (with equally spaced points it does, through
    the alternating side lobes of the truncated series, and they rattle).  The
    nodes with ``x < 0`` are kept (about N / 2, nearly equally spaced in phi,
    spacing ~ pi / N); the interior ones are the zeros of the Jacobi polynomial
    ``P_N^(0, 1)`` (Golub-Welsch, :func:`scipy.special.roots_jacobi`).
    """
    from scipy.special import roots_jacobi

    interior, _ = roots_jacobi(int(modes), 0.0, 1.0)
    x = np.concatenate([[-1.0], interior[interior < 0.0]])
    return np.sort(np.arccos(np.clip(x, -1.0, 1.0)))


def summary(case: Case) -> dict[str, Any]:
    """The membrane's spectrum for the JSON: the operator, the bending by its own names.

    ``membrane`` the operator, ``bending_N_m`` the flexural rigidity B [N m],
    ``bending_beta`` the dimensionless ratio ``beta = B / (T R^2)`` of the
    spectrum and ``omega0_squared`` the breathing mode's ``omega_0^2`` in units
    of ``c^2``.
    """
    data = case.stiffness.as_dict()
    return {
        "membrane": data["membrane"],
        "bending_N_m": case.bending,
        "bending_beta": data["beta"],
        "omega0_squared": data["omega0_squared"],
    }


def membrane_rows(
    phi: np.ndarray, shapes: np.ndarray, masses: np.ndarray, omega_squared: np.ndarray
) -> tuple[np.ndarray, np.ndarray]:
    """The floor rows ``(1, cos(phi_i) S_ik)`` of a radial membrane with its centre, and reach.

    ``shapes[i, k]`` is the radial mode k at floor point i.  The reach bounds the
    vibration's vertical share at each point, ``|cos(phi_i) u_i| <= r_i sqrt(2 E)``
    with ``r_i = |cos(phi_i)| sqrt(sum_k S_ik^2 / (m_k omega_k^2))`` (inf if a mode
    is unstable).
    """
    x = np.cos(phi)
    rows = np.column_stack([np.ones_like(x), x[:, None] * shapes])
    if np.all(omega_squared > 0.0):
        reach = np.abs(x) * np.sqrt((shapes**2) @ (1.0 / (masses * omega_squared)))
    else:
        reach = np.full(x.size, math.inf)
    return rows, reach


def legendre_ball(
    modes: int,
    spectrum: Stiffness,
    law: ModalRatio | Rayleigh,
    *,
    anchored: bool = False,
) -> ModalBall:
    """The centre's height Z, Legendre modes n = 0, 2, ..., N, floor points at Gauss-Radau nodes.

    Parameters
    ----------
    modes : int
        Highest degree N >= 2.
    spectrum : Stiffness
        Membrane operator, bending and gas: ``omega_n^2`` from ``lambda = n (n + 1)``.
    law : ModalRatio or Rayleigh
        The damping law (dimensionless; a fitted Rayleigh law must be fitted already).
    anchored : bool
        Keep degree 1 as a mode of the membrane about a fixed centre (omega_1^2 =
        2 on the paper's operator, 0 on the pressurised one) and no coordinate
        Z (``centre = None``): the paper's restitution-only model.  The drop
        leaves degree 1 out (Z carries it).
    """
    if isinstance(modes, bool) or not isinstance(modes, int) or modes < 2:
        raise ParameterError("modes", "an integer >= 2", modes)
    n = np.arange(modes + 1) if anchored else np.concatenate([[0], np.arange(2, modes + 1)])
    laplace = n * (n + 1.0)
    w2, gas2 = mode_spectrum(spectrum, laplace)
    masses = 1.0 / (2.0 * n + 1.0)
    decay = mode_decay(law, w2)
    phi = floor_angles(modes)
    shapes = legvander(np.cos(phi), modes)[:, n]
    label = f"legendre N = {modes}"
    bending = spectrum.beta > 0.0
    if anchored:
        return ModalBall(
            masses=masses,
            omega_squared=w2,
            gas_squared=gas2,
            decay=decay,
            centre=None,
            phi=phi,
            floor_rows=np.cos(phi)[:, None] * shapes,
            top=np.ones(n.size),
            label=label,
            bending=bending,
            laplace=laplace,
            sampler=lambda angles: legvander(np.cos(angles), modes)[:, n],
            averager=lambda theta: legendre_cap_averages(theta, modes)[n],
        )
    rows, reach = membrane_rows(phi, shapes, masses, w2)
    return ModalBall(
        masses=np.concatenate([[1.0], masses]),
        omega_squared=np.concatenate([[0.0], w2]),
        gas_squared=np.concatenate([[0.0], gas2]),
        decay=np.concatenate([[0.0], decay]),
        centre=0,
        phi=phi,
        floor_rows=rows,
        top=np.ones(n.size + 1),
        label=label,
        bending=bending,
        laplace=np.concatenate([[2.0], laplace]),
        reach=reach,
        sampler=lambda angles: np.column_stack(
            [np.zeros(angles.size), legvander(np.cos(angles), modes)[:, n]]
        ),
        averager=lambda theta: np.concatenate([[1.0], legendre_cap_averages(theta, modes)[n]]),
    )


@checked
@dataclass(frozen=True)
class LegendreBall:
    """The case's membrane on its Legendre modes: a lower ball for the drop and the body's contact.

    Parameters
    ----------
    modes : int, optional
        Legendre degree N in [8, 2000] (default :data:`DEFAULT_MODES`, 192; the
        floor points are its Gauss-Radau nodes on the lower hemisphere, about N/2).

    The membrane's physics is the case's (SI): its radius R, wave speed c,
    excess pressure P (the mass ``m2 = 2 pi R P / c^2``), membrane operator,
    bending, gas and damping law (:attr:`twoball.Case.stiffness`,
    :attr:`twoball.Case.damping_law`).

    Examples
    --------
    >>> import twoball
    >>> twoball.LegendreBall(64).label
    'legendre N = 64'
    >>> twoball.LegendreBall(modes=3)
    Traceback (most recent call last):
    ...
    twoball.ParameterError: modes must be an integer in [8, 2000], got 3
    """

    modes: int | None = None

    #: The physics of this ball (the JSON's ``ball``) and its discretisation.
    kind = "membrane"
    backend = "legendre"
    VALID = {"modes": f"an integer in [{MODES_RANGE[0]}, {MODES_RANGE[1]}]"}  # noqa: RUF012

    def __post_init__(self) -> None:
        if self.modes is not None:
            low, high = MODES_RANGE
            if (
                isinstance(self.modes, bool)
                or not isinstance(self.modes, int | np.integer)
                or not low <= int(self.modes) <= high
            ):
                raise ParameterError("modes", self.VALID["modes"], self.modes)
            object.__setattr__(self, "modes", int(self.modes))

    @property
    def degree(self) -> int:
        """N (the default when none was given)."""
        return DEFAULT_MODES if self.modes is None else self.modes

    @property
    def label(self) -> str:
        """``legendre N = 192``."""
        return f"legendre N = {self.degree}"

    def size(self, case: Case | None = None) -> tuple[int, int]:
        """The drop's size as its cost model counts it: N modes and N / 2 floor points.

        :meth:`describe` has N + 1 coordinates (the centre and n = 0, 2, ..., N) and
        N / 2 + 1 floor points (the Gauss-Radau nodes of the lower hemisphere).
        """
        return self.degree, self.degree // 2

    def mass(self, case: Case) -> float:
        """The ball's mass ``m2 = 2 pi R P / c^2`` [kg] (``membrane_mass`` of the scalings).

        The tension ``T = P R / 2`` with ``c^2 = T / (rho R^2)``, eq. (3.8).
        """
        from twoball.modal.scalings import membrane_mass

        return membrane_mass(case.radius, case.pressure, case.wave_speed)

    def summary(self, case: Case) -> dict[str, Any]:
        """The membrane's spectrum for the JSON (:func:`summary`)."""
        return summary(case)

    def describe(self, case: Case, monitor: Any = None, *, anchored: bool = False) -> ModalBall:
        """The membrane of ``case`` on N Legendre modes (dimensionless: R, 1/c, m2)."""
        return legendre_ball(self.degree, case.stiffness, case.damping_law, anchored=anchored)

    def as_dict(self) -> dict[str, Any]:
        """``{"ball": "membrane", "discretisation": "legendre", "modes": N}``."""
        return {"ball": self.kind, "discretisation": "legendre", "modes": self.modes}
