"""Case parameters in SI units and the one place that defines the scalings.

Inside the solvers everything is dimensionless: length unit R, time unit 1/c,
velocity unit R c, acceleration unit R c^2, and gravity enters only as
``gamma = g / (R c^2)`` (§3(b)).  SI lives at the edges (CLI, files, reports).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace

from .errors import ParameterError
from .initial import phi_a_from_v0

STANDARD_GRAVITY = 9.81  # m/s^2, the value used in the paper (§2)


@dataclass(frozen=True)
class Scalings:
    """Units of the dimensionless model: length R [m], time 1/c [s] (§3(b)).

    Parameters
    ----------
    radius : float
        R [m].
    wave_speed : float
        Angular wave speed c [1/s], eq. (3.8).
    g : float
        Gravitational acceleration [m/s^2].
    """

    radius: float
    wave_speed: float
    g: float = STANDARD_GRAVITY

    @property
    def length(self) -> float:
        """Length unit R [m]."""
        return self.radius

    @property
    def time(self) -> float:
        """Time unit 1/c [s]."""
        return 1.0 / self.wave_speed

    @property
    def velocity(self) -> float:
        """Velocity unit R c [m/s]."""
        return self.radius * self.wave_speed

    @property
    def acceleration(self) -> float:
        """Acceleration unit R c^2 [m/s^2]."""
        return self.radius * self.wave_speed**2

    @property
    def gamma(self) -> float:
        """Dimensionless gravity ``gamma = g / (R c^2) = R g rho / T`` (§3(b))."""
        return self.g / self.acceleration


def wave_speed_from_pressure(pressure: float, mass: float, radius: float) -> float:
    """Angular wave speed c [1/s] from excess pressure P [Pa], mass m [kg], radius R [m].

    Tension ``T = P R / 2`` and surface density ``rho = m / (4 pi R^2)`` (§4(b)),
    then ``c = sqrt(T / rho) / R``, eq. (3.8).  Table 2: P = 77200, m = 0.567,
    R = 0.12 gives c = 320.4 1/s.
    """
    _positive("--pressure", pressure)
    _positive("--mass", mass)
    _positive("--radius", radius)
    tension = pressure * radius / 2.0
    density = mass / (4.0 * math.pi * radius**2)
    return math.sqrt(tension / density) / radius


def _positive(name: str, value: float) -> float:
    value = float(value)
    if not (math.isfinite(value) and value > 0):
        raise ParameterError(name, "a finite number > 0", value)
    return value


@dataclass(frozen=True)
class Case:
    """One impact of the lower ball, in SI units.

    Parameters
    ----------
    radius : float
        R [m], > 0.
    wave_speed : float
        Angular wave speed c [1/s], > 0, eq. (3.8).
    v0 : float
        Impact speed [m/s]; the sign is ignored (``|v0|`` is used).
    phi_a : float
        Contact (truncation) angle [rad] in (pi/2, pi), eq. (3.3).
    damping : float
        Modal damping ratio D in [0, 1), eq. (3.14).
    modes : int
        Legendre truncation N >= 1, eq. (3.16).
    g : float
        Gravitational acceleration [m/s^2].
    """

    radius: float = 0.12
    wave_speed: float = 320.0
    v0: float = 4.1
    phi_a: float = 2.6
    damping: float = 0.13
    modes: int = 30
    g: float = STANDARD_GRAVITY

    def __post_init__(self) -> None:
        _positive("--radius", self.radius)
        _positive("--wave-speed", self.wave_speed)
        _positive("--g", self.g)
        v0 = float(self.v0)
        if not (math.isfinite(v0) and v0 != 0):
            raise ParameterError("--v0", "a finite nonzero speed [m/s]", self.v0)
        object.__setattr__(self, "v0", abs(v0))
        phi_a = float(self.phi_a)
        if not (math.pi / 2 < phi_a < math.pi):
            raise ParameterError("--phi-a", "in (pi/2, pi) = (1.5708, 3.1416) rad", self.phi_a)
        damping = float(self.damping)
        if not (0.0 <= damping < 1.0):
            raise ParameterError("--damping", "in [0, 1)", self.damping)
        if isinstance(self.modes, bool) or int(self.modes) != self.modes or self.modes < 1:
            raise ParameterError("--modes", "an integer >= 1", self.modes)
        object.__setattr__(self, "modes", int(self.modes))

    @property
    def scalings(self) -> Scalings:
        """The units of the dimensionless model for this case."""
        return Scalings(self.radius, self.wave_speed, self.g)

    @property
    def gamma(self) -> float:
        """Dimensionless gravity ``g / (R c^2)``."""
        return self.scalings.gamma

    def with_v0(self, v0: float) -> Case:
        """This case with a new impact speed and phi_a re-derived from eq. (3.7)."""
        return self.derive(v0=v0)

    def derive(self, **changes: float) -> Case:
        """A copy with ``changes``; phi_a follows eq. (3.7) if v0, c or R changes.

        This is how Fig. 12 varies one parameter at a time.
        """
        rederive = any(k in changes for k in ("v0", "wave_speed", "radius")) and (
            "phi_a" not in changes
        )
        case = replace(self, **changes)
        if rederive:
            return replace(case, phi_a=phi_a_from_v0(case.v0, case.radius, case.wave_speed))
        return case

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
    ) -> Case:
        """Build a case from c, or from P and m; phi_a from eq. (3.7) if not given."""
        if wave_speed is None:
            if pressure is None or mass is None:
                raise ParameterError("--wave-speed", "given, or both --pressure and --mass")
            wave_speed = wave_speed_from_pressure(pressure, mass, radius)
        elif pressure is not None or mass is not None:
            raise ParameterError("--wave-speed", "given alone, not with --pressure/--mass")
        _positive("--radius", radius)
        _positive("--wave-speed", wave_speed)
        if phi_a is None:
            phi_a = phi_a_from_v0(v0, radius, wave_speed)
        return cls(radius, wave_speed, v0, phi_a, damping, modes, g)


PRESETS: dict[str, Case] = {
    # Table 2 and Fig. 11: R, c measured; v0 and phi_a both measured; D fitted once.
    "basketball": Case(radius=0.12, wave_speed=320.0, v0=4.1, phi_a=2.6, damping=0.13, modes=30),
}


def preset(name: str) -> Case:
    """The named preset case (currently ``basketball``)."""
    try:
        return PRESETS[name]
    except KeyError:
        raise ParameterError("--preset", "one of " + ", ".join(sorted(PRESETS)), name) from None
