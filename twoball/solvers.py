"""``twoball.liftoff`` and ``twoball.sweep``: one case, or a grid of cases, in SI.

The command line (``twoball liftoff``, ``twoball sweep``) calls exactly these
functions, so the same inputs give bit-identical numbers in Python and in a shell.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass, field, replace
from typing import Any

from twoball.mesh_options import refuse_mesh_options
from twoball.modal.errors import ParameterError, refuse_given
from twoball.modal.parameters import Case
from twoball.modal.report import LiftoffReport
from twoball.progress import Step

BACKENDS: tuple[str, ...] = ("legendre", "fem")

__all__ = ["BACKENDS", "SweepResult", "liftoff", "sweep"]


def liftoff(
    case: Case | None = None,
    *,
    backend: str = "legendre",
    sigma: str = "lanczos",
    recontact: str = "window",
    t_end: float | None = None,
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
    progress: Step | None = None,
    mass_ratio: float | None = None,
    contact_radius: float | None = None,
    restitution: float | None = None,
    energy: str | None = None,
) -> LiftoffReport | Any:
    """Lift-off time and velocity of the body on the ball, in SI.

    Parameters
    ----------
    case : Case, optional
        The impact; default ``Case.preset("basketball")``.
    backend : {"legendre", "fem"}
        Closed-form Legendre series, eqs. (3.12)-(3.16), or finite elements
        (:func:`twoball.fem.solve`, which takes the mesh and time options).
    sigma : {"lanczos", "printed", "none"}
        Spectral filter, eq. (3.16).
    recontact : {"window", "paper"}
        Re-contact horizon of criterion (ii), §3(a).
    t_end : float, optional
        Modelled window [s] (default 4 pi / c).
    mesh, level, elements, order, pole, geometry, scheme, dt, route, damping_model
        Finite-element options (see :func:`twoball.fem.solve`; ``mesh`` may be a
        kind name or the user's mesh: a file path, ``meshio.Mesh`` or ``MeshTri``);
        refused with ``backend="legendre"``.
    progress : callable, optional
        Called with a short text as each stage of a finite-element solve starts
        (a :class:`twoball.progress.Reporter`, for instance).
    mass_ratio : float, optional
        ``mu = m1 / m2`` of an upper body of finite mass in unilateral contact
        (docs/contact.rst); None (default): the massless body of the paper.  0 is
        the massless criteria on the cap-averaged motion.
    contact_radius : float, optional
        Radius a [m] of the contact cap (default R/10); only with ``mass_ratio``.
    restitution : float, optional
        Newton's coefficient at re-contact, in [0, 1] (default 0); only with ``mass_ratio``.
    energy : {"ball", "both"}, optional
        Energy at t = 0: eq. (3.6) for the lower ball alone, or with the upper
        body's kinetic energy; only with ``mass_ratio``.

    Returns
    -------
    LiftoffReport
        ``t_liftoff_s``, ``v_liftoff_m_s``, ``ratio``, ``case`` (with
        ``phi_a_source``), ``notes``; ``as_dict()`` for JSON.  With ``mass_ratio``
        a :class:`~twoball.modal.contact.report.ContactReport` (the same
        properties, plus every contact event).
    """
    case = Case.preset("basketball") if case is None else case
    if not isinstance(case, Case):
        raise ParameterError("case", "a twoball.Case", type(case).__name__)
    if mass_ratio is not None:
        from twoball.provenance import block

        restitution = 0.0 if restitution is None else restitution
        energy = "ball" if energy is None else energy
        contact = _contact_liftoff(
            case, backend, sigma, recontact, t_end, mass_ratio, contact_radius,
            restitution, energy, mesh=mesh, level=level, elements=elements, order=order,
            pole=pole, scheme=scheme, dt=dt, route=route, damping_model=damping_model,
        )  # fmt: skip
        arguments = {
            "backend": backend,
            "mass_ratio": mass_ratio,
            "contact_radius": contact_radius,
            "restitution": restitution,
            "energy": energy,
        }
        return replace(contact, provenance=block(case, "twoball.liftoff", arguments))
    refuse_given(
        "given only with mass_ratio",
        contact_radius=contact_radius,
        restitution=restitution,
        energy=energy,
    )
    fem_options = {
        "mesh": mesh,
        "level": level,
        "elements": elements,
        "order": order,
        "pole": pole,
        "geometry": geometry,
        "scheme": scheme,
        "dt": dt,
        "route": route,
        "damping_model": damping_model,
    }
    options = {"backend": backend, "sigma": sigma, "recontact": recontact, "t_end": t_end}
    if backend == "fem":
        from twoball.fem import solve

        report = solve(
            case, sigma=sigma, recontact=recontact, t_end=t_end, progress=progress, **fem_options
        )
    elif backend != "legendre":
        raise ParameterError("backend", "one of " + ", ".join(BACKENDS), backend)
    else:
        refuse_mesh_options("with backend legendre (no mesh, no time steps)", **fem_options)
        from twoball.modal.report import legendre_liftoff

        report = legendre_liftoff(case, sigma, recontact, t_end)
    from twoball.provenance import block

    arguments = {**options, **{k: v for k, v in fem_options.items() if v is not None}}
    return replace(report, provenance=block(case, "twoball.liftoff", arguments))


def _contact_liftoff(
    case: Case,
    backend: str,
    sigma: str,
    recontact: str,
    t_end: float | None,
    mass_ratio: float,
    contact_radius: float | None,
    restitution: float,
    energy: str,
    **fem_options: Any,
) -> Any:
    """The finite-mass body (issue 13): the shared contact solver on a backend's modes."""
    if recontact != "window":
        raise ParameterError(
            "recontact", "window with mass_ratio (events are simulated)", recontact
        )
    if backend == "fem":
        for name in ("pole", "scheme", "dt", "route", "damping_model"):
            if fem_options[name] is not None:
                raise ParameterError(
                    name, "left out with mass_ratio (modal route only)", fem_options[name]
                )
        from twoball.fem_membrane.contact import fem_contact_solution

        _, report = fem_contact_solution(
            case, mass_ratio, contact_radius, sigma=sigma, restitution=restitution,
            energy=energy, t_end_s=t_end, mesh=fem_options["mesh"], level=fem_options["level"],
            elements=fem_options["elements"], order=fem_options["order"],
        )  # fmt: skip
        return report
    if backend != "legendre":
        raise ParameterError("backend", "one of " + ", ".join(BACKENDS), backend)
    refuse_mesh_options("with backend legendre (no mesh, no time steps)", **fem_options)
    from twoball.modal.contact.report import legendre_contact

    return legendre_contact(
        case, mass_ratio, contact_radius, sigma=sigma, restitution=restitution,
        energy=energy, t_end_s=t_end,
    )  # fmt: skip


@dataclass(frozen=True)
class SweepResult:
    """Lift-off over a grid of cases (row-major: the first parameter varies slowest).

    Attributes
    ----------
    parameters : tuple of str
        Swept parameters (``v0``, ``damping``, ``wave-speed``, ``radius``, ``modes``).
    shape : tuple of int
        Values per parameter.
    points : list of SweepPoint
        One per grid point: ``index``, ``case``, ``report`` (or ``error``).
    provenance : dict
        Versions, command line or call, UTC time, base case (:mod:`twoball.provenance`).
    """

    parameters: tuple[str, ...]
    shape: tuple[int, ...]
    points: list[Any]
    provenance: dict[str, Any] | None = field(default=None, compare=False, repr=False)

    def as_dict(self) -> dict[str, Any]:
        """JSON-ready: parameters, shape, the points (SI) and the provenance."""
        return {
            "parameters": list(self.parameters),
            "shape": list(self.shape),
            "points": [p.as_dict() for p in self.points],
            "provenance": self.provenance,
        }


def _sweep_name(name: str) -> str:
    return name.replace("_", "-")


def sweep(
    values: Mapping[str, Sequence[float]],
    case: Case | None = None,
    *,
    sigma: str = "lanczos",
    recontact: str = "window",
    t_end: float | None = None,
    workers: int | None = None,
    scheduler: str | None = None,
    progress: Callable[[int], None] | None = None,
    contact_radius: float | None = None,
) -> SweepResult:
    """Closed-form lift-off over one parameter or a grid of two (Fig. 11(b), Fig. 12).

    Parameters
    ----------
    values : mapping
        ``{"v0": [2.0, 4.0, 8.0]}`` or two entries for a grid; keys among
        ``damping``, ``v0``, ``wave_speed``, ``radius``, ``modes``.  v0, c and R
        re-apply the phi_a rule of :class:`~twoball.modal.parameters.Case`.
    case : Case, optional
        The base case (default the basketball preset).
    sigma, recontact, t_end
        As in :func:`liftoff` (``t_end`` in seconds).
    workers : int, optional
        Local processes (default 1: serial; the numbers do not depend on it);
        refused with ``scheduler``.
    scheduler : str, optional
        Address of a dask.distributed scheduler.
    progress : callable, optional
        Called with the number of points done (e.g. :meth:`twoball.progress.Reporter.update`).
    contact_radius : float, optional
        Contact cap radius a [m] of a ``mass_ratio`` sweep (default R/10): the
        points then run the finite-mass contact solver (docs/contact.rst).

    Returns
    -------
    SweepResult
    """
    import numpy as np

    from twoball.budget import check_sweep
    from twoball.modal.report import t_end_dimensionless
    from twoball.verify.sweeps.parallel import MIN_PARALLEL_ITEMS, Runner, check_workers
    from twoball.verify.sweeps.sweeps import SWEEP_PARAMETERS, SweepGrid, SweepSolver, run_sweep

    case = Case.preset("basketball") if case is None else case
    if not isinstance(case, Case):
        raise ParameterError("case", "a twoball.Case", type(case).__name__)
    if scheduler and workers is not None:
        raise ParameterError("workers", "left out with scheduler (the cluster decides)", workers)
    workers = 1 if workers is None and not scheduler else workers
    if workers is not None:
        check_workers(workers)  # its type and range, before the budget compares it
    call = {
        "sigma": sigma,
        "recontact": recontact,
        "t_end": t_end,
        "workers": workers,
        "scheduler": scheduler,
    }
    if not isinstance(values, Mapping) or not 1 <= len(values) <= 2:
        raise ParameterError("values", "a mapping of one or two parameters to values", values)
    parameters = tuple(_sweep_name(k) for k in values)
    for key, name in zip(values, parameters, strict=True):
        if name not in SWEEP_PARAMETERS:
            valid = "keys among " + ", ".join(f.replace("-", "_") for f in SWEEP_PARAMETERS)
            raise ParameterError("values", valid, key)
    if len(set(parameters)) != len(parameters):
        raise ParameterError("values", "two different parameters for a grid", list(values))
    arrays = []
    for name, items in values.items():
        array = np.atleast_1d(np.asarray(items, dtype=float))
        if array.ndim != 1 or array.size < 1 or not np.all(np.isfinite(array)):
            raise ParameterError(f"values[{name!r}]", "a non-empty list of finite numbers", items)
        arrays.append(array)
    grid = SweepGrid(parameters, tuple(arrays))
    modes = int(max(arrays[parameters.index("modes")])) if "modes" in parameters else case.modes
    check_sweep(math.prod(grid.shape), modes, t_end_dimensionless(case, t_end), workers)
    cases = grid.cases(case)
    workers = None if scheduler else check_workers(workers)
    if len(cases) < MIN_PARALLEL_ITEMS and not scheduler:
        workers = 1  # would run in process anyway; do not start a pool
    if contact_radius is not None and "mass-ratio" not in parameters:
        raise ParameterError("contact_radius", "given only with a mass_ratio sweep", contact_radius)
    if "mass-ratio" in parameters:
        from twoball.modal.contact.report import check_contact_options

        for mu in arrays[parameters.index("mass-ratio")]:
            check_contact_options(case, float(mu), contact_radius, 0.0, "ball")
        if recontact != "window":
            raise ParameterError("recontact", "window with mass_ratio", recontact)
    if contact_radius is None:
        solver = SweepSolver(sigma, recontact, t_end)
    else:
        solver = SweepSolver(sigma, recontact, t_end, contact_radius=contact_radius)
    with Runner(workers, scheduler) as runner:
        points = run_sweep(cases, solver, progress, runner=runner, indices=grid.indices())
    from twoball.provenance import block

    arguments = {"values": {k: arrays[i] for i, k in enumerate(values)}, **call}
    return SweepResult(parameters, grid.shape, points, block(case, "twoball.sweep", arguments))
