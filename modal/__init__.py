"""twoball.modal -- the continuum elastic model (CEM) in closed form, and the ICM.

Dimensionless inside (length R, time 1/c); SI at :mod:`modal.report`.
"""

from .errors import NumericalError, ParameterError
from .filters import SpectralFilter, legendre_frequency
from .initial import (
    deformation_work,
    initial_displacement,
    phi_a_from_v0,
    v0_dimensionless,
    v0_from_phi_a,
)
from .legendre import legendre_coefficients, legendre_series, mean_displacement
from .liftoff import Candidate, LiftoffResult, PoleMotion, SampledPoleMotion, find_liftoff
from .parameters import PRESETS, Case, Scalings, preset, wave_speed_from_pressure
from .report import LiftoffReport, legendre_liftoff, report_liftoff
from .series import ModalSeries, PoleState

__all__ = [
    "Candidate",
    "Case",
    "LiftoffReport",
    "LiftoffResult",
    "ModalSeries",
    "NumericalError",
    "PRESETS",
    "ParameterError",
    "PoleMotion",
    "PoleState",
    "SampledPoleMotion",
    "Scalings",
    "SpectralFilter",
    "deformation_work",
    "find_liftoff",
    "initial_displacement",
    "legendre_coefficients",
    "legendre_frequency",
    "legendre_liftoff",
    "legendre_series",
    "mean_displacement",
    "phi_a_from_v0",
    "preset",
    "report_liftoff",
    "v0_dimensionless",
    "v0_from_phi_a",
    "wave_speed_from_pressure",
]
