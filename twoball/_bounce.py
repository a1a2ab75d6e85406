"""``twoball.bounce``: one drop of the lower ball on a rigid floor, in SI.

The command line (``twoball bounce``) calls exactly this function, so the same
inputs give bit-identical numbers in Python and in a shell.  The model (the
ball's centre, its membrane, the unilateral floor at every point of the lower
hemisphere, the contact core) is in :mod:`twoball.modal.floor` and
:mod:`twoball.fem_membrane.floor`; docs/bounce.rst explains it.
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING, Any

from twoball._bundles import bundles
from twoball._common.errors import ParameterError
from twoball.modal.floor.options import DEFAULT_MODES, Drop
from twoball.modal.parameters import Case

if TYPE_CHECKING:
    from twoball.modal.floor.report import BounceReport

__all__ = ["BACKENDS", "DEFAULT_DT", "DEFAULT_ELEMENTS", "DEFAULT_WINDOW", "bounce"]

BACKENDS: tuple[str, ...] = ("legendre", "fem")
#: Time step in units of 1/c (the basketball: 15.6 microseconds).
DEFAULT_DT = 0.005
#: Window in units of 1/c: ten pressure x area contact times pi / c.
DEFAULT_WINDOW = 10.0 * math.pi
#: Axisymmetric elements of the finite-element drop (P2: node spacing pi / 192, as N = 192).
DEFAULT_ELEMENTS = 96
#: Largest time step in units of 1/c (a twentieth of the pressure x area contact time).
MAX_DT = math.pi / 20.0
#: Fewest floor points across the largest contact before the result is flagged.
MIN_CONTACT_POINTS = 6


def bounce(
    case: Case | None = None,
    drop: Drop | None = None,
    *,
    backend: str = "legendre",
    mesh: Any = None,
    stepping: Any = None,
    damping: Any = None,
) -> BounceReport:
    """Drop the lower ball on a rigid floor: contact time, rebound, flattening, energy, in SI.

    The ball starts undeformed, its lowest point touching the floor, its centre
    falling at ``|v0|``; its centre's height Z carries the translation (mass
    ``m2 = 4 pi R^2 rho``, gravity), its membrane the deformation measured from
    the centre, and the floor holds every point of the lower hemisphere at
    height >= 0 (docs/bounce.rst, eqs. (F1)-(F3)).  The run ends when the ball
    has left the floor and moves up, or at the window.

    Parameters
    ----------
    case : Case, optional
        The ball and its impact speed ``|v0|`` (default the basketball preset).
        Its excess pressure P (the preset's measured one when the case has
        none) sets the mass ``m2 = 2 pi R P / c^2`` and the gas.
    drop : Drop, optional
        Drop height, gas, floor restitution, Legendre degree N, membrane
        operator (:class:`~twoball.Drop`; default: the case's ``|v0|``, the
        adiabatic gas, e = 0, N = 192, the paper's operator).
    backend : {"legendre", "fem"}
        Legendre modes (floor points at the Gauss-Radau nodes) or axisymmetric
        finite elements (floor points at the nodes).
    mesh : MeshOptions or "axisym", optional
        Finite elements only: the line ``axisym`` (default 96 elements, P2).
    stepping : Stepping, optional
        ``dt`` [s] (default 0.005 / c) with ``scheme="moreau-jean"`` (the only
        scheme of the drop), and the window ``t_end`` [s] (default 10 pi / c).
    damping : ModalRatio or Rayleigh, optional
        The damping law (default the case's ratio D on every mode, eq. (3.14));
        ``Rayleigh()`` is fitted to D at sqrt(2) and sqrt(N (N + 1)), N the
        case's modes.

    Returns
    -------
    BounceReport
        ``contact_time_s``, ``v2_m_s``, ``e2``, ``phi_a_max_rad``,
        ``flattening_max_m``, ``t_max_compression_s``, ``floor_impulse_N_s``,
        ``events``, ``energy_J``, ``warnings``; ``as_dict()`` for JSON.

    Examples
    --------
    >>> import twoball
    >>> report = twoball.bounce(drop=twoball.Drop(modes=16))
    >>> round(report.contact_time_s * 1e3, 1), round(report.e2, 2)
    (14.6, 0.88)
    >>> weight = report.mass_kg * 9.81 * report.contact_time_s  # the impulse balance
    >>> change = report.mass_kg * (report.v2_m_s + 4.1)
    >>> abs(report.floor_impulse_N_s - change - weight) < 1e-12
    True
    """
    from twoball.modal.stepping import Stepping

    given = bundles(
        "twoball.bounce",
        mesh=mesh,
        stepping=stepping,
        damping=damping,
        takes=("mesh", "stepping", "damping"),
    )
    case = Case.preset("basketball") if case is None else case
    if not isinstance(case, Case):
        raise ParameterError("case", "a twoball.Case", type(case).__name__)
    drop = Drop() if drop is None else drop
    if not isinstance(drop, Drop):
        raise ParameterError("drop", "a twoball.Drop", type(drop).__name__)
    if backend not in BACKENDS:
        raise ParameterError("backend", "one of " + ", ".join(BACKENDS), backend)
    from twoball.modal.floor.model import resolve_drop

    model_in = resolve_drop(case, drop, given.damping)
    case, spectrum, law = model_in.case, model_in.spectrum, model_in.law
    warnings = list(model_in.warnings)
    step = given.stepping if given.stepping is not None else Stepping()
    dt, t_end = _times(case, step)
    ball, resolution = _ball(case, drop, backend, given.mesh, spectrum, law, dt, t_end)
    from twoball.modal.floor.drop import DropSettings, run_drop
    from twoball.modal.floor.system import floor_system

    system = floor_system(ball, case.gamma, drop.floor_restitution)
    settings = DropSettings(case.v0 / case.scalings.velocity, case.gamma, dt, t_end)
    result = run_drop(system, settings)
    warnings += _warnings(result, ball, dt)
    model = {
        "resolution": resolution,
        "floor_points": ball.points,
        "modes": ball.modes,
        **spectrum.as_dict(),
        "gas": model_in.gas,
        "damping": law.as_dict(),
        "floor_restitution": drop.floor_restitution,
        "scheme": "moreau-jean",
        "dt_s": dt / case.wave_speed,
        "t_end_s": t_end / case.wave_speed,
    }
    from dataclasses import replace

    from twoball._common.provenance import block
    from twoball.modal.floor.report import BounceReport

    report = BounceReport(
        case, drop, result, backend, model, model_in.pressure, tuple(warnings), model_in.notes
    )
    arguments = {"drop": drop.as_dict(), "backend": backend, **given.as_dict()}
    return replace(report, provenance=block(case, "twoball.bounce", arguments))


def _times(case: Case, step: Any) -> tuple[float, float]:
    """The time step and the window in units of 1/c, checked."""
    from twoball.modal.report import t_end_dimensionless

    step.refuse("for the drop (no eigen route: it steps in time)", "route")
    if step.scheme not in (None, "moreau-jean"):
        raise ParameterError("scheme", "moreau-jean for the drop (its only scheme)", step.scheme)
    t_end = DEFAULT_WINDOW if step.t_end is None else t_end_dimensionless(case, step.t_end)
    if step.dt is None:
        dt = DEFAULT_DT
    else:
        dt = step.dt * case.wave_speed
        high = min(MAX_DT, 0.1 * t_end)
        if not dt <= high:
            valid = f"a time step in (0, {high / case.wave_speed:.3g}] s for the drop"
            raise ParameterError("dt", valid, step.dt)
    if t_end <= 10.0 * dt:
        valid = f"a window longer than 10 time steps ({10.0 * dt / case.wave_speed:.3g} s)"
        raise ParameterError("t_end", valid, step.t_end)
    return dt, t_end


def _ball(
    case: Case,
    drop: Drop,
    backend: str,
    mesh: Any,
    spectrum: Any,
    law: Any,
    dt: float,
    t_end: float,
) -> tuple[Any, str]:
    """The ball in modal coordinates on the chosen backend (after the budget check)."""
    from twoball.modal.floor.cost import check_drop

    if backend == "legendre":
        if mesh is not None:
            shown = mesh.label if hasattr(mesh, "label") else mesh
            raise ParameterError("mesh", "left out with backend legendre (no mesh)", str(shown))
        from twoball.modal.floor.ball import legendre_ball

        modes = DEFAULT_MODES if drop.modes is None else drop.modes
        check_drop(modes, modes // 2, t_end, dt, **_asked(case, drop.modes, "modes", dt, t_end))
        return legendre_ball(modes, spectrum, law), f"legendre N = {modes}"
    if drop.modes is not None:
        raise ParameterError("modes", "left out with backend fem (the mesh sets it)", drop.modes)
    from twoball.fem_membrane.floor import axisym_ball
    from twoball.fem_membrane.options import MeshOptions

    options = (
        MeshOptions("axisym", elements=DEFAULT_ELEMENTS) if mesh is None else MeshOptions.of(mesh)
    )
    if options.kind != "axisym":
        raise ParameterError(
            "mesh", "axisym for the drop (the floor contact is axisymmetric)", options.label
        )
    dofs = options.elements * options.order
    asked = _asked(case, options.elements, "elements", dt, t_end)
    check_drop(dofs, dofs // 2, t_end, dt, dense=True, **asked)
    return axisym_ball(options.elements, options.order, spectrum, law), options.label


def _asked(case: Case, size: int | None, name: str, dt: float, t_end: float) -> dict[str, Any]:
    """The work as asked for, for a budget refusal: the time step first, then window and size."""
    times = {"dt": dt / case.wave_speed, "t_end": t_end / case.wave_speed}
    return times if size is None else {name: size, **times}


def _warnings(result: Any, ball: Any, dt: float) -> list[str]:
    """Accuracy warnings of a drop: not left, too few floor points, too coarse a step."""
    out = []
    if not result.left:
        out.append(
            "the ball has not left the floor within the window (contact time, v2 and e2 are "
            "not defined; raise t_end)"
        )
    inside = int((ball.phi >= result.phi_a_extreme).sum())
    if inside < MIN_CONTACT_POINTS:
        out.append(
            f"the largest contact holds {inside} floor points (< {MIN_CONTACT_POINTS}): refine "
            "(modes, or elements) for its angle and time"
        )
    if result.contact_time is not None and dt > result.contact_time / 200.0:
        out.append(
            f"the time step is {result.contact_time / dt:.0f}th of the contact time: "
            "take a smaller dt for 1e-3"
        )
    return out
