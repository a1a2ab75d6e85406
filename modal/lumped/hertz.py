"""Hertz contacts with a viscoelastic dashpot: ``F = k x^(3/2) + c x^p x'``, never pulling.

The elastic part is Hertz's law, as in Patrício's two-ball model (Am. J. Phys.
72, 1488 (2004), the paper's ref. [11]).  The dashpot follows either

* ``law="tsuji"`` (default), p = 1/4: Tsuji, Tanaka & Ishida, Powder Technol.
  71, 239 (1992).  Its restitution is the same at every impact speed
  (:mod:`twoball.modal.lumped.fitting`), as Table 1's measured e2 and e12 are
  taken to be (§4: the speed ratios were "largely independent" of the impact
  speed), so the fitted contact restitutes e at any speed the bounce produces;
* ``law="kuwabara-kono"``, p = 1/2: Kuwabara & Kono, Jpn. J. Appl. Phys. 26,
  1230 (1987); Brilliantov et al., Phys. Rev. E 53, 5382 (1996) -- the
  viscoelastic solid of Müller & Pöschel's study; e falls with the impact speed
  (Müller & Pöschel, Phys. Rev. E 84, 021302 (2011)), so it holds only at the
  reference speed.

Hunt & Crossley's p = 3/2 is not offered: its restitution ``~ 1 - a v`` is
linear in speed, which Table 1's data do not show.

The hollow balls of Table 1 are not Hertzian solids; k is therefore not taken
from a Young's modulus but fitted, like the linear model's, to the contact time
of the pressure rule at a reference impact speed.
"""

from __future__ import annotations

from dataclasses import dataclass

from twoball._common.errors import ParameterError, bounded
from twoball.modal.lumped.drop import TwoContacts
from twoball.modal.lumped.fitting import fit_hertz
from twoball.modal.lumped.laws import DAMPING_EXPONENTS, HertzLaw
from twoball.modal.lumped.pair_inputs import pair_contacts
from twoball.modal.lumped.spring_dashpot import DURATION_RANGE
from twoball.modal.pairs import Pair
from twoball.modal.scalings import MASS_RANGE

#: Impact speed at which Table 1's pairs were measured and the presets' ``|v0|`` [m/s]
#: (basketball drops from x2 = 0.92 m, §4(b)).
REFERENCE_SPEED = 4.1


@dataclass(frozen=True)
class HertzViscoelastic(TwoContacts):
    """Damped Hertz contacts at the floor and between the bodies.

    Inputs and where they come from (:meth:`from_pair` for a Table 1 pair):
    masses, e2, e12 and the contact times as in
    :class:`~twoball.modal.lumped.spring_dashpot.TwoSpringDashpot`; each Hertz
    contact is fitted to its (duration, restitution) at a reference impact
    speed: ``speed`` for the floor and ``(1 + e2) speed`` between the bodies
    (their closing speed in the ICM, eq. (2.2)).

    Parameters
    ----------
    m1, m2 : float
        Masses [kg] of the body and the lower ball.
    e2, e12 : float
        Restitutions at the reference speeds, in (0, 1].
    tau2, tau12 : float
        Contact durations at the reference speeds [s].
    speed : float, optional
        Reference impact speed [m/s], > 0.
    law : str, optional
        ``"tsuji"`` (p = 1/4) or ``"kuwabara-kono"`` (p = 1/2).
    source : str, optional
        Where the inputs come from.

    Examples
    --------
    >>> from twoball.modal.pairs import PAIRS
    >>> model = HertzViscoelastic.from_pair(PAIRS["tennis-coin"])
    >>> model.floor_law.exponent
    0.25
    >>> model = HertzViscoelastic(0.01, 1.0, 1.0, 1.0, 0.01, 0.002, speed=1.0)
    >>> round(model.run(v0=1.0, dx=1.0, g=0.0).v1_ratio, 6)  # (2.5), mu = 0.01
    2.960396
    """

    m1: float
    m2: float
    e2: float
    e12: float
    tau2: float
    tau12: float
    speed: float = REFERENCE_SPEED
    law: str = "tsuji"
    source: str = ""

    def __post_init__(self) -> None:
        for name in ("m1", "m2"):
            bounded(name, getattr(self, name), *MASS_RANGE, "kg")
        for name in ("tau2", "tau12"):
            bounded(name, getattr(self, name), *DURATION_RANGE, "s")
        for name in ("e2", "e12"):
            bounded(name, getattr(self, name), 0.0, 1.0, low_open=True)
        bounded("speed", self.speed, 1e-6, 1e6, "m/s")
        if self.law not in DAMPING_EXPONENTS:
            raise ParameterError("law", "one of " + ", ".join(DAMPING_EXPONENTS), self.law)
        self.floor_law  # noqa: B018 -- fit now, so an unreachable e fails on construction
        self.pair_law  # noqa: B018

    @classmethod
    def from_pair(
        cls, pair: Pair, speed: float = REFERENCE_SPEED, law: str = "tsuji"
    ) -> HertzViscoelastic:
        """The model of a Table 1 pair with the pressure rule's contact times.

        Parameters
        ----------
        pair : Pair
            A preset of :data:`twoball.modal.pairs.PAIRS`.
        speed : float, optional
            Reference impact speed [m/s].
        law : str, optional
            ``"tsuji"`` or ``"kuwabara-kono"``.

        Returns
        -------
        HertzViscoelastic
            The fitted model.

        Examples
        --------
        >>> from twoball.modal.pairs import PAIRS
        >>> HertzViscoelastic.from_pair(PAIRS["basketball-tennis"], law="kuwabara-kono").law
        'kuwabara-kono'
        """
        c = pair_contacts(pair)
        return cls(c.m1, c.m2, c.e2, c.e12, c.tau2, c.tau12, speed=speed, law=law, source=c.source)

    @property
    def exponent(self) -> float:
        """p of the dashpot term."""
        return DAMPING_EXPONENTS[self.law]

    @property
    def floor_law(self) -> HertzLaw:
        """The floor contact, fitted at ``speed`` (reduced mass m2)."""
        return fit_hertz(self.m2, self.tau2, self.e2, self.speed, self.exponent)

    @property
    def pair_law(self) -> HertzLaw:
        """The body-ball contact, fitted at ``(1 + e2) speed``.

        Reduced mass ``m1 m2 / (m1 + m2)``; ``(1 + e2) |v0|`` is the ICM's closing speed.
        """
        reduced = self.m1 * self.m2 / (self.m1 + self.m2)
        return fit_hertz(reduced, self.tau12, self.e12, (1.0 + self.e2) * self.speed, self.exponent)

    @property
    def label(self) -> str:
        """The model's name in the results."""
        return f"hertz-viscoelastic ({self.law})"
