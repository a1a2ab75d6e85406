"""Finite elements in SI: ``twoball.fem.solve`` (lift-off) and ``twoball.fem.eigen``.

A thin layer over :mod:`twoball.fem_membrane`: SI in (seconds), dimensionless
inside, the shared lift-off criteria of §3(a) out, as the same
:class:`~twoball.modal.report.LiftoffReport` the closed form returns.
"""

from __future__ import annotations

import time as clock
from numbers import Integral
from typing import Any

from twoball._bundles import bundles
from twoball._common.budget import timed
from twoball._common.errors import ParameterError
from twoball._common.progress import Step, check_progress, silent
from twoball.fem_membrane.options import MeshOptions
from twoball.modal.parameters import Case
from twoball.modal.report import LiftoffReport

__all__ = ["eigen", "solve"]


@timed
def solve(
    case: Case | None = None,
    *,
    mesh: Any = None,
    stepping: Any = None,
    damping: Any = None,
    series: Any = None,
    progress: Step | None = None,
    **deprecated: Any,
) -> LiftoffReport:
    """Lift-off from the finite-element membrane, eq. (3.9), with criteria (i)-(ii) of §3(a).

    Parameters
    ----------
    case : Case, optional
        The impact (SI); default the basketball preset.
    mesh : MeshOptions, kind name or the user's mesh, optional
        :class:`~twoball.MeshOptions` (default the level-3 P2 icosphere), a kind
        name, or the user's sphere: a file in any format meshio reads, a
        ``meshio.Mesh`` or a ``MeshTri`` (any radius and centre; it is scaled to
        the unit sphere).
    stepping : Stepping, optional
        Window ``t_end`` [s] (default 4 pi / c), ``scheme`` (modal superposition,
        eqs. (3.14)-(3.16), or generalized-alpha), its step ``dt`` [s] (default
        omega_cut dt = 0.2) and the eigen ``route`` of modal superposition.
    damping : ModalRatio or Rayleigh, optional
        The damping law: the case's (default: ratio D on every mode), or
        Rayleigh damping ``C = alpha M + beta K`` in SI (alpha [1/s], beta [s];
        ``Rayleigh()`` fits it to D at the lowest vibrating mode and the
        filter's cutoff), by modal superposition (each mode its ratio) or
        generalized-alpha (the sparse matrix).
    series : Series, optional
        The spectral filter of eq. (3.16), on the finite-element modes by their
        frequencies, and the re-contact horizon of criterion (ii), §3(a)
        (:class:`~twoball.Series`; default Lanczos and the whole window).
    progress : callable, optional
        Called with a short text as each stage starts (:class:`~twoball.Reporter`).
    **deprecated
        The keywords of version 0.2 (``level``, ``dt``, ``damping_model``,
        ``sigma``, ``recontact``, ...), with a :class:`DeprecationWarning`.

    Returns
    -------
    LiftoffReport
        ``backend == "fem"``; ``extra`` holds DOFs, modes used, mesh, route, time scheme.

    Examples
    --------
    >>> import twoball
    >>> report = twoball.fem.solve(mesh=twoball.MeshOptions("axisym", elements=200))
    >>> report.backend, report.extra["dofs"]
    ('fem', 401)
    >>> round(report.t_liftoff_s * 1e3, 2)
    9.88
    """
    from twoball.modal.stepping import Stepping

    check_progress(progress)
    given = bundles(
        "twoball.fem.solve",
        mesh=mesh,
        stepping=stepping,
        damping=damping,
        series=series,
        old=deprecated,
        takes=("mesh", "stepping", "damping", "series"),
    )
    sigma, recontact = given.rules.sigma, given.rules.recontact
    case = Case.preset("basketball") if case is None else case
    if not isinstance(case, Case):
        raise ParameterError("case", "a twoball.Case", type(case).__name__)
    spec = MeshOptions.of(given.mesh)
    step = given.stepping or Stepping()
    scheme, dt, route, t_end = step.scheme or "modal", step.dt, step.route, step.t_end
    from twoball._bundles import with_damping

    case = with_damping(case, given.damping)
    law = case.rayleigh
    rayleigh = law is not None
    from twoball._common.watch import Watch
    from twoball.fem_membrane.solve import fem_pole_motion
    from twoball.modal.filters import SpectralFilter
    from twoball.modal.report import report_liftoff, t_end_dimensionless

    dt_scaled = None
    if dt is not None:
        from twoball.fem_membrane.validate import check_dt_in_window

        dt_scaled = check_dt_in_window(dt, case.scalings.time, t_end_dimensionless(case, t_end))
    from twoball._costs import check_fem

    if spec.kind != "file":  # the budget in the user's units, before any work
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
    if loaded is not None:  # a user's mesh: its size is known once it is read
        check_fem(
            loaded.mesh,
            spec.level,
            spec.elements,
            None,
            case.modes,
            "auto" if route is None else route,
            scheme=scheme,
            dt=dt_scaled,
            t_end=t_end_dimensionless(case, t_end),
        )
    motion, info = fem_pole_motion(
        case.phi_a,
        case.damping,
        SpectralFilter(sigma, case.modes),
        mesh=spec.kind if loaded is None else loaded.mesh,
        level=spec.level,
        elements=spec.elements,
        order=spec.order if loaded is None else None,
        scheme=scheme,
        damping_model="rayleigh" if rayleigh else "modal",
        rayleigh=law.scaled(case.wave_speed) if rayleigh and not law.fitted else None,
        dt=dt_scaled,
        t_end=t_end_dimensionless(case, t_end),
        route="auto" if route is None else route,
        geometry=spec.geometry,
        initial=spec.initial or "projection",
        stiffness=case.stiffness if case.stiff else None,
        monitor=Watch(),
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
    if "rayleigh" in info:  # coefficients in units of c, and in SI
        c = case.wave_speed
        extra["rayleigh"] = {
            **info["rayleigh"],
            "alpha_1_s": info["rayleigh"]["alpha"] * c if law.fitted else law.alpha,
            "beta_s": info["rayleigh"]["beta"] / c if law.fitted else law.beta,
        }
    if case.membrane.pressurised:
        extra["membrane"] = case.membrane.kind
    from twoball.fem_membrane.guards import fem_warnings

    # a user's mesh has no level: its size stands in for it
    warnings = fem_warnings(
        info,
        SpectralFilter(sigma, case.modes),
        level=spec.level,
        elements=spec.elements,
        time_unit_s=case.scalings.time,
        surface=None if loaded is None else (loaded.mesh.points, loaded.mesh.cells),
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
        monitor=Watch(),
    )
    from dataclasses import replace

    from twoball._common.provenance import block

    return replace(report, provenance=block(case, "twoball.fem.solve", given.as_dict()))


@timed
def eigen(
    mesh: Any = None,
    *,
    count: int = 25,
    membrane: Any = "paper",
    progress: Step | None = None,
    **deprecated: Any,
) -> list[dict[str, float | int]]:
    """The lowest ``count`` nonzero eigenvalues of -Laplace-Beltrami beside l (l + 1), eq. (3.11).

    With ``membrane="pressurised"``: those of ``K - 2 M`` beside ``(l - 1)(l + 2)``
    (:class:`~twoball.Membrane`; l = 1, the free translation, is 0 up to the
    mesh's eigenvalue error at l = 1).

    Parameters
    ----------
    mesh : MeshOptions, kind name or the user's mesh, optional
        As in :func:`solve` (default the level-3 P2 icosphere).
    count : int
        Nonzero eigenvalues listed, >= 1.
    membrane : Membrane or {"paper", "pressurised"}
        The membrane operator.
    progress : callable, optional
        Called with a short text as the solve starts (:class:`~twoball.Reporter`).
    **deprecated
        The mesh keywords of version 0.2 (``level``, ``order``, ...), with a
        :class:`DeprecationWarning`.

    Returns
    -------
    list of dict
        One row per eigenvalue (``index``, ``l``, ``value``, ``exact``,
        ``relative_error``, ``multiplicity``, ``expected_multiplicity``),
        dimensionless.

    Examples
    --------
    >>> import twoball
    >>> rows = twoball.fem.eigen(twoball.MeshOptions("axisym", elements=100), count=3)
    >>> [(row["l"], row["exact"]) for row in rows]
    [(0, 0.0), (1, 2.0), (2, 6.0), (3, 12.0)]
    """
    check_progress(progress)
    given = bundles("twoball.fem.eigen", mesh=mesh, old=deprecated, takes=("mesh",))
    from twoball._common.budget import check, options
    from twoball._common.watch import Watch
    from twoball.fem_membrane.cost import fem_dofs, fem_estimate
    from twoball.fem_membrane.eigen import eigen_table
    from twoball.modal.membrane import Membrane

    spec = MeshOptions.of(given.mesh)
    membrane = Membrane.of(membrane)
    if isinstance(count, bool) or not isinstance(count, Integral) or count < 1:
        raise ParameterError("count", "an integer >= 1", count)
    if spec.kind != "file":  # refuse absurd meshes before building them
        dofs = fem_dofs(spec.kind, spec.level, spec.elements, spec.order)
        size = options(level=spec.level, elements=spec.elements, order=spec.order)
        dimension = 1 if spec.kind == "axisym" else 2
        check(size, fem_estimate(dofs, 30, "krylov", dimension, spec.order))
    (progress or silent)(f"{count} eigenvalues on {spec.label}")
    loaded = spec.load()
    if loaded is not None:
        return eigen_table(
            mesh=loaded.mesh,
            order=None,
            count=count,
            geometry=spec.geometry,
            membrane=membrane,
            monitor=Watch(),
        )
    return eigen_table(
        mesh=spec.kind,
        level=spec.level,
        elements=spec.elements,
        order=spec.order,
        count=count,
        geometry=spec.geometry,
        membrane=membrane,
        monitor=Watch(),
    )
