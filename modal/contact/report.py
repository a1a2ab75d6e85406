"""The finite-mass lift-off in SI units: case in, contact sequence and v1 out.

``mass_ratio > 0`` steps the contact with the nonsmooth core of the drop
(:mod:`twoball.modal.contact.stepped`, Moreau-Jean: one integrator for every
contact of the package); ``exact=True`` solves it event by event in closed form
instead (:mod:`twoball.modal.contact.events`: the verification studies' exact
reference).  ``mass_ratio = 0`` is the massless mode:
the paper's criteria (i)-(ii) of §3(a) applied to the cap-averaged motion
(:func:`twoball.modal.liftoff.find_liftoff` on a series whose "pole values" are the
cap averages), which is today's pole result as the contact radius goes to 0.

Accuracy guards (:func:`contact_guards`), as for the massless body
(:mod:`twoball.modal.guards`):

* truncation: the same contact problem solved in closed form with
  ``N_ref = max(2 N, 60)`` Lanczos modes is reported beside the result (the
  ``truncation`` block) and a warning is added when t_l or v1 differs from it
  by more than 5 %, or when only one of them lifts off.  The contact solutions
  converge like ``N^-2`` (basketball, mu = 0.1, event by event: v1 = 0.4261,
  0.4325, 0.4342, 0.4346 m/s at N = 30, 60, 120, 240), so the difference to
  ``2 N`` estimates the error of N (N = 30: -1.5 %; the converged limit: -2.0
  %); N = 3 does not lift off where N = 60 does at 11.8 ms: warned.  ``N_ref``
  stops at :data:`CONTACT_REFERENCE_MAX_MODES` (240), and above N = 120 the
  block says it was not checked (the difference between N = 120 and 240 is 0.1
  % there).  The finite elements are compared with the same
  closed form: truncation and discretisation together (plus the mesh guard);
* the window: a body that separated moving down at the end of the window is
  not lifted (criterion (ii): no negative lift-off velocity) and this is said;
  a lift-off followed by less than a refocusing period ``2 pi / c``, or past
  its apex, is warned as in :func:`twoball.modal.guards.window_warnings`; unit
  slips and windows in which nothing can lift off as in
  :func:`twoball.modal.guards.case_warnings` and ``span_warnings``.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from twoball._common.errors import ParameterError
from twoball._common.keywords import checked
from twoball._common.monitor import Monitor
from twoball.modal.contact.body import Body
from twoball.modal.contact.caps import cap_angle, legendre_cap_averages
from twoball.modal.contact.events import ContactHistory
from twoball.modal.filters import SpectralFilter
from twoball.modal.legendre import legendre_series
from twoball.modal.liftoff import find_liftoff
from twoball.modal.parameters import FROM_V0, Case
from twoball.modal.report import t_end_dimensionless
from twoball.modal.series import ModalSeries

CONTACT_REFERENCE_MIN_MODES = 60  # twice the paper's N = 30
CONTACT_REFERENCE_MAX_MODES = 240  # one contact solve: 2.7 s at 240 modes, 44 s at 480
CONTACT_WARNING = 0.05  # relative difference of t_l or v1 from the reference


def check_contact_options(case: Case, body: Body) -> float:
    """Check ``body`` against ``case``; return the contact radius [m] (default R/10)."""
    if not isinstance(body, Body):
        raise ParameterError("body", "a twoball.Body", type(body).__name__)
    if case.stiff:  # the contact system is built on the membrane's modes (eq. (3.11)) only
        valid = (
            "left out with bending or gas, or the pressurised membrane (the contact model has "
            "the paper's membrane modes only)"
        )
        raise ParameterError("mass_ratio", valid, body.mass_ratio)
    if case.rayleigh is not None:  # the contact system damps every mode by 2 D omega
        valid = "left out with mass_ratio (the contact model takes the modal ratio D)"
        raise ParameterError("rayleigh", valid, case.rayleigh.as_dict())
    radius = body.radius_m(case.radius)
    cap_angle(radius, case.radius)
    return radius


def membrane_case(case: Case, mass_ratio: float, energy: str) -> Case:
    """The case whose phi_a sets the membrane's initial shape.

    ``ball``: eq. (3.6) as printed, the lower ball's kinetic energy alone becomes
    deformation.  ``both``: the upper body's ``mu m2 v0^2 / 2`` too, i.e. eq. (3.7)
    at ``|v0| sqrt(1 + mu)``.
    """
    if energy == "ball" or mass_ratio == 0.0:
        return case
    return case.derive(v0=case.v0 * math.sqrt(1.0 + mass_ratio), phi_a=FROM_V0)


@checked
@dataclass(frozen=True)
class ContactReport:
    """Finite-mass lift-off of the upper body, in SI (seconds, m/s, N s).

    ``history`` is the dimensionless event history (None in the massless mode,
    where ``massless`` holds the criteria's :class:`LiftoffResult`); ``motion``
    the state at any time (:class:`~twoball.modal.contact.stepped.SteppedMotion`,
    or the exact reference's :class:`~twoball.modal.contact.stepped.ExactMotion`).

    Examples
    --------
    >>> import twoball
    >>> report = twoball.liftoff(body=twoball.Body(mass_ratio=0.1))
    >>> [event["kind"] for event in report.events_si()][:3]
    ['separation', 'impact', 'separation']
    >>> report.lifted, round(report.ratio, 3)
    (True, 0.104)
    """

    case: Case
    mass_ratio: float
    contact_radius_m: float
    restitution: float
    energy: str
    backend: str
    sigma: str
    history: ContactHistory | None
    massless: Any = None
    extra: dict[str, Any] = field(default_factory=dict)
    warnings: tuple[str, ...] = ()
    membrane: Case | None = None
    motion: Any = field(default=None, repr=False, compare=False)
    provenance: dict[str, Any] | None = field(default=None, compare=False, repr=False)

    def __repr__(self) -> str:
        """The answer first, in SI: lifted, final separation [s], v1 [m/s], v1/|v0|, events."""
        impacts = 0 if self.history is None else len(self.history.impacts)
        events = 0 if self.history is None else len(self.history.events)
        return (
            f"ContactReport(lifted={self.lifted}, t_liftoff_s={self.t_liftoff_s!r}, "
            f"v_liftoff_m_s={self.v_liftoff_m_s!r}, ratio={self.ratio!r}, "
            f"mass_ratio={self.mass_ratio!r}, contact_radius_m={self.contact_radius_m!r}, "
            f"restitution={self.restitution!r}, impacts={impacts}, events={events}, "
            f"backend={self.backend!r}, sigma={self.sigma!r}, case={self.case!r})"
        )

    @property
    def result(self) -> Any:
        """The dimensionless outcome: the :class:`ContactHistory` (or the massless
        :class:`LiftoffResult`); both have ``lifted``, ``t`` and ``velocity``."""
        return self.history if self.history is not None else self.massless

    @property
    def lifted(self) -> bool:
        """True if the body is in flight at the end of the window."""
        return bool(self.history.lifted if self.history is not None else self.massless.lifted)

    @property
    def _dimensionless(self) -> tuple[float | None, float | None]:
        if self.history is not None:
            return self.history.t, self.history.velocity
        return self.massless.t, self.massless.velocity

    @property
    def t_liftoff_s(self) -> float | None:
        """Final separation time [s] after maximal compression, or None."""
        t = self._dimensionless[0]
        return None if t is None else t * self.case.scalings.time

    @property
    def v_liftoff_m_s(self) -> float | None:
        """The body's velocity v1 [m/s] at the final separation, or None."""
        v = self._dimensionless[1]
        return None if v is None else v * self.case.scalings.velocity

    @property
    def ratio(self) -> float | None:
        """``v1 / |v0|``."""
        v = self.v_liftoff_m_s
        return None if v is None else v / self.case.v0

    @property
    def notes(self) -> list[str]:
        """How phi_a was chosen and a negative v0 read (as for the massless lift-off)."""
        return (self.membrane or self.case).notes

    def trajectory_si(self, samples: int = 600) -> dict[str, Any]:
        """Body and cap-averaged membrane on ``samples`` times over the window (SI).

        Keys: ``t_s``, ``body_height_m``, ``body_velocity_m_s``, ``cap_displacement_m``,
        ``cap_velocity_m_s``, ``contact`` (bool); empty in the massless mode.
        """
        if self.history is None or self.motion is None:
            return {}
        scale = self.case.scalings
        data = self.motion.sample(np.linspace(0, self.history.t_end, samples))
        return {
            "t_s": data["t"] * scale.time,
            "body_height_m": data["body_height"] * scale.length,
            "body_velocity_m_s": data["body_velocity"] * scale.velocity,
            "cap_displacement_m": data["cap_displacement"] * scale.length,
            "cap_velocity_m_s": data["cap_velocity"] * scale.velocity,
            "contact": data["contact"],
        }

    def events_si(self) -> list[dict[str, Any]]:
        """Every contact event in SI: kind, time, body height and velocity, impulse, loss."""
        if self.history is None:
            return []
        scale = self.case.scalings
        energy_unit = self._energy_unit
        impulse_unit = energy_unit / scale.velocity  # (T R^2) / (R c) = T R / c
        return [
            {
                "kind": e.kind,
                "t_s": e.t * scale.time,
                "height_m": e.height * scale.length,
                "velocity_m_s": e.velocity * scale.velocity,
                "impulse_N_s": e.impulse * impulse_unit,
                "energy_loss_J": e.energy_loss * energy_unit,
            }
            for e in self.history.events
        ]

    @property
    def _energy_unit(self) -> float:
        """T R^2 [J] with ``T = rho R^2 c^2`` and ``rho = m2 / (4 pi R^2)``; m2 unknown here.

        The membrane's mass is not a case parameter, so energies and impulses are
        given per kilogram of membrane: ``T R^2 / m2 = R^2 c^2 / (4 pi)`` [J/kg].
        """
        scale = self.case.scalings
        return scale.velocity**2 / (4.0 * math.pi)

    def as_dict(self) -> dict[str, Any]:
        """JSON-ready (SI; impulses and energies per kilogram of membrane mass)."""
        data: dict[str, Any] = {
            "lifted": self.lifted,
            "t_liftoff_s": self.t_liftoff_s,
            "v_liftoff_m_s": self.v_liftoff_m_s,
            "ratio": self.ratio,
            "mass_ratio": self.mass_ratio,
            "contact_radius_m": self.contact_radius_m,
            "restitution": self.restitution,
            "energy": self.energy,
            "mode": "massless criteria" if self.history is None else "contact dynamics",
            "impacts": 0 if self.history is None else len(self.history.impacts),
            "events": self.events_si(),
            "events_units": "impulse_N_s and energy_loss_J per kg of membrane mass m2",
            "phi_a_rad": (self.membrane or self.case).phi_a,
            "phi_a_source": (self.membrane or self.case).phi_a_source,
            "gamma": self.case.gamma,
            "backend": self.backend,
            "radius_m": self.case.radius,
            "wave_speed_1_s": self.case.wave_speed,
            "v0_m_s": self.case.v0,
            "damping": self.case.damping,
            "modes": self.case.modes,
            "sigma": self.sigma,
        }
        data.update(self.extra)
        data["notes"] = self.notes
        data["warnings"] = list(self.warnings)
        if self.provenance is not None:
            data["provenance"] = self.provenance
        return data


@dataclass(frozen=True)
class ContactCase:
    """A case with an upper body of mass ratio ``mass_ratio``: one point of a mass sweep.

    Reads like its :class:`Case` (``phi_a``, ``v0``, ...) plus ``mass_ratio``.
    """

    case: Case
    mass_ratio: float

    def __getattr__(self, name: str) -> Any:
        if name.startswith("__"):
            raise AttributeError(name)
        return getattr(self.case, name)


def solve_contact(
    case: Case,
    series: ModalSeries,
    contact: np.ndarray,
    *,
    mass_ratio: float,
    contact_radius_m: float,
    restitution: float,
    energy: str,
    backend: str,
    sigma: str,
    t_end: float,
    membrane: Case,
    extra: dict[str, Any] | None = None,
    dt: float | None = None,
    exact: bool = False,
    monitor: Monitor | None = None,
) -> ContactReport:
    """Run the shared contact solver on any backend's series and cap averages.

    ``dt`` is the time step of the contact core (units 1/c; default
    :data:`~twoball.modal.contact.stepped.DEFAULT_DT`); ``exact`` solves event by
    event in closed form instead (the verification studies' reference).
    """
    from twoball.modal.contact.stepped import DEFAULT_DT, ExactMotion, stepped_contact

    motion = None
    if mass_ratio == 0.0:
        cap_series = ModalSeries(
            series.omega,
            series.coefficients,
            np.asarray(contact, dtype=float),
            series.damping,
            series.filter,
            series.mode_norms,
            monitor=monitor,
        )
        result = find_liftoff(cap_series, case.gamma, t_end=t_end)
        history = None
    elif exact:
        from twoball.modal.contact.events import integrate
        from twoball.modal.contact.system import ContactSystem

        system = ContactSystem.from_series(series, contact, mass_ratio, case.gamma)
        history = integrate(system, t_end, restitution, monitor=monitor)
        motion, result = ExactMotion(history, system), None
    else:
        step = DEFAULT_DT if dt is None else float(dt)
        motion = stepped_contact(
            series,
            contact,
            mass_ratio,
            case.gamma,
            t_end,
            restitution,
            dt=step,
            monitor=monitor,
        )
        history, result = motion.history, None
    extra = dict(extra or {})
    if mass_ratio > 0.0:
        extra["integrator"] = "event by event (closed form)" if exact else "moreau-jean"
        if not exact:
            extra["dt_s"] = (DEFAULT_DT if dt is None else float(dt)) * case.scalings.time
    return ContactReport(
        case,
        mass_ratio,
        contact_radius_m,
        restitution,
        energy,
        backend,
        sigma,
        history,
        result,
        extra,
        (),
        membrane,
        motion,
    )


def _relative(value: float | None, reference: float | None) -> float | None:
    if value is None or reference is None or reference == 0:
        return None
    return value / reference - 1.0


def contact_reference(
    case: Case,
    body: Body,
    t_end_s: float | None,
    *,
    dt: float | None = None,
    exact: bool = False,
    monitor: Monitor | None = None,
) -> tuple[int, ContactReport | None]:
    """The Legendre contact solution with ``max(2 N, 60)`` Lanczos modes (None above 240),
    by the same integrator and step."""
    modes = max(2 * case.modes, CONTACT_REFERENCE_MIN_MODES)
    if modes > CONTACT_REFERENCE_MAX_MODES:
        return modes, None
    finer = case.derive(modes=modes)
    report = legendre_contact(
        finer, body, t_end_s=t_end_s, reference=False, dt=dt, exact=exact, monitor=monitor
    )
    return modes, report


def contact_guards(
    report: ContactReport,
    reference_modes: int | None = None,
    reference: ContactReport | None = None,
    window_given: bool = True,
) -> tuple[list[str], dict[str, Any] | None]:
    """Warnings of a contact result and its ``truncation`` block (module docstring).

    ``reference_modes`` None: no truncation check (sweeps), the block is None;
    ``window_given``: whether the user gave the window t_end (a slip in it is
    suggested only then).
    """
    from twoball.modal.guards import case_warnings, span_warnings, window_warnings

    case, result = report.case, report.result
    warnings = case_warnings(case) + span_warnings(case, result, window_given)
    history = report.history
    last = history.events[-1] if history is not None and history.events else None
    scale = case.scalings
    if not result.lifted and last is not None and last.kind == "separation":
        t_end_ms = history.t_end * scale.time * 1e3
        warnings.append(
            f"the body left the membrane at {last.t * scale.time * 1e3:.4g} ms moving down "
            f"(v1 = {last.velocity * scale.velocity:.3g} m/s) and is still falling when the "
            f"window ends at {t_end_ms:.4g} ms: not a lift-off (a negative lift-off velocity "
            "means a second impact, §3(a)(ii)); lengthen the window t_end"
        )
    if result.lifted:
        warnings += window_warnings(case, result)
    if reference_modes is None:
        return warnings, None
    block: dict[str, Any] = {
        "modes": case.modes,
        "reference_modes": reference_modes,
        "reference": "the same contact problem in closed form, Lanczos filter",
        "checked": reference is not None,
        "t_liftoff_s": None,
        "v_liftoff_m_s": None,
        "t_difference": None,
        "v_difference": None,
        "warning_above": CONTACT_WARNING,
    }
    if reference is None:
        block["not_checked_because"] = (
            f"the reference would need {reference_modes} modes (above "
            f"{CONTACT_REFERENCE_MAX_MODES}: one contact solve takes ~45 s at 480)"
        )
        return warnings, block
    t_diff = _relative(report.t_liftoff_s, reference.t_liftoff_s)
    v_diff = _relative(report.v_liftoff_m_s, reference.v_liftoff_m_s)
    block.update(
        t_liftoff_s=reference.t_liftoff_s,
        v_liftoff_m_s=reference.v_liftoff_m_s,
        t_difference=t_diff,
        v_difference=v_diff,
    )
    subject = (
        f"N = {case.modes}" if report.backend == "legendre" else f"the {report.backend} result"
    )
    cure = (
        "raise the number of modes N"
        if report.backend == "legendre"
        else f"N = {case.modes} truncation and discretisation (mesh) together"
    )
    named = f"the contact solution with N = {reference_modes}"
    if result.lifted != reference.lifted:
        if reference.lifted:
            found = (
                f"{named} lifts off at {reference.t_liftoff_s * 1e3:.4g} ms with "
                f"{reference.v_liftoff_m_s:.4g} m/s"
            )
            return [*warnings, f"{subject} finds no lift-off, but {found}; {cure}"], block
        return [*warnings, f"{subject} lifts off, but {named} does not; {cure}"], block
    differences = [d for d in (t_diff, v_diff) if d is not None]
    if not differences or max(abs(d) for d in differences) <= CONTACT_WARNING:
        return warnings, block
    shown = (
        f"t_l {t_diff:+.1%}, v1 {v_diff:+.1%} from {named} "
        f"({reference.t_liftoff_s * 1e3:.4f} ms, {reference.v_liftoff_m_s:.4g} m/s)"
    )
    if report.backend == "legendre":
        return [*warnings, f"N = {case.modes} truncation: {shown}; {cure}"], block
    return [*warnings, f"{subject} is {shown}: {cure}"], block


def guarded(
    report: ContactReport,
    body: Body,
    t_end_s: float | None,
    *,
    more: tuple[str, ...] | list[str] = (),
    dt: float | None = None,
    exact: bool = False,
    monitor: Monitor | None = None,
) -> ContactReport:
    """``report`` with its warnings (:func:`contact_guards`) and ``truncation`` block."""
    from dataclasses import replace

    modes, reference = contact_reference(
        report.case, body, t_end_s, dt=dt, exact=exact, monitor=monitor
    )
    warnings, block = contact_guards(report, modes, reference, t_end_s is not None)
    extra = {**report.extra, "truncation": block}
    return replace(report, extra=extra, warnings=(*more, *warnings))


def legendre_contact(
    case: Case,
    body: Body,
    *,
    sigma: str = "lanczos",
    t_end_s: float | None = None,
    reference: bool = True,
    dt: float | None = None,
    exact: bool = False,
    monitor: Monitor | None = None,
) -> ContactReport:
    """Finite-mass lift-off on the Legendre modes.

    Parameters
    ----------
    case : Case
        The impact (SI).
    body : Body
        The upper body: mass ratio (0 is the massless mode, criteria (i)-(ii)),
        contact radius, restitution, energy at t = 0 (see :func:`membrane_case`).
    sigma : {"lanczos", "printed", "none"}
        Spectral filter of the initial values, eq. (3.16).
    t_end_s : float, optional
        Modelled window [s] (default 4 pi / c).
    reference : bool
        Add the truncation block and its warning (:func:`contact_guards`; one
        more solve with ``max(2 N, 60)`` modes); False: the other warnings only.
    dt : float, optional
        Time step of the contact core (units 1/c; default 0.005).
    exact : bool
        Event by event in closed form instead (the verification studies' reference).
    monitor : Monitor, optional
        Told of every step (:class:`~twoball._common.monitor.Monitor`).
    """
    radius = check_contact_options(case, body)
    mass_ratio, restitution, energy = body.mass_ratio, body.restitution, body.energy
    membrane = membrane_case(case, mass_ratio, energy)
    series = legendre_series(
        membrane.phi_a, case.damping, SpectralFilter(sigma, case.modes), monitor=monitor
    )
    theta = cap_angle(radius, case.radius)
    contact = legendre_cap_averages(theta, case.modes)
    report = solve_contact(
        case,
        series,
        contact,
        mass_ratio=mass_ratio,
        contact_radius_m=radius,
        restitution=float(restitution),
        energy=energy,
        backend="legendre",
        sigma=sigma,
        t_end=t_end_dimensionless(case, t_end_s),
        membrane=membrane,
        extra={"cap_angle_rad": theta},
        dt=dt,
        exact=exact,
        monitor=monitor,
    )
    if reference:
        return guarded(report, body, t_end_s, dt=dt, exact=exact, monitor=monitor)
    from dataclasses import replace

    guards = contact_guards(report, window_given=t_end_s is not None)
    return replace(report, warnings=tuple(guards[0]))
