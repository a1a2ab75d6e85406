"""A soft upper body's own contact law: its stiffness, its dissipation, its contact disc (SI).

Three stiffness laws, each from the body's own properties (never from a
collision's measured e12):

``pressure`` (a pressurised hollow ball)
    Excess pressure times the flattened area: a ball of radius R1 at excess
    pressure P1 pressed a distance delta onto a flat flattens a disc of radius
    ``a = sqrt(2 R1 delta)`` and pushes with ``F = P1 pi a^2 = 2 pi R1 P1 delta``
    (Cross 1999, Am. J. Phys. 67:222, the paper's ref. [14]; Hubbard & Stronge
    2001, ref. [25]).  On a ball of radius R2 the disc follows the two
    curvatures, ``a^2 = 2 R* delta``, ``R* = R1 R2 / (R1 + R2)`` (Johnson,
    *Contact Mechanics*, 1985, §4.2), and ``k = 2 pi R* P1``.
``reissner`` (a thin unpressurised shell: the table tennis ball)
    Reissner's point load on a shallow spherical shell, ``F = k delta`` with
    ``k = 4 E h^2 / (R1 sqrt(3 (1 - nu^2)))`` (Reissner 1946, J. Math. Phys.
    25:80; the thin-shell indentation law used by Vella et al. 2012, J. R.
    Soc. Interface 9:448).  Valid up to a deflection of a few h, where the
    shell buckles into an inverted cap (Pauchard & Rica 1998, Phil. Mag. B
    78:225): the buckled regime (a softer, then stiffening, force) is *not*
    modelled.  The disc: the flattened cap, ``a^2 = 2 R* delta``.
``hertz`` (a solid elastic body)
    Hertz, ``F = (4/3) E* sqrt(R*) delta^(3/2)``, ``E* = E / (1 - nu^2)`` (the
    partner rigid: the lower ball's own compliance is in its modes), ``a^2 = R*
    delta`` (Johnson 1985, eqs. (4.22)-(4.23); :mod:`twoball.modal.solid.hertz`).
    A coin or a nut touches with a rounded rim or edge: R1 is that rim's
    radius of curvature.

The dissipation is set by the body's own restitution e against a rigid floor
(a measurement, or a stated assumption): a linear law takes a Kelvin-Voigt
dashpot ``c delta'``, a Hertz law Tsuji's ``c delta^(1/4) delta'`` (Tsuji,
Tanaka & Ishida 1992, Powder Technol. 71:239); both never pull (the contact
opens when the force vanishes: Schwager & Pöschel 2007, Granular Matter
9:465), and with both the restitution against a rigid floor is the same at
every impact speed, so "the speed of interest" does not change c.  For the
linear law ``e = exp(-q (pi - 2 arctan q))``, ``q = zeta / sqrt(1 - zeta^2)``;
for Tsuji's ``c = b sqrt(m k)`` with b from the reduced Hertz equation
(:mod:`twoball.modal.lumped.fitting`).  The contact time on a rigid floor
follows (computed, not assumed): ``sqrt(1 + q^2) (pi - 2 arctan q) sqrt(m /
k)`` and, for Hertz, ``T(b) (m^2 / (k^2 v))^(1/5)`` (2.87 (m^2/(R E*^2
v))^(1/5) at b = 0).
"""

from __future__ import annotations

import math
from dataclasses import asdict, dataclass
from typing import Any

from twoball._common.errors import ParameterError, bounded
from twoball._common.keywords import checked
from twoball.modal.nonsmooth.compliant import PowerLaw

__all__ = ["LAWS", "ContactLaw"]

#: The stiffness laws a lumped body takes, with the fields each needs.
LAWS: dict[str, tuple[str, ...]] = {
    "pressure": ("radius", "pressure"),
    "reissner": ("radius", "youngs_modulus", "poisson", "thickness"),
    "hertz": ("radius", "youngs_modulus", "poisson"),
}


@checked
@dataclass(frozen=True)
class ContactLaw:
    """A body's own contact law against a rigid surface (SI; module documentation).

    Parameters
    ----------
    law : {"pressure", "reissner", "hertz"}
    restitution : float
        Its coefficient of restitution against a rigid floor, in (exp(-2), 1]
        (a linear law that never pulls cannot go lower) or (0.22, 1] for Hertz.
    radius : float
        R1 [m]: the ball's radius, or the radius of curvature of the rim or
        edge that touches (coin, nut).
    pressure : float, optional
        Excess pressure P1 [Pa] (``pressure``).
    youngs_modulus, poisson : float, optional
        E [Pa] and nu (``reissner``, ``hertz``).
    thickness : float, optional
        Wall thickness h [m] (``reissner``).

    Examples
    --------
    >>> import twoball
    >>> law = twoball.ContactLaw("pressure", 0.83, radius=0.0335, pressure=82700.0)
    >>> round(law.stiffness(), 1)  # 2 pi R P [N/m]
    17407.3
    >>> round(law.contact_time(0.0573) * 1e3, 3)  # ms on a rigid floor, its dashpot's e = 0.83
    5.487
    """

    law: str
    restitution: float
    radius: float
    pressure: float | None = None
    youngs_modulus: float | None = None
    poisson: float | None = None
    thickness: float | None = None

    def __post_init__(self) -> None:
        if not isinstance(self.law, str) or self.law not in LAWS:
            raise ParameterError("law", "one of " + ", ".join(LAWS), self.law)
        bounded("radius", self.radius, 0.0, 10.0, "m", low_open=True)
        needed = LAWS[self.law]
        for name in ("pressure", "youngs_modulus", "poisson", "thickness"):
            value = getattr(self, name)
            if name in needed and value is None:
                raise ParameterError(name, f"given for the {self.law} law", None)
            if name not in needed and value is not None:
                raise ParameterError(name, f"left out for the {self.law} law", value)
        if self.pressure is not None:
            bounded("pressure", self.pressure, 0.0, 1e8, "Pa", low_open=True)
        if self.youngs_modulus is not None:
            bounded("youngs_modulus", self.youngs_modulus, 0.0, 1e13, "Pa", low_open=True)
        if self.poisson is not None:
            bounded("poisson", self.poisson, -0.99, 0.5, "")
        if self.thickness is not None:
            bounded("thickness", self.thickness, 0.0, self.radius, "m", low_open=True)
        self._check_restitution()

    def _check_restitution(self) -> None:
        from twoball.modal.lumped.fitting import LINEAR_FORCE_RULE_MIN_E, hertz_restitution

        low = hertz_restitution(50.0, 0.25)[0] if self.power > 1.0 else LINEAR_FORCE_RULE_MIN_E
        valid = f"in ({low:.4f}, 1] for the {self.law} law (a dashpot that never pulls)"
        e = bounded("restitution", self.restitution, 0.0, 1.0, low_open=True)
        if e <= low:
            raise ParameterError("restitution", valid, self.restitution)

    # --- the law ----------------------------------------------------------------------
    @property
    def power(self) -> float:
        """p of ``F = k delta^p``: 1 (pressure, reissner) or 3/2 (hertz)."""
        return 1.5 if self.law == "hertz" else 1.0

    @property
    def damping_power(self) -> float:
        """r of the dashpot ``c delta^r delta'``: 0 (Kelvin-Voigt) or 1/4 (Tsuji)."""
        return 0.25 if self.law == "hertz" else 0.0

    @property
    def disc_factor(self) -> float:
        """``a^2 = factor R* delta``: 2 (a flattened cap) or 1 (Hertz)."""
        return 1.0 if self.law == "hertz" else 2.0

    def effective_radius(self, partner: float | None = None) -> float:
        """``R* = R1 R2 / (R1 + R2)`` [m] against a ball of radius R2 (None: a flat)."""
        if partner is None:
            return self.radius
        return self.radius * partner / (self.radius + partner)

    def stiffness(self, partner: float | None = None) -> float:
        """k of ``F = k delta^p`` against a flat or a rigid ball of radius ``partner`` [SI].

        [N/m] for the linear laws, [N/m^(3/2)] for Hertz.
        """
        r = self.effective_radius(partner)
        if self.law == "pressure":
            return 2.0 * math.pi * r * float(self.pressure)  # type: ignore[arg-type]
        e, nu = float(self.youngs_modulus), float(self.poisson)  # type: ignore[arg-type]
        if self.law == "reissner":
            h = float(self.thickness)  # type: ignore[arg-type]
            return 4.0 * e * h * h / (self.radius * math.sqrt(3.0 * (1.0 - nu * nu)))
        return 4.0 / 3.0 * e / (1.0 - nu * nu) * math.sqrt(r)

    def reduced_damping(self) -> float:
        """``q = zeta / sqrt(1 - zeta^2)`` (linear) or b (Hertz, Tsuji) of the restitution."""
        from twoball.modal.lumped.fitting import _q_from_e, hertz_damping

        if self.power > 1.0:
            return hertz_damping(self.restitution, 0.25)
        return _q_from_e(self.restitution, tensile=False)

    def damping(self, mass: float) -> float:
        """The dashpot c [SI] that gives :attr:`restitution` to ``mass`` [kg] on a rigid floor.

        Linear: ``c = 2 zeta sqrt(m k)``; Hertz (Tsuji): ``c = b sqrt(m k)``.
        """
        k = self.stiffness()
        q = self.reduced_damping()
        if self.power > 1.0:
            return q * math.sqrt(mass * k)
        zeta = q / math.sqrt(1.0 + q * q)
        return 2.0 * zeta * math.sqrt(mass * k)

    def power_law(self, mass: float, partner: float | None = None) -> PowerLaw:
        """The law (C1) in SI for the core: k against ``partner``, c calibrated with ``mass``."""
        return PowerLaw(
            stiffness=self.stiffness(partner),
            power=self.power,
            damping=self.damping(mass),
            damping_power=self.damping_power,
            scale=self.peak_compression(mass, 1.0),
        )

    def disc_radius(self, compression: float, partner: float | None = None) -> float:
        """Radius a [m] of the contact disc at a compression [m]: ``sqrt(factor R* delta)``."""
        if compression <= 0.0:
            return 0.0
        return math.sqrt(self.disc_factor * self.effective_radius(partner) * compression)

    # --- on a rigid floor ---------------------------------------------------------------
    def peak_compression(self, mass: float, speed: float) -> float:
        """Largest compression [m] of an undamped impact at ``speed`` [m/s] on a rigid floor."""
        p = self.power
        return ((p + 1.0) * 0.5 * mass * speed * speed / self.stiffness()) ** (1.0 / (p + 1.0))

    def contact_time(self, mass: float, speed: float = 4.1) -> float:
        """Duration [s] of the damped impact of ``mass`` at ``speed`` on a rigid floor.

        The linear laws: ``sqrt(1 + q^2) (pi - 2 arctan q) sqrt(m / k)``,
        independent of the speed; Hertz with Tsuji's dashpot: the reduced
        duration ``T(b)`` of :func:`~twoball.modal.lumped.fitting.hertz_restitution`
        times ``L / v``, ``L = (m v^2 / k)^(2/5)``.
        """
        from twoball.modal.lumped.fitting import hertz_restitution, linear_restitution

        bounded("mass", mass, 0.0, 1e6, "kg", low_open=True)
        bounded("speed", speed, 0.0, 1e3, "m/s", low_open=True)
        k = self.stiffness()
        q = self.reduced_damping()
        if self.power > 1.0:
            reduced = hertz_restitution(q, 0.25)[1]
            length = (mass * speed * speed / k) ** 0.4
            return reduced * length / speed
        return linear_restitution(q, tensile=False)[1] * math.sqrt(mass / k)

    def undamped_contact_time(self, mass: float, speed: float = 4.1) -> float:
        """The closed form without the dashpot [s]: ``pi sqrt(m / k)``; Hertz's 2.87 law."""
        return PowerLaw(self.stiffness(), self.power).contact_time(mass, speed)

    def as_dict(self) -> dict[str, Any]:
        """The fields (SI) with the derived stiffness for the JSON."""
        out = {k: v for k, v in asdict(self).items() if v is not None}
        out["stiffness_SI"] = self.stiffness()
        return out
