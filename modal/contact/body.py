"""The upper body of finite mass: mass ratio, contact cap, restitution, initial energy."""

from __future__ import annotations

import math
from dataclasses import asdict, dataclass
from typing import Any

from twoball._common.choices import ENERGY_OPTIONS, MAX_MASS_RATIO
from twoball._common.errors import ParameterError, real_number
from twoball._common.keywords import checked

__all__ = ["ENERGY_OPTIONS", "MAX_MASS_RATIO", "Body"]

#: Largest mass ratio mu = m1 / m2 accepted (a body 100 times the lower ball).
#: Energy at t = 0: eq. (3.6) for the lower ball alone, or with the body's kinetic energy.
#: Default contact radius as a fraction of R (docs/contact.rst, "The contact radius").
DEFAULT_RADIUS_FRACTION = 0.1


@checked
@dataclass(frozen=True)
class Body:
    """A rigid upper body of finite mass in unilateral contact with the ball (SI).

    Parameters
    ----------
    mass_ratio : float
        mu = m1 / m2 in [0, 100]; 0 applies the massless criteria of §3(a) to
        the motion averaged over the contact cap.
    contact_radius : float, optional
        Radius a [m] of the contact cap (default R / 10; checked against R by
        the solve).
    restitution : float
        Newton's coefficient e in [0, 1] at a re-contact (default 0).
    energy : {"ball", "both"}
        Energy at t = 0: eq. (3.6) for the lower ball alone (default), or with
        the body's kinetic energy ``mu m2 v0^2 / 2`` too.

    Raises
    ------
    ParameterError
        Naming the field and its valid range.

    Examples
    --------
    >>> import twoball
    >>> twoball.Body(mass_ratio=0.1).as_dict()
    {'mass_ratio': 0.1, 'contact_radius': None, 'restitution': 0.0, 'energy': 'ball'}
    >>> twoball.Body(mass_ratio=0.1, restitution=2.0)
    Traceback (most recent call last):
    ...
    twoball.ParameterError: restitution must be a number in [0, 1], got 2.0
    """

    mass_ratio: float
    contact_radius: float | None = None
    restitution: float = 0.0
    energy: str = "ball"

    #: Valid range of each field, in words (the command line names its flags).
    VALID = {  # noqa: RUF012 -- a class constant, not a field
        "mass_ratio": f"a number in [0, {MAX_MASS_RATIO:g}]",
        "contact_radius": "a radius in (0, R) [m]",
        "restitution": "a number in [0, 1]",
        "energy": "one of " + ", ".join(ENERGY_OPTIONS),
    }

    def __post_init__(self) -> None:
        mu = real_number("mass_ratio", self.mass_ratio, self.VALID["mass_ratio"])
        if not 0.0 <= mu <= MAX_MASS_RATIO:
            raise ParameterError("mass_ratio", self.VALID["mass_ratio"], self.mass_ratio)
        e = real_number("restitution", self.restitution, self.VALID["restitution"])
        if not 0.0 <= e <= 1.0:
            raise ParameterError("restitution", self.VALID["restitution"], self.restitution)
        if self.energy not in ENERGY_OPTIONS:
            raise ParameterError("energy", self.VALID["energy"], self.energy)
        if self.contact_radius is not None:
            a = real_number("contact_radius", self.contact_radius, self.VALID["contact_radius"])
            if not (a > 0.0 and math.isfinite(a)):
                raise ParameterError(
                    "contact_radius", self.VALID["contact_radius"], self.contact_radius
                )
            object.__setattr__(self, "contact_radius", a)
        object.__setattr__(self, "mass_ratio", mu)
        object.__setattr__(self, "restitution", e)

    def radius_m(self, ball_radius: float) -> float:
        """The contact radius a [m] on a ball of radius R [m]: the given one, or R / 10."""
        if self.contact_radius is None:
            return DEFAULT_RADIUS_FRACTION * ball_radius
        if not self.contact_radius < ball_radius:
            valid = f"in (0, R) = (0, {ball_radius:g}) m"
            raise ParameterError("contact_radius", valid, self.contact_radius)
        return self.contact_radius

    def as_dict(self) -> dict[str, Any]:
        """The fields, for JSON and provenance (SI)."""
        return asdict(self)
