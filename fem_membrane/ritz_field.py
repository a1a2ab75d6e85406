"""Stopping rule on the whole filtered field for the rational Krylov route.

The Krylov route (:mod:`twoball.fem_membrane.krylov`) stops when the pole
trajectory has settled.  Files, pictures and plots need the field on every node,

    u(x, t) = sum_k sigma(omega_k) q_k(t) y_k(x),   y_k = V s_k  (Ritz vectors),

and likewise u_t, u_tt (eqs. (3.14)-(3.16) on Ritz pairs).  On the M-orthonormal
Krylov basis V (``V^T M V = I``) the field at time t is ``V c(t)`` with
``c(t) = S_below diag(sigma q(t))``-weighted coordinates, and its M-norm is the
Euclidean norm of ``c(t)``; since the bases are nested, the field of an earlier
step is the same ``c`` padded with zeros.  So the M-norm change of the field
over one cycle of shifts costs O(T x basis) per step, no work of size n.

Stopping rule (``tol``, default 1e-10 as for the pole): for each of u, u_t,
u_tt, ``max_t ||c_now(t) - c_before(t)|| / max_t ||c_now(t)||`` at the sample
instants (4 per period of omega_cut over [0, t_end]) is at most ``tol``, on two
consecutive steps, where "before" is one full cycle of shifts earlier.  Like the
pole's rule it is a difference of iterates, not a bound; the agreement with the
full eigen route is tested (1e-8 relative in the M-norm at sphere P2 level 3).

Dimensionless.
"""

from __future__ import annotations

import math

import numpy as np

from twoball.modal.series import ModalSeries

SAMPLES_PER_PERIOD = 4  # field samples per period of omega_cut


def field_times(t_end: float, omega_cut: float) -> np.ndarray:
    """Sample instants on [0, t_end] for the field criterion (dimensionless)."""
    count = math.ceil(t_end * omega_cut * SAMPLES_PER_PERIOD / (2 * math.pi)) + 1
    return np.linspace(0.0, t_end, max(count, 2))


class FieldChange:
    """Relative M-norm change of the filtered u, u_t, u_tt over ``lag`` Ritz steps.

    Parameters
    ----------
    times : ndarray
        Sample instants (dimensionless).
    lag : int
        Steps in one cycle of shifts.
    """

    def __init__(self, times: np.ndarray, lag: int) -> None:
        self.times = np.asarray(times, dtype=float)
        self.lag = int(lag)
        self._history: list[list[np.ndarray]] = []

    def coordinates(self, series: ModalSeries, small: np.ndarray) -> list[np.ndarray]:
        """Basis coordinates of u, u_t, u_tt at the sample instants, each (T, basis)."""
        return [series.modal_coordinates(self.times, d) @ small.T for d in range(3)]

    def update(self, series: ModalSeries, small: np.ndarray) -> float:
        """Record this step's field; its change against ``lag`` steps earlier (inf if none).

        ``small`` holds the Ritz coordinates of the series' modes as columns
        (basis x modes), in the series' order.
        """
        current = self.coordinates(series, small)
        self._history.append(current)
        if len(self._history) <= self.lag:
            return math.inf
        previous = self._history.pop(0)
        change = 0.0
        for now, before in zip(current, previous, strict=True):
            padded = np.zeros_like(now)
            padded[:, : before.shape[1]] = before
            scale = max(float(np.linalg.norm(now, axis=1).max()), np.finfo(float).tiny)
            change = max(change, float(np.linalg.norm(now - padded, axis=1).max()) / scale)
        return change
