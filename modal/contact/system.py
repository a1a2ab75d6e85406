"""The modal membrane plus a rigid body in unilateral contact (dimensionless).

Units: length R, time 1/c, energy T R^2 (so that the membrane's energy is the
:meth:`~twoball.modal.series.ModalSeries.energy` of its series).  With the radial
displacement ``u = sum_k q_k phi_k`` over modes of mass ``m_k = int phi_k^2 dS``
(the unit sphere; ``4 pi / (2n + 1)`` for ``P_n``, 1 for M-orthonormal finite-element
vectors) the equations of motion are (docs/contact.rst, eqs. (C1)-(C4))::

    m_k (q_k'' + 2 D omega_k q_k' + omega_k^2 q_k) = -b_k Lambda        (C1)
    mu_t (s'' + gamma) = Lambda                                          (C2)
    g = s - sum_k b_k q_k >= 0,  Lambda >= 0,  Lambda g = 0              (C3)

where ``b_k`` is mode k averaged over the contact cap, ``s`` the body's height
above the undeformed pole, ``Lambda = lambda / (T R)`` the contact force and
``mu_t = 4 pi m1 / m2 = 4 pi mu`` the body's mass in units of ``rho R^2`` (the
membrane's mass is ``m2 = 4 pi rho R^2``, i.e. 4 pi in these units).  The energy
(C4) is ``E = 1/2 sum m_k (q_k'^2 + omega_k^2 q_k^2) + 1/2 mu_t s'^2 + mu_t gamma s``.

The state is the augmented vector ``z = (q, q', s, s', 1)``; in each phase (free
flight of the body, or persistent contact) it obeys ``z' = A z`` with a constant
matrix, so the motion between events is ``exp(A t) z`` in closed form.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from functools import cached_property

import numpy as np

from twoball._common.errors import NumericalError, ParameterError
from twoball.modal.series import ModalSeries


@dataclass(frozen=True)
class ContactSystem:
    """Modes, contact vector and body of the contact problem (dimensionless).

    Parameters
    ----------
    omega : ndarray, shape (K,)
        Undamped modal frequencies (0 for the constant mode).
    masses : ndarray, shape (K,)
        Modal masses ``m_k = int phi_k^2 dS`` on the unit sphere.
    contact : ndarray, shape (K,)
        Cap averages ``b_k`` of the modes (the contact vector); ``phi_k(0)`` for a point.
    initial : ndarray, shape (K,)
        Initial modal displacements (filtered, ``sigma_k q_k(0)``); velocities are 0.
    damping : float
        Modal damping ratio D in [0, 1), eq. (3.14).
    body_mass : float
        ``mu_t = 4 pi mu`` (mu = m1/m2); 0 is the massless body.
    gamma : float
        ``g / (R c^2)``.
    """

    omega: np.ndarray
    masses: np.ndarray
    contact: np.ndarray
    initial: np.ndarray
    damping: float
    body_mass: float
    gamma: float

    def __post_init__(self) -> None:
        arrays = [
            np.asarray(getattr(self, k), dtype=float)
            for k in ("omega", "masses", "contact", "initial")
        ]
        if len({a.shape for a in arrays}) != 1 or arrays[0].ndim != 1:
            raise ValueError("omega, masses, contact and initial must be 1-D of equal length")
        for name, a in zip(("omega", "masses", "contact", "initial"), arrays, strict=True):
            if not np.all(np.isfinite(a)):
                raise NumericalError(f"contact system: {name} contains NaN or inf")
            object.__setattr__(self, name, a)
        if np.any(self.masses <= 0):
            raise NumericalError("contact system: modal masses must be > 0")
        if not (math.isfinite(self.body_mass) and self.body_mass >= 0):
            raise ParameterError(
                "mass_ratio", "a finite number >= 0", self.body_mass / (4 * math.pi)
            )

    @classmethod
    def from_series(
        cls, series: ModalSeries, contact: np.ndarray, mass_ratio: float, gamma: float
    ) -> ContactSystem:
        """The contact system on a backend's :class:`ModalSeries` (every mode, filtered start).

        Modes the filter drops start at rest but are still forced by the contact.
        The damping is the paper's ratio D (``2 D omega`` per mode): a series
        under another law is refused.
        """
        if not isinstance(series.damping, float):
            raise ParameterError("damping", "the modal ratio D with a body of finite mass", "law")
        return cls(
            omega=series.omega,
            masses=series.mode_norms,
            contact=np.asarray(contact, dtype=float),
            initial=series.weights * series.coefficients,
            damping=series.damping,
            body_mass=4.0 * math.pi * float(mass_ratio),
            gamma=float(gamma),
        )

    # --- sizes and slices of the augmented state z = (q, q', s, s', 1) -------------
    @property
    def size(self) -> int:
        """Number of modes K."""
        return int(self.omega.size)

    @property
    def max_frequency(self) -> float:
        """Largest modal frequency (sets the event-detection grid)."""
        return float(self.omega.max(initial=0.0))

    @cached_property
    def compliance(self) -> float:
        """``kappa = sum_k b_k^2 / m_k``: the cap's displacement per unit impulse-velocity."""
        return float(np.sum(self.contact**2 / self.masses))

    @cached_property
    def effective_mass(self) -> float:
        """Mass of the impact, ``1 / (1/mu_t + kappa)`` (0 for a massless body)."""
        if self.body_mass == 0.0:
            return 0.0
        return 1.0 / (1.0 / self.body_mass + self.compliance)

    def start(self) -> np.ndarray:
        """``z(0)``: filtered modes at rest, the body at rest on the cap (g = 0)."""
        k = self.size
        z = np.zeros(2 * k + 3)
        z[:k] = self.initial
        z[2 * k] = float(self.contact @ self.initial)
        z[-1] = 1.0
        return z

    # --- the two phase matrices -------------------------------------------------------
    def _free_rows(self) -> np.ndarray:
        """Rows of ``q''`` of the free membrane: ``-omega^2 q - 2 D omega q'``."""
        k = self.size
        rows = np.zeros((k, 2 * k + 3))
        rows[:, :k] = -np.diag(self.omega**2)
        rows[:, k : 2 * k] = -np.diag(2.0 * self.damping * self.omega)
        return rows

    @cached_property
    def force_row(self) -> np.ndarray:
        """Row ``l`` with ``Lambda = l . z`` while in contact (eq. (C5)).

        ``Lambda = mu_t (b . a + gamma) / (1 + mu_t kappa)``, ``a`` the free
        membrane's acceleration.
        """
        row = self.contact @ self._free_rows()
        row[-1] += self.gamma
        return row * (self.body_mass / (1.0 + self.body_mass * self.compliance))

    @cached_property
    def flight_matrix(self) -> np.ndarray:
        """``A`` of free flight: free damped modes, body under gravity."""
        k = self.size
        a = np.zeros((2 * k + 3, 2 * k + 3))
        a[:k, k : 2 * k] = np.eye(k)
        a[k : 2 * k] = self._free_rows()
        a[2 * k, 2 * k + 1] = 1.0
        a[2 * k + 1, -1] = -self.gamma
        return a

    @cached_property
    def contact_matrix(self) -> np.ndarray:
        """``A`` of persistent contact, ``g = 0``: modes forced by ``-b Lambda`` (eq. (C5))."""
        k = self.size
        a = self.flight_matrix.copy()
        a[k : 2 * k] -= np.outer(self.contact / self.masses, self.force_row)
        # the body moves with the cap: s'' = b . q''
        a[2 * k + 1] = self.contact @ a[k : 2 * k]
        return a

    def apply(self, z: np.ndarray, mode: str) -> np.ndarray:
        """``A z`` for the ``flight`` or ``contact`` matrix, in O(K) without forming ``A``.

        The same rows as :attr:`flight_matrix` and :attr:`contact_matrix`:
        ``q' = q'``, ``q'' = -omega^2 q - 2 D omega q' (- b Lambda / m in contact,
        Lambda = l . z of eq. (C5))``, ``s' = s'``, ``s'' = -gamma`` in flight and
        ``b . q''`` in contact, and 0 for the constant 1.
        """
        k = self.size
        q, v = z[:k], z[k : 2 * k]
        out = np.empty_like(z, dtype=float)
        out[:k] = v
        accel = -(self.omega**2) * q - (2.0 * self.damping * self.omega) * v
        if mode == "contact":
            accel = accel - (self.contact / self.masses) * float(self.force_row @ z)
            out[2 * k + 1] = float(self.contact @ accel)
        elif mode == "flight":
            out[2 * k + 1] = -self.gamma * z[-1]
        else:
            raise ValueError("mode must be flight or contact")
        out[k : 2 * k] = accel
        out[2 * k] = z[2 * k + 1]
        out[-1] = 0.0
        return out

    # --- observables ------------------------------------------------------------------
    def gap(self, z: np.ndarray) -> np.ndarray:
        """``g = s - b . q`` for states ``z`` (shape (..., 2K+3))."""
        k = self.size
        return z[..., 2 * k] - z[..., :k] @ self.contact

    def gap_rate(self, z: np.ndarray) -> np.ndarray:
        """``g' = s' - b . q'``."""
        k = self.size
        return z[..., 2 * k + 1] - z[..., k : 2 * k] @ self.contact

    def cap_motion(self, z: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Cap-averaged membrane displacement and velocity ``(b . q, b . q')``."""
        k = self.size
        return z[..., :k] @ self.contact, z[..., k : 2 * k] @ self.contact

    def energy(self, z: np.ndarray) -> np.ndarray:
        """Total energy (C4): membrane, body kinetic and potential (unit T R^2)."""
        k = self.size
        q, v = z[..., :k], z[..., k : 2 * k]
        membrane = 0.5 * ((v**2 + (self.omega * q) ** 2) * self.masses).sum(axis=-1)
        s, w = z[..., 2 * k], z[..., 2 * k + 1]
        return membrane + self.body_mass * (0.5 * w**2 + self.gamma * s)

    def dissipation_rate(self, z: np.ndarray) -> np.ndarray:
        """``dE/dt`` away from impacts: ``-sum 2 D omega_k m_k q_k'^2`` (<= 0)."""
        k = self.size
        v = z[..., k : 2 * k]
        return -(2.0 * self.damping * self.omega * self.masses * v**2).sum(axis=-1)

    def impact(self, z: np.ndarray, restitution: float) -> tuple[np.ndarray, float]:
        """State after a Newton impact and the impulse ``P`` (dimensionless).

        ``mu_t [s'] = P``, ``m_k [q_k'] = -b_k P`` and ``g'+ = -e g'-`` give
        ``P = -(1 + e) g'- m_eff``; the energy lost is ``(1 - e^2) m_eff g'-^2 / 2``.
        """
        k = self.size
        rate = float(self.gap_rate(z))
        impulse = -(1.0 + restitution) * rate * self.effective_mass
        out = z.copy()
        out[2 * k + 1] += impulse / self.body_mass
        out[k : 2 * k] -= self.contact / self.masses * impulse
        return out, impulse
