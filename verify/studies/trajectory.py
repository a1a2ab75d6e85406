"""Pole trajectories compared as a whole: the L2-in-time norm and a Hermite resampling.

Dimensionless (time unit 1/c).
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np
from numpy.polynomial.legendre import leggauss

from twoball.modal.liftoff import PoleMotion, SampledPoleMotion


class TrajectoryNorm:
    """L2(0, t_end) norms of the pole displacement against one reference motion.

    Composite 8-point Gauss-Legendre quadrature on uniform panels; the
    reference is sampled once.  ``frequency`` sets the panel count (the fastest
    mode that matters; default the reference's).  Dimensionless.
    """

    def __init__(self, reference: PoleMotion, t_end: float, frequency: float | None = None) -> None:
        fastest = max(float(reference.max_frequency if frequency is None else frequency), 1.0)
        panels = min(20000, 64 + math.ceil(t_end * fastest / math.pi))
        nodes, weights = leggauss(8)
        edges = np.linspace(0.0, t_end, panels + 1)
        half = 0.5 * np.diff(edges)
        self.times = (edges[:-1, None] + half[:, None] * (nodes[None, :] + 1.0)).ravel()
        self.weights = (half[:, None] * weights[None, :]).ravel()
        self.reference = reference.pole(self.times).u
        self.norm = float(np.sqrt(np.sum(self.weights * self.reference**2)))

    def error(self, motion: PoleMotion) -> float:
        """``||u - u_ref||`` in L2(0, t_end)."""
        u = motion.pole(self.times).u
        return float(np.sqrt(np.sum(self.weights * (u - self.reference) ** 2)))

    def relative_error(self, motion: PoleMotion) -> float:
        """``||u - u_ref|| / ||u_ref||``."""
        return self.error(motion) / self.norm


def hermite_resample(motion: Any) -> SampledPoleMotion:
    """The samples of a sampled motion re-interpolated by one quintic Hermite spline.

    For comparison only: direct time stepping gives u, u_t and u_tt that are each
    O(dt^2) but not derivatives of one another, so this interpolant's u_tt is
    O(dt) between the steps (the finite-element backend uses per-field splines).
    """
    t = np.asarray(motion.times)
    state = motion.pole(t)
    return SampledPoleMotion(t, state.u, state.u_t, state.u_tt, interpolation="hermite")
