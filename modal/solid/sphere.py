"""A homogeneous isotropic elastic sphere in SI units, and its Lamb frequencies."""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from twoball._common.errors import ParameterError
from twoball.modal.solid.lamb import lamb_roots, speed_ratio

__all__ = ["ElasticSphere"]


@dataclass(frozen=True)
class ElasticSphere:
    """Radius R [m], density rho [kg/m^3], Young's modulus E [Pa], Poisson's ratio nu [-].

    Derived: shear modulus mu = E / (2 (1 + nu)), Lame lambda = E nu / ((1 + nu)(1 - 2 nu)),
    wave speeds c_s = sqrt(mu / rho), c_p = sqrt((lambda + 2 mu) / rho) [m/s],
    mass M = (4/3) pi R^3 rho [kg], and E* = E / (1 - nu^2) [Pa] (Hertz on a rigid flat).
    """

    radius: float
    density: float
    youngs_modulus: float
    poisson: float

    def __post_init__(self) -> None:
        for name in ("radius", "density", "youngs_modulus"):
            value = getattr(self, name)
            if not (math.isfinite(value) and value > 0):
                raise ParameterError(name, "a finite number > 0", value)
        speed_ratio(self.poisson)  # validates nu in (-1, 1/2)

    @property
    def shear_modulus(self) -> float:
        """mu [Pa]."""
        return self.youngs_modulus / (2.0 * (1.0 + self.poisson))

    @property
    def lame_lambda(self) -> float:
        """Lame's first parameter lambda [Pa]."""
        nu = self.poisson
        return self.youngs_modulus * nu / ((1.0 + nu) * (1.0 - 2.0 * nu))

    @property
    def shear_speed(self) -> float:
        """c_s [m/s]."""
        return math.sqrt(self.shear_modulus / self.density)

    @property
    def pressure_speed(self) -> float:
        """c_p [m/s]."""
        return self.shear_speed * speed_ratio(self.poisson)

    @property
    def mass(self) -> float:
        """M [kg]."""
        return 4.0 / 3.0 * math.pi * self.radius**3 * self.density

    @property
    def effective_modulus(self) -> float:
        """E* = E / (1 - nu^2) [Pa], a sphere against a rigid flat."""
        return self.youngs_modulus / (1.0 - self.poisson**2)

    def angular_frequencies(self, degree: int, count: int) -> np.ndarray:
        """omega_{n,k} = eta_{n,k} c_s / R [rad/s] for k = 1 .. count (Lamb's roots)."""
        eta = lamb_roots(degree, self.poisson, count)
        return eta * self.shear_speed / self.radius
