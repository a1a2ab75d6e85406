"""Weak forms of linear elastodynamics: axisymmetric (r, z) and 3-D.

Written like :mod:`skfem.models.elasticity` (``linear_elasticity``: the
stress C(eps) = 2 mu eps + lambda tr(eps) I contracted with the test strain).

Axisymmetric, torsion-free fields u = u_r(r, z) e_r + u_z(r, z) e_z have the strains
of the cylindrical coordinates (as in the axisymmetric stress analysis of
Zienkiewicz & Taylor, *The Finite Element Method*, vol. 1)

    eps_rr = du_r/dr, eps_zz = du_z/dz, eps_rz = (du_r/dz + du_z/dr)/2,
    eps_tt = u_r / r  (the hoop strain),                                  (A1)

and the energy and mass over the whole ball (the azimuth integrated, 2 pi r)

    a(u, v) = int [2 mu (eps(u) : eps(v) + u_r v_r / r^2)
                   + lambda (div u + u_r/r)(div v + v_r/r)] 2 pi r dr dz,   (A2)
    m(u, v) = int rho (u_r v_r + u_z v_z) 2 pi r dr dz,                     (A3)

with eps the in-plane (r, z) strain and div u = eps_rr + eps_zz.  Regularity on
the axis requires u_r = 0 at r = 0; the solvers impose it.  The forms are the
3-D energy and mass of the field swept around the axis, so eigenvalues are those
of the 3-D ball restricted to m = 0 spheroidal fields (torsion u_theta is not a
variable: the torsional family is excluded by construction).
"""

from __future__ import annotations

import math

from skfem import BilinearForm
from skfem.helpers import ddot, dot, sym_grad, trace
from skfem.models.elasticity import linear_elasticity

__all__ = ["axisymmetric_elasticity", "axisymmetric_mass", "elasticity", "lame", "mass"]


def lame(poisson: float, shear_modulus: float = 1.0) -> tuple[float, float]:
    """(lambda, mu) [Pa, or units of mu] from nu and mu: lambda = 2 mu nu / (1 - 2 nu)."""
    return 2.0 * shear_modulus * poisson / (1.0 - 2.0 * poisson), shear_modulus


def axisymmetric_elasticity(lam: float = 1.0, mu: float = 1.0) -> BilinearForm:
    """Eq. (A2): the axisymmetric strain energy form (lambda, mu in consistent units)."""

    @BilinearForm
    def weakform(u, v, w):
        r = w.x[0]
        hoop_u, hoop_v = u[0] / r, v[0] / r
        eps_u, eps_v = sym_grad(u), sym_grad(v)
        volumetric = (trace(eps_u) + hoop_u) * (trace(eps_v) + hoop_v)
        return (2.0 * mu * (ddot(eps_u, eps_v) + hoop_u * hoop_v) + lam * volumetric) * (
            2.0 * math.pi * r
        )

    return weakform


def axisymmetric_mass(density: float = 1.0) -> BilinearForm:
    """Eq. (A3): the axisymmetric mass form, rho u.v 2 pi r."""

    @BilinearForm
    def weakform(u, v, w):
        return density * dot(u, v) * 2.0 * math.pi * w.x[0]

    return weakform


def elasticity(lam: float = 1.0, mu: float = 1.0) -> BilinearForm:
    """3-D strain energy form: scikit-fem's ``linear_elasticity`` (C(eps(u)) : eps(v))."""
    return linear_elasticity(lam, mu)


def mass(density: float = 1.0) -> BilinearForm:
    """3-D mass form rho u.v."""

    @BilinearForm
    def weakform(u, v, w):
        return density * dot(u, v)

    return weakform
