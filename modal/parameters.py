"""One impact of the lower ball in SI units: :class:`Case`, its presets and its phi_a rule.

The scalings to the dimensionless model and the SI ranges are in
:mod:`twoball.modal.scalings`, the measured parameters of the presets in
:mod:`twoball.modal.presets`; SI lives at the edges
(CLI, files, reports).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field, replace
from typing import Any

from twoball._common.errors import ParameterError, bounded, real_number
from twoball._common.keywords import checked
from twoball.modal.damping import ModalRatio, Rayleigh
from twoball.modal.initial import check_phi_a, phi_a_from_v0
from twoball.modal.membrane import Membrane
from twoball.modal.presets import MEASURED, Measured
from twoball.modal.scalings import (
    BENDING_RANGE,
    PRESSURE_RANGE,
    STANDARD_GRAVITY,
    Scalings,
    check_g,
    check_modes,
    check_radius,
    check_v0,
    check_wave_speed,
    wave_speed_from_pressure,
)
from twoball.modal.stiffness import ATMOSPHERE, GAS_MODELS, Stiffness, stiffness_from_si


def _number(name: str, value: object, valid: str) -> float:
    return real_number(name, value, valid)


#: ``phi_a`` request meaning "derive it from ``|v0|``, R and c by eq. (3.7)".
FROM_V0 = "eq. (3.7)"
_SAME = 1e-12  # relative: a typed value equal to the measured one to double precision


def _measured(name: str | None) -> Measured | None:
    if name is None:
        return None
    if not isinstance(name, str):
        raise ParameterError("preset", "one of " + ", ".join(sorted(MEASURED)), name)
    try:
        return MEASURED[name]
    except KeyError:
        raise ParameterError("preset", "one of " + ", ".join(sorted(MEASURED)), name) from None


def _same(a: float, b: float) -> bool:
    return math.isclose(a, b, rel_tol=_SAME, abs_tol=0.0)


@checked
@dataclass(frozen=True)
class Case:
    """One impact of the lower ball, in SI units, with one rule for phi_a.

    The contact angle phi_a is (1) the value given; else (2) the preset's
    measured phi_a when R, c and ``|v0|`` are the preset's own measured values (so
    typing a preset's own value never changes the answer); else (3) derived from
    ``|v0|``, R and c by eq. (3.7) (with the enclosed gas's energy added when
    ``gas`` is set).  :attr:`phi_a_source` says which, and
    :attr:`phi_a_note` explains when (3) departs from a preset's measured angle.

    Parameters
    ----------
    radius : float
        R [m], > 0.
    wave_speed : float
        Angular wave speed c [1/s], > 0, eq. (3.8).
    v0 : float
        Impact speed [m/s]; ``|v0|`` is used.  A negative value is read as the
        paper's signed velocity (Fig. 6: v0 = -4.1 m/s, downwards) and said in
        :attr:`notes`; only ``v0^2`` enters eqs. (3.6)-(3.7).
    phi_a : float or None or "eq. (3.7)"
        Contact (truncation) angle [rad] in (pi/2, pi - 1e-6], eq. (3.3); None: by the
        rule above; ``"eq. (3.7)"``: from ``|v0|``, R, c by eq. (3.7) in any case.
    damping : float
        Modal damping ratio D in [0, 1), eq. (3.14).
    modes : int
        Legendre truncation N >= 1, eq. (3.16).
    g : float
        Gravitational acceleration [m/s^2].
    bending : float
        Flexural rigidity B [N m] >= 0 of the wall (0: the paper's membrane);
        see :mod:`twoball.modal.stiffness`.
    gas : {"none", "isothermal", "adiabatic"}
        The enclosed gas's compression law (none: the paper's membrane).
    pressure : float or None
        Excess pressure P [Pa]; with bending or gas it sets ``T = P R / 2``
        (§4(b)) and the gas pressure ``P + atmosphere``.  Unused otherwise.
    atmosphere : float
        Ambient pressure [Pa] (default 101325).
    membrane : Membrane or {"paper", "pressurised"}
        The membrane operator (:mod:`twoball.modal.membrane`): the paper's
        ``omega_n^2 = n (n + 1)`` (default) or the one consistent with the
        pressure, ``(n - 1)(n + 2)``, which needs a gas (docs/pressurised.rst).
        Stored as a :class:`~twoball.Membrane`.
    rayleigh : Rayleigh or None
        A Rayleigh damping law in SI (alpha [1/s], beta [s]) instead of the
        modal ratio D on every mode; ``Rayleigh()`` is fitted to D at the
        lowest vibrating mode and at degree N (:attr:`damping_law`).  None:
        the paper's ratio D, eq. (3.14).
    preset_name : str or None
        The preset whose measurements the case starts from (default
        ``basketball``, whose values are the defaults above); None for a case of
        the user's own measurements (phi_a then given or from eq. (3.7)).
    phi_a_source : str, optional
        Set by the class: ``"given"``, ``"measured (<preset>)"`` or ``"eq. (3.7)"``.

    Examples
    --------
    >>> import twoball
    >>> case = twoball.Case.preset("basketball")
    >>> case.radius, case.wave_speed, case.v0, case.phi_a, case.phi_a_source
    (0.12, 320.0, 4.1, 2.6, 'measured (basketball)')
    >>> slower = case.derive(v0=3.0)  # phi_a follows eq. (3.7) at the new speed
    >>> round(slower.phi_a, 4), slower.phi_a_source
    (2.6719, 'eq. (3.7)')
    """

    radius: float = 0.12
    wave_speed: float = 320.0
    v0: float = 4.1
    phi_a: float | None = None
    damping: float = 0.13
    modes: int = 30
    g: float = STANDARD_GRAVITY
    preset_name: str | None = "basketball"
    phi_a_source: str | None = None
    bending: float = 0.0
    gas: str = "none"
    pressure: float | None = None
    atmosphere: float = ATMOSPHERE
    membrane: Membrane | str = Membrane()
    rayleigh: Rayleigh | None = None
    #: The v0 as given when it was negative (the paper's sign: downwards), else None.
    v0_given: float | None = field(default=None, compare=False, repr=False)
    #: True when c came from the pressure and the mass (:meth:`from_pressure`).
    pressure_sets_c: bool = field(default=False, compare=False, repr=False)

    def __post_init__(self) -> None:
        object.__setattr__(self, "radius", check_radius(self.radius))
        object.__setattr__(self, "wave_speed", check_wave_speed(self.wave_speed))
        object.__setattr__(self, "g", check_g(self.g))
        given = self.v0
        object.__setattr__(self, "v0", check_v0(self.v0))
        if given != self.v0:  # negative: kept to say how it was read
            object.__setattr__(self, "v0_given", float(given))
        elif self.v0_given is not None and not (  # kept through a copy: still -|v0|?
            isinstance(self.v0_given, float) and self.v0_given == -self.v0
        ):
            valid = "None (set by the class from a negative v0)"
            raise ParameterError("v0_given", valid, self.v0_given)
        if not isinstance(self.pressure_sets_c, bool) or (
            self.pressure_sets_c and self.pressure is None
        ):
            valid = "False (set by Case.from_pressure)"
            raise ParameterError("pressure_sets_c", valid, self.pressure_sets_c)
        damping = _number("damping", self.damping, "in [0, 1)")
        if not (0.0 <= damping < 1.0):
            raise ParameterError("damping", "in [0, 1)", self.damping)
        object.__setattr__(self, "damping", damping)
        object.__setattr__(self, "modes", check_modes(self.modes))
        if self.preset_name is not None and not isinstance(self.preset_name, str):
            raise ParameterError("preset", "a preset name or None", self.preset_name)
        self._check_stiffness()
        phi_a, source = self._resolve_phi_a()
        object.__setattr__(self, "phi_a", phi_a)
        object.__setattr__(self, "phi_a_source", source)

    def _check_stiffness(self) -> None:
        bending = bounded("bending", self.bending, *BENDING_RANGE, "N m")
        if not isinstance(self.gas, str) or self.gas not in GAS_MODELS:
            raise ParameterError("gas", "one of " + ", ".join(GAS_MODELS), self.gas)
        if self.pressure is not None:
            object.__setattr__(
                self, "pressure", bounded("pressure", self.pressure, *PRESSURE_RANGE, "Pa")
            )
        atmosphere = bounded("atmosphere", self.atmosphere, 0.0, PRESSURE_RANGE[1], "Pa")
        if self.gas == "none" and atmosphere != ATMOSPHERE:  # it acts on the gas alone
            raise ParameterError(
                "atmosphere",
                f"left at {ATMOSPHERE:g} Pa without a gas (it sets the enclosed gas's "
                "pressure P + atmosphere; give gas isothermal or adiabatic)",
                self.atmosphere,
            )
        object.__setattr__(self, "bending", bending)
        object.__setattr__(self, "atmosphere", atmosphere)
        object.__setattr__(self, "membrane", Membrane.of(self.membrane))
        if self.rayleigh is not None and not isinstance(self.rayleigh, Rayleigh):
            raise ParameterError("rayleigh", "a twoball.Rayleigh or None", self.rayleigh)
        self.stiffness  # noqa: B018 -- raises ParameterError when pressure is missing

    @property
    def stiffness(self) -> Stiffness:
        """The dimensionless spectrum: membrane operator, bending ratio beta, gas stiffness."""
        return stiffness_from_si(
            radius=self.radius,
            pressure=self.pressure,
            bending=self.bending,
            gas=self.gas,
            atmosphere=self.atmosphere,
            membrane=self.membrane,
        )

    @property
    def stiff(self) -> bool:
        """True when the membrane operator, bending or gas departs from the paper's membrane."""
        return self.bending > 0.0 or self.gas != "none" or self.membrane.pressurised

    @property
    def damping_law(self) -> ModalRatio | Rayleigh:
        """The damping law, dimensionless (units of c): what the solvers take.

        ``ModalRatio(D)`` without :attr:`rayleigh`; else the Rayleigh law with
        ``alpha / c`` and ``beta c``, or, for ``Rayleigh()``, the one whose ratio
        is D at :meth:`~twoball.modal.stiffness.Stiffness.fit_band` (sqrt(2) and
        ``sqrt(N (N + 1))`` for the paper's membrane).
        """
        if self.rayleigh is None:
            return ModalRatio(self.damping)
        if self.rayleigh.fitted:
            return Rayleigh.fit(self.damping, *self.stiffness.fit_band(self.modes))
        return self.rayleigh.scaled(self.wave_speed)

    @property
    def floor_time(self) -> float:
        """Estimated time [s] from maximum compression until the ball leaves the floor.

        ``pi / (2 c)``: half the period of the pressure spring ``k = 2 pi R P``
        (:func:`twoball.modal.stiffness.floor_contact_time`).
        """
        from twoball.modal.stiffness import floor_contact_time

        return floor_contact_time(self.wave_speed)

    def _resolve_phi_a(self) -> tuple[float, str]:
        """The rule for phi_a: given, else the preset's measurement, else eq. (3.7)."""
        measured = _measured(self.preset_name)
        if self.phi_a_source is not None and (
            not isinstance(self.phi_a_source, str) or not self._known_source(self.phi_a_source)
        ):
            valid = "None (set by the class), 'given', 'eq. (3.7)' or 'measured (<preset>)'"
            raise ParameterError("phi_a_source", valid, self.phi_a_source)
        if self.phi_a is None or self.phi_a == FROM_V0:
            if (
                self.phi_a is None
                and measured is not None
                and measured.phi_a is not None
                and self.at_measured_point
            ):
                phi_a, source = measured.phi_a, f"measured ({self.preset_name})"
            else:
                phi_a, source = self._phi_a_from_v0(), FROM_V0
            if self.phi_a_source not in (None, source):  # a source the rule did not give
                raise ParameterError(
                    "phi_a_source", f"None (set by the class; here {source!r})", self.phi_a_source
                )
            return phi_a, source
        phi_a = check_phi_a(self.phi_a)
        source = self.phi_a_source or "given"
        if source == "given":
            return phi_a, source
        if source == FROM_V0:  # kept through derive(): still the root of eq. (3.7)?
            if phi_a == self._phi_a_from_v0():
                return phi_a, source
        if measured is not None and source == f"measured ({self.preset_name})":
            if self.at_measured_point and measured.phi_a is not None and phi_a == measured.phi_a:
                return phi_a, source
        raise ParameterError(
            "phi_a_source", "None, 'given' or consistent with the preset", self.phi_a_source
        )

    def _phi_a_from_v0(self) -> float:
        """Eq. (3.7) with the energies of the gas and of the membrane operator."""
        stiffness = self.stiffness
        return phi_a_from_v0(
            self.v0, self.radius, self.wave_speed, stiffness.gas, stiffness.membrane
        )

    @staticmethod
    def _known_source(source: str) -> bool:
        """Whether ``source`` is one of the words the class itself writes."""
        measured = [f"measured ({name})" for name in MEASURED]
        return source in ("given", FROM_V0, *measured)

    @property
    def at_measured_point(self) -> bool:
        """True if R, c and ``|v0|`` are the preset's own measured values."""
        m = _measured(self.preset_name)
        return (
            m is not None
            and _same(self.radius, m.radius)
            and _same(self.wave_speed, m.wave_speed)
            and _same(self.v0, m.v0)
        )

    @property
    def phi_a_note(self) -> str | None:
        """Why phi_a differs from the preset's measured angle (eq. (3.7) applied), or None."""
        m = _measured(self.preset_name)
        if m is None or m.phi_a is None or self.phi_a_source != FROM_V0 or self.phi_a == m.phi_a:
            return None
        moved = [
            f"{label} = {value:g} {unit}"
            for label, value, ref, unit in (
                ("R", self.radius, m.radius, "m"),
                ("c", self.wave_speed, m.wave_speed, "1/s"),
                ("|v0|", self.v0, m.v0, "m/s"),
            )
            if not _same(value, ref)
        ]
        if not moved:  # asked for at the preset's own point (a sweep's one rule, or by name)
            return (
                f"phi_a = {self.phi_a:.4f} rad from eq. (3.7), as asked, at the "
                f"{self.preset_name} preset's own R, c, |v0| (its measured {m.phi_a:g} rad "
                "not used)"
            )
        return (
            f"phi_a = {self.phi_a:.4f} rad from eq. (3.7) for {', '.join(moved)}; the "
            f"{self.preset_name} preset's measured {m.phi_a:g} rad applies only at its own "
            "R, c, |v0|"
        )

    @property
    def v0_note(self) -> str | None:
        """How a negative v0 was read (None for a positive one)."""
        if self.v0_given is None:
            return None
        return (
            f"v0 = {self.v0_given:g} m/s read as an impact at {self.v0:g} m/s downwards (the "
            "paper's sign, Fig. 6: v0 < 0 falls); the model uses |v0|"
        )

    @property
    def pressure_note(self) -> str | None:
        """That the excess pressure acts on nothing here, or None.

        P acts with bending or gas (the tension ``T = P R / 2`` and the gas's
        pressure) and sets c with the mass (:meth:`from_pressure`); on the paper's
        membrane with c given, the lift-off does not depend on it.  (The drop on
        the floor uses it for the ball's mass and gas: :func:`twoball.bounce`.)
        """
        if self.pressure is None or self.stiff or self.pressure_sets_c:
            return None
        return (
            f"P = {self.pressure:g} Pa has no effect on this lift-off: the paper's membrane "
            "takes its tension through c alone (P acts with bending or gas, and sets c "
            "with the mass through Case.from_pressure)"
        )

    @property
    def notes(self) -> list[str]:
        """The remarks on how the case was read: :attr:`phi_a_note`, :attr:`v0_note`,
        :attr:`pressure_note`."""
        return [note for note in (self.phi_a_note, self.v0_note, self.pressure_note) if note]

    @property
    def scalings(self) -> Scalings:
        """The units of the dimensionless model for this case."""
        return Scalings(self.radius, self.wave_speed, self.g)

    @property
    def gamma(self) -> float:
        """Dimensionless gravity ``g / (R c^2)``."""
        return self.scalings.gamma

    def as_dict(self) -> dict[str, Any]:
        """The case in SI, JSON-ready, with ``phi_a_source`` and ``membrane``.

        Bending and gas keys (and beta, omega_0^2 of the breathing mode) appear
        only for a stiffened ball, ``rayleigh`` only with a Rayleigh law (SI and
        dimensionless coefficients).
        """
        out = {
            "radius_m": self.radius,
            "wave_speed_1_s": self.wave_speed,
            "v0_m_s": self.v0,
            "phi_a_rad": self.phi_a,
            "phi_a_source": self.phi_a_source,
            "damping": self.damping,
            "modes": self.modes,
            "g_m_s2": self.g,
            "preset": self.preset_name,
            "membrane": self.membrane.kind,
        }
        if self.stiff:
            stiffness = self.stiffness
            out.update(
                bending_N_m=self.bending,
                gas=self.gas,
                pressure_Pa=self.pressure,
                atmosphere_Pa=self.atmosphere,
                beta=stiffness.beta,
                omega0_squared=stiffness.breathing,
            )
        if self.rayleigh is not None:
            out["rayleigh"] = self.rayleigh_dict()
        return out

    def rayleigh_dict(self) -> dict[str, Any]:
        """The Rayleigh law in SI (``alpha_1_s``, ``beta_s``), units of c and ``fitted``."""
        law = self.damping_law
        if not isinstance(law, Rayleigh):
            raise ParameterError("rayleigh", "a twoball.Rayleigh law in this case", None)
        fitted = self.rayleigh.fitted
        return {
            "alpha_1_s": law.alpha * self.wave_speed if fitted else self.rayleigh.alpha,
            "beta_s": law.beta / self.wave_speed if fitted else self.rayleigh.beta,
            "alpha": law.alpha,
            "beta": law.beta,
            "fitted": fitted,
        }

    def with_v0(self, v0: float) -> Case:
        """This case with a new impact speed; phi_a by the rule (see :class:`Case`)."""
        return self.derive(v0=v0)

    def derive(self, **changes: Any) -> Case:
        """A copy with ``changes``; phi_a follows the rule again if v0, c or R changes.

        Without ``phi_a`` in ``changes``, a new v0, c or R (or ``preset_name``)
        re-applies the rule: the preset's measured phi_a at its own values, eq.
        (3.7) elsewhere.  ``phi_a="eq. (3.7)"`` asks for eq. (3.7) explicitly.
        ``gas``, ``atmosphere`` and ``membrane`` re-apply the rule too (their
        energies enter eq. (3.7)); ``pressure`` is not a change here: it comes with the mass
        through :meth:`from_pressure`, which sets c and T together.
        This is how Fig. 12 varies one parameter at a time.
        """
        if "phi_a_source" in changes:
            raise ParameterError("phi_a_source", "set by the class, not given", None)
        hidden = ("phi_a_source", "pressure", "v0_given", "pressure_sets_c")
        known = [f for f in self.__dataclass_fields__ if f not in hidden]
        for name in changes:
            if name not in known:
                hint = (
                    " (pressure and mass: Case.from_pressure)"
                    if name in ("pressure", "mass")
                    else ""
                )
                valid = "a field of Case, one of " + ", ".join(known) + hint
                raise ParameterError(name, valid, None)
        rule = ("v0", "wave_speed", "radius", "preset_name", "gas", "atmosphere", "membrane")
        if "phi_a" in changes or any(k in changes for k in rule):
            changes = {"phi_a": None, **changes, "phi_a_source": None}
        if "v0" in changes:
            changes["v0_given"] = None
        if "wave_speed" in changes or "radius" in changes:  # c no longer P's and m's
            changes["pressure_sets_c"] = False
        documented = self._documented_pressure(changes)
        if documented is not None:
            changes["pressure"] = documented
        return replace(self, **changes)

    def _documented_pressure(self, changes: dict[str, Any]) -> float | None:
        """The preset's own pressure when ``changes`` make a case without one stiff.

        A preset without bending or gas keeps no pressure (it would act on
        nothing, :attr:`pressure_note`), though it has one: the basketball's 77200 Pa
        (Table 2, with m = 0.567 kg its c of eq. (3.8)).  Bending or a gas given to it
        need the tension ``T = P R / 2`` (§4(b)): they take that pressure, as the
        drop does, rather than asking for it.
        """
        if self.pressure is not None or self.preset_name not in MEASURED:
            return None
        own = MEASURED[self.preset_name]
        radius = changes.get("radius", self.radius)
        wave_speed = changes.get("wave_speed", self.wave_speed)
        if radius != own.radius or wave_speed != own.wave_speed:
            return None  # another ball: the preset's pressure is not its own
        bending = changes.get("bending", self.bending)
        gas = changes.get("gas", self.gas)
        if not (bending or gas != "none"):
            return None
        return MEASURED[self.preset_name].pressure

    @classmethod
    def preset(cls, name: str = "basketball", **changes: Any) -> Case:
        """The named preset (``basketball``: Table 2, Fig. 11), optionally with changes.

        ``Case.preset("basketball", v0=3.0)`` is the preset with a new impact speed
        and phi_a from eq. (3.7) (see :class:`Case`).
        """
        base = preset(name)
        return base.derive(**changes) if changes else base

    @classmethod
    def from_pressure(
        cls,
        pressure: float,
        mass: float,
        *,
        preset: str | None = "basketball",
        **changes: Any,
    ) -> Case:
        """A case whose wave speed comes from excess pressure P [Pa] and mass m [kg].

        ``c`` by eq. (3.8) with ``T = P R / 2`` and ``rho = m / (4 pi R^2)`` (§4(b));
        R and the other values from ``changes``, else from the preset (None: the
        class defaults without a preset).  phi_a by the rule of :class:`Case`.
        """
        if "wave_speed" in changes:
            raise ParameterError("wave_speed", "given alone, not with pressure and mass")
        base = cls(preset_name=None) if preset is None else cls.preset(preset)
        radius = changes.get("radius", base.radius)
        wave_speed = wave_speed_from_pressure(pressure, mass, radius)
        # P also sets T = P R / 2 of bending and gas (and the gas's energy in eq. (3.7))
        base = replace(base, pressure=float(pressure), phi_a=None, phi_a_source=None)
        case = base.derive(**changes, wave_speed=wave_speed)
        return replace(case, pressure_sets_c=True)

    @classmethod
    def from_measurements(
        cls,
        *,
        radius: float,
        v0: float,
        wave_speed: float | None = None,
        pressure: float | None = None,
        mass: float | None = None,
        phi_a: float | None = None,
        damping: float = 0.13,
        modes: int = 30,
        g: float = STANDARD_GRAVITY,
        bending: float = 0.0,
        gas: str = "none",
        membrane: Membrane | str = "paper",
    ) -> Case:
        """A case of one's own measurements (no preset): c, or P and m; phi_a given or eq. (3.7).

        ``bending`` B [N m] and ``gas`` (:mod:`twoball.modal.stiffness`) need the
        excess pressure P for the tension ``T = P R / 2``; ``membrane`` is the
        operator (:mod:`twoball.modal.membrane`).
        """
        if wave_speed is None:
            if pressure is None or mass is None:
                raise ParameterError("wave_speed", "given, or both pressure and mass")
            wave_speed = wave_speed_from_pressure(pressure, mass, radius)
        elif mass is not None or (pressure is not None and bending == 0 and gas == "none"):
            raise ParameterError("wave_speed", "given alone, not with pressure and mass")
        return cls(
            radius,
            wave_speed,
            v0,
            phi_a,
            damping,
            modes,
            g,
            preset_name=None,
            bending=bending,
            gas=gas,
            pressure=pressure,
            membrane=membrane,
        )


PRESETS: dict[str, Case] = {
    name: Case(
        preset_name=name,
        radius=m.radius,
        wave_speed=m.wave_speed,
        v0=m.v0,
        damping=m.damping,
        modes=m.modes,
        bending=m.bending,
        gas=m.gas,
        pressure=m.pressure if m.bending or m.gas != "none" else None,
    )
    for name, m in MEASURED.items()
}


def preset(name: str) -> Case:
    """The named preset case (basketball, tennis, volleyball); see :data:`MEASURED`."""
    if not isinstance(name, str):
        raise ParameterError("preset", "one of " + ", ".join(sorted(PRESETS)), name)
    try:
        return PRESETS[name]
    except KeyError:
        raise ParameterError("preset", "one of " + ", ".join(sorted(PRESETS)), name) from None
