"""Finite-element modes at the mesh nodes with the contact solution on them (issue 13).

Exports and pictures of the membrane under a body of finite mass need the mode
shapes at the nodes *and* the contact solver's modal state on the same modes.
This takes both from the one eigen solve of the contact solution (the full route:
every eigenpair below the filter cutoff,
:func:`twoball.fem_membrane.contact.fem_contact_solution`), so the
drawn field ``u = sum_k q_k phi_k`` is exactly the one the contact solver moved
(eq. (C1) of docs/contact.rst).  Dimensionless inside; the report is SI.
"""

from __future__ import annotations

from typing import Any

import numpy as np
from twoball.fem_membrane.build import DEFAULT_LEVEL
from twoball.fem_membrane.mesh import SphereMesh


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
    from twoball.fem_membrane.contact import fem_contact_solution
    from twoball.fem_membrane.space import dof_mesh

    model, report = fem_contact_solution(
        case, mass_ratio, contact_radius, sigma=sigma, restitution=restitution, energy=energy,
        t_end_s=t_end_s, mesh=mesh, level=level, order=order, initial=initial,
    )  # fmt: skip
    kind = "icosphere" if mesh == "sphere" else "ring sphere"
    lvl = DEFAULT_LEVEL if level is None else level
    ring = report.membrane.phi_a if mesh == "ring" else None
    nodes = dof_mesh(model.space.basis, f"{kind} level {lvl}, P{model.space.order}", ring)
    return nodes, model.pairs.vectors.T, model.series, report
