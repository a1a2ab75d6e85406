"""A drop of the lower ball in SI: the edge between the dimensionless drop and people.

:class:`BounceReport` holds the case, the drop's options and the
dimensionless :class:`~twoball.modal.floor.drop.DropResult`, and converts on
demand: times by 1/c, lengths by R, velocities by R c, impulses by m2 R c and
energies by m2 (R c)^2, with the ball's mass ``m2 = 4 pi R^2 rho = 2 pi R P /
c^2`` (``T = P R / 2 = rho c^2 R^2``, §4(b)).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

from twoball.modal.floor.options import Drop
from twoball.modal.parameters import Case

if TYPE_CHECKING:
    from twoball.modal.floor.drop import DropResult

__all__ = ["BounceReport", "pressure_area"]

#: Table 1's measured e2 of the lower balls (Berdeni et al. 2015).
TABLE1_E2: dict[str, tuple[float, ...]] = {"basketball": (0.80, 0.90), "tennis": (0.83,)}
#: Compression of a basketball per unit impact speed [m per m/s] (Dowell & Krebs 1991).
MEASURED_COMPRESSION = 3.07e-3


def pressure_area(v0: float, radius: float, wave_speed: float) -> dict[str, float]:
    """The pressure x area spring of a ball on the floor, in SI.

    Cross 1999, Am. J. Phys. 67 222; Hubbard & Stronge 2001, Sports Eng. 4 49.

    The floor force ``F = P pi (2 R x)`` for a flattening x is a spring ``k = 2 pi
    R P`` with ``k / m2 = c^2``: contact time ``pi / c``, largest flattening
    ``|v0| / c`` and the contact cap through the plane at depth x, ``cos psi = 1
    - x / R``, i.e. ``phi_a = pi - psi``.
    """
    flattening = v0 / wave_speed
    cosine = max(1.0 - flattening / radius, -1.0)
    return {
        "contact_time_s": math.pi / wave_speed,
        "flattening_max_m": flattening,
        "phi_a_max_rad": math.pi - math.acos(cosine),
        "e2": 1.0,
    }


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
        The model that ran: resolution, membrane operator, gas, omega_0^2, beta,
        damping law, floor restitution, time step and window (SI).
    pressure : float
        Excess pressure P [Pa] behind the tension ``T = P R / 2`` and the mass.
    warnings : tuple of str
        What the reader must know to trust the numbers.
    notes : tuple of str
        Remarks (where a value came from).
    provenance : dict, optional
        Versions, command line or call, UTC time and case.

    Examples
    --------
    >>> import twoball
    >>> report = twoball.bounce(drop=twoball.Drop(modes=16))
    >>> report.left_floor, 0.8 < report.e2 < 1.0
    (True, True)
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
        """The energy books [J]; see :meth:`as_dict`."""
        unit = self._energy_unit
        e = self.result.energy
        final = {
            key: e[key] * unit
            for key in ("rigid_kinetic", "membrane_kinetic", "membrane_elastic", "gas")
        }
        return {
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

    @property
    def events(self) -> list[dict[str, Any]]:
        """Every touch and separation of the floor: kind, time [s], centre velocity [m/s]."""
        return [
            {
                "kind": ev.kind,
                "t_s": ev.t / self.case.wave_speed,
                "velocity_m_s": ev.velocity * self.case.scalings.velocity,
                "floor_points": ev.points,
            }
            for ev in self.result.events
        ]

    def comparisons(self) -> dict[str, Any]:
        """The drop beside eq. (3.7), pressure x area and the measurements (SI)."""
        from twoball.modal.initial import phi_a_from_v0
        from twoball.modal.presets import MEASURED

        from twoball._common.errors import ParameterError

        case = self.case
        try:
            eq37 = phi_a_from_v0(case.v0, case.radius, case.wave_speed)
        except ParameterError:  # beyond the largest speed eq. (3.7) can store
            eq37 = None
        out: dict[str, Any] = {
            "phi_a_eq_3_7_rad": eq37,
            "pressure_area": pressure_area(case.v0, case.radius, case.wave_speed),
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
        if self.provenance is not None:
            data["provenance"] = self.provenance
        return data
