"""Finite-element backend of the spherical-membrane model (scikit-fem), §3 of the paper.

The damped membrane equation (3.9) on the unit sphere, discretised with P1 or
isoparametric P2 triangles on the sphere itself (a surface mapping makes
scikit-fem's ``grad`` the surface gradient) or on the axisymmetric line
x = cos(phi).  The initial displacement (3.10) is Galerkin-projected, all
eigenpairs below the spectral filter's cutoff are computed, and the pole motion
is obtained either by modal superposition (a :class:`twoball.modal.series.ModalSeries`)
or by generalized-alpha time stepping (a :class:`twoball.modal.liftoff.SampledPoleMotion`).
Lift-off, filters and scalings live in :mod:`modal`; everything here is
dimensionless.

Entry points for the command line:

* :func:`fem_pole_motion` -- pole motion and a dict of run information;
* :func:`eigen_table` -- lowest eigenvalues beside ``l (l + 1)``.
"""

from twoball._common.lazy import attach

__getattr__, __dir__ = attach(
    __name__,
    {
        "eigen_table": ".eigen",
        "fem_pole_motion": ".solve",
    },
)

__all__ = sorted(__dir__())
