"""A damped modal series evaluated with, at each time, only the modes that still count.

With the paper's modal damping every mode of eq. (3.14) decays like
``exp(-D omega_n t)`` (under a Rayleigh law every mode is kept):
at a time t a mode whose whole contribution to u, u_t and u_tt at the pole,

    ``|sigma_n a_n| max(1, omega_n^2) exp(-D omega_n t) / sqrt(1 - D^2)``,

is below :data:`NEGLIGIBLE` (dimensionless, against u_tt ~ 1 and gamma ~ 1e-3)
changes nothing but the last bits.  Dropping such modes and sampling the rest at
their own highest frequency makes a series of thousands of modes as cheap as one
of a few hundred, except near t = 0: the time it costs to bracket the lift-off of
eq. (3.16) grows like N (dyadic blocks of time, ~16 * 40 / (2 pi D) samples each)
instead of N^2 (N^3 with bending, ``omega_n ~ sqrt(beta) n^2``).  Used by the
converged reference of the truncation guard (:mod:`twoball.modal.converged`).
Dimensionless (length R, time 1/c).
"""

from __future__ import annotations

import math

import numpy as np
from numpy.typing import ArrayLike

from twoball.modal.filters import SpectralFilter
from twoball.modal.series import ModalSeries, PoleState

__all__ = ["NEGLIGIBLE", "DecayingSeries", "mode_bounds", "significant"]

NEGLIGIBLE = 1e-15  # largest pole contribution of a dropped mode (dimensionless)
SAMPLES_PER_PERIOD = 16  # of the bracketing grid, as twoball.modal.liftoff.bracketing_grid


def mode_bounds(series: ModalSeries) -> tuple[np.ndarray, np.ndarray]:
    """Retained indices and the bound of each one's pole contribution at t = 0 (module doc)."""
    keep = np.flatnonzero(series.retained)
    if not isinstance(series.damping, float):  # a Rayleigh law: every mode is kept
        return keep, np.full(keep.size, np.inf)
    root = math.sqrt(1.0 - series.damping**2)
    amplitude = np.abs(series.pole_amplitudes[keep]) / root
    return keep, amplitude * np.maximum(1.0, series.omega[keep] ** 2)


def significant(series: ModalSeries, t: float) -> np.ndarray:
    """Indices of the modes whose pole contribution at times >= ``t`` exceeds NEGLIGIBLE."""
    keep, bound = mode_bounds(series)
    decay = np.exp(-_ratio(series) * series.omega[keep] * max(t, 0.0))
    return keep[bound * decay > NEGLIGIBLE]


def _ratio(series: ModalSeries) -> float:
    """The paper's ratio D of ``series`` (0 under a Rayleigh law, whose modes are all kept)."""
    return series.damping if isinstance(series.damping, float) else 0.0


def reduced(series: ModalSeries, modes: np.ndarray) -> ModalSeries:
    """The series restricted to ``modes`` (filter weights folded into the coefficients).

    It keeps the series' monitor (:attr:`~twoball.modal.series.ModalSeries.monitor`).
    """
    return ModalSeries(
        omega=series.omega[modes],
        coefficients=(series.weights * series.coefficients)[modes],
        pole_values=series.pole_values[modes],
        damping=series.damping,
        filter=SpectralFilter("none", 1),
        mode_norms=series.mode_norms[modes],
        filter_omega=np.zeros(modes.size),  # weight 1 for every mode kept
        monitor=series.monitor,
    )


class DecayingSeries:
    """A :class:`~twoball.modal.series.ModalSeries` as a pole motion on [0, t_end], blockwise.

    Time is cut into blocks ``[0, tau), [tau, 2 tau), [2 tau, 4 tau), ...`` with
    ``tau = 1 / omega_max``; on each block only the modes significant at its start
    are summed (:func:`significant`), and the bracketing grid has 16 samples per
    period of the highest of them (``grid_times``, used by
    :func:`twoball.modal.liftoff.find_liftoff`).  The values differ from the
    series' own by less than ``NEGLIGIBLE`` per dropped mode.  D = 0 drops nothing.

    Parameters
    ----------
    series : ModalSeries
        The damped (filtered or not) series, dimensionless.
    t_end : float
        End of the window (dimensionless).
    """

    def __init__(self, series: ModalSeries, t_end: float) -> None:
        self.series = series
        keep, bound = mode_bounds(series)
        omega = series.omega[keep]
        top = float(omega.max()) if omega.size else 0.0
        starts = [0.0]
        tau = 1.0 / max(top, 1.0)
        while tau < t_end:
            starts.append(tau)
            tau *= 2.0
        blocks: list[tuple[float, np.ndarray]] = []
        for start in starts:
            kept = keep[bound * np.exp(-_ratio(series) * omega * start) > NEGLIGIBLE]
            if blocks and blocks[-1][1].size == kept.size:
                continue  # the same modes as the block before: one block
            blocks.append((start, kept))
        self.starts = np.array([b[0] for b in blocks])
        self.parts = [reduced(series, kept) for _, kept in blocks]
        ends = [*self.starts[1:], t_end]
        grids = []
        for start, end, part in zip(self.starts, ends, self.parts, strict=True):
            omega_max = max(part.max_frequency, 1.0)
            count = math.ceil((end - start) * omega_max * SAMPLES_PER_PERIOD / (2 * math.pi))
            grids.append(np.linspace(start, end, max(count, 1) + 1)[:-1])
        grids.append(np.array([t_end]))
        self.grid_times = np.concatenate(grids)
        self.work = sum(
            g.size * p.omega.size for g, p in zip(grids, self.parts, strict=False)
        )  # terms summed on the grid: the cost measure of twoball.modal.cost

    @property
    def max_frequency(self) -> float:
        """Highest frequency of the series (sets the round-off skip after a lift-off)."""
        return self.series.max_frequency

    def pole(self, t: ArrayLike) -> PoleState:
        """u, u_t, u_tt at the pole at times ``t``, each block from its significant modes."""
        times = np.asarray(t, dtype=float)
        flat = times.reshape(-1)
        which = np.clip(np.searchsorted(self.starts, flat, side="right") - 1, 0, None)
        out = np.empty((3, flat.size))
        for block in np.unique(which):
            at = np.flatnonzero(which == block)
            state = self.parts[block].pole(flat[at])
            out[:, at] = np.stack(state)
        return PoleState(*(row.reshape(times.shape) for row in out))
