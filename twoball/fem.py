"""Finite elements in SI: ``twoball.fem.solve`` (lift-off) and ``twoball.fem.eigen``.

A thin layer over :mod:`twoball.fem_membrane`: SI in (seconds), dimensionless
inside, the shared lift-off criteria of §3(a) out, as the same
:class:`~twoball.modal.report.LiftoffReport` the closed form returns.
"""

from __future__ import annotations

import time as clock
from numbers import Integral
from typing import Any

from twoball._common.errors import ParameterError
from twoball._common.progress import Step, silent
from twoball.fem_membrane.options import MeshOptions
from twoball.modal.parameters import Case
from twoball.modal.report import LiftoffReport

__all__ = ["eigen", "solve"]


def solve(
    case: Case | None = None,
    *,
    mesh: Any = None,
    level: int | None = None,
    elements: int | None = None,
    order: int | None = None,
    pole: Any = None,
    geometry: str | None = None,
    scheme: str | None = None,
    dt: float | None = None,
    route: str | None = None,
    damping_model: str | None = None,
    sigma: str = "lanczos",
    recontact: str = "window",
    t_end: float | None = None,
    progress: Step | None = None,
) -> LiftoffReport:
    """Lift-off from the finite-element membrane, eq. (3.9), with criteria (i)-(ii) of §3(a).

    Parameters
    ----------
    case : Case, optional
        The impact (SI); default the basketball preset.
    mesh : {"sphere", "ring", "axisym"}, path, meshio.Mesh or scikit-fem mesh, optional
        Mesh kind (default ``sphere``), or the user's sphere: a file in any
        format meshio reads, a ``meshio.Mesh`` or a ``MeshTri`` (any radius and
        centre; it is scaled to the unit sphere), see
        :class:`twoball.fem_membrane.options.MeshOptions`.
    level : int, optional
        Sphere refinement level >= 0 (default 3); not with ``axisym`` or a file.
    elements : int, optional
        Elements >= 2 of ``axisym`` (default 400); not with a sphere.
    order : {1, 2, 3, 4}, optional
        Element and geometry order (default 2; a file: its own).
    pole : (x, y, z) or "X,Y,Z", optional
        Pole direction of a mesh file, in its frame (default +z).
    geometry : {"isoparametric", "exact"}, optional
        Discrete sphere: the order-p interpolant through the nodes (default),
        or the exact sphere (radial projection of the flat triangles; not on
        the ring sphere or the axisymmetric line).
    scheme : {"modal", "alpha"}, optional
        Modal superposition, eqs. (3.14)-(3.16) (default), or generalized-alpha stepping.
    dt : float, optional
        Time step [s] of ``scheme="alpha"`` (default: omega_cut dt = 0.2); refused with modal.
    route : {"auto", "full", "krylov"}, optional
        Eigen route of ``scheme="modal"`` (default auto); ``alpha`` needs the full pairs.
    damping_model : {"modal", "rayleigh"}, optional
        ``alpha`` only: one ratio D per mode (default) or Rayleigh damping.
    sigma : {"lanczos", "printed", "none"}
        Spectral filter, eq. (3.16).
    recontact : {"window", "paper"}
        Re-contact horizon of criterion (ii), §3(a).
    t_end : float, optional
        Modelled window [s] (default 4 pi / c).
    progress : callable, optional
        Called with a short text as each stage starts (:class:`twoball._common.progress.Reporter`).

    Returns
    -------
    LiftoffReport
        ``backend == "fem"``; ``extra`` holds DOFs, modes used, mesh, route, time scheme.
    """
    from twoball.fem_membrane.solve import fem_pole_motion
    from twoball.modal.filters import SpectralFilter
    from twoball.modal.report import report_liftoff, t_end_dimensionless

    case = Case.preset("basketball") if case is None else case
    spec = MeshOptions.resolve(
        mesh, level=level, elements=elements, order=order, pole=pole, geometry=geometry
    )
    scheme = "modal" if scheme is None else scheme
    if scheme == "modal":
        if dt is not None:
            raise ParameterError("dt", "left out with scheme modal (no time steps)", dt)
        if damping_model not in (None, "modal"):
            raise ParameterError(
                "damping_model", "modal with scheme modal (one ratio D per mode)", damping_model
            )
    elif scheme == "alpha" and route not in (None, "full", "auto"):
        raise ParameterError("route", "full or auto with scheme alpha", route)
    dt_scaled = None
    if dt is not None:
        from twoball.fem_membrane.checks import check_dt_in_window

        dt_scaled = check_dt_in_window(dt, case.scalings.time, t_end_dimensionless(case, t_end))
    if spec.kind != "file":  # the budget in the user's units (the model layer checks again)
        from twoball._common.budget import check_fem

        check_fem(
            spec.kind,
            spec.level,
            spec.elements,
            spec.order,
            case.modes,
            "auto" if route is None else route,
            scheme=scheme,
            dt=dt_scaled,
            t_end=t_end_dimensionless(case, t_end),
            time_unit_s=case.scalings.time,
        )
    say = progress or silent
    say(f"finite elements on {spec.label}: mesh, assembly, eigenpairs")
    started = clock.perf_counter()
    loaded = spec.load()  # the user's mesh, checked, on the unit sphere (None for a kind)
    motion, info = fem_pole_motion(
        case.phi_a,
        case.damping,
        SpectralFilter(sigma, case.modes),
        mesh=spec.kind if loaded is None else loaded.mesh,
        level=spec.level,
        elements=spec.elements,
        order=spec.order if loaded is None else None,
        scheme=scheme,
        damping_model="modal" if damping_model is None else damping_model,
        dt=dt_scaled,
        t_end=t_end_dimensionless(case, t_end),
        route="auto" if route is None else route,
        geometry=spec.geometry,
        stiffness=case.stiffness if case.stiff else None,
    )
    extra: dict[str, Any] = {
        "dofs": info["dofs"],
        "modes_used": info["modes_used"],
        "mesh": info["mesh"],
        "order": info["order"],
        "geometry": info["geometry"],
        "time_scheme": info["time_scheme"],
        "route": info["route"],
        "damping_model": info["damping_model"],
        "seconds": clock.perf_counter() - started,
    }
    if loaded is not None:
        extra["mesh_file"] = loaded.as_dict()
        extra["mesh_description"] = loaded.description
    if "dt" in info:
        extra["dt_s"] = info["dt"] * case.scalings.time
    if "rayleigh" in info:
        extra["rayleigh"] = info["rayleigh"]
    from twoball.fem_membrane.guards import fem_warnings

    # a user's mesh has no level: its resolution is not estimated (time step still is)
    warnings = fem_warnings(
        info if loaded is None else {**info, "mesh_kind": None},
        SpectralFilter(sigma, case.modes),
        level=spec.level,
        elements=spec.elements,
        time_unit_s=case.scalings.time,
    )
    say("lift-off criteria and the converged closed form beside it")
    report = report_liftoff(
        case,
        motion,
        backend="fem",
        sigma=sigma,
        recontact=recontact,
        t_end_s=t_end,
        extra=extra,
        warnings=warnings,
    )
    from dataclasses import replace

    from twoball._common.provenance import block

    arguments = {
        "mesh": mesh,
        "level": level,
        "elements": elements,
        "order": order,
        "pole": pole,
        "scheme": scheme,
        "dt": dt,
        "route": route,
        "damping_model": damping_model,
        "sigma": sigma,
        "recontact": recontact,
        "t_end": t_end,
    }
    return replace(report, provenance=block(case, "twoball.fem.solve", arguments))


def eigen(
    *,
    mesh: Any = None,
    level: int | None = None,
    elements: int | None = None,
    order: int | None = None,
    pole: Any = None,
    geometry: str | None = None,
    count: int = 25,
    progress: Step | None = None,
) -> list[dict[str, float | int]]:
    """The lowest ``count`` nonzero eigenvalues of -Laplace-Beltrami beside l (l + 1), eq. (3.11).

    Mesh arguments as in :func:`solve`; one row per eigenvalue (``index``, ``l``,
    ``value``, ``exact``, ``relative_error``, ``multiplicity``,
    ``expected_multiplicity``), dimensionless.  ``progress`` is called with a short
    text as the solve starts (:class:`twoball._common.progress.Reporter`).
    """
    from twoball._common.budget import check, fem_dofs, fem_estimate, options
    from twoball.fem_membrane.eigen import eigen_table

    spec = MeshOptions.resolve(
        mesh, level=level, elements=elements, order=order, pole=pole, geometry=geometry
    )
    if isinstance(count, bool) or not isinstance(count, Integral) or count < 1:
        raise ParameterError("count", "an integer >= 1", count)
    if spec.kind != "file":  # refuse absurd meshes before building them
        dofs = fem_dofs(spec.kind, spec.level, spec.elements, spec.order)
        size = options(level=spec.level, elements=spec.elements, order=spec.order)
        check(size, fem_estimate(dofs, 30, "krylov"))
    (progress or silent)(f"{count} eigenvalues on {spec.label}")
    loaded = spec.load()
    if loaded is not None:
        return eigen_table(mesh=loaded.mesh, order=None, count=count, geometry=spec.geometry)
    return eigen_table(
        mesh=spec.kind,
        level=spec.level,
        elements=spec.elements,
        order=spec.order,
        count=count,
        geometry=spec.geometry,
    )
