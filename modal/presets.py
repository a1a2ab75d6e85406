"""The presets: measured or rule-book parameters of real balls, with their sources.

``basketball`` is the paper's (Table 2, Fig. 11); ``tennis`` and ``volleyball``
come from the rule books and the literature cited in each :attr:`Measured.source`
(docs/stiff_balls.rst lists them).  :class:`twoball.modal.parameters.Case` builds
its presets from :data:`MEASURED`.
"""

from __future__ import annotations

from dataclasses import dataclass

from twoball.modal.scalings import wave_speed_from_pressure


@dataclass(frozen=True)
class Measured:
    """A preset: R [m], c [1/s], ``|v0|`` [m/s], phi_a [rad] (None: eq. (3.7)), D, N.

    ``pressure`` [Pa] (excess) and ``mass`` [kg] document c (eq. (3.8)) and set
    the tension ``T = P R / 2`` of the bending and gas terms; ``bending`` B [N m]
    and ``gas`` as in :mod:`twoball.modal.stiffness`.  ``source``: where the
    values come from (see docs/stiff_balls.rst).
    """

    radius: float
    wave_speed: float
    v0: float
    phi_a: float | None
    damping: float
    modes: int
    pressure: float | None = None
    mass: float | None = None
    bending: float = 0.0
    gas: str = "none"
    source: str = ""


def _tennis() -> Measured:
    from twoball.modal.stiffness import flexural_rigidity

    radius, mass, pressure = 0.0335, 0.0577, 82700.0
    return Measured(
        radius=radius,
        wave_speed=wave_speed_from_pressure(pressure, mass, radius),
        v0=4.1,
        phi_a=None,
        damping=0.13,
        modes=30,
        pressure=pressure,
        mass=mass,
        bending=flexural_rigidity(6.0e6, 3.2e-3, 0.5),
        gas="adiabatic",
        source="ITF Rules of Tennis, App. I (diameter 6.54-6.86 cm, mass 56.0-59.4 g); "
        "12 psi = 82.7 kPa excess pressure and a 3.2 mm rubber wall (Cross 1999, Sports "
        "Eng. 2 23; Brody, Cross & Lindsey 2002); rubber E = 6 MPa, nu = 0.5 assumed; "
        "D = 0.13 and |v0| = 4.1 m/s taken from the basketball (not measured)",
    )


def _volleyball() -> Measured:
    radius, mass, pressure = 0.105, 0.270, 30600.0
    return Measured(
        radius=radius,
        wave_speed=wave_speed_from_pressure(pressure, mass, radius),
        v0=4.1,
        phi_a=None,
        damping=0.13,
        modes=30,
        pressure=pressure,
        mass=mass,
        gas="adiabatic",
        source="FIVB Official Volleyball Rules 2021-2024, rule 3.1 (circumference 65-67 "
        "cm, mass 260-280 g, pressure 0.30-0.325 kgf/cm^2 = 29.4-31.9 kPa); a membrane "
        "like the basketball (B = 0); D = 0.13 and |v0| = 4.1 m/s from the basketball",
    )


#: The superball's radius [m]: a 50 mm ball (assumed, the classroom size).
SUPERBALL_RADIUS = 0.025
#: The superball's material (SI; every value assumed: docs/solid.rst), the source of
#: :data:`twoball.modal.balls.solid.MATERIALS`.
SUPERBALL_MATERIAL = {
    "density": 1100.0,
    "youngs_modulus": 8.0e6,
    "poisson": 0.45,
    "source": "polybutadiene (Zectron) superball: every value assumed, no measurement reached "
    "(the paper gives none): rho = 1100 kg/m^3 (a filled polybutadiene compound), E = 8 "
    "MPa (a hard rubber of Shore A ~80 by Gent's hardness-modulus relation), nu = 0.45 "
    "(rubber is 0.49-0.5; 0.45 keeps the displacement elements free of locking and is "
    "one of the reference Poisson ratios of Lamb's roots)",
}


def _superball() -> Measured:
    m = SUPERBALL_MATERIAL
    shear = m["youngs_modulus"] / (2.0 * (1.0 + m["poisson"]))  # mu [Pa]
    radius = SUPERBALL_RADIUS
    return Measured(
        radius=radius,
        wave_speed=(shear / m["density"]) ** 0.5 / radius,  # c = c_s / R
        v0=4.1,
        phi_a=None,
        damping=0.0,
        modes=30,
        mass=4.0 / 3.0 * 3.141592653589793 * radius**3 * m["density"],
        source="a solid polybutadiene ball (docs/solid.rst): R = 25 mm assumed; c = c_s / R "
        "of its material (SUPERBALL_MATERIAL, every value assumed); undamped (D = 0: no "
        "measured losses); |v0| = 4.1 m/s from the basketball",
    )


#: Presets.  basketball: Table 2, Fig. 11 (R, c, ``|v0|``, phi_a measured; D fitted
#: once).  tennis, volleyball: rule-book sizes and pressures, phi_a from eq. (3.7).
#: superball: a solid ball (no pressure), c = c_s / R of its assumed material.
MEASURED: dict[str, Measured] = {
    "basketball": Measured(
        radius=0.12,
        wave_speed=320.0,
        v0=4.1,
        phi_a=2.6,
        damping=0.13,
        modes=30,
        pressure=77200.0,
        mass=0.567,
        source="Berdeni et al. 2015, two-ball bounce, Table 2 and Fig. 11 (measured)",
    ),  # fmt: skip
    "tennis": _tennis(),
    "volleyball": _volleyball(),
    "superball": _superball(),
}
