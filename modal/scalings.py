"""SI ranges of the case parameters and the one place that defines the scalings.

Inside the solvers everything is dimensionless: length unit R, time unit 1/c,
velocity unit R c, acceleration unit R c^2, and gravity enters only as
``gamma = g / (R c^2)`` (§3(b)).  The ranges keep those numbers far from
overflow; each ``check_*`` raises :class:`~twoball._common.errors.ParameterError`
naming the parameter and its valid range.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from numbers import Real

from twoball._common.choices import STANDARD_GRAVITY
from twoball._common.errors import ParameterError, bounded, real_number

# Physically meaningful magnitudes (SI).  They also keep the dimensionless numbers
# of the model (gamma = g / (R c^2), |v0| / (R c), t_end c) far from overflow.
RADIUS_RANGE = (1e-6, 1e6)  # m: a micrometre bubble to a 1000 km balloon
WAVE_SPEED_RANGE = (1e-6, 1e9)  # 1/s
G_RANGE = (1e-6, 1e6)  # m/s^2
V0_MAX = 1e6  # m/s
PRESSURE_RANGE = (1e-6, 1e12)  # Pa
MASS_RANGE = (1e-12, 1e12)  # kg
BENDING_RANGE = (0.0, 1e6)  # N m: flexural rigidity B (a tennis ball's is ~0.02)
MODES_MAX = 10**6  # far above what the resource guards let run


def check_radius(radius: object) -> float:
    """Ball radius R [m] in :data:`RADIUS_RANGE`."""
    return bounded("radius", radius, *RADIUS_RANGE, "m")


def check_wave_speed(wave_speed: object) -> float:
    """Angular wave speed c [1/s] in :data:`WAVE_SPEED_RANGE`, eq. (3.8)."""
    return bounded("wave_speed", wave_speed, *WAVE_SPEED_RANGE, "1/s")


def check_g(g: object) -> float:
    """Gravitational acceleration [m/s^2] in :data:`G_RANGE`."""
    return bounded("g", g, *G_RANGE, "m/s^2")


def check_v0(v0: object) -> float:
    """``|v0|`` [m/s] of an impact speed: nonzero, ``|v0| <= V0_MAX`` (the sign is ignored)."""
    valid = f"a nonzero speed with |v0| <= {V0_MAX:g} [m/s]"
    speed = abs(real_number("v0", v0, valid))
    if not (0.0 < speed <= V0_MAX):
        raise ParameterError("v0", valid, v0)
    return speed


def check_modes(modes: object) -> int:
    """Legendre truncation N: an integer in [1, :data:`MODES_MAX`], eq. (3.16)."""
    valid = f"an integer in [1, {MODES_MAX}]"
    if isinstance(modes, bool) or not isinstance(modes, Real):
        raise ParameterError("modes", valid, modes)
    if not (math.isfinite(modes) and int(modes) == modes and 1 <= modes <= MODES_MAX):
        raise ParameterError("modes", valid, modes)
    return int(modes)


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

    def __post_init__(self) -> None:
        object.__setattr__(self, "radius", check_radius(self.radius))
        object.__setattr__(self, "wave_speed", check_wave_speed(self.wave_speed))
        object.__setattr__(self, "g", check_g(self.g))

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


def membrane_mass(radius: float, pressure: float, wave_speed: float) -> float:
    """The mass m [kg] of a pressurised membrane ball: ``m = 2 pi R P / c^2``.

    The inverse of :func:`wave_speed_from_pressure`: with the tension ``T = P R /
    2`` (§4(b)) and ``c^2 = T / (rho R^2)``, eq. (3.8), the surface density is ``rho
    = P / (2 R c^2)`` and ``m = 4 pi R^2 rho``.  The paper's basketball: R = 0.12
    m, P = 77200 Pa, c = 320.4 1/s give m = 0.567 kg.

    Examples
    --------
    >>> round(membrane_mass(0.12, 77200.0, 320.4), 4)
    0.5667
    """
    return 2.0 * math.pi * radius * pressure / wave_speed**2


def wave_speed_from_pressure(pressure: float, mass: float, radius: float) -> float:
    """Angular wave speed c [1/s] from excess pressure P [Pa], mass m [kg], radius R [m].

    Tension ``T = P R / 2`` and surface density ``rho = m / (4 pi R^2)`` (§4(b)),
    then ``c = sqrt(T / rho) / R``, eq. (3.8).  Table 2: P = 77200, m = 0.567,
    R = 0.12 gives c = 320.4 1/s.
    """
    pressure = bounded("pressure", pressure, *PRESSURE_RANGE, "Pa")
    mass = bounded("mass", mass, *MASS_RANGE, "kg")
    radius = check_radius(radius)
    # within the bounds above, T / rho <= 5e42: no overflow or underflow
    tension = pressure * radius / 2.0
    density = mass / (4.0 * math.pi * radius**2)
    wave_speed = math.sqrt(tension / density) / radius
    low, high = WAVE_SPEED_RANGE
    if not (low <= wave_speed <= high):
        raise ParameterError(
            "pressure",
            f"such that c = sqrt(2 pi P R / m) is in [{low:g}, {high:g}] 1/s "
            f"(m = {mass:g} kg, R = {radius:g} m)",
            pressure,
        )
    return wave_speed
