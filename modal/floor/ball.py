"""The lower ball in modal coordinates, with the points where it may touch the floor.

Dimensionless: length R, time 1/c, mass m2 = 4 pi rho R^2.  Both backends hand
the contact core the same description (:class:`ModalBall`): the radial
displacement is ``u = sum_k a_k phi_k`` over modes of mass ``m_k = int phi_k^2
dS / (4 pi)``, stiffness ``m_k omega_k^2`` and damping ``m_k d_k`` (the decay
``d_k = 2 zeta_k omega_k`` of the damping law), and ``shapes[i, k] = phi_k(phi_i)``
at the floor points.

* Legendre modes (:func:`legendre_ball`): ``phi_k = P_n(cos phi)``, ``m_n = 1 /
  (2n + 1)``, the floor points at the Gauss-Radau nodes of degree N + 1 on the
  lower hemisphere (:func:`floor_angles`; the south pole is one).
* Finite elements (:func:`twoball.fem_membrane.floor.axisym_ball`): the
  M-orthonormal eigenvectors of the whole finite-element space (``m_k = 1``), the
  floor points at the nodes of the lower hemisphere.  A change of coordinates,
  exact to rounding: the contact core integrates the finite-element equations.

The rigid translation is carried by the centre's height Z, so the degree-1
content of u (``int u cos(phi) dS``, the centre of mass's offset) is left out:
a translation is carried once.  :func:`mode_spectrum` reads each mode's
frequency from the ball's :class:`~twoball.modal.stiffness.Stiffness` (membrane
operator, bending, enclosed gas) by its Laplace-Beltrami eigenvalue, and
:func:`mode_decay` its damping from the law.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass, field

import numpy as np
from numpy.polynomial.legendre import legvander
from twoball.modal.contact.caps import legendre_cap_averages
from twoball.modal.damping import ModalRatio, Rayleigh
from twoball.modal.stiffness import Stiffness

from twoball._common.errors import NumericalError, ParameterError

__all__ = [
    "ModalBall",
    "floor_angles",
    "legendre_ball",
    "mode_decay",
    "mode_spectrum",
]

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


@dataclass(frozen=True, eq=False)
class ModalBall:
    """The membrane in modal coordinates and its floor points (dimensionless).

    Attributes
    ----------
    masses : ndarray, shape (K,)
        ``m_k`` in units of m2.
    omega_squared : ndarray, shape (K,)
        omega_k^2 (membrane operator, bending and gas), units c^2.
    gas_squared : ndarray, shape (K,)
        The gas's share of omega_k^2 (for the energy books).
    decay : ndarray, shape (K,)
        ``2 zeta_k omega_k``, units c.
    phi : ndarray, shape (P,)
        Polar angles of the floor points [rad], ascending, in ``(pi/2, pi]``.
    shapes : ndarray, shape (P, K)
        Mode k at floor point i.
    top : ndarray, shape (K,)
        Mode values at the north pole (phi = 0), where an upper body rests.
    laplace : ndarray, shape (K,)
        Laplace-Beltrami eigenvalue of each mode (``n (n + 1)`` or the FE one).
    label : str
        ``"legendre N = 128"``, ``"axisym 64 P2"``, ...
    bending : bool
        The spectrum has bending stiffness (``beta > 0``): the membrane then
        leaves the floor with its curvature continuous too, and the gap outside
        the contact grows like the cube of the distance from the edge instead of
        its square (:func:`~twoball.modal.floor.measure.contact_edge`).
    sampler : callable, optional
        ``sampler(phi) -> (len(phi), K)``: every mode at any polar angles (for
        fields and pictures); the Legendre polynomials, or the finite-element
        interpolant.
    averager : callable, optional
        ``averager(theta) -> (K,)``: every mode averaged over the polar cap of
        half-angle theta around the north pole, exactly (where an upper body
        touches; :meth:`cap_average`).
    """

    masses: np.ndarray
    omega_squared: np.ndarray
    gas_squared: np.ndarray
    decay: np.ndarray
    phi: np.ndarray
    shapes: np.ndarray
    top: np.ndarray
    laplace: np.ndarray
    label: str = ""
    bending: bool = False
    sampler: Callable[[np.ndarray], np.ndarray] | None = field(default=None, repr=False)
    averager: Callable[[float], np.ndarray] | None = field(default=None, repr=False)

    def __post_init__(self) -> None:
        k = self.masses.size
        for name in ("omega_squared", "gas_squared", "decay", "top", "laplace"):
            if getattr(self, name).shape != (k,):
                raise NumericalError(f"ModalBall: {name} has the wrong shape")
        if self.shapes.shape != (self.phi.size, k):
            raise NumericalError("ModalBall: shapes must be (points, modes)")
        if np.any(self.masses <= 0) or np.any(self.decay < 0):
            raise NumericalError("ModalBall: masses must be > 0 and decays >= 0")
        if np.any(np.diff(self.phi) <= 0) or self.phi[0] <= 0.5 * math.pi:
            raise NumericalError("ModalBall: floor points must ascend in (pi/2, pi]")

    @property
    def modes(self) -> int:
        """Number of modal coordinates K."""
        return int(self.masses.size)

    @property
    def points(self) -> int:
        """Number of floor points P."""
        return int(self.phi.size)

    @property
    def stable(self) -> bool:
        """True when every mode has omega^2 > 0 (no free drift of the shape)."""
        return bool(np.all(self.omega_squared > 0.0))

    def modes_at(self, phi: np.ndarray) -> np.ndarray:
        """Every mode at the polar angles ``phi`` [rad], shape (len(phi), K)."""
        if self.sampler is None:
            raise NumericalError(f"ModalBall {self.label!r}: no sampler of the modes")
        return self.sampler(np.asarray(phi, dtype=float).reshape(-1))

    def cap_average(self, theta: float) -> np.ndarray:
        """``b_k``: every mode averaged over the cap ``phi <= theta`` [rad] (the pole: theta -> 0).

        The cap's area element is ``dS = d(cos phi) d alpha``, so the average of an
        axisymmetric function is its plain mean over ``x = cos(phi)`` in ``[cos
        theta, 1]`` (:mod:`twoball.modal.contact.caps`).
        """
        if self.averager is None:
            raise NumericalError(f"ModalBall {self.label!r}: no cap averages of the modes")
        if not (math.isfinite(theta) and 0.0 < theta < math.pi / 2):
            raise ParameterError("contact_radius", "a cap of half-angle in (0, pi/2)", theta)
        return np.asarray(self.averager(float(theta)), dtype=float)

    def amplitude_bound(self) -> np.ndarray:
        """``b_i``: ``|u(phi_i)| <= b_i sqrt(2 E)`` for a membrane energy E (inf if unstable).

        Cauchy-Schwarz on ``u_i = sum_k S_ik a_k`` with ``E >= 1/2 sum m_k omega_k^2
        a_k^2``: ``b_i^2 = sum_k S_ik^2 / (m_k omega_k^2)``.
        """
        if not self.stable:
            return np.full(self.points, math.inf)
        return np.sqrt((self.shapes**2) @ (1.0 / (self.masses * self.omega_squared)))


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


def legendre_ball(
    modes: int,
    spectrum: Stiffness,
    law: ModalRatio | Rayleigh,
    *,
    anchored: bool = False,
) -> ModalBall:
    """Legendre modes n = 0, 2, 3, ..., N and the floor points at the Gauss-Radau nodes.

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
        2 on the paper's operator, 0 on the pressurised one): the paper's
        restitution-only model.  The drop leaves it out (Z carries it).
    """
    if isinstance(modes, bool) or not isinstance(modes, int) or modes < 2:
        raise ParameterError("modes", "an integer >= 2", modes)
    n = np.arange(modes + 1) if anchored else np.concatenate([[0], np.arange(2, modes + 1)])
    laplace = n * (n + 1.0)
    w2, gas2 = mode_spectrum(spectrum, laplace)
    phi = floor_angles(modes)
    shapes = legvander(np.cos(phi), modes)[:, n]
    return ModalBall(
        masses=1.0 / (2.0 * n + 1.0),
        omega_squared=w2,
        gas_squared=gas2,
        decay=mode_decay(law, w2),
        phi=phi,
        shapes=shapes,
        top=np.ones(n.size),
        laplace=laplace,
        label=f"legendre N = {modes}",
        bending=spectrum.beta > 0.0,
        sampler=lambda angles: legvander(np.cos(angles), modes)[:, n],
        averager=lambda theta: legendre_cap_averages(theta, modes)[n],
    )
