"""Parameters of the thin spherical shell ball: dimensionless and SI.

The shell (radius R, thickness h, Young's modulus E, Poisson's ratio nu, mass m,
gauge pressure P) enters the closed form (:mod:`twoball.modal.shell.spectrum`)
and the finite elements (:mod:`twoball.fem_shell`) through four numbers:

``poisson``
    nu in (0, 1/2].
``bending``
    ``beta_h = h^2 / (12 R^2) = D_b / (C R^2)``, with the in-plane stiffness
    ``C = E h / (1 - nu^2)`` [N/m] and the bending stiffness
    ``D_b = E h^3 / (12 (1 - nu^2))`` [N m].
``prestress``
    ``p = N0 / C`` with the inflation tension ``N0 = P R / 2`` [N/m] (Laplace's
    law for a sphere).  ``1 / p`` is the wall-stiffness ratio C / N0.
``gas``
    ``g = 3 kappa P_abs R / C``: the enclosed gas (kappa = 1 isothermal, 1.4
    adiabatic, ``P_abs = P + P_atm``) acting on the volume, i.e. on the n = 0
    mode only; the constants are those of :mod:`twoball.modal.stiffness`.

Units inside: length R, mass ``rho_s R^2`` per area (``rho_s = m / (4 pi R^2)``),
stiffness C, so that the frequency is ``Omega = omega R sqrt(rho_s / C)`` and the
time unit is ``R / c_e`` with the in-plane (extensional) wave speed
``c_e = sqrt(C / rho_s)`` [m/s].  :class:`ShellSI` converts back.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from twoball._common.errors import ParameterError, bounded, real_number
from twoball.modal.stiffness import ATMOSPHERE, GAS_MODELS

__all__ = ["ShellParameters", "ShellSI", "shell_from_si"]


def _nonnegative(name: str, value: object) -> float:
    """A finite float >= 0, else ParameterError naming ``name``."""
    valid = "a finite number >= 0"
    out = real_number(name, value, valid)
    if out < 0.0:
        raise ParameterError(name, valid, value)
    return out


@dataclass(frozen=True)
class ShellParameters:
    """Dimensionless shell: nu, ``beta_h = h^2/(12 R^2)``, ``p = N0/C``, ``g = 3 kappa P_abs R/C``.

    Parameters
    ----------
    poisson : float
        Poisson's ratio nu in (0, 0.5].
    bending : float
        ``beta_h = h^2 / (12 R^2)`` >= 0 (0: membrane shell, no bending).
    prestress : float
        ``p = N0 / C`` >= 0, the inflation tension over the in-plane stiffness.
    gas : float
        ``g = 3 kappa P_abs R / C`` >= 0, the enclosed gas's stiffness of the
        breathing mode (0: none).

    Raises
    ------
    ParameterError
        A value out of range, or a breathing mode that is not stable:
        ``Omega_0^2 = 2 (1 + nu) - 2 p + g`` must be > 0 (a tension above
        ``(1 + nu) C`` without gas cannot be held at constant pressure).
    """

    poisson: float
    bending: float = 0.0
    prestress: float = 0.0
    gas: float = 0.0

    def __post_init__(self) -> None:
        nu = bounded("poisson", self.poisson, 0.0, 0.5, low_open=True)
        object.__setattr__(self, "poisson", nu)
        for name in ("bending", "prestress", "gas"):
            object.__setattr__(self, name, _nonnegative(name, getattr(self, name)))
        if self.breathing_squared <= 0.0:
            raise ParameterError(
                "prestress",
                "such that the breathing mode is stable, 2 (1 + nu) - 2 p + g > 0 "
                f"(nu = {nu:g}, g = {self.gas:g})",
                self.prestress,
            )

    @classmethod
    def from_ratios(
        cls,
        poisson: float,
        thickness_ratio: float = 0.0,
        wall_stiffness_ratio: float | None = None,
        gas: float = 0.0,
    ) -> ShellParameters:
        """From h/R and C/N0 (None: no prestress, ``p = 0``).

        Parameters
        ----------
        poisson : float
            nu in (0, 0.5].
        thickness_ratio : float
            h / R >= 0; ``beta_h = (h / R)^2 / 12``.
        wall_stiffness_ratio : float or None
            C / N0 > 0; ``p = N0 / C``.
        gas : float
            ``g = 3 kappa P_abs R / C`` >= 0.
        """
        ratio = _nonnegative("thickness_ratio", thickness_ratio)
        if wall_stiffness_ratio is None:
            prestress = 0.0
        else:
            stiff = real_number("wall_stiffness_ratio", wall_stiffness_ratio, "a number > 0")
            if not stiff > 0.0:
                raise ParameterError("wall_stiffness_ratio", "a number > 0", wall_stiffness_ratio)
            prestress = 1.0 / stiff
        return cls(poisson=poisson, bending=ratio**2 / 12.0, prestress=prestress, gas=gas)

    @property
    def thickness_ratio(self) -> float:
        """h / R = ``sqrt(12 beta_h)``."""
        return math.sqrt(12.0 * self.bending)

    @property
    def breathing_squared(self) -> float:
        """``Omega_0^2 = 2 (1 + nu) - 2 p + g`` of the breathing mode (n = 0)."""
        return 2.0 * (1.0 + self.poisson) - 2.0 * self.prestress + self.gas

    def as_dict(self) -> dict[str, float]:
        """The four numbers by name (``poisson``, ``bending``, ``prestress``, ``gas``)."""
        return {
            "poisson": self.poisson,
            "bending": self.bending,
            "prestress": self.prestress,
            "gas": self.gas,
        }


@dataclass(frozen=True)
class ShellSI:
    """A shell ball in SI and its dimensionless parameters; converts frequencies and times.

    Build it with :func:`shell_from_si`.  Attributes are in SI: ``radius`` R [m],
    ``mass`` m [kg], ``wall_stiffness`` C [N/m], ``tension`` N0 [N/m],
    ``surface_density`` rho_s [kg/m^2]; ``parameters`` is the
    :class:`ShellParameters`.
    """

    radius: float
    mass: float
    wall_stiffness: float
    tension: float
    surface_density: float
    parameters: ShellParameters

    @property
    def extensional_speed(self) -> float:
        """In-plane wave speed ``c_e = sqrt(C / rho_s)`` [m/s]."""
        return math.sqrt(self.wall_stiffness / self.surface_density)

    @property
    def time_unit(self) -> float:
        """The time unit of the dimensionless model, ``R / c_e`` [s]."""
        return self.radius / self.extensional_speed

    @property
    def in_plane_arrival(self) -> float:
        """``pi R / c_e`` [s]: an in-plane wave's time from the south pole to the north pole."""
        return math.pi * self.time_unit

    @property
    def pressure_wave_speed(self) -> float:
        """The membrane's angular wave speed ``c = sqrt(N0 / rho_s) / R`` [1/s], eq. (3.8)."""
        return math.sqrt(self.tension / self.surface_density) / self.radius

    def omega_rad_s(self, omega: np.ndarray | float) -> np.ndarray:
        """Angular frequency ``omega = Omega c_e / R`` [rad/s] of a dimensionless Omega."""
        return np.asarray(omega, dtype=float) / self.time_unit

    def frequency_hz(self, omega: np.ndarray | float) -> np.ndarray:
        """Frequency ``f = Omega c_e / (2 pi R)`` [Hz] of a dimensionless Omega."""
        return self.omega_rad_s(omega) / (2.0 * math.pi)


def shell_from_si(
    *,
    youngs_modulus: float,
    thickness: float,
    poisson: float,
    radius: float,
    mass: float,
    pressure: float = 0.0,
    gas: str = "none",
    atmosphere: float = ATMOSPHERE,
) -> ShellSI:
    """The shell of a ball given in SI.

    Parameters
    ----------
    youngs_modulus : float
        E [Pa] > 0.
    thickness : float
        Wall thickness h [m] > 0.
    poisson : float
        nu in (0, 0.5].
    radius : float
        Mid-surface radius R [m] > 0.
    mass : float
        Mass of the wall m [kg] > 0 (``rho_s = m / (4 pi R^2)``).
    pressure : float
        Gauge pressure P [Pa] >= 0: ``N0 = P R / 2``.
    gas : {"none", "isothermal", "adiabatic"}
        The enclosed gas's law (kappa 0, 1, 1.4; :data:`twoball.modal.stiffness.GAS_MODELS`).
    atmosphere : float
        Ambient pressure [Pa] >= 0; the gas is at ``P + atmosphere``.

    Returns
    -------
    ShellSI
        With ``C = E h / (1 - nu^2)``, ``beta_h = h^2 / (12 R^2)``, ``p = P R / (2 C)``
        and ``g = 3 kappa (P + P_atm) R / C``.
    """
    youngs_modulus = bounded("youngs_modulus", youngs_modulus, 0.0, 1e15, "Pa", low_open=True)
    thickness = bounded("thickness", thickness, 0.0, 1e6, "m", low_open=True)
    poisson = bounded("poisson", poisson, 0.0, 0.5, low_open=True)
    radius = bounded("radius", radius, 0.0, 1e6, "m", low_open=True)
    mass = bounded("mass", mass, 0.0, 1e12, "kg", low_open=True)
    pressure = bounded("pressure", pressure, 0.0, 1e12, "Pa")
    atmosphere = bounded("atmosphere", atmosphere, 0.0, 1e12, "Pa")
    if gas not in GAS_MODELS:
        raise ParameterError("gas", "one of " + ", ".join(GAS_MODELS), gas)
    stiffness = youngs_modulus * thickness / (1.0 - poisson**2)
    tension = pressure * radius / 2.0
    kappa = GAS_MODELS[gas]
    parameters = ShellParameters(
        poisson=poisson,
        bending=(thickness / radius) ** 2 / 12.0,
        prestress=tension / stiffness,
        gas=3.0 * kappa * (pressure + atmosphere) * radius / stiffness,
    )
    return ShellSI(
        radius=radius,
        mass=mass,
        wall_stiffness=stiffness,
        tension=tension,
        surface_density=mass / (4.0 * math.pi * radius**2),
        parameters=parameters,
    )
