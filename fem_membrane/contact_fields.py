"""Finite-element modes at the mesh nodes with the contact solution on them (issue 13).

Exports and pictures of the membrane under a body of finite mass need the mode
shapes at the nodes *and* the contact solver's modal state on the same modes.
This builds both from one eigen solve (the full route: every eigenpair below the
filter cutoff, as :func:`twoball.fem_membrane.contact.fem_contact_model`), so the
drawn field ``u = sum_k q_k phi_k`` is exactly the one the contact solver moved
(eq. (C1) of docs/contact.rst).  Dimensionless inside; the report is SI.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from .build import DEFAULT_LEVEL
from .contact import cap_functional, model_facts
from .mesh import SphereMesh, icosphere, ring_sphere


def fem_contact_fields(
    case: Any,
    mass_ratio: float,
    contact_radius: float | None,
    *,
    sigma: str,
    restitution: float,
    energy: str,
    t_end_s: float | None,
    mesh: str = "sphere",
    level: int | None = None,
    order: int = 2,
    initial: str = "projection",
) -> tuple[SphereMesh, np.ndarray, Any, Any]:
    """The node mesh, the mode shapes at its nodes and the contact report (SI).

    Parameters
    ----------
    case : Case
        The impact (SI).
    mass_ratio, contact_radius, restitution, energy
        As in :func:`twoball.liftoff` (``contact_radius`` in m, default R/10).
    sigma : str
        Spectral filter of eq. (3.16).
    t_end_s : float or None
        Modelled window [s] (default 4 pi / c).
    mesh : {"sphere", "ring"}
        Icosphere, or ring sphere with a ring at the membrane's phi_a.
    level, order : int
        Mesh level (default 3) and element order.
    initial : {"projection", "interpolation"}
        FE representation of eq. (3.10).

    Returns
    -------
    nodes : SphereMesh
        Unit sphere whose nodes are the degrees of freedom (as
        :func:`twoball.verify.output.fields.fem_nodal_series`).
    shapes : ndarray, shape (K, P)
        M-orthonormal eigenvectors at the nodes, one row per mode of the report's system.
    series : ModalSeries
        The free membrane's filtered modal series on these modes (eq. (3.16)).
    report : ContactReport
        The contact solution on these modes (``report.system``, ``report.history``).
    """
    from twoball.modal.contact.caps import cap_angle
    from twoball.modal.contact.report import check_contact_options, membrane_case, solve_contact
    from twoball.modal.filters import SpectralFilter
    from twoball.modal.report import t_end_dimensionless

    from twoball.budget import check_fem

    from .solve import modal_model

    radius = check_contact_options(case, mass_ratio, contact_radius, restitution, energy)
    lvl = DEFAULT_LEVEL if level is None else level
    check_fem(mesh, lvl, None, order, case.modes, "full")  # before any allocation
    membrane = membrane_case(case, float(mass_ratio), energy)
    theta = cap_angle(radius, case.radius)
    if mesh == "ring":
        geometry = ring_sphere(lvl, membrane.phi_a, order)
    else:
        geometry = icosphere(lvl, order)
    model = modal_model(
        membrane.phi_a,
        case.damping,
        SpectralFilter(sigma, case.modes),
        mesh=geometry,
        order=None,
        initial=initial,
        route="full",
    )
    f = cap_functional(model.space, theta, geometry)
    vectors = model.pairs.vectors
    basis = model.space.basis
    kind = "icosphere" if mesh == "sphere" else "ring sphere"
    nodes = SphereMesh(
        basis.doflocs.T,
        basis.element_dofs.T,
        f"{kind} level {lvl}, P{order}",
        membrane.phi_a if mesh == "ring" else None,
    )
    info = {**model_facts(model, mesh, f), "cap_angle_rad": theta}
    report = solve_contact(
        case, model.series, vectors.T @ f,
        mass_ratio=float(mass_ratio), contact_radius_m=radius, restitution=float(restitution),
        energy=energy, backend="fem", sigma=sigma, t_end=t_end_dimensionless(case, t_end_s),
        membrane=membrane, extra=info,
    )  # fmt: skip
    return nodes, vectors.T, model.series, report
