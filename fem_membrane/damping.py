"""Damping operators for direct time stepping of ``M u'' + C u' + K u = 0``.

``modal``
    Ratio D on each computed mode, eq. (3.14): ``C = M Phi diag(2 D omega)
    Phi^T M``.  Kept as the low-rank factors ``U = M Phi`` and ``c = 2 D omega``
    -- never a dense n x n matrix.  On the computed modes it reproduces the
    damped oscillators of the modal series exactly; modes beyond the cutoff are
    undamped (they are not excited by the filtered initial data).
``rayleigh``
    ``C = alpha M + beta K``, sparse, fitted to ratio D at two frequencies.  A
    mode of frequency omega then has the effective ratio
    ``zeta(omega) = alpha / (2 omega) + beta omega / 2``: exact at the two
    fitting frequencies, smaller between them, larger outside.

Dimensionless.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
import scipy.sparse as sp
from twoball.fem_membrane.eigen import Eigenpairs
from twoball.modal.series import check_damping

from twoball._common.errors import ParameterError

RAYLEIGH_LOW = math.sqrt(2.0)  # default lower fitting frequency: omega_1 of the sphere
ZERO_FREQUENCY = 1e-3  # below this a computed frequency is the constant mode (omega = 0)


@dataclass(frozen=True)
class ModalDamping:
    """Low-rank modal damping ``C = U diag(c) U^T`` with ``U = M Phi``, ``c = 2 D omega``."""

    basis: np.ndarray
    rates: np.ndarray
    ratio: float

    @classmethod
    def from_modes(cls, mass: sp.spmatrix, pairs: Eigenpairs, ratio: float) -> ModalDamping:
        """Ratio D on every mode in ``pairs`` (those with omega = 0 are not damped)."""
        ratio = check_damping(ratio)
        return cls(np.asarray(mass @ pairs.vectors), 2.0 * ratio * pairs.omega, ratio)

    def __matmul__(self, v: np.ndarray) -> np.ndarray:
        """``C v`` in O(n r) operations."""
        return self.basis @ (self.rates * (self.basis.T @ v))


@dataclass(frozen=True)
class RayleighDamping:
    """``C = alpha M + beta K`` fitted to ratio D at ``omega_low`` and ``omega_high``."""

    alpha: float
    beta: float
    omega_low: float
    omega_high: float
    ratio: float

    @classmethod
    def fit(
        cls, ratio: float, omega_low: float = RAYLEIGH_LOW, omega_high: float = 1.0
    ) -> RayleighDamping:
        """Solve ``zeta(omega_low) = zeta(omega_high) = D`` for alpha and beta.

        ``alpha = 2 D w1 w2 / (w1 + w2)``, ``beta = 2 D / (w1 + w2)``.
        """
        ratio = check_damping(ratio)
        low, high = float(omega_low), float(omega_high)
        if not (math.isfinite(low) and math.isfinite(high) and 0.0 < low < high):
            raise ParameterError(
                "rayleigh_frequencies", "two finite frequencies 0 < w1 < w2", (low, high)
            )
        alpha = 2.0 * ratio * low * high / (low + high)
        beta = 2.0 * ratio / (low + high)
        return cls(alpha, beta, low, high, ratio)

    def matrix(self, mass: sp.spmatrix, stiffness: sp.spmatrix) -> sp.csr_matrix:
        """The sparse damping matrix ``alpha M + beta K``."""
        return (self.alpha * mass + self.beta * stiffness).tocsr()

    def effective_ratio(self, omega: np.ndarray) -> np.ndarray:
        """``zeta(omega) = alpha / (2 omega) + beta omega / 2`` (inf at omega = 0)."""
        omega = np.asarray(omega, dtype=float)
        with np.errstate(divide="ignore"):
            return self.alpha / (2.0 * omega) + 0.5 * self.beta * omega

    def table(self, omega: np.ndarray) -> list[dict[str, float]]:
        """One row per mode except the constant one: index, omega, ratio zeta, zeta / D."""
        omega = np.asarray(omega, dtype=float)
        rows = []
        for k in np.flatnonzero(omega > ZERO_FREQUENCY):
            zeta = float(self.effective_ratio(omega[k]))
            relative = zeta / self.ratio if self.ratio > 0 else math.inf
            rows.append({"mode": int(k), "omega": float(omega[k]), "zeta": zeta, "ratio": relative})
        return rows
