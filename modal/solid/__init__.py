"""twoball.modal.solid -- Lamb's homogeneous elastic sphere in closed form.

Spheroidal axisymmetric modes (Lamb 1882), their shapes and projections, and
Hertz's impact of a sphere on a rigid flat.  Dimensionless frequencies are
eta = omega R / c_s throughout; SI where a function says so.
"""

from twoball._common.lazy import attach

__getattr__, __dir__ = attach(
    __name__,
    {
        "HERTZ_TIME_COEFFICIENT": ".hertz",
        "SphereMode": ".modes",
        "boundary_matrix": ".lamb",
        "effective_modulus": ".hertz",
        "hertz_contact_time": ".hertz",
        "hertz_force": ".hertz",
        "hertz_max_compression": ".hertz",
        "hertz_peak_force": ".hertz",
        "lamb_function": ".lamb",
        "lamb_roots": ".lamb",
        "scaled_bessel_pair": ".lamb",
        "modal_coefficients": ".modes",
        "spheroidal_modes": ".modes",
        "speed_ratio": ".lamb",
        "translation_mode": ".modes",
    },
)

__all__ = sorted(__dir__())
