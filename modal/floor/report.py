"""The drop and the whole two-ball bounce reported in SI: seconds, metres, m/s, N s, J.

:class:`BounceReport` turns a dimensionless
:class:`~twoball.modal.floor.drop.DropResult` into the numbers a reader asks
for, with the ICM of eqs. (2.1)-(2.5) beside the whole bounce
(:attr:`BounceReport.icm_solver`) and the drop beside eq. (3.7), pressure x area
and the measurements (:meth:`BounceReport.comparisons`); :meth:`~BounceReport.as_dict`
is the JSON of ``twoball bounce``.  The files (figure, fields, pictures) are the
face's (:class:`twoball.BounceReport`).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field, replace
from typing import Any

from twoball._common.errors import ParameterError
from twoball.modal.floor.drop import DropResult
from twoball.modal.floor.options import Drop
from twoball.modal.parameters import Case

__all__ = ["BounceReport"]


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
        The ball's discretisation: ``legendre`` or ``fem`` (any ball's ``backend``).
    model : dict
        The model that ran: resolution, membrane operator, bending (``bending_N_m``
        [N m] and its ratio ``bending_beta = B / (T R^2)``), gas, omega_0^2 (units
        c^2), damping law (Rayleigh's ``alpha_1_s`` [1/s] and ``beta_s`` [s]),
        floor restitution, time step and window (SI).
    pressure : float
        Excess pressure P [Pa] behind the tension ``T = P R / 2`` and the mass.
    mass : float
        The lower ball's mass m2 [kg] (the unit of mass of the run; the membranes'
        ``2 pi R P / c^2``).
    warnings : tuple of str
        What the reader must know to trust the numbers.
    notes : tuple of str
        Remarks (where a value came from).
    provenance : dict, optional
        Versions, command line or call, UTC time and case.
    whole : WholeBody, optional
        The upper body as resolved (:func:`twoball.modal.floor.inputs.resolve_body`):
        the whole two-ball bounce.
    baselines : dict, optional
        The lumped models of §1(b) for the same drop
        (:func:`twoball.modal.lumped.baselines.baselines`), with their inputs.
    caveats : tuple of str
        With a body, what the answer is beside its numbers
        (:func:`~twoball.modal.floor.bounce.answer_caveats`): ``artefact`` (the first
        strike came from the radial membrane's degree-1 precursor), ``e12_low``
        (``e12_effective`` below half the body's Newton e12), ``overlap`` (the
        contacts overlap: ``e12_effective`` and ``icm_solver`` undefined).

    Examples
    --------
    >>> from twoball.modal.floor.bounce import bounce_problem, simulate
    >>> from twoball.modal.balls.membrane import LegendreBall
    >>> report = simulate(bounce_problem(ball=LegendreBall(16)))
    >>> report.left_floor, 0.8 < report.e2 < 1.0
    (True, True)
    """

    case: Case
    drop: Drop
    result: DropResult
    backend: str
    model: dict[str, Any]
    pressure: float
    mass: float
    warnings: tuple[str, ...] = ()
    notes: tuple[str, ...] = ()
    provenance: dict[str, Any] | None = field(default=None, compare=False, repr=False)
    whole: Any = field(default=None, repr=False)
    baselines: dict[str, Any] | None = field(default=None, repr=False)
    caveats: tuple[str, ...] = ()

    def light(self) -> BounceReport:
        """The report without the run's history (every number kept): a sweep's point."""
        return replace(self, result=self.result.light())

    # --- units -------------------------------------------------------------------------
    @property
    def mass_kg(self) -> float:
        """The lower ball's mass m2 [kg]."""
        return self.mass

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
        if "body_internal" in e:  # an elastic body's own books (modal/upper/measure.py)
            books["final_body_internal"] = e["body_internal"] * unit
            books["body_dissipated"] = e["body_dissipated"] * unit
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
        from twoball.modal.icm.impacts import icm_velocities

        v0, g, gap = self.case.v0, self.case.g, self.drop.gap
        e2 = min(max(self.e2, 0.0), 1.0)
        try:
            mu = self.result.system.body_mass  # the rigid body's mass_ratio; a ball body's own
            v1, v2 = icm_velocities(gap, v0, e2, min(e12, 1.0), mu, g)
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
        body = self.result.body
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
            "caveats": list(self.caveats),
            "e12_velocities_m_s": {"before_u1_u2": before, "after_v1_v2": after},
            "body_contacts": body.contacts,
            "body_impulse_N_s": body.impulse * self.mass_kg * speed,
            "body": self._body_dict(),
            "icm_solver": self.icm_solver,
            "baselines": self.baselines,
        } | self._elastic_block()

    def _body_dict(self) -> dict[str, Any]:
        """The body's own keys: the rigid body's cap and e12, or an elastic body's kind."""
        whole = self.whole
        pair = None if whole.pair is None else whole.pair.name
        if whole.kind == "rigid":
            return {
                "mass_ratio": whole.body.mass_ratio,
                "mass_kg": whole.body.mass_ratio * self.mass_kg,
                "contact_radius_m": whole.contact_radius,
                "cap_angle_rad": whole.cap_angle,
                "restitution": whole.body.restitution,
                "gap_m": self.drop.gap,
                "pair": pair,
            }
        mu = self.result.system.body_mass
        return {
            "kind": whole.kind,
            "mass_ratio": mu,
            "mass_kg": mu * self.mass_kg,
            "body_restitution": whole.body.restitution,
            "gap_m": self.drop.gap,
            "pair": pair,
            "parameters": whole.body.as_dict(),
        }

    def _elastic_block(self) -> dict[str, Any]:
        """An elastic body's contact: duration, peak force, disc (SI; none for a rigid body)."""
        elastic = self.result.elastic
        if elastic is None:
            return {}
        case = self.case
        force = self.mass_kg * case.radius * case.wave_speed**2
        return {
            "body_contact": {
                "duration_s": self._time(elastic.contact_time),
                "first_contact_s": self._time(elastic.first_contact),
                "main_contact_s": self._time(elastic.main_contact),
                "peak_force_N": elastic.peak_force * force,
                "disc_max_radius_m": elastic.disc_max * case.radius,
                "impacts_N_s": elastic.impacts * self.mass_kg * case.scalings.velocity,
                "peak_compression_m": None
                if elastic.peak_compression is None
                else elastic.peak_compression * case.radius,
                "drift_m": elastic.drift * case.radius,
            }
        }

    def comparisons(self) -> dict[str, Any]:
        """The drop beside eq. (3.7), pressure x area and the measurements (SI).

        A Table 1 pair adds ``table1``: the row's measured ``v1/|v0|`` and
        ``v2/|v0|`` and its printed ICM beside this run's (Table 1's drops are
        touching, Delta x -> 0; the ICM and the lumped baselines of this drop are
        ``icm_solver`` and ``baselines``).
        """
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
        pair = None if self.whole is None else self.whole.pair
        if pair is not None:
            out["table1"] = self._table1(pair)
        return out

    def _table1(self, pair: Any) -> dict[str, Any]:
        """Table 1's row of ``pair``: measured and printed ICM ratios beside this run's."""
        row = pair.table1
        v1, v2 = self.v1_ratio, self.v2_ratio
        note = "Table 1's drops are touching (Delta x -> 0); ratios over |v0|"
        if self.drop.gap > 0.0:
            note += f"; this run's gap is {self.drop.gap * 1e3:g} mm"
        return {
            "row": pair.row,
            "pair": pair.name,
            "measured_v1_ratio": row.measured_v1,
            "measured_v2_ratio": row.measured_v2,
            "icm_printed_v1_ratio": row.icm_v1,
            "icm_printed_v2_ratio": row.icm_v2,
            "model_v1_ratio": v1,
            "model_v2_ratio": v2,
            "model_minus_measured_v1": None if v1 is None else v1 - row.measured_v1,
            "model_minus_measured_v2": None if v2 is None else v2 - row.measured_v2,
            "note": note,
        }

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
            "drop_height_m": self.drop.fall(self.case.radius),
            "centre_height_m": self.drop.centre_height,
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
