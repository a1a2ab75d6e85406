"""The modal description of a lower ball: what the contact core is handed (dimensionless).

Every kind of ball (the Legendre membrane, the finite-element membrane, a shell,
a solid) reaches the drop as one :class:`ModalBall`, in units of its radius R,
of the time ``1/c`` of the case and of its own mass ``m2``.  The description is
linear in K generalised coordinates ``q`` with diagonal mass, stiffness and
damping::

    m_k (q_k'' + d_k q_k' + omega_k^2 q_k) = (forces on coordinate k),

and it says how the ball meets the world through *vertical* displacements only:

* the floor: point i of polar angle ``phi_i`` (the ball's reference surface is
  the unit sphere about its centre) stands at height ``cos(phi_i) +
  floor_rows[i] @ q`` above the floor, where ``floor_rows[i, k]`` is the vertical
  displacement ``u_r cos(phi) - u_phi sin(phi)`` of that material point per unit
  of coordinate k, the rigid translation included;
* an upper body: the north pole's vertical displacement is ``top @ q`` and its
  average over the polar cap ``phi <= theta`` is ``cap_average(theta) @ q``
  (the pole stands at ``1 + top @ q``);
* gravity and the momentum books: coordinate :attr:`ModalBall.centre` is the
  rigid vertical translation of the whole ball, normalised so that it *is* the
  centre of mass's height (its mass is the ball's, 1); every other coordinate
  leaves the centre of mass where it is (mass-orthogonal to the translation).

A ball without a free centre (the paper's model, degree 1 a mode about a
centre that does not move) has ``centre = None``.  Whether the ball moves only
radially (the membranes) or also tangentially (a shell, a solid) is inside its
rows; the contact core, the measures and the reports never ask.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass, field

import numpy as np

from twoball._common.errors import NumericalError, ParameterError
from twoball._common.keywords import checked

__all__ = ["ModalBall"]


@checked
@dataclass(frozen=True, eq=False)
class ModalBall:
    """A ball in modal coordinates with the points where it may touch the floor.

    Attributes
    ----------
    masses : ndarray, shape (K,)
        ``m_k`` in units of the ball's mass (``masses[centre] == 1``).
    omega_squared : ndarray, shape (K,)
        omega_k^2 in units of c^2 (0 on the translation).
    gas_squared : ndarray, shape (K,)
        The enclosed gas's share of omega_k^2 (for the energy books).
    decay : ndarray, shape (K,)
        ``2 zeta_k omega_k`` in units of c (0 on the translation).
    centre : int or None
        The coordinate that is the height of the centre of mass (units R), a
        rigid vertical translation of unit amplitude; None when the centre is held.
    phi : ndarray, shape (P,)
        Polar angles of the floor points [rad], ascending in ``(pi/2, pi]``
        (empty: a ball that never meets the floor, the paper's special case).
    floor_rows : ndarray, shape (P, K)
        Vertical displacement of floor point i per unit of coordinate k.
    top : ndarray, shape (K,)
        Vertical displacement of the north pole per unit of each coordinate.
    label : str
        ``"legendre N = 192"``, ``"axisym 96 P2"``, ...
    bending : bool
        The surface keeps its curvature continuous at the contact edge (bending
        stiffness): the gap outside the contact grows like the cube of the
        distance from the edge instead of its square
        (:func:`~twoball.modal.floor.measure.edge_law`).
    laplace : ndarray, shape (K,), optional
        The Laplace-Beltrami eigenvalue of each mode where the ball has one
        (the membranes: ``n (n + 1)`` or its finite-element value).
    reach : ndarray, shape (P,), optional
        ``r_i`` with ``|(floor_rows[i] @ q)_deformation| <= r_i sqrt(2 E)`` for a
        vibration energy E (default from :meth:`floor_reach`).
    sampler : callable, optional
        ``sampler(phi) -> (len(phi), K)``: the radial displacement of each
        coordinate's deformation at any polar angles (0 in the translation's
        column), for fields and pictures.
    tangential : callable, optional
        ``tangential(phi) -> (len(phi), K)``: the meridional displacement of the
        deformation (None: the ball moves radially only).
    averager : callable, optional
        ``averager(theta) -> (K,)``: the vertical displacement of each coordinate
        averaged over the polar cap of half-angle theta around the north pole
        (:meth:`cap_average`).

    Examples
    --------
    A rigid ball of unit mass: its translation alone, one floor point, the pole.

    >>> import math, numpy as np
    >>> from twoball.modal.balls.description import ModalBall
    >>> one = np.ones(1)
    >>> ball = ModalBall(one, np.zeros(1), np.zeros(1), np.zeros(1), 0,
    ...     np.array([math.pi]), one[None, :], one, averager=lambda theta: one)
    >>> ball.modes, ball.points, ball.stable, ball.floor_reach()
    (1, 1, True, array([0.]))
    """

    masses: np.ndarray
    omega_squared: np.ndarray
    gas_squared: np.ndarray
    decay: np.ndarray
    centre: int | None
    phi: np.ndarray
    floor_rows: np.ndarray
    top: np.ndarray
    label: str = ""
    bending: bool = False
    laplace: np.ndarray | None = None
    reach: np.ndarray | None = field(default=None, repr=False)
    sampler: Callable[[np.ndarray], np.ndarray] | None = field(default=None, repr=False)
    tangential: Callable[[np.ndarray], np.ndarray] | None = field(default=None, repr=False)
    averager: Callable[[float], np.ndarray] | None = field(default=None, repr=False)

    def __post_init__(self) -> None:
        k = self.masses.size
        for name in ("omega_squared", "gas_squared", "decay", "top"):
            if getattr(self, name).shape != (k,):
                raise NumericalError(f"ModalBall: {name} has the wrong shape")
        if self.laplace is not None and self.laplace.shape != (k,):
            raise NumericalError("ModalBall: laplace has the wrong shape")
        if self.floor_rows.shape != (self.phi.size, k):
            raise NumericalError("ModalBall: floor_rows must be (points, coordinates)")
        if self.reach is not None and self.reach.shape != self.phi.shape:
            raise NumericalError("ModalBall: reach must have one bound per floor point")
        if np.any(self.masses <= 0) or np.any(self.decay < 0):
            raise NumericalError("ModalBall: masses must be > 0 and decays >= 0")
        if self.phi.size and (np.any(np.diff(self.phi) <= 0) or self.phi[0] <= 0.5 * math.pi):
            raise NumericalError("ModalBall: floor points must ascend in (pi/2, pi]")
        if self.centre is not None:
            c = self.centre
            if not 0 <= c < k:
                raise NumericalError("ModalBall: centre is not a coordinate")
            if self.masses[c] != 1.0 or self.omega_squared[c] != 0.0 or self.decay[c] != 0.0:
                raise NumericalError(
                    "ModalBall: the centre's coordinate must be a free translation of unit mass"
                )

    @property
    def modes(self) -> int:
        """Number of coordinates K (the translation, where there is one, included)."""
        return int(self.masses.size)

    @property
    def points(self) -> int:
        """Number of floor points P."""
        return int(self.phi.size)

    @property
    def deformation(self) -> np.ndarray:
        """Indices of the coordinates that deform the ball (all but the translation)."""
        every = np.arange(self.modes)
        return every if self.centre is None else np.delete(every, self.centre)

    @property
    def stable(self) -> bool:
        """True when every deformation has omega^2 > 0 (no free drift of the shape)."""
        return bool(np.all(self.omega_squared[self.deformation] > 0.0))

    def modes_at(self, phi: np.ndarray) -> np.ndarray:
        """The radial displacement of each coordinate's deformation at ``phi`` [rad], (n, K)."""
        if self.sampler is None:
            raise NumericalError(f"ModalBall {self.label!r}: no sampler of the modes")
        return self.sampler(np.asarray(phi, dtype=float).reshape(-1))

    def tangential_at(self, phi: np.ndarray) -> np.ndarray:
        """The meridional displacement of each coordinate's deformation at ``phi``, (n, K)."""
        angles = np.asarray(phi, dtype=float).reshape(-1)
        if self.tangential is None:
            return np.zeros((angles.size, self.modes))
        return self.tangential(angles)

    def cap_average(self, theta: float) -> np.ndarray:
        """Each coordinate's vertical displacement averaged over the cap ``phi <= theta`` [rad].

        The translation's entry is 1; the pole is the limit theta -> 0 (:attr:`top`).
        """
        if self.averager is None:
            raise NumericalError(f"ModalBall {self.label!r}: no cap averages of the modes")
        if not (math.isfinite(theta) and 0.0 < theta < math.pi / 2):
            raise ParameterError("contact_radius", "a cap of half-angle in (0, pi/2)", theta)
        return np.asarray(self.averager(float(theta)), dtype=float)

    def bound(self, rows: np.ndarray) -> np.ndarray:
        """``b`` with ``|rows[:, deformation] @ q| <= b sqrt(2 E)``, E the vibration energy.

        Cauchy-Schwarz with ``E >= 1/2 sum m_k omega_k^2 q_k^2`` over the
        deformation: ``b^2 = sum_k rows_k^2 / (m_k omega_k^2)`` (inf if unstable).
        """
        rows = np.atleast_2d(rows)
        if not self.stable:
            return np.full(rows.shape[0], math.inf)
        d = self.deformation
        return np.sqrt((rows[:, d] ** 2) @ (1.0 / (self.masses[d] * self.omega_squared[d])))

    def floor_reach(self) -> np.ndarray:
        """``r_i``: how far the vibration can move floor point i vertically, per ``sqrt(2 E)``."""
        return self.bound(self.floor_rows) if self.reach is None else self.reach

    def without_samplers(self) -> ModalBall:
        """The same description without its closures (it then pickles: sweeps' light results)."""
        from dataclasses import replace

        return replace(self, sampler=None, tangential=None, averager=None)
