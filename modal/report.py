"""Lift-off in SI units: the edge between the dimensionless solvers and people.

One function turns any backend's pole motion into the same report, so the
Legendre series and the finite elements are judged by one lift-off check.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass, field
from typing import Any

from twoball._common.keywords import checked
from twoball._common.monitor import Monitor
from twoball.modal.filters import FilterKind, SpectralFilter
from twoball.modal.legendre import legendre_series
from twoball.modal.liftoff import DEFAULT_T_END, Horizon, LiftoffResult, PoleMotion, find_liftoff
from twoball.modal.parameters import Case

FLOOR_TIME_ESTIMATE = (
    "pi/(2c): half period of the pressure spring k = 2 pi R P of a ball flattened on the "
    "floor (Cross 1999, Am. J. Phys. 67 222); an upper bound with bending or gas"
)


@checked
@dataclass(frozen=True)
class LiftoffReport:
    """A lift-off result with its case, in SI units (seconds, m/s).

    Attributes
    ----------
    case : Case
        The impact (SI).
    result : LiftoffResult
        The dimensionless outcome of :func:`twoball.modal.liftoff.find_liftoff`.
    backend : str
        Which solver produced the pole motion (``legendre``, ``fem``).
    sigma, recontact : str
        Filter and re-contact horizon used.
    extra : dict
        Backend details (DOFs, modes used, mesh, ...), passed through to JSON.
    warnings : tuple of str
        Accuracy warnings (:mod:`twoball.modal.guards`, :mod:`twoball.fem_membrane.guards`):
        empty when the result is inside its trustworthy regime.
    provenance : dict, optional
        Versions, command line or API call, UTC time and case
        (:func:`twoball._common.provenance.block`); set by the public API.

    Examples
    --------
    >>> import twoball
    >>> report = twoball.liftoff()
    >>> report.lifted, round(report.ratio, 4), report.backend
    (True, 0.9347, 'legendre')
    >>> sorted(report.as_dict())[:4]
    ['backend', 'before_floor_departure', 'damping', 'floor_time_estimate']
    """

    case: Case
    result: LiftoffResult
    backend: str
    sigma: str
    recontact: str
    extra: dict[str, Any] = field(default_factory=dict)
    warnings: tuple[str, ...] = ()
    provenance: dict[str, Any] | None = field(default=None, compare=False, repr=False)

    def __repr__(self) -> str:
        """The answer first, in SI: lifted, t_l [s], v_l [m/s], v_l/|v0|; then how and on what.

        The dimensionless :attr:`result` is left to its own repr.
        """
        return (
            f"LiftoffReport(lifted={self.lifted}, t_liftoff_s={self.t_liftoff_s!r}, "
            f"v_liftoff_m_s={self.v_liftoff_m_s!r}, ratio={self.ratio!r}, "
            f"backend={self.backend!r}, sigma={self.sigma!r}, recontact={self.recontact!r}, "
            f"warnings={len(self.warnings)}, case={self.case!r})"
        )

    @property
    def notes(self) -> list[str]:
        """Remarks the reader must see (the CLI prints them on standard error): how
        phi_a was chosen, when eq. (3.7) departs from a preset's measured angle, and
        how a negative v0 was read (:attr:`Case.notes`)."""
        return self.case.notes

    @property
    def lifted(self) -> bool:
        """Whether the body lifts off within the modelled window."""
        return bool(self.result.lifted)

    @property
    def t_liftoff_s(self) -> float | None:
        """Lift-off time t_l [s] after maximal compression, or None."""
        return None if self.result.t is None else self.result.t * self.case.scalings.time

    @property
    def v_liftoff_m_s(self) -> float | None:
        """Lift-off velocity v_l [m/s] (upwards), or None."""
        if self.result.velocity is None:
            return None
        return self.result.velocity * self.case.scalings.velocity

    @property
    def before_floor_departure(self) -> bool | None:
        """True if t_l precedes the estimated floor departure ``pi / (2 c)`` (None: no lift-off)."""
        t = self.t_liftoff_s
        return None if t is None else t < self.case.floor_time

    @property
    def ratio(self) -> float | None:
        """``v_l / |v0|``, the rebound ratio of the upper body (Fig. 11, 12)."""
        v = self.v_liftoff_m_s
        return None if v is None else v / self.case.v0

    def as_dict(self) -> dict[str, Any]:
        """JSON-ready dictionary (SI units; keys end in their unit)."""
        scale = self.case.scalings
        rejected = [
            {
                "t_s": c.t * scale.time,
                "v_m_s": c.velocity * scale.velocity,
                "u_m": c.displacement * scale.length,
                "reason": c.reason,
                "recontact_s": None if c.recontact is None else c.recontact * scale.time,
                "clearance_m": None if c.clearance is None else c.clearance * scale.length,
            }
            for c in self.result.rejected
        ]
        data: dict[str, Any] = {
            "lifted": self.result.lifted,
            "t_liftoff_s": self.t_liftoff_s,
            "v_liftoff_m_s": self.v_liftoff_m_s,
            "ratio": self.ratio,
            "floor_time_s": self.case.floor_time,
            "floor_time_estimate": FLOOR_TIME_ESTIMATE,
            "before_floor_departure": self.before_floor_departure,
            "phi_a_rad": self.case.phi_a,
            "phi_a_source": self.case.phi_a_source,
            "gamma": self.case.gamma,
            "backend": self.backend,
            "rejected": rejected,
            "radius_m": self.case.radius,
            "wave_speed_1_s": self.case.wave_speed,
            "v0_m_s": self.case.v0,
            "damping": self.case.damping,
            "modes": self.case.modes,
            "sigma": self.sigma,
            "recontact": self.recontact,
            "t_end_s": self.result.t_end * scale.time,
        }
        data["membrane"] = self.case.membrane.kind
        if self.case.stiff:  # bending, gas, pressure term (absent for the paper's membrane)
            case = self.case.as_dict()
            for key in ("bending_N_m", "gas", "pressure_Pa", "atmosphere_Pa", "beta"):
                data[key] = case[key]
            data["omega0_squared"] = case["omega0_squared"]
        if self.case.rayleigh is not None:  # the law instead of D (a backend may add its table)
            data["rayleigh"] = self.case.rayleigh_dict()
        data.update(self.extra)
        data["notes"] = self.notes
        data["warnings"] = list(self.warnings)
        if self.provenance is not None:
            data["provenance"] = self.provenance
        return data


T_END_RANGE = (1e-3, 1e9)  # dimensionless window t_end c


def t_end_dimensionless(case: Case, t_end_s: float | None) -> float:
    """The modelled window in units of 1/c; default 4 pi (i.e. 4 pi / c seconds)."""
    if t_end_s is None:
        return DEFAULT_T_END
    from twoball._common.errors import ParameterError, real_number

    # [1e-3, 1e9] time units 1/c: shorter windows hold no sample of the series,
    # longer ones overflow the sample counts (and the resource guards refuse far less)
    low, high = T_END_RANGE[0] / case.wave_speed, T_END_RANGE[1] / case.wave_speed
    valid = f"a window in [{low:.3g}, {high:.3g}] s (1e-3 to 1e9 times 1/c)"
    value = real_number("t_end", t_end_s, valid)
    if not (low <= value <= high):
        raise ParameterError("t_end", valid, t_end_s)
    return value / case.scalings.time


def report_liftoff(
    case: Case,
    motion: PoleMotion,
    *,
    backend: str,
    sigma: str,
    recontact: Horizon = "window",
    t_end_s: float | None = None,
    extra: dict[str, Any] | None = None,
    warnings: Sequence[str] = (),
    reference: bool = True,
    window_given: bool | None = None,
    monitor: Monitor | None = None,
) -> LiftoffReport:
    """Apply the shared lift-off criteria to any backend's pole motion; report in SI.

    ``window_given``: whether the user gave the window (default: ``t_end_s`` is
    given); a unit slip in it is suggested only then.

    ``warnings`` come from the backend (time step, mesh); the closed-form guards
    (:mod:`twoball.modal.guards`) add the re-contact window's and, with
    ``reference``, the ``truncation`` block: the converged series beside the
    N-result (~10 ms for the basketball, up to ~1 s for D -> 0, where the series
    converges slowly); then the inputs far from any ball and the windows in which
    nothing can lift off (:func:`twoball.modal.guards.case_warnings`, ``span_warnings``).
    ``monitor`` (:class:`~twoball._common.monitor.Monitor`) is told as the converged
    reference is computed; the motion tells its own (:attr:`ModalSeries.monitor`).
    """
    result = find_liftoff(
        motion, case.gamma, t_end=t_end_dimensionless(case, t_end_s), horizon=recontact
    )
    extra, notes = dict(extra or {}), list(warnings)
    from twoball.modal.guards import case_warnings, liftoff_guards, span_warnings, window_warnings

    if reference:
        found, block = liftoff_guards(case, result, backend, sigma, monitor)
        notes += found
        extra["truncation"] = block.as_dict()
    else:
        notes += window_warnings(case, result)
    given = t_end_s is not None if window_given is None else window_given
    notes += case_warnings(case) + span_warnings(case, result, given)
    return LiftoffReport(case, result, backend, sigma, recontact, extra, tuple(notes))


def legendre_liftoff(
    case: Case,
    sigma: FilterKind = "lanczos",
    recontact: Horizon = "window",
    t_end_s: float | None = None,
    *,
    reference: bool = True,
    monitor: Monitor | None = None,
) -> LiftoffReport:
    """Lift-off of the closed-form CEM, eqs. (3.12)-(3.16) with criteria (i)-(ii) of §3(a).

    ``monitor`` (:class:`~twoball._common.monitor.Monitor`) is told as the series
    and the converged reference are evaluated; it may stop the work by raising.
    Its cost (:func:`twoball.modal.cost.case_liftoff_work`) is the caller's to
    check before (:func:`twoball._costs.check_series`).
    """
    t_end_dimensionless(case, t_end_s)  # a bad window is refused before any work
    series = legendre_series(
        case.phi_a,
        case.damping_law,
        SpectralFilter(sigma, case.modes),
        stiffness=case.stiffness,
        monitor=monitor,
    )
    return report_liftoff(
        case,
        series,
        backend="legendre",
        sigma=sigma,
        recontact=recontact,
        t_end_s=t_end_s,
        reference=reference,
        monitor=monitor,
    )
