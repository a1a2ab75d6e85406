"""Closed-form references of the studies: one Legendre run, and its converged limit N -> infinity.

The converged limit is model knowledge and lives in :mod:`twoball.modal.converged`.
Dimensionless (length R, time 1/c); :func:`legendre_row`
gives a run in SI.
"""

from __future__ import annotations

import time
from dataclasses import dataclass
from typing import Any

import numpy as np

from twoball._common.watch import Watch
from twoball.modal.filters import FilterKind, SpectralFilter
from twoball.modal.legendre import legendre_series
from twoball.modal.liftoff import Horizon, find_liftoff
from twoball.modal.parameters import Case
from twoball.modal.series import ModalSeries
from twoball.verify.studies.result import si

__all__ = [
    "LegendreRun",
    "legendre_row",
    "legendre_run",
]


@dataclass(frozen=True)
class LegendreRun:
    """One closed-form run (dimensionless results, SI through ``case``)."""

    modes: int
    sigma: str
    t: float | None
    velocity: float | None
    energy_end: float
    seconds: float
    series: ModalSeries


def legendre_run(
    case: Case, modes: int, sigma: FilterKind, recontact: Horizon, t_end: float
) -> LegendreRun:
    """Lift-off and end energy of the filtered Legendre series with ``modes`` modes."""
    start = time.perf_counter()
    series = legendre_series(
        case.phi_a, case.damping, SpectralFilter(sigma, modes), monitor=Watch()
    )
    result = find_liftoff(series, case.gamma, t_end=t_end, horizon=recontact)
    energy = float(series.energy(np.array([t_end]))[0])
    return LegendreRun(
        modes, sigma, result.t, result.velocity, energy, time.perf_counter() - start, series
    )


def legendre_row(case: Case, run: LegendreRun) -> dict[str, Any]:
    """One run-table row of a Legendre run (SI)."""
    scale = case.scalings
    return {
        "label": f"N = {run.modes}",
        "backend": "legendre",
        "dofs": run.modes + 1,
        "t_liftoff_s": si(run.t, scale.time),
        "v_liftoff_m_s": si(run.velocity, scale.velocity),
        "energy_end": run.energy_end,
        "seconds": run.seconds,
    }
