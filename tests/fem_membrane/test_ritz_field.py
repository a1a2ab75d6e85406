"""Fields from the Krylov Ritz basis (fem_membrane/ritz_field.py) against the full eigen route."""

from __future__ import annotations

import numpy as np
import pytest

from twoball.fem_membrane.build import build_space
from twoball.fem_membrane.eigen import eigenpairs
from twoball.fem_membrane.initial import initial_moments
from twoball.fem_membrane.krylov import krylov_modal_series
from twoball.fem_membrane.modal import modal_series
from twoball.fem_membrane.ritz_field import field_times
from twoball.modal.filters import SpectralFilter

PHI_A = 2.6
DAMPING = 0.13


FILTER = SpectralFilter("lanczos", 30)


def _m_norm(M, fields: np.ndarray) -> np.ndarray:
    """M-norm of each row (one field per row)."""
    return np.sqrt(np.einsum("ti,ti->t", fields @ M, fields))


@pytest.mark.slow
def test_ritz_fields_agree_with_full_route_at_level_3():
    """u, u_t, u_tt on every node: Ritz basis vs all eigenpairs, 1e-8 in the M-norm."""
    space = build_space("sphere", level=3, order=2, phi_a=PHI_A)  # 2562 unknowns
    moments = initial_moments(space, PHI_A)
    pairs = eigenpairs(space.stiffness, space.mass, FILTER.omega_cut**2)
    full = modal_series(pairs, moments, space.pole_row, DAMPING, FILTER)
    t_end = 4 * np.pi
    fast, info = krylov_modal_series(
        space,
        moments,
        DAMPING,
        FILTER,
        t_end=t_end,
        vectors=True,
        field_times=field_times(t_end, FILTER.omega_cut),
    )
    assert info.pairs is not None and info.converged
    assert len(info.pairs) < len(pairs)  # fewer modes than the full route (817)
    times = np.linspace(0.0, t_end, 37)  # not the criterion's sample instants
    M = space.mass
    for derivative in range(3):
        reference = full.field(times, pairs.vectors.T, derivative)
        ritz = fast.field(times, info.pairs.vectors.T, derivative)
        error = _m_norm(M, ritz - reference).max() / _m_norm(M, reference).max()
        assert error < 1e-8, (derivative, error)
    # the pole-only rule stops earlier: the field rule is what makes the fields converge
    _, pole_only = krylov_modal_series(space, moments, DAMPING, FILTER, t_end=t_end)
    assert pole_only.basis_size < info.basis_size
