"""Accuracy guards of the closed-form facts: N-truncation and the re-contact window.

Each guard returns short warning strings (SI, actionable), empty when the result
is inside its trustworthy regime.  They judge any backend's lift-off, since every
backend truncates the same filtered series at N (eq. (3.16)) and applies the same
criteria (i)-(ii) of §3(a) over the same window.

Truncation (eq. (3.16))
    The N-truncated, filtered series is compared with its N -> infinity limit,
    the unfiltered damped series (3.14) followed to convergence
    (:func:`twoball.modal.converged.converged_legendre`, ~10-100 ms): from the
    N of the result (at least 30) the filtered N is doubled until the lift-off
    stays on one root, and that root is followed in the unfiltered series until
    it changes by less than 1e-7.  The result is always reported beside the
    N-result as a ``truncation`` block; a warning is added when t_l or v_l
    differs from the limit by more than :data:`TRUNCATION_WARNING` (5 %), when
    only one of them lifts off, or when the limit could not be established (then
    the error of the result is unknown, and the warning says so).  The paper's
    N = 30 (Lanczos) is 2.9 % low in v_l for the basketball: reported, not
    warned; N = 20 (6.3 %) is warned.  The tennis ball at N = 30 lifts off on a
    neighbouring root (0.583 ms against 0.518 ms, v_l -5.8 %): warned; from
    N = 60 on it is within 5 % (N = 60: v_l -4.6 %; N = 240: -0.3 %): quiet.

Re-contact window (§3(a)(ii))
    An accepted lift-off only means that no re-contact happened before the window
    ends.  The check is complete when (a) the window runs at least one refocusing
    period ``2 pi / c`` past t_l -- omega_n = sqrt(n (n + 1)) ~ n + 1/2 (eq. (3.11)),
    so after 2 pi every mode's phase has advanced by (2n + 1) pi and the wave that
    lifted the body is back at the pole -- and (b) the body is still rising at the
    window's end, ``t_end - t_l < v_l / g``: a body already falling back at t_end
    meets the (bounded) pole after the window, unchecked.  Either failing gives a
    warning.  Basketball default: 29.4 ms after t_l > 19.6 ms, apex at 390 ms:
    quiet; ``t_end`` = 0.005 s: lift-off at 0.48 ms, 4.5 ms of window < 19.6 ms and
    the apex (1.1 ms) passed: warned.

Inputs far from any ball (unit and sign slips)
    SI is read as typed; a value far outside any ball is most likely a unit
    slip, and it is said, with the value probably meant.  R outside
    :data:`BALL_RADIUS` (2 mm to 2 m: a bead to a push ball): ``radius`` = 120
    (meant mm) is a 120 m ball, warned "did you mean 0.12 m (120 mm)?".  ``|v0|``
    above :data:`IMPACT_SPEED` (100 m/s, beyond the fastest ball sports).  For the
    drop on the floor, a drop height above :data:`DROP_HEIGHT` (100 m: a ball
    dropped from a tower; ``--drop-height 1000``, meant mm, falls at 140 m/s)
    takes the place of the speed's check, and a gap between the body and the
    ball above :data:`GAP_LARGE` (1 m, several ball diameters; ``--gap 5``, meant
    mm) is said as well.  Each guess is the value read in mm (and cm, for a
    length) that lands inside the range.  The wave speed c more than
    :data:`SLIP_FACTOR` (100) times from its preset's (``--wave-speed 3.2e5``,
    meant 320 1/s; without a preset, outside :data:`WAVE_SPEED_BAND`), and the
    mass behind a pressure and mass (``--pressure 77200 --mass 567``, meant
    0.567 kg: ``m = 2 pi R P / c^2`` by eq. (3.8)) more than 100 times from its
    preset's (without one, outside :data:`BALL_MASS`) are said with the value
    read as 1/1000 of it (or 1000 times it) when that lands within ten times the
    preset's.  A sweep checks its values against the same ranges before any point
    runs (:func:`sweep_slips`), so that a sweep of slips is said even when no
    point is run.  A window
    in which nothing could lift off: longer than the flight ``2 |v0| / g`` of a
    body leaving at the impact speed, with the whole window as the re-contact
    horizon, every lift-off falls back inside it and is rejected (``t_end`` = 5,
    meant ms: 0.84 s of flight for the basketball; "did you mean 5 ms?"); shorter
    than ``pi / c``, near which the membrane's wave lifts the body, nothing lifted
    off yet (``t_end`` = 0.001: 1 ms < 9.8 ms).  These two only when nothing lifted
    off -- except that on a membrane the pole stays still until the wave front
    from the contact edge arrives (unit wave speed, eq. (3.9)) at ``phi_a / c``,
    so a lift-off in a window shorter than that (8.1 ms for the basketball) is
    said to be a truncation artefact.  A negative v0 is the paper's signed
    velocity (Fig. 6: v0 = -4.1 m/s, downwards): it is accepted as the impact
    speed ``|v0|`` with a note (:attr:`twoball.modal.parameters.Case.v0_note`),
    since only ``v0^2`` enters eq. (3.6)-(3.7) and an upward velocity would be no
    impact at all.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

from twoball._common.monitor import Monitor
from twoball.modal.liftoff import LiftoffResult
from twoball.modal.parameters import Case

TRUNCATION_WARNING = 0.05  # relative difference of t_l or v_l from the converged series
BALL_RADIUS = (2e-3, 2.0)  # m: a 4 mm bead to a 4 m push ball
IMPACT_SPEED = 100.0  # m/s: above the fastest ball sports (golf, jai alai ~80 m/s)
DROP_HEIGHT = 100.0  # m: a drop from a tower (44 m/s without air drag)
GAP_LARGE = 1.0  # m: several ball diameters between the body and the ball's top
SLIP_FACTOR = 100.0  # c or m this many times from the preset's: a slip of units (x1000)
WAVE_SPEED_BAND = (1.0, 1e5)  # 1/s, without a preset: the balls' 273-2000 1/s well inside
BALL_MASS = (1e-4, 100.0)  # kg, without a preset: a 0.1 g bead to a 100 kg medicine ball
REFOCUS_PERIOD = 2.0 * math.pi  # dimensionless: the wave is back at the pole after 2 pi / c


@dataclass(frozen=True)
class Truncation:
    """The N-truncated lift-off beside the converged series (SI).

    Attributes
    ----------
    modes : int
        N of the result.
    reference_modes : int
        N at which the unfiltered series converged (or stopped).
    converged : bool
        Whether the reference reached its tolerance (False for D = 0, where the
        series converges only algebraically at t_l).
    t_liftoff_s, v_liftoff_m_s : float or None
        Lift-off time [s] and velocity [m/s] of the converged series.
    t_difference, v_difference : float or None
        Relative differences ``result / converged - 1`` (None if either is missing).
    result_lifted : bool
        Whether the judged result lifts off.
    unknown : str or None
        Why the converged series could not be established (None: it was).
    """

    modes: int
    reference_modes: int
    converged: bool
    t_liftoff_s: float | None
    v_liftoff_m_s: float | None
    t_difference: float | None
    v_difference: float | None
    result_lifted: bool = True
    unknown: str | None = None

    def as_dict(self) -> dict[str, Any]:
        """JSON-ready block (SI)."""
        return {
            "modes": self.modes,
            "converged_modes": self.reference_modes,
            "converged": self.converged,
            "t_liftoff_s": self.t_liftoff_s,
            "v_liftoff_m_s": self.v_liftoff_m_s,
            "t_difference": self.t_difference,
            "v_difference": self.v_difference,
            "warning_above": TRUNCATION_WARNING,
            "not_converged_because": self.unknown,
        }


def _relative(value: float | None, reference: float | None) -> float | None:
    if value is None or reference is None or reference == 0:
        return None
    return value / reference - 1.0


def _unknown(case: Case, reference: Any) -> str | None:
    """Why the converged series was not established (None when it was)."""
    if reference.converged:
        return None
    if not reference.identified:
        shown = ", ".join(
            f"{n}: {'none' if t is None else f'{t * case.scalings.time * 1e3:.4g} ms'}"
            for n, t, _ in reference.filtered
        )
        return f"the lift-off of the filtered series did not settle as N doubled ({shown})"
    if case.damping == 0.0:
        return (
            f"the series did not converge by N = {reference.modes} (D = 0 converges only "
            "algebraically)"
        )
    return f"the unfiltered series did not settle on the lift-off by N = {reference.modes}"


def truncation(
    case: Case,
    result: LiftoffResult,
    base: LiftoffResult | None = None,
    monitor: Monitor | None = None,
) -> Truncation:
    """The converged-series lift-off beside ``result`` (same case, window and horizon).

    Parameters
    ----------
    case : Case
        The impact (SI); ``case.modes`` is the N of ``result``, and the least N
        of the reference (at least 30).
    result : LiftoffResult
        Any backend's lift-off (dimensionless), from
        :func:`twoball.modal.liftoff.find_liftoff`.
    base : LiftoffResult, optional
        ``result`` itself when it is the Lanczos closed form with ``case.modes``
        >= 30, the first root the reference tries (saves recomputing it).
    monitor : Monitor, optional
        Told as the converged series is computed (it may stop the work by raising).
    """
    from twoball.modal.converged import PAPER_MODES, converged_legendre

    horizon = "paper" if result.horizon == "paper" else "window"
    reference = converged_legendre(
        case,
        recontact=horizon,
        t_end=result.t_end,
        start_modes=max(case.modes, PAPER_MODES),
        base=base,
        flight=False,
        min_samples=201,
        monitor=monitor,
    )
    scale = case.scalings
    t_ref = None if reference.t is None else reference.t * scale.time
    v_ref = None if reference.velocity is None else reference.velocity * scale.velocity
    return Truncation(
        case.modes,
        reference.modes,
        reference.converged,
        t_ref,
        v_ref,
        _relative(result.t, reference.t),
        _relative(result.velocity, reference.velocity),
        result.lifted,
        _unknown(case, reference),
    )


def truncation_warnings(block: Truncation, backend: str = "legendre") -> list[str]:
    """A warning when the N-result is more than 5 % from the converged series.

    Also when only one of the two lifts off, and when the converged series could
    not be established (the error is then unknown).  For the closed form the
    difference is the N-truncation; for another backend it also holds its
    discretisation error (mesh, time step), so the text says so.
    """
    subject = f"N = {block.modes}" if backend == "legendre" else f"the {backend} result"
    if not block.converged:
        return [
            f"the truncation error of {subject} is not known: {block.unknown or 'no limit'}; "
            "compare with a larger number of modes N"
        ]
    if block.t_liftoff_s is None:
        if not block.result_lifted:
            return []
        return [
            f"{subject} lifts off, but the converged series (N -> infinity) does not within "
            "the window: the lift-off is an artefact of the truncation; raise the number of "
            "modes N"
        ]
    differences = [d for d in (block.t_difference, block.v_difference) if d is not None]
    if not differences:
        return [
            f"{subject} finds no lift-off; the converged series lifts off at "
            f"{block.t_liftoff_s * 1e3:.4g} ms with {block.v_liftoff_m_s:.4g} m/s"
        ]
    if max(abs(d) for d in differences) <= TRUNCATION_WARNING:
        return []
    t_text = f"{block.t_difference:+.1%}" if block.t_difference is not None else "-"
    v_text = f"{block.v_difference:+.1%}" if block.v_difference is not None else "-"
    converged = (
        f"the converged series ({block.t_liftoff_s * 1e3:.4f} ms, "
        f"{block.v_liftoff_m_s:.4g} m/s at N = {block.reference_modes})"
    )
    if backend != "legendre":
        return [
            f"{backend} result is t_l {t_text}, v_l {v_text} from {converged}: N = "
            f"{block.modes} truncation and discretisation (mesh, time step) together"
        ]
    return [
        f"N = {block.modes} truncation: t_l {t_text}, v_l {v_text} from {converged}; "
        "raise the number of modes N"
    ]


def window_warnings(case: Case, result: LiftoffResult) -> list[str]:
    """Warnings when the window is too short to have checked re-contact (module docstring)."""
    if not result.lifted or result.t is None or result.velocity is None:
        return []
    scale = case.scalings
    after = (result.t_end - result.t) * scale.time  # window left after lift-off [s]
    refocus = REFOCUS_PERIOD * scale.time
    apex = result.velocity * scale.velocity / case.g  # v_l / g [s]
    t_end_ms = result.t_end * scale.time * 1e3
    warnings = []
    if after < refocus:
        warnings.append(
            f"window too short for the re-contact check: it ends {after * 1e3:.3g} ms after "
            f"lift-off, before the wave returns to the pole (2 pi / c = {refocus * 1e3:.3g} ms); "
            f"lengthen the window t_end (now {t_end_ms:.4g} ms) to at least "
            f"{(result.t * scale.time + refocus) * 1e3:.4g} ms"
        )
    if after > apex:
        warnings.append(
            f"the body is falling back at the end of the window (apex v_l / g = "
            f"{apex * 1e3:.3g} ms after lift-off, window {after * 1e3:.3g} ms): its "
            "re-contact lies beyond the window t_end and was not checked"
        )
    return warnings


def _inside(value: float, bounds: tuple[float, float]) -> bool:
    return bounds[0] <= value <= bounds[1]


def _lengths_meant(value: float, bounds: tuple[float, float]) -> str:
    """``"; did you mean 0.12 m (120 mm)?"``: ``value`` read in mm or cm inside ``bounds``."""
    meant = [
        f"{value * factor:g} m ({value:g} {unit})"
        for factor, unit in ((1e-3, "mm"), (1e-2, "cm"))
        if _inside(value * factor, bounds)
    ]
    return f"; did you mean {' or '.join(meant)}?" if meant else ""


def _preset_value(case: Case, name: str) -> float | None:
    """The case's preset's measured ``wave_speed`` or ``mass`` (None without one)."""
    from twoball.modal.presets import MEASURED

    measured = MEASURED.get(case.preset_name or "")
    value = None if measured is None else getattr(measured, name, None)
    return None if value is None else float(value)


def slip_range(field: str, case: Case) -> tuple[float, float] | None:
    """The values of ``field`` said to be no slip of units for ``case`` (None: any value).

    ``field``: ``radius``, ``v0``, ``wave_speed`` [1/s], ``mass`` [kg] (behind a
    pressure and mass), ``drop_height`` or ``gap`` [m] (module docstring).
    """
    if field in ("wave_speed", "mass"):
        preset = _preset_value(case, field)
        if preset is None:
            return WAVE_SPEED_BAND if field == "wave_speed" else BALL_MASS
        return preset / SLIP_FACTOR, preset * SLIP_FACTOR
    return {
        "radius": BALL_RADIUS,
        "v0": (0.0, IMPACT_SPEED),
        "drop_height": (0.0, DROP_HEIGHT),
        "gap": (0.0, GAP_LARGE),
    }.get(field)


def _thousand_meant(value: float, preset: float | None, unit: str, small: str = "") -> str:
    """``"; did you mean 320 1/s?"``: ``value`` / 1000 (or x 1000) within ten times the preset's.

    ``small``: the unit a thousandth of ``unit`` is (``g`` for ``kg``), named beside it.
    """
    if preset is None:
        return ""
    for meant in (value * 1e-3, value * 1e3):
        if preset / 10.0 <= meant <= preset * 10.0:
            typed = f" ({value:g} {small})" if small and meant < value else ""
            return f"; did you mean {meant:g} {unit}{typed}?"
    return ""


def value_slip(field: str, value: float, case: Case) -> str | None:
    """The warning for a value of ``field`` outside :func:`slip_range`, with the value meant.

    None inside it (or for a field without a range).  ``case`` gives the preset and,
    for a drop height or a mass, g, R and the pressure.
    """
    bounds = slip_range(field, case)
    if bounds is None or _inside(value, bounds):
        return None
    if field == "radius":
        size = "larger" if value > BALL_RADIUS[1] else "smaller"
        return (
            f"R = {value:g} m is far {size} than any ball ({BALL_RADIUS[0]:g} to "
            f"{BALL_RADIUS[1]:g} m; lengths are in metres){_lengths_meant(value, BALL_RADIUS)}"
        )
    if field == "v0":
        return (
            f"|v0| = {value:g} m/s is far faster than any ball's impact (up to "
            f"{IMPACT_SPEED:g} m/s; speeds are in m/s); did you mean {value * 1e-3:g} m/s "
            f"({value:g} mm/s)?"
        )
    if field == "drop_height":
        speed = math.sqrt(2.0 * case.g * value)
        return (
            f"the drop height H = {value:g} m is far higher than any drop of a ball "
            f"(up to {DROP_HEIGHT:g} m; heights are in metres), an impact at |v0| = "
            f"sqrt(2 g H) = {speed:.4g} m/s{_lengths_meant(value, (0.0, DROP_HEIGHT))}"
        )
    if field == "gap":
        return (
            f"the gap Delta x = {value:g} m between the body and the ball's top is far larger "
            f"than in any stacked drop (up to {GAP_LARGE:g} m; lengths are in metres)"
            f"{_lengths_meant(value, (0.0, GAP_LARGE))}"
        )
    preset = _preset_value(case, field)
    if preset is None:
        where = f"outside {bounds[0]:g} to {bounds[1]:g}"
    else:
        factor = max(value / preset, preset / value)
        unit = "1/s" if field == "wave_speed" else "kg"
        where = f"{factor:.4g} times from the {case.preset_name} preset's {preset:g} {unit}"
    if field == "wave_speed":
        return (
            f"the wave speed c = {value:g} 1/s is {where} (c is the angular wave speed "
            f"sqrt(T / rho) / R in 1/s){_thousand_meant(value, preset, '1/s')}"
        )
    return (
        f"the mass m = {value:g} kg (with P = {case.pressure:g} Pa, c = "
        f"{case.wave_speed:.4g} 1/s by eq. (3.8)) is {where} (masses are in kg)"
        f"{_thousand_meant(value, preset, 'kg', 'g')}"
    )


def case_mass(case: Case) -> float | None:
    """The mass [kg] a case was given with its pressure (``2 pi R P / c^2``, eq. (3.8)), or None."""
    if not case.pressure_sets_c or case.pressure is None:
        return None
    return 2.0 * math.pi * case.radius * case.pressure / case.wave_speed**2


def case_warnings(
    case: Case, *, drop_height: float | None = None, gap: float | None = None
) -> list[str]:
    """R, ``|v0|``, c or the mass far outside any ball, with the value probably meant
    (module docstring).

    ``drop_height`` [m]: the drop's height, which set ``|v0| = sqrt(2 g H)``; it is
    judged in place of the speed (the user typed the height).  ``gap`` [m]: the
    whole bounce's gap between the body and the ball's top.  A wave speed that came
    from a pressure and a mass is judged by the mass (the user typed the mass).
    """
    mass = case_mass(case)
    checks: list[tuple[str, float | None]] = [
        ("radius", case.radius),
        ("drop_height", drop_height) if drop_height is not None else ("v0", case.v0),
        ("mass", mass) if mass is not None else ("wave_speed", case.wave_speed),
        ("gap", gap),
    ]
    said = (value_slip(field, value, case) for field, value in checks if value is not None)
    return [text for text in said if text is not None]


def sweep_slips(field: str, name: str, values: Any, case: Case) -> str | None:
    """One warning for the swept values of ``field`` (CLI ``name``) outside
    :func:`slip_range` for the base ``case``: how many, and the first one's warning.

    Checked on the values alone, before any point runs (and so also when the budget
    refuses the sweep); None when none is a slip.
    """
    import numpy as np

    bounds = slip_range(field, case)
    if bounds is None:
        return None
    array = np.asarray(values, dtype=float)
    outside = (array < bounds[0]) | (array > bounds[1])
    count = int(outside.sum())
    if count == 0:
        return None
    first = float(array[outside][0])
    text = value_slip(field, first, case)
    every = " (every value)" if count == array.size else ""
    return (
        f"{count} of {array.size} values of {name}{every} lie far outside any ball, the first "
        f"{name} = {first:g}: {text}"
    )


def span_warnings(case: Case, result: LiftoffResult, window_given: bool = True) -> list[str]:
    """A window in which nothing could lift off: longer than the flight, or shorter than
    the wave's transit to the pole (module docstring).

    ``window_given``: whether the user gave the window t_end; only then is a unit
    slip in it suggested ("did you mean 5 ms?"): the default window is no slip.
    """
    scale = case.scalings
    t_end = result.t_end * scale.time  # [s]
    flight = 2.0 * case.v0 / case.g  # [s]: a body leaving at |v0| is back after this
    transit = math.pi * scale.time  # [s]: pi / c, the membrane's lift-off ~ there
    front = case.phi_a * scale.time  # [s]: the membrane's wave front reaches the pole
    horizon = getattr(result, "horizon", "window")  # a contact history: the whole window
    if not result.lifted and horizon == "window" and t_end >= flight:
        said = (
            f"the window t_end = {t_end:g} s is {t_end * case.wave_speed:.3g} / c "
            f"({t_end / (2 * math.pi * scale.time):.3g} wave periods 2 pi / c): a body lifted "
            f"at up to |v0| = {case.v0:g} m/s falls back onto the ball within it "
            f"(2 |v0| / g = {flight:.3g} s), so every lift-off is rejected as a re-contact"
        )
        if not window_given:  # the default window: no slip to guess at
            return [f"{said}; only a window shorter than the flight can accept one"]
        return [
            f"{said}; did you mean {t_end:g} ms (t_end = {t_end * 1e-3:g} s)?"
            + (
                f" (that window too would end before the wave reaches the pole, ~pi / c = "
                f"{transit * 1e3:.3g} ms; the default is 4 pi / c = {4 * transit * 1e3:.3g} ms)"
                if t_end * 1e-3 < transit
                else ""
            )
        ]
    membrane = not case.stiff
    early = membrane and t_end < front  # the pole has not moved yet (unit wave speed)
    if not (early or (not result.lifted and t_end < transit)):
        return []
    why = (
        f"the wave front from the contact edge arrives at phi_a / c = {front * 1e3:.3g} ms"
        if membrane
        else "sooner with bending or gas"
    )
    consequence = (
        "a lift-off found in it is an artefact of the truncation"
        if result.lifted
        else "nothing can lift off in it"
    )
    return [
        f"the window ends at {t_end * 1e3:.3g} ms, before the wave reaches the pole "
        f"(~pi / c = {transit * 1e3:.3g} ms; {why}): {consequence}; lengthen the window "
        f"t_end (default 4 pi / c = {4 * transit * 1e3:.3g} ms)"
    ]


def liftoff_guards(
    case: Case,
    result: LiftoffResult,
    backend: str = "legendre",
    sigma: str = "lanczos",
    monitor: Monitor | None = None,
) -> tuple[list[str], Truncation]:
    """All closed-form guards of one lift-off: (warnings, truncation block).

    ``monitor`` is told as the converged reference is computed (:func:`truncation`).
    """
    from twoball.modal.converged import PAPER_MODES

    same = backend == "legendre" and sigma == "lanczos" and case.modes >= PAPER_MODES
    block = truncation(case, result, result if same else None, monitor)
    return window_warnings(case, result) + truncation_warnings(block, backend), block
