"""``twoball.bounce``: one drop of the lower ball on a rigid floor, in SI.

The command line (``twoball bounce``) calls exactly this function, so the same
inputs give bit-identical numbers in Python and in a shell.  The model (the
ball's centre, its membrane, the unilateral floor at every point of the lower
hemisphere, the contact core) is in :mod:`twoball.modal.floor` and
:mod:`twoball.fem_membrane.floor`; docs/bounce.rst explains it.
"""

from __future__ import annotations

import math
import os
from dataclasses import dataclass, field, replace
from pathlib import Path
from typing import TYPE_CHECKING, Any

from twoball._bundles import bundles
from twoball._common.errors import NumericalError, ParameterError
from twoball.modal.floor.options import DEFAULT_MODES, Drop
from twoball.modal.parameters import Case

if TYPE_CHECKING:
    from twoball.modal.floor.drop import DropResult

__all__ = [
    "BACKENDS",
    "BounceSweep",
    "DEFAULT_DT",
    "DEFAULT_ELEMENTS",
    "DEFAULT_WINDOW",
    "BounceReport",
    "drop_elements",
    "bounce",
    "bounce_sweep",
]

BACKENDS: tuple[str, ...] = ("legendre", "fem")
#: Time step in units of 1/c (the basketball: 15.6 microseconds).
DEFAULT_DT = 0.005
#: Window in units of 1/c: ten pressure x area contact times pi / c.
DEFAULT_WINDOW = 10.0 * math.pi
#: Axisymmetric elements of the finite-element drop at P2: node spacing pi / 192, as N = 192.
DEFAULT_ELEMENTS = 96
#: Nodes of the drop's default line at every order: ``NODE_INTERVALS / order`` elements.
NODE_INTERVALS = 2 * DEFAULT_ELEMENTS


def drop_elements(order: int) -> int:
    """Default axisymmetric elements of the drop at ``order``: the node spacing pi / 192.

    192 at P1, 96 at P2, 64 at P3, 48 at P4: the floor points (the nodes of the
    lower hemisphere) are the same 96 whatever the order, so the contact is
    resolved alike and an order given explicitly changes the polynomial, not
    the floor.
    """
    return -(-NODE_INTERVALS // int(order))


#: Largest time step in units of 1/c (a twentieth of the pressure x area contact time).
MAX_DT = math.pi / 20.0
#: Fewest floor points across the largest contact before the result is flagged.
MIN_CONTACT_POINTS = 6


def bounce(
    case: Case | None = None,
    drop: Drop | None = None,
    *,
    body: Any = None,
    pair: str | None = None,
    backend: str = "legendre",
    mesh: Any = None,
    stepping: Any = None,
    damping: Any = None,
) -> BounceReport:
    """Drop the lower ball on a rigid floor, alone or with a body on top, in SI.

    The ball starts undeformed, its lowest point touching the floor, its centre
    falling at ``|v0|``; its centre's height Z carries the translation (mass
    ``m2 = 4 pi R^2 rho``, gravity), its membrane the deformation measured from
    the centre, and the floor holds every point of the lower hemisphere at
    height >= 0 (docs/bounce.rst, eqs. (F1)-(F3)).  With an upper body (the
    whole two-ball bounce, docs/whole_bounce.rst, eqs. (B1)-(B2)) a rigid body of
    mass ``mu m2`` starts ``drop.gap`` above the ball's top, falling at the same
    speed, and touches the top over a cap of radius a with Newton's e12.  The
    run ends when everything has moved apart for good, or at the window.

    Parameters
    ----------
    case : Case, optional
        The ball and its impact speed ``|v0|`` (default the basketball preset,
        or the pair's lower ball).  Its excess pressure P (the preset's
        measured one when the case has none) sets the mass ``m2 = 2 pi R P /
        c^2`` and the gas.
    drop : Drop, optional
        Drop height, gas, floor restitution, Legendre degree N, membrane
        operator, gap Delta x [m] (:class:`~twoball.Drop`; default: the case's
        ``|v0|``, its gas or else the adiabatic gas, e = 0, N = 192, the
        pressurised operator, touching).
    body : Body, optional
        The upper body: ``mass_ratio`` mu in (0, 100], ``contact_radius`` a [m]
        (default R / 10), ``restitution`` e12 (Newton's, at its impacts).
    pair : str, optional
        A Table 1 pair (``"basketball-tennis"``, ...; :data:`twoball.modal.pairs.PAIRS`):
        the lower ball's preset, mu, e12 and a (:attr:`~twoball.modal.pairs.Pair.cap_radius`);
        refused with ``body``.
    backend : {"legendre", "fem"}
        Legendre modes (floor points at the Gauss-Radau nodes) or axisymmetric
        finite elements (floor points at the nodes).
    mesh : MeshOptions or "axisym", optional
        Finite elements only: the line ``axisym`` (default, or ``"axisym"``: 96
        P2 elements, node spacing pi / 192).  A :class:`MeshOptions` is used as
        given: give its ``elements`` (:func:`drop_elements` is the drop's
        default at each order, as the command line takes it; MeshOptions' own
        default of 400 line elements is the lift-off's).
    stepping : Stepping, optional
        ``dt`` [s] (default 0.005 / c) with ``scheme="moreau-jean"`` (the only
        scheme of the drop), and the window ``t_end`` [s] (default 10 pi / c,
        plus twice the gap's fall time ``Delta x / |v0|``).
    damping : ModalRatio or Rayleigh, optional
        The damping law (default the case's own: its ratio D on every mode, eq.
        (3.14), or its ``rayleigh``); ``Rayleigh()`` is fitted to D as
        :attr:`twoball.Case.damping_law` fits it; Rayleigh's alpha [1/s] and
        beta [s] are SI.

    Returns
    -------
    BounceReport
        ``contact_time_s``, ``v2_m_s``, ``e2``, ``phi_a_max_rad``,
        ``flattening_max_m``, ``t_max_compression_s``, ``floor_impulse_N_s``,
        ``events``, ``energy_J``, ``warnings``; with a body also ``v1_m_s``,
        ``v1_ratio``, ``v2_ratio``, ``t_liftoff_s``, ``body_left_first``,
        ``e12_effective`` and the lumped baselines; ``as_dict()`` for JSON.

    Examples
    --------
    >>> import twoball
    >>> report = twoball.bounce(drop=twoball.Drop(modes=16))
    >>> round(report.contact_time_s * 1e3, 1), round(report.e2, 2)
    (16.3, 0.87)
    >>> weight = report.mass_kg * 9.81 * report.contact_time_s  # the impulse balance
    >>> change = report.mass_kg * (report.v2_m_s + 4.1)
    >>> abs(report.floor_impulse_N_s - change - weight) < 1e-12
    True
    >>> whole = twoball.bounce(drop=twoball.Drop(modes=24), pair="basketball-tennis")
    >>> round(whole.v1_ratio, 1), whole.body_left_first
    (1.4, True)
    """
    from twoball.modal.stepping import Stepping

    if isinstance(mesh, str) and mesh == "axisym":  # the kind named: the drop's own default line
        from twoball.fem_membrane.options import MeshOptions

        mesh = MeshOptions("axisym", elements=DEFAULT_ELEMENTS)
    given = bundles(
        "twoball.bounce",
        mesh=mesh,
        stepping=stepping,
        body=body,
        damping=damping,
        takes=("mesh", "stepping", "body", "damping"),
    )
    from twoball.modal.floor.model import resolve_body, resolve_drop, resolve_pair

    if case is not None and not isinstance(case, Case):
        raise ParameterError("case", "a twoball.Case", type(case).__name__)
    case, body, chosen = resolve_pair(case, given.body, pair)
    case = Case.preset("basketball") if case is None else case
    drop = Drop() if drop is None else drop
    if not isinstance(drop, Drop):
        raise ParameterError("drop", "a twoball.Drop", type(drop).__name__)
    if backend not in BACKENDS:
        raise ParameterError("backend", "one of " + ", ".join(BACKENDS), backend)
    whole = resolve_body(case, body, chosen, drop)
    check_drop_case(case, drop)
    given_v0_note = case.v0_note
    model_in = resolve_drop(case, drop, given.damping)
    case, spectrum, law = model_in.case, model_in.spectrum, model_in.law
    from twoball.modal.guards import case_warnings

    # inputs far from any ball first (unit slips), then the model's and the accuracy's
    warnings = case_warnings(
        case, drop_height=drop.drop_height, gap=None if whole is None else drop.gap
    )
    warnings += model_in.warnings
    step = given.stepping if given.stepping is not None else Stepping()
    gap = drop.gap / case.radius
    dt, t_end = _times(case, step, gap)
    from twoball.modal.floor.cost import expected_span

    v0 = case.v0 / case.scalings.velocity
    work = {  # the likely cost (the step loop watches the deadline beyond it)
        "span": expected_span(whole is not None, gap, v0),
        "v0": v0,
        # a body that is not a Table 1 pair: the ball alone is dropped again (baselines)
        "runs": 2 if whole is not None and whole.pair is None else 1,
    }
    ball, resolution = _ball(case, drop, backend, given.mesh, spectrum, law, dt, t_end, work)
    from twoball.modal.floor.drop import DropSettings, run_drop
    from twoball.modal.floor.system import floor_system

    row = None if whole is None else _body_row(ball, whole, gap)
    system = floor_system(ball, case.gamma, drop.floor_restitution, row)
    settings = DropSettings(case.v0 / case.scalings.velocity, case.gamma, dt, t_end)
    result = run_drop(system, settings, label="the whole bounce" if row is not None else "the drop")
    warnings += _warnings(result, ball, dt)
    model = {
        "resolution": resolution,
        "floor_points": ball.points,
        "modes": ball.modes,
        **_spectrum_block(case, spectrum),
        "gas": model_in.gas,
        "damping": _damping_block(case, law),
        "floor_restitution": drop.floor_restitution,
        "scheme": "moreau-jean",
        "dt_s": dt / case.wave_speed,
        "t_end_s": t_end / case.wave_speed,
    }
    from twoball._common.provenance import block

    # how the case was read (a negative v0: the paper's sign), then the drop's own notes
    notes = tuple(n for n in (given_v0_note,) if n) + model_in.notes
    extra: dict[str, Any] = {}
    if whole is not None:
        notes += whole.notes
        warnings += _body_warnings(result, whole, ball)
        extra = {"whole": whole, "baselines": _baselines(case, drop, whole, model_in, result)}
    report = BounceReport(
        case, drop, result, backend, model, model_in.pressure, tuple(warnings), notes, **extra
    )
    arguments = {"drop": drop.as_dict(), "backend": backend, **given.as_dict()}
    if pair is not None:
        arguments["pair"] = pair
    return replace(report, provenance=block(case, "twoball.bounce", arguments))


def _spectrum_block(case: Case, spectrum: Any) -> dict[str, Any]:
    """The spectrum of the drop for the JSON: the bending by its own names, SI and ratio.

    ``bending_N_m`` is the flexural rigidity B [N m], ``bending_beta`` the
    dimensionless ratio ``beta = B / (T R^2)`` of the spectrum, ``omega0_squared``
    the breathing mode's ``omega_0^2`` in units of ``c^2`` and ``membrane`` the
    operator.
    """
    data = spectrum.as_dict()
    return {
        "membrane": data["membrane"],
        "bending_N_m": case.bending,
        "bending_beta": data["beta"],
        "omega0_squared": data["omega0_squared"],
    }


def _damping_block(case: Case, law: Any) -> dict[str, Any]:
    """The damping law of the drop for the JSON, in SI.

    The modal ratio: ``{"law": "modal", "ratio": D}``.  Rayleigh's law as
    :meth:`twoball.Case.rayleigh_dict` gives it: ``alpha_1_s`` [1/s] and
    ``beta_s`` [s] (the decay of a mode of angular frequency omega [rad/s] is
    ``alpha + beta omega^2``), the same law in units of c as ``alpha_c_units``
    (``alpha / c``) and ``beta_c_units`` (``beta c``), and ``fitted`` (True when
    fitted to D at :meth:`~twoball.modal.stiffness.Stiffness.fit_band`).
    """
    from twoball.modal.damping import Rayleigh

    if not isinstance(law, Rayleigh):
        return law.as_dict()
    si = case.rayleigh_dict()
    return {
        "law": law.name,
        "alpha_1_s": si["alpha_1_s"],
        "beta_s": si["beta_s"],
        "alpha_c_units": si["alpha"],
        "beta_c_units": si["beta"],
        "fitted": si["fitted"],
    }


def check_drop_case(case: Case, drop: Drop) -> None:
    """Refuse what the drop would not use: a given phi_a, a v0 set beside a drop height.

    The drop computes its contact angle (``phi_a_max_rad``), so a given phi_a would be
    ignored; a drop height sets ``|v0| = sqrt(2 g H)``, eq. (2.1), so a case whose v0 is
    not its preset's own (the user set one) would be overridden.
    """
    if case.phi_a_source == "given":
        valid = "left out for the drop (the contact angle is its output, phi_a_max_rad)"
        raise ParameterError("phi_a", valid, case.phi_a)
    if drop.drop_height is not None and v0_set(case):
        speed = case.v0 if case.v0_given is None else case.v0_given
        valid = (
            f"given alone, not with the case's own v0 = {speed:g} m/s (the height sets "
            "|v0| = sqrt(2 g H); build the case without a v0 of its own)"
        )
        raise ParameterError("drop_height", valid, drop.drop_height)


def check_point(
    case: Case, drop: Drop, body: Any, pair: str | None, *, stepping: Any = None
) -> None:
    """The checks :func:`bounce` makes before its work, for one point of a sweep."""
    from twoball.modal.floor.model import resolve_body, resolve_drop, resolve_pair
    from twoball.modal.stepping import Stepping

    case, body, chosen = resolve_pair(case, body, pair)
    resolve_body(case, body, chosen, drop)
    check_drop_case(case, drop)
    ball = resolve_drop(case, drop).case
    _times(ball, Stepping() if stepping is None else stepping, drop.gap / ball.radius)


def v0_set(case: Case) -> bool:
    """Whether ``case``'s v0 was set: not its preset's own measured speed (or the default)."""
    from twoball.modal.presets import MEASURED

    measured = MEASURED.get(case.preset_name or "")
    default = measured.v0 if measured is not None else Case.__dataclass_fields__["v0"].default
    return case.v0_given is not None or not math.isclose(case.v0, default, rel_tol=1e-12)


def _body_row(ball: Any, whole: Any, gap: float) -> Any:
    """The body's coordinate and row (B1)-(B2) on ``ball`` (dimensionless)."""
    from twoball.modal.floor.system import BodyOnTop

    cap = ball.cap_average(whole.cap_angle)
    b = whole.body
    return BodyOnTop(b.mass_ratio, cap, whole.cap_angle, b.restitution, gap)


def _baselines(case: Case, drop: Drop, whole: Any, model_in: Any, result: Any) -> dict[str, Any]:
    """The lumped models of §1(b) for the same drop (SI), with their inputs.

    A Table 1 pair takes its own inputs (Table 1's mu, e2, e12, the pressure
    rule); any other body takes the ball's e2 as this solver gives it for the
    ball alone (from the run itself when the ball left the floor before the body
    touched, else from a drop of the ball alone) and Newton's e12 given.
    """
    from twoball.modal.lumped.baselines import baselines, body_inputs, pair_inputs

    if whole.pair is not None:
        inputs = pair_inputs(whole.pair)
    else:
        e2, where = _e2_alone(result)
        mass = model_in.mass
        inputs = body_inputs(
            whole.body.mass_ratio * mass,
            mass,
            case.radius,
            model_in.pressure,
            whole.contact_radius,
            e2,
            whole.body.restitution,
            f"e2 = {e2:.4g} of this solver's ball alone ({where}), e12 = Newton's given",
        )
    return baselines(inputs, case.v0, drop.gap, case.g)


def _e2_alone(result: Any) -> tuple[float, str]:
    """The solver's e2 of the ball alone: the run's floor release if the body came later."""
    body = result.body
    if body is not None and body.sequence == "independent" and result.e2 is not None:
        return float(result.e2), "the floor release of this run, before the body touched"
    from twoball.modal.floor.drop import run_drop
    from twoball.modal.floor.system import floor_system

    system = result.system
    alone = floor_system(system.ball, system.gamma, float(system.problem.restitution[0]))
    # the ball alone is a reference: its own default window, whatever window the run had
    settings = replace(result.settings, t_end=max(result.settings.t_end, DEFAULT_WINDOW))
    run = run_drop(alone, settings, label="the ball alone (the baselines' e2)")
    if run.e2 is None:
        raise NumericalError("the ball alone did not leave the floor within the window")
    return float(run.e2), "a drop of the ball alone at the same resolution"


def check_field_targets(
    export: str | os.PathLike[str] | None,
    render: str | os.PathLike[str] | None,
    frames: int | None,
) -> tuple[Path | None, Path | None, int]:
    """The files of ``twoball bounce --export/--render`` checked before any work.

    Returns the export path (``.xdmf``, ``.pvd`` or one ``.vtu`` frame), the
    picture path (``.png``, ``.gif``, ``.mp4``) and the number of instants
    (default 40; 1 for a ``.vtu``).  Refuses a folder, a link, an existing
    side file twoball did not write, an unknown suffix, and ``frames`` without
    a file.
    """
    from twoball._common.staging import check_file
    from twoball._files import check_path_type
    from twoball.verify.output.fields import check_frames
    from twoball.verify.output.render import image_kind
    from twoball.verify.output.series import check_side_entries, series_format

    count = check_frames(frames) if frames is not None else 40
    target = picture = None
    if export is not None:
        check_path_type(export, "export")
        try:
            fmt = series_format(export, None)
        except ParameterError as error:  # named after the API's "out"
            raise ParameterError("export", error.valid, os.fspath(export)) from None
        target = check_file(export, "export")
        check_side_entries(target, fmt, "export")
        if fmt == "vtu":
            if frames not in (None, 1):
                raise ParameterError("frames", "1 for a single .vtu file", frames)
            count = 1
    if render is not None:
        check_path_type(render, "render")
        image_kind(render, "render")
        picture = check_file(render, "render")
    if frames is not None and target is None and picture is None:
        raise ParameterError("frames", "given with export or render", frames)
    return target, picture, count


def _times(case: Case, step: Any, gap: float = 0.0) -> tuple[float, float]:
    """The time step and the window in units of 1/c, checked (``gap``: Delta x / R)."""
    from twoball.modal.report import t_end_dimensionless

    step.refuse("for the drop (no eigen route: it steps in time)", "route")
    if step.scheme not in (None, "moreau-jean"):
        raise ParameterError("scheme", "moreau-jean for the drop (its only scheme)", step.scheme)
    # the body needs about Delta x / ((1 + e2) |v0|) to reach the ball, eq. (2.2)
    window = DEFAULT_WINDOW + 2.0 * gap / (case.v0 / case.scalings.velocity)
    t_end = window if step.t_end is None else t_end_dimensionless(case, step.t_end)
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
    work: dict[str, float],
) -> tuple[Any, str]:
    """The ball in modal coordinates on the chosen backend (after the budget check).

    ``work``: the expected span, the dimensionless |v0| and the number of drops
    (:func:`~twoball.modal.floor.cost.check_drop`).
    """
    from twoball.modal.floor.cost import check_drop

    if backend == "legendre":
        if mesh is not None:
            shown = mesh.label if hasattr(mesh, "label") else mesh
            raise ParameterError("mesh", "left out with backend legendre (no mesh)", str(shown))
        from twoball.modal.floor.ball import legendre_ball

        modes = DEFAULT_MODES if drop.modes is None else drop.modes
        asked = _asked(case, drop.modes, "modes", dt, t_end)
        check_drop(modes, modes // 2, t_end, dt, **work, **asked)
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
    check_drop(dofs, dofs // 2, t_end, dt, dense=True, **work, **asked)
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


def _body_warnings(result: Any, whole: Any, ball: Any) -> list[str]:
    """Warnings of the whole bounce: not apart within the window, a cap too small for the points."""
    out = []
    body = result.body
    if body is not None and not body.touched:
        out.append("the body never touched the ball within the window (raise t_end)")
    elif body is not None and not body.left:
        out.append(
            "the body and the ball have not moved apart for good within the window (v1, "
            "t_liftoff_s and e12_effective are not defined; raise t_end)"
        )
    spacing = (math.pi / 2.0) / ball.points
    if whole.cap_angle < 2.0 * spacing:
        out.append(
            f"the contact cap's half-angle {whole.cap_angle:.3g} rad spans fewer than two "
            f"spacings of the ball's points ({spacing:.3g} rad): refine (modes, or elements)"
        )
    return out


def _pressure_area(case: Case) -> dict[str, float]:
    from twoball.modal.floor.references import pressure_area

    return pressure_area(case.v0, case.radius, case.wave_speed)


@dataclass(frozen=True)
class BounceReport:
    """One drop of the lower ball on the floor, in SI (seconds, metres, m/s, N s, J).

    Attributes
    ----------
    case : Case
        The ball and its impact speed ``|v0|`` (``drop.drop_height`` already applied).
    drop : Drop
        The drop's options as given.
    result : DropResult
        The dimensionless drop (length R, time 1/c, mass m2).
    backend : str
        ``legendre`` or ``fem``.
    model : dict
        The model that ran: resolution, membrane operator, bending (``bending_N_m``
        [N m] and its ratio ``bending_beta = B / (T R^2)``), gas, omega_0^2 (units
        c^2), damping law (Rayleigh's ``alpha_1_s`` [1/s] and ``beta_s`` [s]),
        floor restitution, time step and window (SI).
    pressure : float
        Excess pressure P [Pa] behind the tension ``T = P R / 2`` and the mass.
    warnings : tuple of str
        What the reader must know to trust the numbers.
    notes : tuple of str
        Remarks (where a value came from).
    provenance : dict, optional
        Versions, command line or call, UTC time and case.
    whole : WholeBody, optional
        The upper body as resolved (:func:`twoball.modal.floor.model.resolve_body`):
        the whole two-ball bounce.
    baselines : dict, optional
        The lumped models of §1(b) for the same drop
        (:func:`twoball.modal.lumped.baselines.baselines`), with their inputs.

    Examples
    --------
    >>> import tempfile, pathlib, twoball
    >>> report = twoball.bounce(drop=twoball.Drop(modes=16))
    >>> report.left_floor, 0.8 < report.e2 < 1.0
    (True, True)
    >>> folder = pathlib.Path(tempfile.mkdtemp())
    >>> report.plot(folder / "drop.svg").name
    'drop.svg'
    >>> [p.name for p in report.export(folder / "drop.xdmf", frames=3)]
    ['drop.xdmf', 'drop.h5']
    """

    case: Case
    drop: Drop
    result: DropResult
    backend: str
    model: dict[str, Any]
    pressure: float
    warnings: tuple[str, ...] = ()
    notes: tuple[str, ...] = ()
    provenance: dict[str, Any] | None = field(default=None, compare=False, repr=False)
    whole: Any = field(default=None, repr=False)
    baselines: dict[str, Any] | None = field(default=None, repr=False)

    def light(self) -> BounceReport:
        """The report without the run's history (every number kept): a sweep's point."""
        return replace(self, result=self.result.light())

    # --- units -------------------------------------------------------------------------
    @property
    def mass_kg(self) -> float:
        """The ball's mass ``m2 = 2 pi R P / c^2`` [kg]."""
        return 2.0 * math.pi * self.case.radius * self.pressure / self.case.wave_speed**2

    def _time(self, value: float | None) -> float | None:
        return None if value is None else value / self.case.wave_speed

    def _speed(self, value: float | None) -> float | None:
        return None if value is None else value * self.case.scalings.velocity

    @property
    def _energy_unit(self) -> float:
        return self.mass_kg * self.case.scalings.velocity**2

    # --- the measured quantities ------------------------------------------------------
    @property
    def left_floor(self) -> bool:
        """The ball left the floor and moves up within the window."""
        return self.result.left

    @property
    def contact_time_s(self) -> float | None:
        """First touch to leaving the floor [s] (None if it has not left)."""
        return self._time(self.result.contact_time)

    @property
    def v2_m_s(self) -> float | None:
        """The centre's velocity on leaving [m/s], upward positive."""
        return self._speed(self.result.v2)

    @property
    def e2(self) -> float | None:
        """``v2 / |v0|``, the coefficient of restitution of the drop."""
        return self.result.e2

    @property
    def phi_a_max_rad(self) -> float:
        """Contact angle of the largest contact [rad] (the contact is ``phi >= phi_a``)."""
        return self.result.phi_a_max

    @property
    def flattening_max_m(self) -> float:
        """Largest drop of the centre below R while in contact [m]."""
        return self.result.flattening_max * self.case.radius

    @property
    def t_max_compression_s(self) -> float:
        """When the centre is lowest [s] after the first touch."""
        return self.result.t_max_compression / self.case.wave_speed

    @property
    def floor_impulse_N_s(self) -> float:
        """Total impulse of the floor on the ball [N s]."""
        return self.result.impulse * self.mass_kg * self.case.scalings.velocity

    @property
    def energy_J(self) -> dict[str, float]:
        """The energy books [J]; see :meth:`as_dict`.

        With a body: ``initial_kinetic`` is both bodies', ``initial_kinetic_body``
        the body's part, ``final_body_kinetic`` and ``body_gravity_gained`` its
        books at the end, ``body_share_of_initial`` its final kinetic energy as a
        fraction of the initial total (dimensionless).
        """
        unit = self._energy_unit
        e = self.result.energy
        final = {
            key: e[key] * unit
            for key in ("rigid_kinetic", "membrane_kinetic", "membrane_elastic", "gas")
        }
        books = {
            "initial_kinetic": 0.5 * self.result.settings.v0**2 * unit,
            "final_rigid_kinetic": final["rigid_kinetic"],
            "final_membrane_kinetic": final["membrane_kinetic"],
            "final_membrane_elastic": final["membrane_elastic"],
            "final_gas": final["gas"],
            "gravity_gained": (e["gravity"] - self.result.settings.gamma) * unit,
            "dissipated_damping": -e["damped"] * unit,
            "lost_impacts": -e["impacts"] * unit,
            "held_arrivals": -e["contact"] * unit,
            "vibration_after_leaving": e["vibration"] * unit,
            "balance_error": e["balance"] * unit,
        }
        if self.result.body is not None:
            start = e["body_kinetic_start"]
            books["initial_kinetic"] += start * unit
            books["initial_kinetic_body"] = start * unit
            books["final_body_kinetic"] = e["body_kinetic"] * unit
            books["body_gravity_gained"] = (e["body_gravity"] - e["body_gravity_start"]) * unit
            total = 0.5 * self.result.settings.v0**2 + start
            books["body_share_of_initial"] = e["body_kinetic"] / total
        return books

    @property
    def events(self) -> list[dict[str, Any]]:
        """Every touch and separation: contact, kind, time [s], velocities [m/s].

        ``velocity_m_s`` is the ball's centre; with a body, ``body_velocity_m_s``
        is the body's and the events of both contacts are listed in time order.
        """
        speed = self.case.scalings.velocity
        if self.result.body is not None:
            return [
                {
                    "contact": ev.contact,
                    "kind": ev.kind,
                    "t_s": ev.t / self.case.wave_speed,
                    "velocity_m_s": ev.ball_velocity * speed,
                    "body_velocity_m_s": ev.body_velocity * speed,
                }
                for ev in self.result.body.events
            ]
        return [
            {
                "contact": "floor",
                "kind": ev.kind,
                "t_s": ev.t / self.case.wave_speed,
                "velocity_m_s": ev.velocity * speed,
                "floor_points": ev.points,
            }
            for ev in self.result.events
        ]

    # --- the whole bounce (a body on the ball) ----------------------------------------
    @property
    def has_body(self) -> bool:
        """True for the whole two-ball bounce (an upper body on the ball)."""
        return self.result.body is not None

    def _body_value(self, name: str) -> Any:
        body = self.result.body
        return None if body is None else getattr(body, name)

    @property
    def v1_m_s(self) -> float | None:
        """The body's velocity at its last separation from the ball [m/s] (None: no body)."""
        return self._speed(self._body_value("v1"))

    @property
    def v1_ratio(self) -> float | None:
        """``v1 / |v0|`` (Table 1's upper-body column)."""
        v1 = self.v1_m_s
        return None if v1 is None else v1 / self.case.v0

    @property
    def v2_ratio(self) -> float | None:
        """``v2 / |v0|``: the centre at the ball's last release (floor or body), over ``|v0|``.

        Without a body the drop's ``e2``.
        """
        if self.result.body is None:
            return self.e2
        v2 = self._body_value("v2")
        return None if v2 is None else v2 / self.result.settings.v0

    @property
    def t_liftoff_s(self) -> float | None:
        """The body's last separation after the first floor touch [s]."""
        return self._time(self._body_value("t_liftoff"))

    @property
    def t_liftoff_from_max_compression_s(self) -> float | None:
        """``t_l`` of Fig. 9: the lift-off after the ball's maximal compression [s]."""
        t = self.t_liftoff_s
        return None if t is None else t - self.t_max_compression_s

    @property
    def body_left_first(self) -> bool | None:
        """True when the body left before the ball left the floor."""
        return self._body_value("body_left_first")

    @property
    def e12_effective(self) -> float | None:
        """Eq. (2.4) between the centres, before the body's first touch and after its last
        separation (None when the collisions overlap)."""
        return self._body_value("e12_effective")

    @property
    def icm_solver(self) -> dict[str, Any] | None:
        """The ICM (2.5) with this run's own e2 and e12_effective (None when they overlap).

        With the independent sequence the ball's floor bounce is the ball alone, so
        ``e2`` is the solver's e2 of the ball alone; eqs. (2.1)-(2.5) at the
        run's ``|v0|``, Delta x and g.
        """
        e12 = self.e12_effective
        if e12 is None or self.e2 is None or self.whole is None:
            return None
        from twoball.modal.icm.impacts import post_impact_velocities

        v0, g, gap = self.case.v0, self.case.g, self.drop.gap
        e2 = min(max(self.e2, 0.0), 1.0)
        # eqs. (2.1), (2.2): the floor impact at t0, the second after dt; gravity on both
        delay = gap / ((1.0 + e2) * v0)
        u1, u2 = -v0 - g * delay, e2 * v0 - g * delay
        try:
            v1, v2 = post_impact_velocities(u1, u2, self.whole.body.mass_ratio, min(e12, 1.0))
        except ParameterError:
            return None
        return {
            "e2": self.e2,
            "e12": e12,
            "v1_m_s": v1,
            "v2_m_s": v2,
            "v1_ratio": v1 / v0,
            "v2_ratio": v2 / v0,
            "source": "eqs. (2.1)-(2.5) with this run's e2 (the ball alone: it left the floor "
            "before the body touched) and e12_effective",
        }

    def _body_block(self) -> dict[str, Any]:
        """The JSON keys of the whole bounce (SI)."""
        whole, body = self.whole, self.result.body
        speed = self.case.scalings.velocity
        t_floor = body.t_floor_release
        before = None if body.before is None else [x * speed for x in body.before]
        after = None if body.after is None else [x * speed for x in body.after]
        return {
            "v1_m_s": self.v1_m_s,
            "v1_ratio": self.v1_ratio,
            "v2_ratio": self.v2_ratio,
            "t_liftoff_s": self.t_liftoff_s,
            "t_liftoff_from_max_compression_s": self.t_liftoff_from_max_compression_s,
            "t_floor_release_s": self._time(t_floor),
            "body_left_first": self.body_left_first,
            "sequence": body.sequence,
            "e12_effective": self.e12_effective,
            "e12_velocities_m_s": {"before_u1_u2": before, "after_v1_v2": after},
            "body_contacts": body.contacts,
            "body_impulse_N_s": body.impulse * self.mass_kg * speed,
            "body": {
                "mass_ratio": whole.body.mass_ratio,
                "mass_kg": whole.body.mass_ratio * self.mass_kg,
                "contact_radius_m": whole.contact_radius,
                "cap_angle_rad": whole.cap_angle,
                "restitution": whole.body.restitution,
                "gap_m": self.drop.gap,
                "pair": None if whole.pair is None else whole.pair.name,
            },
            "icm_solver": self.icm_solver,
            "baselines": self.baselines,
        }

    def comparisons(self) -> dict[str, Any]:
        """The drop beside eq. (3.7), pressure x area and the measurements (SI)."""
        from twoball.modal.floor.references import MEASURED_COMPRESSION, TABLE1_E2
        from twoball.modal.initial import phi_a_from_v0
        from twoball.modal.presets import MEASURED

        case = self.case
        try:
            eq37 = phi_a_from_v0(case.v0, case.radius, case.wave_speed)
        except ParameterError:  # beyond the largest speed eq. (3.7) can store
            eq37 = None
        out: dict[str, Any] = {
            "phi_a_eq_3_7_rad": eq37,
            "pressure_area": _pressure_area(case),
            "measured_compression_m": MEASURED_COMPRESSION * case.v0,
        }
        measured = MEASURED.get(case.preset_name or "")
        if measured is not None and measured.phi_a is not None and case.at_measured_point:
            out["table2_phi_a_rad"] = measured.phi_a
        if case.preset_name in TABLE1_E2:
            out["table1_e2"] = list(TABLE1_E2[case.preset_name])
        return out

    def as_dict(self) -> dict[str, Any]:
        """JSON-ready dictionary (SI; keys end in their unit)."""
        r = self.result
        data: dict[str, Any] = {
            "left_floor": r.left,
            "stop": r.stop,
            "contact_time_s": self.contact_time_s,
            "v2_m_s": self.v2_m_s,
            "e2": self.e2,
            "phi_a_max_rad": r.phi_a_max,
            "phi_a_extreme_rad": r.phi_a_extreme,
            "t_phi_a_max_s": r.t_phi_a_max / self.case.wave_speed,
            "flattening_max_m": self.flattening_max_m,
            "t_max_compression_s": self.t_max_compression_s,
            "floor_impulse_N_s": self.floor_impulse_N_s,
            "impulse_balance": None if math.isnan(r.impulse_balance) else r.impulse_balance,
            "events": self.events,
            "point_events": r.point_events,
            "energy_J": self.energy_J,
            "v0_m_s": self.case.v0,
            "drop_height_m": self.drop.drop_height,
            "mass_kg": self.mass_kg,
            "pressure_Pa": self.pressure,
            "backend": self.backend,
            "model": dict(self.model),
            "comparisons": self.comparisons(),
            "steps": r.steps,
            "wall_s": r.wall_s,
            "notes": list(self.notes),
            "warnings": list(self.warnings),
        }
        if self.result.body is not None:
            data |= self._body_block()
            data["v2_m_s"] = self._speed(self.result.body.v2)
            data["v2_floor_release_m_s"] = self.v2_m_s
        if self.provenance is not None:
            data["provenance"] = self.provenance
        return data

    # --- files ------------------------------------------------------------------------
    def plot(self, out: str | os.PathLike[str], *, dpi: float | None = None) -> Path:
        """Figure of the drop: floor force, contact angle, centre height, energy books.

        With a body (the whole bounce): heights, both contact forces, both
        velocities (with the ICM's of :attr:`icm_solver`), the energy books, every
        event marked.  ``out``'s suffix chooses the format (``.png``, ``.pdf``, ...).
        """
        from twoball.verify.output.figures import save_figure
        from twoball.verify.output.figures.bounce import drop_figure, whole_figure

        self._require_history()
        title = f"{self.backend}, {self.model['membrane']} membrane"
        if self.has_body:
            icm = self.icm_solver
            lines = None if icm is None else (icm["v1_m_s"], icm["v2_m_s"])
            figure = whole_figure(self.result, self.case, self.mass_kg, title, lines)
        else:
            figure = drop_figure(self.result, self.case, self.mass_kg, title)
        return save_figure(figure, out, "plot", dpi)

    def _require_history(self) -> None:
        if not self.result.has_history:
            raise NumericalError(
                "a light report keeps no history (a sweep point): run twoball.bounce for its "
                "figure, fields and pictures"
            )

    def _mesh_and_times(self, mesh: Any, frames: int) -> tuple[Any, Any]:
        from twoball.fem_membrane.mesh import sphere_mesh
        from twoball.fem_membrane.options import MeshOptions
        from twoball.verify.output.drop_fields import drop_frames
        from twoball.verify.output.fields import check_frames

        self._require_history()
        spec = MeshOptions.of(mesh).require(("sphere",), files=False)
        if spec.order > 2:
            raise ParameterError("order", "1 or 2 for field files and pictures", spec.order)
        count = check_frames(frames)
        return sphere_mesh(spec.level, spec.order, None), drop_frames(self.result, count, self.case)

    def export(
        self,
        out: str | os.PathLike[str],
        *,
        mesh: Any = None,
        frames: int = 40,
        format: str | None = None,
    ) -> list[Path]:
        """Write the drop on a sphere mesh: XDMF (+ HDF5), PVD (+ VTUs) or one VTU frame.

        Point data ``u_m``, ``displacement_m`` (the centre's fall and the
        membrane's flattening: warp by it), ``height_m``; frame data ``Z_m``,
        ``floor_force_N`` (with a body ``body_height_m``, ``body_gap_m``,
        ``body_force_N``); field data the results and the events of both
        contacts (the text ``contact_events``, JSON of :attr:`events`, and their
        counts); every field in SI (:mod:`twoball.verify.output.drop_fields`).
        ``mesh``: a sphere (default the level-3 P2 icosphere); ``frames``
        instants from the first touch to the end of the run.
        """
        import json

        from twoball.verify.output.drop_fields import drop_series
        from twoball.verify.output.series import write_series

        sphere, times = self._mesh_and_times(mesh, frames)
        series = drop_series(
            self.result, self.case, sphere, times, self.mass_kg, self._text, self.events
        )
        if self.provenance is not None:
            series = replace(
                series, text={**series.text, "provenance": json.dumps(self.provenance)}
            )
        return write_series(out, series, format)

    def render(
        self,
        out: str | os.PathLike[str],
        *,
        mesh: Any = None,
        frames: int = 40,
        warp: float | None = None,
        size: Any = None,
        fps: float = 20.0,
    ) -> Path:
        """Picture (``.png``: the largest compression) or animation (``.gif``, ``.mp4``).

        The membrane's displacement from the centre, coloured, in the centre's
        frame: the bottom flattens on the floor and springs back; the caption
        gives the time, the floor force, the centre's height above R and
        whether the ball is on the floor.
        """
        from twoball.verify.output.drop_fields import drop_scene
        from twoball.verify.output.render import DEFAULT_SIZE, render_scene

        sphere, times = self._mesh_and_times(mesh, frames)
        if Path(out).suffix.lower() == ".png":  # one picture: the largest compression
            times = times[:1] * 0.0 + self.t_max_compression_s
        scene = drop_scene(self.result, self.case, sphere, times, self.mass_kg, self._text)
        return render_scene(out, scene, warp=warp, size=size or DEFAULT_SIZE, fps=fps)

    @property
    def _text(self) -> str:
        c = self.case
        return (
            f"twoball bounce, {self.model['resolution']}: R = {c.radius:g} m, "
            f"c = {c.wave_speed:g} 1/s, v0 = {c.v0:g} m/s, {self.model['membrane']} membrane, "
            f"{self.model['gas']} gas"
        )


@dataclass(frozen=True)
class BounceSweep:
    """Drops over one parameter (``v0``, ``drop-height``, ``gap`` or ``mass-ratio``), in SI.

    Attributes
    ----------
    parameter : str
        ``v0``, ``drop-height``, ``gap`` or ``mass-ratio``.
    values : tuple of float
        Its values (m/s, m, m or none).
    reports : list of BounceReport or None
        One run per value without its history (:meth:`BounceReport.light`;
        None where it failed; ``errors`` says why).
    errors : list of str or None
    provenance : dict

    Examples
    --------
    >>> import twoball
    >>> result = twoball.sweep({"v0": [2.0, 4.1]}, drop=twoball.Drop(modes=32))
    >>> [round(r.flattening_max_m * 1e3, 1) for r in result.reports]
    [12.0, 20.5]
    """

    parameter: str
    values: tuple[float, ...]
    reports: list[Any]
    errors: list[str | None]
    provenance: dict[str, Any] | None = field(default=None, compare=False, repr=False)

    def as_dict(self) -> dict[str, Any]:
        """JSON-ready: the parameter and one drop per value (SI), with the provenance."""
        points = []
        for value, report, error in zip(self.values, self.reports, self.errors, strict=True):
            data = {"parameter": self.parameter, "value": value, "error": error}
            if report is not None:
                data |= {k: v for k, v in report.as_dict().items() if k != "provenance"}
            points.append(data)
        return {"parameter": self.parameter, "points": points, "provenance": self.provenance}

    def plot(self, out: str | os.PathLike[str], *, dpi: float | None = None) -> Path:
        """phi_a,max and the flattening against |v0|, with eq. (3.7), pressure x area and the
        measurements (Table 2; 3.07 mm per m/s); for a gap or mass-ratio sweep, v1/|v0|,
        v2/|v0| and the lift-off time against it with the ICM and the lumped baselines."""
        from twoball.verify.output.figures import save_figure
        from twoball.verify.output.figures.bounce import speeds_figure

        done = [r for r in self.reports if r is not None]
        if not done:
            raise ParameterError("values", "at least one drop that ran, to plot", None)
        if self.parameter in ("gap", "mass-ratio"):
            from twoball.verify.output.figures.bounce import gap_figure

            pairs = [(v, r) for v, r in zip(self.values, self.reports, strict=True) if r]
            return save_figure(gap_figure(pairs, self.parameter), out, "plot", dpi)
        rows = [(r.case.v0, r.phi_a_max_rad, r.flattening_max_m) for r in done]
        return save_figure(speeds_figure(rows, done[0].case), out, "plot", dpi)


def bounce_sweep(
    values: Any,
    case: Case | None,
    drop: Drop,
    *,
    body: Any = None,
    pair: str | None = None,
    stepping: Any = None,
    damping: Any = None,
    workers: int | None = None,
    scheduler: str | None = None,
    progress: Any = None,
) -> BounceSweep:
    """Drops over ``values`` (``{"v0": [...]}``, ``drop_height``, ``gap`` or ``mass_ratio``), SI.

    The points run in this process (``workers`` 1 or None), on a local process
    pool or on a Dask scheduler (:class:`~twoball.verify.sweeps.parallel.Runner`):
    the numbers do not depend on where.  Each point is kept without its history
    (:meth:`BounceReport.light`).
    """
    from twoball._common.provenance import block
    from twoball.modal.floor.model import resolve_pair
    from twoball.verify.sweeps.bounce import bounce_points, bounce_values
    from twoball.verify.sweeps.parallel import Runner, check_workers

    if case is not None and not isinstance(case, Case):
        raise ParameterError("case", "a twoball.Case", type(case).__name__)
    if not isinstance(drop, Drop):
        raise ParameterError("drop", "a twoball.Drop", type(drop).__name__)
    if not hasattr(values, "items") or not values:
        raise ParameterError(
            "values", "a mapping of v0, drop_height, gap or mass_ratio to values", values
        )
    parameter, array = bounce_values(list(values), list(values.values()))
    if pair is not None and parameter == "mass-ratio":
        raise ParameterError("pair", "left out when the mass ratio is swept (it fixes mu)", pair)
    if parameter == "gap" and body is None and pair is None:
        raise ParameterError("gap", "swept only with an upper body (body or pair)", None)
    if scheduler and workers is not None:
        raise ParameterError("workers", "left out with scheduler (the cluster decides)", workers)
    workers = 1 if workers is None and not scheduler else workers
    if workers is not None:
        check_workers(workers)
    base, _, _ = resolve_pair(case, None, pair) if pair is not None else (case, None, None)
    base = Case.preset("basketball") if base is None else base
    if parameter == "drop-height" and v0_set(base):
        speed = base.v0 if base.v0_given is None else base.v0_given
        valid = "left out when drop_height is swept (each height sets |v0| = sqrt(2 g H))"
        raise ParameterError("v0", valid, speed)
    check_drop_case(base, drop)  # a given phi_a: a v0 sweep would drop it unsaid
    points = [(*point, pair) for point in bounce_points(base, drop, parameter, array, body)]
    for point in points:  # every point's values refused here, before the first run
        check_point(*point, stepping=stepping)
    task = BounceTask(stepping=stepping, damping=damping)
    reports: list[Any] = []
    errors: list[str | None] = []
    with Runner(workers=workers, scheduler=scheduler) as runner:
        outcomes = runner.map(task, points, progress=progress, min_parallel=2, chunk=1)
        where = runner.describe()
    for outcome in outcomes:
        reports.append(outcome.value if outcome.ok else None)
        errors.append(None if outcome.ok else _short(outcome.error))
    arguments: dict[str, Any] = {"values": {parameter: array}, "drop": drop.as_dict()}
    if body is not None:
        arguments["body"] = body.as_dict()
    if pair is not None:
        arguments["pair"] = pair
    if stepping is not None:
        arguments["stepping"] = stepping.as_dict()
    if damping is not None:
        arguments["damping"] = damping.as_dict()
    arguments["runner"] = where
    provenance = block(base, "twoball.sweep", arguments)
    return BounceSweep(parameter, tuple(float(v) for v in array), reports, errors, provenance)


def _short(error: str | None) -> str | None:
    """``ParameterError: gap must be ...`` -> the message (the type only for other errors)."""
    if error is None:
        return None
    kind, _, text = error.partition(": ")
    return text if kind in ("ParameterError", "NumericalError") else error


@dataclass(frozen=True)
class BounceTask:
    """One run of :func:`bounce`, picklable for the process pool or Dask.

    Called with ``(case, drop, body, pair)``, it runs :func:`bounce` with the
    task's backend, mesh, stepping and damping and returns the report without
    its history (:meth:`BounceReport.light`, about 0.1 MB) or provenance.
    """

    backend: str = "legendre"
    mesh: Any = None
    stepping: Any = None
    damping: Any = None

    def __call__(self, item: tuple[Any, Any, Any, Any]) -> BounceReport:
        case, drop, body, pair = item
        report = bounce(
            case,
            drop,
            body=body,
            pair=pair,
            backend=self.backend,
            mesh=self.mesh,
            stepping=self.stepping,
            damping=self.damping,
        )
        return replace(report.light(), provenance=None)
