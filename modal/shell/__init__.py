"""twoball.modal.shell -- the thin spherical shell ball in closed form.

Radial and meridional displacement on Love-Kirchhoff kinematics, inflation
prestress and enclosed gas: per Legendre degree a 2 x 2 eigenproblem with two
branches (:mod:`.spectrum`, the derivation), the mass-normalised modes and their
vertical rows, cap averages and centre of mass (:mod:`.modes`), SI conversions
(:mod:`.parameters`) and the response to a smoothed impulse at the south pole
(:mod:`.impulse`).  Dimensionless inside: length R, time ``R / c_e`` with
``c_e = sqrt(C / rho_s)``.
"""

from twoball._common.lazy import attach

__getattr__, __dir__ = attach(
    __name__,
    {
        "ShellParameters": ".parameters",
        "ShellSI": ".parameters",
        "shell_from_si": ".parameters",
        "branches": ".spectrum",
        "degree_matrices": ".spectrum",
        "frequency_coefficients": ".spectrum",
        "frequency_residual": ".spectrum",
        "mode_vectors": ".spectrum",
        "ShellModes": ".modes",
        "legendre_table": ".modes",
        "shell_modes": ".modes",
        "ImpulseResponse": ".impulse",
        "causality_study": ".impulse",
        "closed_form_impulse": ".impulse",
        "superluminal_degree": ".impulse",
        "gaussian_cap_average": ".impulse",
        "modal_impulse_response": ".impulse",
    },
)

__all__ = sorted(__dir__())
