"""Contact force laws of the lumped models: a linear spring-dashpot and a damped Hertz law.

Each law gives the compressive force ``F(delta, rate)`` [N] of one contact as a
function of its overlap ``delta`` [m] (> 0 when compressed) and the overlap rate
[m/s], the elastic energy it stores, and the dissipative part of the force.

Two rules end a contact (Schwager & Pöschel, Granular Matter 9, 465 (2007)):

* ``tensile=True`` -- the damped harmonic oscillator: the contact lasts while
  the overlap is positive, so the dashpot may pull at the end (the rule of
  the classical linear-dashpot restitution ``e = exp(-pi zeta / sqrt(1 - zeta^2))``);
* ``tensile=False`` -- the contact opens as soon as the force would become
  attractive (force 0); the overlap left at that instant is not recovered by
  the other body.

SI units throughout.
"""

from __future__ import annotations

from dataclasses import dataclass

from twoball._common.errors import ParameterError, bounded

#: Hertz exponents of the dissipative term ``c delta^p d(delta)/dt``: Tsuji et al.
#: (1992) use p = 1/4 (restitution independent of the impact speed); Kuwabara &
#: Kono (1987) and Brilliantov et al. (1996) derive p = 1/2 for viscoelastic solids.
DAMPING_EXPONENTS = {"tsuji": 0.25, "kuwabara-kono": 0.5}

_BIG = 1e15  # upper bound of stiffnesses and damping coefficients (SI)


@dataclass(frozen=True)
class LinearLaw:
    """A linear spring and dashpot: ``F = k delta + c d(delta)/dt``.

    Parameters
    ----------
    stiffness : float
        Spring constant k [N/m], > 0.
    damping : float
        Dashpot constant c [N s/m], >= 0.
    tensile : bool
        True: the contact lasts while ``delta > 0`` (the dashpot may pull);
        False: it opens when F reaches 0.

    Examples
    --------
    >>> law = LinearLaw(stiffness=1000.0, damping=2.0, tensile=False)
    >>> law.force(0.001, -0.5)
    0.0
    >>> law.elastic_energy(0.002)
    0.002
    """

    stiffness: float
    damping: float
    tensile: bool

    def __post_init__(self) -> None:
        bounded("stiffness", self.stiffness, 0.0, _BIG, "N/m", low_open=True)
        bounded("damping", self.damping, 0.0, _BIG, "N s/m")

    def force(self, delta: float, rate: float) -> float:
        """Compressive force [N] at overlap ``delta`` [m] and overlap rate ``rate`` [m/s]."""
        return self.stiffness * delta + self.damping * rate

    def dissipative_force(self, delta: float, rate: float) -> float:
        """The dashpot's part of :meth:`force` [N]."""
        return self.damping * rate

    def elastic_energy(self, delta: float) -> float:
        """Energy stored in the spring, ``k delta^2 / 2`` [J]."""
        return 0.5 * self.stiffness * delta * delta

    @property
    def length_per_force(self) -> float:
        """``1 / k`` [m/N]: turns a force into a length for event functions."""
        return 1.0 / self.stiffness


@dataclass(frozen=True)
class HertzLaw:
    """Hertz elasticity with a power-law dashpot: ``F = k delta^(3/2) + c delta^p d(delta)/dt``.

    The force never pulls: the contact opens when F reaches 0 (``tensile`` is
    always False).  Elastic Hertz contact of spheres: ``k = (4/3) E* sqrt(R*)``
    (Hertz 1882; Johnson, *Contact Mechanics*, 1985, §4.2).

    Parameters
    ----------
    stiffness : float
        Hertz constant k [N/m^(3/2)], > 0.
    damping : float
        Dashpot constant c [N s / m^(1+p)], >= 0.
    exponent : float
        p of the dashpot term: 1/4 (Tsuji, Tanaka & Ishida, Powder Technol. 71,
        239 (1992)) or 1/2 (Kuwabara & Kono, Jpn. J. Appl. Phys. 26, 1230
        (1987); Brilliantov et al., Phys. Rev. E 53, 5382 (1996)); any value in
        [0, 3/2].
    length_scale : float, optional
        A typical overlap [m] (e.g. the peak compression), > 0; only scales the
        event function that finds the force's zero.

    Examples
    --------
    >>> law = HertzLaw(stiffness=1.0e6, damping=0.0, exponent=0.25)
    >>> round(law.force(1.0e-4, 0.0), 6)
    1.0
    >>> round(law.elastic_energy(1.0e-4), 12)
    4e-05
    """

    stiffness: float
    damping: float
    exponent: float
    length_scale: float = 1e-3
    tensile: bool = False

    def __post_init__(self) -> None:
        bounded("stiffness", self.stiffness, 0.0, _BIG, "N/m^1.5", low_open=True)
        bounded("damping", self.damping, 0.0, _BIG, "SI")
        bounded("exponent", self.exponent, 0.0, 1.5)
        bounded("length_scale", self.length_scale, 0.0, 1e3, "m", low_open=True)
        if self.tensile is not False:
            raise ParameterError("tensile", "False for a Hertz law (it never pulls)", self.tensile)

    def force(self, delta: float, rate: float) -> float:
        """Compressive force [N]; 0 for ``delta <= 0``."""
        if delta <= 0.0:
            return 0.0
        return self.stiffness * delta**1.5 + self.damping * delta**self.exponent * rate

    def dissipative_force(self, delta: float, rate: float) -> float:
        """The dashpot's part of :meth:`force` [N]."""
        if delta <= 0.0:
            return 0.0
        return self.damping * delta**self.exponent * rate

    def elastic_energy(self, delta: float) -> float:
        """Energy stored, ``(2/5) k delta^(5/2)`` [J]; 0 for ``delta <= 0``."""
        if delta <= 0.0:
            return 0.0
        return 0.4 * self.stiffness * delta**2.5

    @property
    def length_per_force(self) -> float:
        """``1 / (k sqrt(length_scale))`` [m/N]: turns a force into a length."""
        return 1.0 / (self.stiffness * self.length_scale**0.5)
