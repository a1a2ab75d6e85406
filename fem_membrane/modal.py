"""Modal superposition on finite-element eigenpairs, eqs. (3.14)-(3.16).

With M-orthonormal eigenvectors Phi (``Phi^T M Phi = I``) the initial modal
displacements are ``q_k(0) = phi_k^T M u0`` -- for the Galerkin projection of F
this is ``int F phi_k dS``, the discrete form of eq. (3.12) -- and each mode
evolves as the damped oscillator of eq. (3.14) with its own frequency
``omega_k = sqrt(lambda_k)``.  The result is the shared
:class:`twoball.modal.series.ModalSeries`, so filter, pole motion and lift-off are
evaluated by exactly the same code as for the Legendre series.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from twoball._common.monitor import Monitor
from twoball.fem_membrane.eigen import Eigenpairs
from twoball.fem_membrane.space import PoleFunctional, pole_value
from twoball.modal.filters import SpectralFilter
from twoball.modal.series import ModalSeries


def modal_series(
    pairs: Eigenpairs,
    moments: np.ndarray,
    pole: PoleFunctional,
    damping: Any,
    filter: SpectralFilter,
    monitor: Monitor | None = None,
) -> ModalSeries:
    """The finite-element modal series of eq. (3.16) (dimensionless).

    Parameters
    ----------
    pairs : Eigenpairs
        M-orthonormal eigenpairs (all of them below the filter's cutoff).
    moments : ndarray, shape (dofs,)
        ``M u0``; for the Galerkin projection the load ``b_i = int F phi_i dS``.
    pole : int or sparse row
        Degree of freedom at the north pole, or the pole functional
        (:attr:`twoball.fem_membrane.space.Discretisation.pole_row`).
    damping : float, ModalRatio or Rayleigh
        Modal damping ratio D in [0, 1), or a damping law in units of c: mode k
        is damped by ``zeta(omega_k)`` (C = alpha M + beta K is diagonal on the
        M-orthonormal eigenvectors, so this is exact for Rayleigh damping).
    filter : SpectralFilter
        Weights by frequency; the same object as for the Legendre series.
    monitor : Monitor, optional
        Told as the series is evaluated (:attr:`ModalSeries.monitor`).

    Returns
    -------
    ModalSeries
        ``omega = sqrt(lambda)``, ``coefficients = Phi^T M u0``,
        ``pole_values = Phi[pole]`` (the modes at the pole), ``mode_norms = 1``.
    """
    vectors = pairs.vectors
    return ModalSeries(
        omega=pairs.omega,
        coefficients=vectors.T @ moments,
        pole_values=np.array(pole_value(pole, vectors)),
        damping=damping,
        filter=filter,
        mode_norms=np.ones(len(pairs)),
        monitor=monitor,
    )


def filtered_displacement(series: ModalSeries, pairs: Eigenpairs) -> np.ndarray:
    """The filtered initial displacement ``Phi diag(sigma) Phi^T M u0`` (dimensionless).

    The starting value of direct time stepping that matches the filtered modal
    series as dt -> 0.
    """
    return pairs.vectors @ (series.weights * series.coefficients)
