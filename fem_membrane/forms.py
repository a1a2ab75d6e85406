"""Weak forms of the membrane equation (3.9), as scikit-fem bilinear forms.

Dimensionless.  On the sphere ``grad`` is the surface gradient (see
:mod:`twoball.fem_membrane.mapping`), so the stiffness form is the weak Laplace-Beltrami
operator.  On the axisymmetric line ``x = cos(phi)`` the surface measure is
``dS = dx dtheta`` and ``|grad_s u|^2 = (1 - x^2) u'^2``; the forms there carry
the full azimuthal factor 2 pi, so that both backends use the measure of the
whole unit sphere (mass of the constant 4 pi, same energies).

The pressurised membrane (:mod:`twoball.modal.membrane`) adds
``-2 int u v dS`` to the stiffness form, the second variation of ``T dA - P dV``
beyond the Laplacian's: a mass-like form, assembled as ``-2 M`` from :func:`mass`
(or :func:`axisym_mass`) -- no form of its own
(:meth:`twoball.fem_membrane.space.Discretisation.operator`).
"""

from __future__ import annotations

import numpy as np
from skfem import BilinearForm
from skfem.helpers import dot, grad

AZIMUTH = 2.0 * np.pi  # integral over the azimuth of an axisymmetric integrand


@BilinearForm
def stiffness(u, v, w):
    """``int grad_s u . grad_s v dS`` (weak Laplace-Beltrami, eq. (3.9))."""
    return dot(grad(u), grad(v))


@BilinearForm
def mass(u, v, w):
    """``int u v dS``."""
    return u * v


@BilinearForm
def axisym_stiffness(u, v, w):
    """``2 pi int (1 - x^2) u' v' dx`` on x = cos(phi) in [-1, 1], eq. (3.9)."""
    x = w.x[0]
    return AZIMUTH * (1.0 - x**2) * u.grad[0] * v.grad[0]


@BilinearForm
def axisym_mass(u, v, w):
    """``2 pi int u v dx`` on x = cos(phi) in [-1, 1]."""
    return AZIMUTH * u * v
