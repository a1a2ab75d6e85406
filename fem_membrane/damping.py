"""Damping operators for direct time stepping of ``M u'' + C u' + K u = 0``.

``modal``
    Ratio D on each computed mode, eq. (3.14): ``C = M Phi diag(2 D omega)
    Phi^T M``.  Kept as the low-rank factors ``U = M Phi`` and ``c = 2 D omega``
    -- never a dense n x n matrix.  On the computed modes it reproduces the
    damped oscillators of the modal series exactly; modes beyond the cutoff are
    undamped (they are not excited by the filtered initial data).
``rayleigh``
    ``C = alpha M + beta K``, sparse, of a :class:`~twoball.modal.damping.Rayleigh`
    law (given, or fitted to ratio D at two frequencies).  A mode of frequency
    omega then has the effective ratio ``zeta(omega) = alpha / (2 omega) +
    beta omega / 2``: with a fit, exact at the two fitting frequencies, smaller
    between them, larger outside.

Dimensionless.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
import scipy.sparse as sp

from twoball.fem_membrane.eigen import Eigenpairs
from twoball.modal.damping import Rayleigh
from twoball.modal.series import check_damping

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


def rayleigh_matrix(law: Rayleigh, mass: sp.spmatrix, stiffness: sp.spmatrix) -> sp.csr_matrix:
    """The sparse damping matrix ``alpha M + beta K`` of a Rayleigh law."""
    return (law.alpha * mass + law.beta * stiffness).tocsr()


def rayleigh_table(
    law: Rayleigh, omega: np.ndarray, ratio: float | None
) -> list[dict[str, float | None]]:
    """One row per mode except the constant one: index, omega, ratio zeta, zeta / D.

    ``ratio`` None (a law given without D): the last column is None.
    """
    omega = np.asarray(omega, dtype=float)
    rows = []
    for k in np.flatnonzero(omega > ZERO_FREQUENCY):
        zeta = float(law.ratios(omega[k]))
        if ratio is None:
            relative = None
        else:
            relative = zeta / ratio if ratio > 0 else math.inf
        rows.append({"mode": int(k), "omega": float(omega[k]), "zeta": zeta, "ratio": relative})
    return rows
