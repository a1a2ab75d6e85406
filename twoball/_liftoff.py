"""``twoball.liftoff``: the lift-off of one case, in SI.

The command line (``twoball liftoff``) calls exactly this function, so the same
inputs give bit-identical numbers in Python and in a shell.
"""

from __future__ import annotations

import os
from dataclasses import replace
from typing import Any

from twoball._bundles import bundles, with_damping
from twoball._common.budget import timed
from twoball._common.errors import ParameterError
from twoball._common.progress import Step, check_progress
from twoball.modal.parameters import Case
from twoball.modal.report import LiftoffReport

BACKENDS: tuple[str, ...] = ("legendre", "fem")

__all__ = ["BACKENDS", "liftoff"]


@timed
def liftoff(
    case: Case | None = None,
    *,
    backend: str = "legendre",
    mesh: Any = None,
    stepping: Any = None,
    body: Any = None,
    damping: Any = None,
    series: Any = None,
    progress: Step | None = None,
    **deprecated: Any,
) -> LiftoffReport | Any:
    """Lift-off time and velocity of the body on the ball, in SI.

    Parameters
    ----------
    case : Case, optional
        The impact; default ``Case.preset("basketball")``.
    backend : {"legendre", "fem"}
        Closed-form Legendre series, eqs. (3.12)-(3.16), or finite elements
        (:func:`twoball.fem.solve`).
    mesh : MeshOptions, kind name or the user's mesh, optional
        Finite elements only: :class:`~twoball.MeshOptions`, a kind name
        (``"sphere"``, ``"ring"``, ``"axisym"``) or the user's sphere (a file
        path, ``meshio.Mesh`` or ``MeshTri``); default the level-3 P2 icosphere.
    stepping : Stepping, optional
        The window ``t_end`` [s] (default 4 pi / c) and, finite elements only,
        the scheme, step and eigen route (:class:`~twoball.Stepping`).
    body : Body, optional
        An upper body of finite mass in unilateral contact (docs/contact.rst,
        :class:`~twoball.Body`); default the massless body of the paper.
    damping : ModalRatio or Rayleigh, optional
        The damping law (default the case's: the paper's ratio D on every mode,
        eq. (3.14), or its ``rayleigh``); :class:`~twoball.Rayleigh` in SI
        (alpha [1/s], beta [s]; ``Rayleigh()`` fitted to D) on every backend
        and scheme, each mode with its own ratio (docs/pressurised.rst).
    series : Series, optional
        The spectral filter of eq. (3.16) and the re-contact horizon of
        criterion (ii), §3(a) (:class:`~twoball.Series`; default Lanczos and
        the whole window).
    progress : callable, optional
        Called with a short text as each stage of a finite-element solve starts
        (a :class:`~twoball.Reporter`, for instance).
    **deprecated
        The keywords of version 0.2 (``t_end``, ``level``, ``mass_ratio``,
        ``sigma``, ``recontact``, ...), folded into the bundles above with a
        :class:`DeprecationWarning`.

    Returns
    -------
    LiftoffReport
        ``t_liftoff_s``, ``v_liftoff_m_s``, ``ratio``, ``case`` (with
        ``phi_a_source``), ``notes``, ``warnings``; ``as_dict()`` for JSON.  With
        ``body`` a ContactReport (the same properties, plus every contact event).

    Examples
    --------
    >>> import twoball
    >>> report = twoball.liftoff(twoball.Case.preset("basketball"))
    >>> round(report.t_liftoff_s * 1e3, 4), round(report.v_liftoff_m_s, 4)
    (9.8825, 3.8322)
    >>> fe = twoball.liftoff(backend="fem", mesh=twoball.MeshOptions("axisym"))
    >>> abs(fe.t_liftoff_s / report.t_liftoff_s - 1) < 1e-3
    True
    >>> twoball.liftoff(body=twoball.Body(mass_ratio=0.1)).lifted
    True
    """
    check_progress(progress)
    given = bundles(
        "twoball.liftoff",
        mesh=mesh,
        stepping=stepping,
        body=body,
        damping=damping,
        series=series,
        old=deprecated,
    )
    sigma, recontact = given.rules.sigma, given.rules.recontact
    case = Case.preset("basketball") if case is None else case
    if not isinstance(case, Case):
        raise ParameterError("case", "a twoball.Case", type(case).__name__)
    if backend not in BACKENDS:
        raise ParameterError("backend", "one of " + ", ".join(BACKENDS), backend)
    case = with_damping(case, given.damping)
    stepping = given.stepping
    t_end = None if stepping is None else stepping.t_end
    if given.body is not None:
        report = _contact_liftoff(case, backend, given, sigma, recontact, progress)
    elif backend == "fem":
        from twoball.fem import solve

        report = solve(
            case,
            mesh=given.mesh,
            stepping=stepping,
            damping=given.damping,
            series=given.series,
            progress=progress,
        )
    else:
        _refuse_fem_options(given)
        from twoball._common.watch import Watch
        from twoball._costs import check_legendre_liftoff
        from twoball.modal.report import legendre_liftoff

        if progress is not None:  # the truncation guard's reference may take a while
            progress(f"the closed form on {case.modes} Legendre modes")
        check_legendre_liftoff(case, t_end)
        report = legendre_liftoff(case, sigma, recontact, t_end, monitor=Watch())
    from twoball._common.provenance import block

    arguments = {"backend": backend, **given.as_dict()}
    return replace(report, provenance=block(case, "twoball.liftoff", arguments))


def _refuse_fem_options(given: Any, why: str = "with backend legendre") -> None:
    """Refuse the mesh and the time steps on the closed form."""
    if given.mesh is not None:
        shown = given.mesh.label if hasattr(given.mesh, "label") else given.mesh
        raise ParameterError("mesh", f"left out {why} (no mesh)", os.fspath(shown))
    if given.stepping is not None:
        given.stepping.refuse(f"{why} (no time steps)", "scheme", "dt", "route")


def _contact_liftoff(
    case: Case, backend: str, given: Any, sigma: str, recontact: str, progress: Step | None = None
) -> Any:
    """The finite-mass body: the shared contact solver on a backend's modes."""
    if recontact != "window":
        raise ParameterError(
            "recontact", "window with mass_ratio (events are simulated)", recontact
        )
    from twoball._common.watch import Watch
    from twoball._costs import check_fem_contact, check_legendre_contact

    if backend == "fem":
        if given.stepping is not None:
            given.stepping.refuse("with mass_ratio (modal route only)", "scheme", "dt", "route")
        from twoball.fem_membrane.contact import fem_contact_solution
        from twoball.fem_membrane.options import MeshOptions

        mesh = MeshOptions.of(given.mesh)
        if mesh.pole is not None:
            raise ParameterError("pole", "left out with mass_ratio (no mesh file)", mesh.pole)
        if progress is not None:
            progress(f"finite elements on {mesh.label} (full eigen route) and the contact solver")
        check_fem_contact(case, given.body, mesh, _t_end(given))
        _, report = fem_contact_solution(
            case, given.body, mesh, sigma=sigma, t_end_s=_t_end(given), monitor=Watch()
        )
        return report
    _refuse_fem_options(given)
    from twoball.modal.contact.report import legendre_contact

    if progress is not None:
        progress(f"the contact solver on {case.modes + 1} Legendre modes")
    check_legendre_contact(case, given.body, _t_end(given))
    return legendre_contact(case, given.body, sigma=sigma, t_end_s=_t_end(given), monitor=Watch())


def _t_end(given: Any) -> float | None:
    return None if given.stepping is None else given.stepping.t_end
