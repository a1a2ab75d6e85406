"""``twoball.liftoff``: the lift-off of one case, in SI.

The command line (``twoball liftoff``) calls exactly this
function, so the same inputs give bit-identical numbers in Python and in a shell.
"""

from __future__ import annotations

from dataclasses import replace
from typing import Any

from twoball._common.errors import ParameterError, refuse_given
from twoball._common.progress import Step
from twoball.fem_membrane.options import refuse_mesh_options
from twoball.modal.parameters import Case
from twoball.modal.report import LiftoffReport

BACKENDS: tuple[str, ...] = ("legendre", "fem")

__all__ = ["BACKENDS", "liftoff"]


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
        (a :class:`twoball._common.progress.Reporter`, for instance).
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
        from twoball._common.provenance import block

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
    from twoball._common.provenance import block

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
