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
from twoball._common.errors import ParameterError
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
    "bounce",
    "bounce_sweep",
]

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
        operator (:class:`~twoball.Drop`; default: the case's ``|v0|``, its gas
        or else the adiabatic gas, e = 0, N = 192, the pressurised operator).
    backend : {"legendre", "fem"}
        Legendre modes (floor points at the Gauss-Radau nodes) or axisymmetric
        finite elements (floor points at the nodes).
    mesh : MeshOptions or "axisym", optional
        Finite elements only: the line ``axisym`` (default 96 elements, P2).
    stepping : Stepping, optional
        ``dt`` [s] (default 0.005 / c) with ``scheme="moreau-jean"`` (the only
        scheme of the drop), and the window ``t_end`` [s] (default 10 pi / c).
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
        ``events``, ``energy_J``, ``warnings``; ``as_dict()`` for JSON.

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

    given_phi_a = case.phi_a if case.phi_a_source == "given" else None
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
    from twoball._common.provenance import block

    notes = model_in.notes
    if given_phi_a is not None:
        notes += (
            f"the case's phi_a = {given_phi_a:g} rad is not used: the drop computes "
            "the contact angle (phi_a_max_rad)",
        )
    report = BounceReport(
        case, drop, result, backend, model, model_in.pressure, tuple(warnings), notes
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
        if self.provenance is not None:
            data["provenance"] = self.provenance
        return data

    # --- files ------------------------------------------------------------------------
    def plot(self, out: str | os.PathLike[str], *, dpi: float | None = None) -> Path:
        """Figure of the drop: floor force, contact angle, centre height, energy books.

        ``out``'s suffix chooses the format (``.png``, ``.pdf``, ``.svg``, ...).
        """
        from twoball.verify.output.figures import save_figure
        from twoball.verify.output.figures.bounce import drop_figure

        title = f"{self.backend}, {self.model['membrane']} membrane"
        figure = drop_figure(self.result, self.case, self.mass_kg, title)
        return save_figure(figure, out, "plot", dpi)

    def _mesh_and_times(self, mesh: Any, frames: int) -> tuple[Any, Any]:
        from twoball.fem_membrane.mesh import sphere_mesh
        from twoball.fem_membrane.options import MeshOptions
        from twoball.verify.output.drop_fields import drop_frames
        from twoball.verify.output.fields import check_frames

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
        ``floor_force_N``; every field in SI (:mod:`twoball.verify.output.drop_fields`).
        ``mesh``: a sphere (default the level-3 P2 icosphere); ``frames``
        instants from the first touch to the end of the run.
        """
        import json

        from twoball.verify.output.drop_fields import drop_series
        from twoball.verify.output.series import write_series

        sphere, times = self._mesh_and_times(mesh, frames)
        series = drop_series(self.result, self.case, sphere, times, self.mass_kg, self._text)
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
            f"twoball bounce ({self.backend}, {self.model['resolution']}): R = {c.radius:g} m, "
            f"c = {c.wave_speed:g} 1/s, v0 = {c.v0:g} m/s, membrane {self.model['membrane']}, "
            f"gas {self.model['gas']}"
        )


@dataclass(frozen=True)
class BounceSweep:
    """Drops over one parameter (``v0`` or ``drop-height``), in SI.

    Attributes
    ----------
    parameter : str
        ``v0`` or ``drop-height``.
    values : tuple of float
        Its values (m/s or m).
    reports : list of BounceReport or None
        One drop per value (None where it failed; ``errors`` says why).
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
        measurements (Table 2; 3.07 mm per m/s)."""
        from twoball.verify.output.figures import save_figure
        from twoball.verify.output.figures.bounce import speeds_figure

        done = [r for r in self.reports if r is not None]
        if not done:
            raise ParameterError("values", "at least one drop that ran, to plot", None)
        rows = [(r.case.v0, r.phi_a_max_rad, r.flattening_max_m) for r in done]
        return save_figure(speeds_figure(rows, done[0].case), out, "plot", dpi)


def bounce_sweep(
    values: Any, case: Case | None, drop: Drop, *, stepping: Any = None, progress: Any = None
) -> BounceSweep:
    """Drops over ``values`` (``{"v0": [...]}`` or ``{"drop_height": [...]}``), in SI."""
    from twoball._common.errors import NumericalError
    from twoball._common.provenance import block
    from twoball.verify.sweeps.bounce import bounce_points, bounce_values

    case = Case.preset("basketball") if case is None else case
    if not isinstance(case, Case):
        raise ParameterError("case", "a twoball.Case", type(case).__name__)
    if not isinstance(drop, Drop):
        raise ParameterError("drop", "a twoball.Drop", type(drop).__name__)
    if not hasattr(values, "items") or not values:
        raise ParameterError("values", "a mapping of v0 or drop_height to values", values)
    parameter, array = bounce_values(list(values), list(values.values()))
    points = bounce_points(case, drop, parameter, array)
    reports: list[Any] = []
    errors: list[str | None] = []
    for k, (point_case, point_drop) in enumerate(points, start=1):
        try:
            reports.append(bounce(point_case, point_drop, stepping=stepping))
            errors.append(None)
        except (ParameterError, NumericalError) as error:
            reports.append(None)
            errors.append(str(error))
        if progress is not None:
            progress(k)
    arguments = {"values": {parameter: array}, "drop": drop.as_dict()}
    if stepping is not None:
        arguments["stepping"] = stepping.as_dict()
    provenance = block(case, "twoball.sweep", arguments)
    return BounceSweep(parameter, tuple(float(v) for v in array), reports, errors, provenance)
