"""Finite-element modal models of the paper's case, cached across the tests of a session."""

from __future__ import annotations

import twoball.fem_membrane.slicing as slicing
from twoball.fem_membrane.solve import modal_model
from twoball.modal.filters import SpectralFilter

PHI_A, DAMPING = 2.6, 0.13
FILTER = SpectralFilter("lanczos", 30)
_MODELS: dict = {}


def model(mesh: str, order: int, size: int):
    """Modal model, cached for the session (sphere levels are expensive)."""
    key = (mesh, order, size)
    if key not in _MODELS:
        where = {"elements": size} if mesh == "axisym" else {"level": size}
        _MODELS[key] = modal_model(PHI_A, DAMPING, FILTER, mesh=mesh, order=order, **where)
    return _MODELS[key]


def force_slicing(monkeypatch) -> None:
    """Make the full eigen route take spectrum slicing at every size (never dense LAPACK)."""
    monkeypatch.setattr(slicing, "DENSE_ALWAYS", 0)
    monkeypatch.setattr(slicing, "DENSE_COUNT", 10**9)
