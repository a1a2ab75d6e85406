"""twoball.modal -- the continuum elastic model (CEM) in closed form, and the ICM.

Dimensionless inside (length R, time 1/c); SI at :mod:`twoball.modal.report`.
"""

from twoball._common.lazy import attach

__getattr__, __dir__ = attach(
    __name__,
    {
        "Candidate": ".liftoff",
        "Case": ".parameters",
        "LiftoffReport": ".report",
        "LiftoffResult": ".liftoff",
        "Membrane": ".membrane",
        "ModalSeries": ".series",
        "NumericalError": "twoball._common.errors",
        "PRESETS": ".parameters",
        "ParameterError": "twoball._common.errors",
        "Rayleigh": ".damping",
        "ModalRatio": ".damping",
        "PoleMotion": ".liftoff",
        "PoleState": ".series",
        "SampledPoleMotion": ".liftoff",
        "Scalings": ".scalings",
        "SpectralFilter": ".filters",
        "deformation_work": ".initial",
        "find_liftoff": ".liftoff",
        "initial_displacement": ".initial",
        "legendre_coefficients": ".legendre",
        "legendre_frequency": ".filters",
        "legendre_liftoff": ".report",
        "legendre_series": ".legendre",
        "mean_displacement": ".legendre",
        "phi_a_from_v0": ".initial",
        "preset": ".parameters",
        "report_liftoff": ".report",
        "v0_dimensionless": ".initial",
        "v0_from_phi_a": ".initial",
        "wave_speed_from_pressure": ".scalings",
    },
)

__all__ = sorted(__dir__())
