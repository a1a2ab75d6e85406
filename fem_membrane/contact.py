"""The finite-element backend of the finite-mass contact.

The eigenpairs give the same :class:`~twoball.modal.series.ModalSeries` as for the
massless lift-off; the contact vector is ``b_k = f . phi_k`` with ``f`` the cap
functional: ``f . u`` is the average of the finite-element function u over the
polar cap, by the quadrature of :mod:`twoball.modal.contact.caps` (Gauss in
``cos(phi)``, times the trapezoid rule in azimuth on the sphere), at points
located in their elements (the pole search of
:func:`twoball.fem_membrane.locate.locate_pole`, on the mesh rotated so that the
point lies on the axis).  The shared solver of :mod:`twoball.modal.contact` does
the rest.  Dimensionless.
"""

from __future__ import annotations

from dataclasses import replace
from typing import Any

import numpy as np
import scipy.sparse as sp

from twoball._common.errors import ParameterError
from twoball._common.monitor import Monitor
from twoball.fem_membrane.build import DEFAULT_LEVEL
from twoball.fem_membrane.locate import locate_pole
from twoball.fem_membrane.mesh import SphereMesh, icosphere, ring_sphere
from twoball.fem_membrane.space import Discretisation
from twoball.modal.contact.caps import cap_rule, sphere_cap_points

#: Cap quadrature: Gauss points in cos(phi), and azimuthal points on the sphere.
CAP_RINGS = 12
CAP_SPOKES = 24


def _rotation_to_pole(direction: np.ndarray) -> np.ndarray:
    """Rotation matrix taking the unit vector ``direction`` to (0, 0, 1) (Rodrigues)."""
    d = direction / np.linalg.norm(direction)
    z = np.array([0.0, 0.0, 1.0])
    v = np.cross(d, z)
    c = float(d @ z)
    if np.linalg.norm(v) < 1e-15:
        return np.eye(3) if c > 0 else np.diag([1.0, -1.0, -1.0])
    vx = np.array([[0, -v[2], v[1]], [v[2], 0, -v[0]], [-v[1], v[0], 0]])
    return np.eye(3) + vx + vx @ vx / (1.0 + c)


def sphere_point_row(space: Discretisation, mesh: SphereMesh, point: np.ndarray) -> np.ndarray:
    """Dense row r with ``r . u = u(point)`` on the discrete sphere (radial projection)."""
    rotated = replace(mesh, points=mesh.points @ _rotation_to_pole(point).T)
    element, xi = locate_pole(rotated)
    basis = space.basis
    values = np.array([basis.elem.lbasis(xi[:, None], i)[0][0] for i in range(basis.Nbfun)])
    row = np.zeros(basis.N)
    np.add.at(row, basis.element_dofs[:, element], values)
    return row


def cap_functional(
    space: Discretisation, theta: float, mesh: SphereMesh | None = None
) -> np.ndarray:
    """Vector f with ``f . u`` = the cap average of u (half-angle ``theta``), dimensionless."""
    if space.kind == "axisym":
        x, w = cap_rule(theta, CAP_RINGS)
        probes = space.basis.probes(x[None, :])
        return np.asarray(sp.csr_matrix(probes).T @ w).ravel()
    if mesh is None:
        raise ValueError("a sphere space needs its SphereMesh for the cap functional")
    points, weights = sphere_cap_points(theta, CAP_RINGS, CAP_SPOKES)
    f = np.zeros(space.dofs)
    for j in range(points.shape[1]):
        f += weights[j] * sphere_point_row(space, mesh, points[:, j])
    return f


def model_facts(model: Any, mesh: str, cap: np.ndarray) -> dict[str, Any]:
    """Facts of a contact model for reports and files: unknowns, mesh, order, modes, cap sum."""
    return {
        "dofs": model.space.dofs,
        "mesh": model.space.name,
        "mesh_kind": mesh,
        "order": model.space.order,
        "modes_computed": len(model.series.omega),
        "cap_functional_sum": float(cap.sum()),
    }


def fem_contact_model(
    phi_a: float,
    damping: float,
    filter: Any,
    theta: float,
    *,
    mesh: str = "axisym",
    level: int | None = None,
    elements: int | None = None,
    order: int | None = 2,
    initial: str = "projection",
    monitor: Monitor | None = None,
) -> tuple[Any, np.ndarray, dict[str, Any]]:
    """Modal model (full eigen route), contact vector and details for one FE mesh.

    ``monitor`` is told as the model is built (:func:`~twoball.fem_membrane.solve.modal_model`).
    """
    from twoball.fem_membrane.solve import modal_model

    if mesh not in ("axisym", "sphere", "ring"):
        raise ParameterError("mesh", "axisym, sphere or ring with mass_ratio", mesh)
    order = 2 if order is None else order
    sphere_mesh = None
    if mesh == "axisym":
        if level is not None:
            raise ParameterError("level", "left out with mesh axisym", level)
        model = modal_model(
            phi_a,
            damping,
            filter,
            mesh="axisym",
            elements=elements,
            order=order,
            initial=initial,
            route="full",
            monitor=monitor,
        )
    else:
        if elements is not None:
            raise ParameterError("elements", "left out with a sphere mesh", elements)
        lvl = DEFAULT_LEVEL if level is None else level
        sphere_mesh = icosphere(lvl, order) if mesh == "sphere" else ring_sphere(lvl, phi_a, order)
        model = modal_model(
            phi_a,
            damping,
            filter,
            mesh=sphere_mesh,
            order=None,
            initial=initial,
            route="full",
            monitor=monitor,
        )
    f = cap_functional(model.space, theta, sphere_mesh)
    contact = model.pairs.vectors.T @ f
    return model, contact, model_facts(model, mesh, f)


def fem_contact_solution(
    case: Any,
    body: Any,
    mesh: Any = None,
    *,
    sigma: str = "lanczos",
    t_end_s: float | None = None,
    dt: float | None = None,
    monitor: Monitor | None = None,
) -> tuple[Any, Any]:
    """The finite-element modal model (full eigen route) and its contact report (SI).

    The same body (:class:`~twoball.modal.contact.body.Body`) and the same
    shared solver as :func:`twoball.modal.contact.report.legendre_contact`;
    ``mesh`` a :class:`~twoball.fem_membrane.options.MeshOptions` (or a kind
    name): ``sphere`` (default, level 3), ``ring`` or ``axisym`` (default 400
    elements), no mesh file.  The model holds the eigenvectors the contact
    solver moved.  ``dt`` is the contact core's step (units 1/c), ``monitor``
    is told of the eigenpairs and the steps.  The budget is the caller's.
    """
    from twoball.fem_membrane.options import MeshOptions
    from twoball.modal.contact.caps import cap_angle
    from twoball.modal.contact.report import check_contact_options, membrane_case, solve_contact
    from twoball.modal.filters import SpectralFilter
    from twoball.modal.report import t_end_dimensionless

    radius = check_contact_options(case, body)
    spec = MeshOptions.of(mesh).require(files=False)
    if spec.geometry != "isoparametric":
        raise ParameterError("geometry", "isoparametric with a body of finite mass", spec.geometry)
    t_end = t_end_dimensionless(case, t_end_s)
    membrane = membrane_case(case, body.mass_ratio, body.energy)
    theta = cap_angle(radius, case.radius)
    model, contact, info = fem_contact_model(
        membrane.phi_a,
        case.damping,
        SpectralFilter(sigma, case.modes),
        theta,
        mesh=spec.kind,
        level=spec.level,
        elements=spec.elements,
        order=spec.order,
        initial=spec.initial or "projection",
        monitor=monitor,
    )
    report = solve_contact(
        case,
        model.series,
        contact,
        mass_ratio=body.mass_ratio,
        contact_radius_m=radius,
        restitution=body.restitution,
        energy=body.energy,
        backend="fem",
        sigma=sigma,
        t_end=t_end,
        membrane=membrane,
        extra={"cap_angle_rad": theta, **info},
        dt=dt,
        monitor=monitor,
    )
    # the mesh guard of the massless path, and the closed-form contact solution beside it
    from twoball.fem_membrane.guards import mesh_warnings
    from twoball.modal.contact.report import guarded

    mesh_said = mesh_warnings(
        spec.kind, spec.level, spec.elements, model.space.order, SpectralFilter(sigma, case.modes)
    )
    return model, guarded(report, body, t_end_s, more=mesh_said, dt=dt, monitor=monitor)


def fem_contact_fields(
    case: Any,
    body: Any,
    mesh: Any = None,
    *,
    sigma: str = "lanczos",
    t_end_s: float | None = None,
    dt: float | None = None,
    monitor: Monitor | None = None,
) -> tuple[Any, Any, Any, Any]:
    """The node mesh, the mode shapes at its nodes and the contact report (SI).

    Exports and pictures of the membrane under a body of finite mass need the
    mode shapes at the nodes *and* the contact solver's modal state on the same
    modes; both come from the one eigen solve of :func:`fem_contact_solution`
    (the full route), so the drawn field ``u = sum_k q_k phi_k`` is exactly the
    one the contact solver moved (eq. (C1) of docs/contact.rst).

    Parameters
    ----------
    case : Case
        The impact (SI).
    body : Body
        The upper body.
    mesh : MeshOptions or {"sphere", "ring"}
        Icosphere, or ring sphere with a ring at the membrane's phi_a.
    sigma : str
        Spectral filter of eq. (3.16).
    t_end_s : float or None
        Modelled window [s] (default 4 pi / c).
    monitor : Monitor, optional
        Told as the work goes on (:func:`fem_contact_solution`).

    Returns
    -------
    nodes : SphereMesh
        Unit sphere whose nodes are the degrees of freedom (as
        :func:`twoball.verify.output.fields.fem_nodal_series`).
    shapes : ndarray, shape (K, P)
        M-orthonormal eigenvectors at the nodes, one row per mode of the report's motion.
    series : ModalSeries
        The free membrane's filtered modal series on these modes (eq. (3.16)).
    report : ContactReport
        The contact solution on these modes (``report.motion``, ``report.history``).
    """
    from twoball.fem_membrane.options import MeshOptions
    from twoball.fem_membrane.space import dof_mesh

    spec = MeshOptions.of(mesh)
    model, report = fem_contact_solution(
        case, body, spec, sigma=sigma, t_end_s=t_end_s, dt=dt, monitor=monitor
    )
    kind = "icosphere" if spec.kind == "sphere" else "ring sphere"
    ring = report.membrane.phi_a if spec.kind == "ring" else None
    nodes = dof_mesh(model.space.basis, f"{kind} level {spec.level}, P{model.space.order}", ring)
    return nodes, model.pairs.vectors.T, model.series, report
