"""Nodal values of a solved ball computed without :mod:`twoball.verify.output.fields`."""

from __future__ import annotations

import numpy as np

from twoball.modal.filters import SpectralFilter
from twoball.modal.legendre import displacement, legendre_series


def closed_form(sphere, t_s):
    """u [m] of eq. (3.16) at the node angles, evaluated without twoball.verify.output.fields."""
    case = sphere.case
    scale = case.scalings
    legendre = legendre_series(case.phi_a, case.damping, SpectralFilter("lanczos", case.modes))
    z = sphere.mesh.points[:, 2] / np.linalg.norm(sphere.mesh.points, axis=1)
    return displacement(legendre, np.atleast_1d(t_s) / scale.time, np.arccos(z)) * scale.length


def fem_values(sphere, t_s, derivative=0):
    """FE field [SI] at the nodes: filtered modal coordinates times the node shapes."""
    fem = sphere.backends["fem"]
    scale = sphere.case.scalings
    unit = (scale.length, scale.velocity, scale.acceleration)[derivative]
    q = fem.series.modal_coordinates(np.atleast_1d(t_s) / scale.time, derivative)  # (T, K)
    return q @ fem.shapes * unit
