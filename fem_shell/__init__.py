"""twoball.fem_shell -- the thin spherical shell ball in finite elements on the meridian.

Cubic Hermite w and Lagrange v on a 1-D mesh of the polar angle (scikit-fem),
the pole conditions of axisymmetry, the energy of :mod:`twoball.modal.shell`
(membrane, bending, inflation prestress, gas), dense eigenpairs with the rigid
translation held exactly, and the closed form's rows: vertical displacement at
any angle or at the nodes, cap averages, the centre of mass, the impulse
response.  Dimensionless (length R, Omega = omega R sqrt(rho_s / C)).
"""

from twoball._common.lazy import attach

__getattr__, __dir__ = attach(
    __name__,
    {
        "FEShellBall": ".ball",
        "ShellSpace": ".space",
        "shell_space": ".space",
        "ShellFEModes": ".modes",
        "fem_impulse": ".modes",
        "fem_shell_modes": ".modes",
    },
)

__all__ = sorted(__dir__())
