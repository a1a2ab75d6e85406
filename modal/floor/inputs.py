"""The drop's inputs resolved: from a case, a drop and a body in SI to what the run needs.

The one place where the drop reads the ball's membrane operator, its gas and
its damping law (:func:`resolve_drop`), the upper body and a Table 1 pair
(:func:`resolve_pair`, :func:`resolve_body`), the time step and the window
(:func:`drop_times`), and refuses what the drop would not use
(:func:`check_drop_case`).  The run (:mod:`twoball.modal.floor.bounce`) and the
studies (:mod:`twoball.verify.studies.floor`) both start here.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace
from typing import Any

from twoball._common.errors import ParameterError
from twoball.modal.damping import ModalRatio, Rayleigh
from twoball.modal.floor.options import Drop
from twoball.modal.membrane import Membrane
from twoball.modal.parameters import Case
from twoball.modal.stiffness import Stiffness

__all__ = [
    "DEFAULT_DT",
    "DEFAULT_WINDOW",
    "MAX_DT",
    "DropModel",
    "WholeBody",
    "check_centre_height",
    "check_drop_case",
    "check_drop_height",
    "drop_times",
    "resolve_body",
    "resolve_drop",
    "resolve_pair",
    "v0_set",
]

#: Time step of the drop in units of 1/c (the basketball: 15.6 microseconds).
DEFAULT_DT = 0.005
#: Window of the drop in units of 1/c: ten pressure x area contact times pi / c.
DEFAULT_WINDOW = 10.0 * math.pi
#: Largest time step in units of 1/c (a twentieth of the pressure x area contact time).
MAX_DT = math.pi / 20.0


@dataclass(frozen=True)
class DropModel:
    """A drop ready for the solvers.

    Attributes
    ----------
    case : Case
        The ball as it drops (SI): the impact speed ``|v0|``, the excess
        pressure, the gas and the membrane operator in use.
    drop : Drop
        The options as given.
    pressure : float or None
        Excess pressure P [Pa] (the case's, else its preset's measured one; None
        for a ball that is not pressurised).
    gas : str
        The gas law used.
    spectrum : Stiffness
        Membrane operator, bending and gas (dimensionless): ``case.stiffness``.
    law : ModalRatio or Rayleigh
        The damping law in units of c: ``case.damping_law`` (a fitted Rayleigh
        law fitted at :meth:`~twoball.modal.stiffness.Stiffness.fit_band`).
    notes, warnings : tuple of str
    """

    case: Case
    drop: Drop
    pressure: float | None
    gas: str
    spectrum: Stiffness
    law: ModalRatio | Rayleigh
    notes: tuple[str, ...] = ()
    warnings: tuple[str, ...] = ()

    @property
    def mass(self) -> float:
        """The membrane's mass ``m2 = 2 pi R P / c^2`` [kg] (``T = P R / 2 = rho c^2 R^2``)."""
        from twoball.modal.scalings import membrane_mass

        return membrane_mass(self.case.radius, self.pressure, self.case.wave_speed)

    @property
    def v0(self) -> float:
        """Impact speed ``|v0| / (R c)`` (dimensionless)."""
        return self.case.v0 / self.case.scalings.velocity

    @property
    def gamma(self) -> float:
        """``g / (R c^2)``."""
        return self.case.gamma


def resolve_drop(
    case: Case,
    drop: Drop,
    damping: Any = None,
    *,
    membrane_ball: bool = True,
    pressurised: bool = True,
) -> DropModel:
    """The drop of ``case`` with ``drop``'s options and the damping law ``damping``.

    The case as it drops: the drop's impact speed, the excess pressure (the
    case's, else its preset's measured one), the gas (the drop's, else the
    case's, else adiabatic), the membrane operator (the drop's, else the
    pressurised one: with the centre free, degree 1 must be a free translation)
    and the damping law (``damping``, else the case's).  Its
    :attr:`~twoball.Case.stiffness` and :attr:`~twoball.Case.damping_law` are
    the spectrum and the law the solvers take.  ``membrane_ball=False`` (a shell,
    a solid: their own walls hold the breathing mode) leaves the membrane
    operator out of it: the case keeps the paper's, and a drop without gas runs.
    ``pressurised=False`` (a solid ball: no excess pressure, no enclosed gas)
    needs no pressure and takes no gas (``pressure`` None, ``gas`` "none").

    Raises
    ------
    ParameterError
        A drop height below the case's radius R or whose speed the case refuses,
        no pressure known, the pressurised membrane without gas.
    """
    notes: list[str] = []
    warnings: list[str] = []
    case = _impact(case, drop)
    if drop.centre_height is not None:
        notes.append(
            f"centre height x2 = {drop.centre_height:g} m: the lowest point falls x2 - R = "
            f"{drop.fall(case.radius):.4g} m, |v0| = sqrt(2 g (x2 - R)) = {case.v0:.4g} m/s"
        )
    if pressurised:
        pressure = _pressure(case, notes)
        gas = drop.gas or (case.gas if case.gas != "none" else "adiabatic")
    else:
        if drop.gas is not None:
            valid = "left out with a ball without enclosed gas (a solid ball)"
            raise ParameterError("gas", valid, drop.gas)
        pressure, gas = case.pressure, "none"
    # a free centre needs the operator whose degree 1 is a free translation
    membrane = Membrane("pressurised") if drop.membrane is None else Membrane.of(drop.membrane)
    if not membrane_ball:
        if drop.membrane is not None:
            valid = "left out with a ball that is not a membrane (no membrane operator)"
            raise ParameterError("membrane", valid, drop.membrane.kind)
        membrane = Membrane("paper")  # not the ball's physics: no operator to hold it
    law = _law(damping)
    ball = replace(
        case,
        pressure=pressure,
        gas=gas,
        membrane=membrane,
        rayleigh=law if isinstance(law, Rayleigh) else case.rayleigh,
        damping=law.ratio if isinstance(law, ModalRatio) else case.damping,
        phi_a=None,
        phi_a_source=None,
    )
    if gas == "none" and membrane_ball:
        warnings.append(
            "no gas on the paper's membrane: the breathing mode has omega_0 = 0, so the "
            "floor's push shrinks the mean radius for good and the ball hardly bounces "
            "(use the gas: isothermal or adiabatic)"
        )
    return DropModel(
        ball,
        drop,
        pressure,
        gas,
        ball.stiffness,
        ball.damping_law,
        tuple(notes),
        tuple(warnings),
    )


def check_drop_height(case: Case, height: float) -> float:
    """A drop height H [m] for ``case``'s ball: at least its radius R, else refused.

    H is the height of the lowest point above the floor at release (as in
    ``twoball icm``).  A height below one radius is refused: it is easily the
    centre's height or a slip of units, and an impact slower than ``sqrt(2 g R)``
    is given by its speed (the case's ``v0``; ``--v0`` on the command line).

    Raises
    ------
    ParameterError
        Naming ``drop_height`` (``--drop-height`` on the command line), with the
        valid range ``>= R`` of the case.
    """
    if not height >= case.radius:
        valid = (
            f"a height >= R = {case.radius:g} m of the lowest point above the floor (a slower "
            "impact is given by its speed: the case's v0, --v0 on the command line)"
        )
        raise ParameterError("drop_height", valid, height)
    return height


def check_centre_height(case: Case, centre: float) -> float:
    """The lowest point's fall ``x2 - R`` [m] of a centre height x2 [m]: at least R, else refused.

    The paper's x2 (§2) is the centre's height; the drop's ``H`` is the lowest
    point's, so ``H = x2 - R``, held to ``H >= R`` as :func:`check_drop_height`
    holds it (a slower impact is given by its speed).

    Raises
    ------
    ParameterError
        Naming ``centre_height`` (``--centre-height``), with the valid range ``>= 2 R``.
    """
    fall = centre - case.radius
    if not fall >= case.radius:
        valid = (
            f"a centre height >= 2 R = {2.0 * case.radius:g} m (the lowest point at least R "
            "above the floor; a slower impact is given by its speed: the case's v0, --v0 on "
            "the command line)"
        )
        raise ParameterError("centre_height", valid, centre)
    return fall


def _impact(case: Case, drop: Drop) -> Case:
    """The case at the drop's impact speed ``sqrt(2 g H)``, eq. (2.1), if a height is given.

    H is the lowest point's fall: ``drop_height``, or ``centre_height - R``.
    """
    if drop.centre_height is not None:
        name, given = "centre_height", drop.centre_height
        height = check_centre_height(case, drop.centre_height)
    elif drop.drop_height is not None:
        name, given = "drop_height", drop.drop_height
        height = check_drop_height(case, drop.drop_height)
    else:
        return case
    speed = math.sqrt(2.0 * case.g * height)
    try:
        return case.derive(v0=speed)
    except ParameterError:
        raise ParameterError(
            name, "a height > 0 [m] whose impact speed sqrt(2 g H) the model can take", given
        ) from None


def _pressure(case: Case, notes: list[str]) -> float:
    """Excess pressure P [Pa]: the case's, else its preset's measured one."""
    if case.pressure is not None:
        return float(case.pressure)
    from twoball.modal.presets import MEASURED

    measured = MEASURED.get(case.preset_name or "")
    if measured is None or measured.pressure is None:
        raise ParameterError(
            "pressure",
            "given for the drop (its tension T = P R / 2 sets the ball's mass 2 pi R P / c^2 "
            "and the gas): Case.from_pressure, or a preset",
            None,
        )
    from twoball.modal.scalings import membrane_mass

    mass = membrane_mass(case.radius, measured.pressure, case.wave_speed)
    notes.append(
        f"P = {measured.pressure:g} Pa, the {case.preset_name} preset's measured excess "
        f"pressure: m2 = 2 pi R P / c^2 = {mass:.4g} kg"
    )
    return float(measured.pressure)


def _law(damping: Any) -> ModalRatio | Rayleigh | None:
    """The damping law as given (None: the case's own)."""
    if damping is None or isinstance(damping, (ModalRatio, Rayleigh)):
        return damping
    raise ParameterError("damping", "a twoball.ModalRatio or twoball.Rayleigh", damping)


@dataclass(frozen=True)
class WholeBody:
    """The upper body of a whole bounce, resolved (SI).

    Attributes
    ----------
    body : Body
        Mass ratio, contact radius (None: R / 10), Newton's e12.
    pair : Pair or None
        The Table 1 pair it comes from.
    contact_radius : float
        Cap radius a [m] on the case's ball.
    cap_angle : float
        ``arcsin(a / R)`` [rad].
    notes : tuple of str
    """

    body: Any
    pair: Any
    contact_radius: float
    cap_angle: float
    notes: tuple[str, ...] = ()

    @property
    def kind(self) -> str:
        """``rigid`` (a :class:`~twoball.Body`), ``lumped`` or ``ball`` (an elastic body)."""
        return str(getattr(self.body, "kind", "rigid"))


def resolve_pair(case: Case | None, body: Any, pair: str | None) -> tuple[Case | None, Any, Any]:
    """A Table 1 pair as the case's lower ball and the body (``(case, body, pair)``).

    The pair fixes the lower ball (its preset), mu, e12 and the contact radius
    (:attr:`~twoball.modal.pairs.Pair.cap_radius`); a body given with it, or a
    case of another preset, is refused.  ``body`` may name a kind instead
    (``"rigid"``, ``"lumped"``, ``"ball"``): the pair's preset body of that kind
    (:func:`twoball.modal.bodies.preset_body`); an elastic body object rides the
    pair's lower ball as given.  Without a pair, ``case`` and ``body`` pass
    through.
    """
    if pair is None:
        return case, body, None
    from twoball.modal.contact.body import Body
    from twoball.modal.pairs import pair as find_pair

    chosen = find_pair(pair)
    kind = "rigid"
    if isinstance(body, str):  # a kind: the pair's preset body of that kind
        kind, body = body, None
    if body is not None and getattr(body, "kind", "rigid") == "rigid":
        raise ParameterError(
            "body", "left out with pair (the pair fixes mu, e12 and the contact radius)", body
        )
    if case is None:
        case = Case.preset(chosen.lower)
    elif case.preset_name != chosen.lower:
        valid = f"a case of the {chosen.lower} preset (the pair's lower ball)"
        raise ParameterError("case", valid, case.preset_name)
    if body is not None:  # an elastic body of its own on the pair's lower ball
        return case, body, chosen
    if kind != "rigid":  # the pair's elastic body (twoball.modal.bodies)
        from twoball.modal.upper.inputs import pair_body

        return case, pair_body(chosen.name, kind), chosen
    body = Body(chosen.mu, contact_radius=chosen.cap_radius, restitution=chosen.e12)
    return case, body, chosen


def resolve_body(case: Case, body: Any, pair: Any, drop: Drop) -> WholeBody | None:
    """Check an upper body against the whole bounce and the case's ball.

    Raises
    ------
    ParameterError
        A gap without a body, a massless body (the lift-off's criteria are the
        massless limit: ``twoball liftoff``), ``energy="both"`` (both bodies fall
        at ``|v0|`` here) or a contact radius outside (0, R).
    """
    if body is None:
        if drop.gap > 0.0:
            raise ParameterError("gap", "left out without an upper body (mass_ratio)", drop.gap)
        return None
    from twoball.modal.contact.body import MAX_MASS_RATIO, Body
    from twoball.modal.contact.caps import cap_angle

    if isinstance(body, str) or getattr(body, "kind", "rigid") != "rigid":
        from twoball.modal.upper.inputs import resolve_elastic

        if isinstance(body, str):
            valid = "a body object (a kind name such as 'lumped' needs a pair)"
            raise ParameterError("body", valid, body)
        notes = resolve_elastic(case, body, pair, drop)
        return WholeBody(body, pair, math.nan, math.nan, notes)
    if not isinstance(body, Body):
        raise ParameterError("body", "a twoball.Body", type(body).__name__)
    if body.mass_ratio <= 0.0:
        raise ParameterError(
            "mass_ratio",
            f"a number in (0, {MAX_MASS_RATIO:g}] for the whole bounce "
            "(the massless body: twoball liftoff)",
            body.mass_ratio,
        )
    if body.energy != "ball":
        raise ParameterError(
            "energy", "left out for the whole bounce (both bodies fall at |v0|)", body.energy
        )
    radius = body.radius_m(case.radius)
    notes = []
    if body.contact_radius is None:
        notes.append(f"contact radius a = R/10 = {radius:g} m (the default)")
    if pair is not None:
        notes.append(
            f"pair {pair.name} (Table 1 row {pair.row}): mu = {pair.mu:g}, e12 = {pair.e12:g} "
            f"(Newton's coefficient at the body's impacts), a = {radius * 1e3:.4g} mm "
            + ("(the flat face's half width)" if pair.body.face_radius is None else "(R*)")
        )
    return WholeBody(body, pair, radius, cap_angle(radius, case.radius), tuple(notes))


def v0_set(case: Case) -> bool:
    """Whether ``case``'s v0 was set: not its preset's own measured speed (or the default)."""
    from twoball.modal.presets import MEASURED

    measured = MEASURED.get(case.preset_name or "")
    default = measured.v0 if measured is not None else Case.__dataclass_fields__["v0"].default
    return case.v0_given is not None or not math.isclose(case.v0, default, rel_tol=1e-12)


def check_drop_case(case: Case, drop: Drop) -> None:
    """Refuse what the drop would not use: a given phi_a, a v0 set beside a drop height.

    The drop computes its contact angle (``phi_a_max_rad``), so a given phi_a would be
    ignored; a drop height sets ``|v0| = sqrt(2 g H)``, eq. (2.1), so a case whose v0 is
    not its preset's own (the user set one) would be overridden.
    """
    if case.phi_a_source == "given":
        valid = "left out for the drop (the contact angle is its output, phi_a_max_rad)"
        raise ParameterError("phi_a", valid, case.phi_a)
    name = "centre_height" if drop.centre_height is not None else "drop_height"
    given = getattr(drop, name)
    if given is not None and v0_set(case):
        speed = case.v0 if case.v0_given is None else case.v0_given
        valid = (
            f"given alone, not with the case's own v0 = {speed:g} m/s (the height sets "
            "|v0| = sqrt(2 g H); build the case without a v0 of its own)"
        )
        raise ParameterError(name, valid, given)


def drop_times(
    case: Case, dt: float | None, t_end: float | None, gap: float = 0.0
) -> tuple[float, float]:
    """The time step and the window of a drop in units of 1/c, checked.

    Parameters
    ----------
    case : Case
        The ball (its c and |v0|).
    dt, t_end : float or None
        The step and the window [s] as given (None: :data:`DEFAULT_DT`, and
        :data:`DEFAULT_WINDOW` plus twice the gap's closing time).
    gap : float
        ``Delta x / R`` of a body above the ball.
    """
    from twoball.modal.report import t_end_dimensionless

    # the body needs about Delta x / ((1 + e2) |v0|) to reach the ball, eq. (2.2)
    window = DEFAULT_WINDOW + 2.0 * gap / (case.v0 / case.scalings.velocity)
    t_end_c = window if t_end is None else t_end_dimensionless(case, t_end)
    if dt is None:
        dt_c = DEFAULT_DT
    else:
        dt_c = dt * case.wave_speed
        high = min(MAX_DT, 0.1 * t_end_c)
        if not dt_c <= high:
            valid = f"a time step in (0, {high / case.wave_speed:.3g}] s for the drop"
            raise ParameterError("dt", valid, dt)
    if t_end_c <= 10.0 * dt_c:
        valid = f"a window longer than 10 time steps ({10.0 * dt_c / case.wave_speed:.3g} s)"
        raise ParameterError("t_end", valid, t_end)
    return dt_c, t_end_c
