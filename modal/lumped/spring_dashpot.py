"""Two linear spring-dashpot contacts fitted to each contact's duration and restitution.

The model of Cross (Am. J. Phys. 75, 1009 (2007), "Vertical bounce of two
vertically aligned balls", the paper's ref. [10]) and, in the paper's account
(§1(b)), of Müller & Pöschel (Phys. Rev. E 83, 041304 (2011), ref. [9]): each
contact a linear spring and a dashpot.  Each is fitted to an isolated contact's
duration and restitution (:func:`twoball.modal.lumped.fitting.fit_linear`) and
never pulls: a contact opens when its force vanishes (Schwager & Pöschel,
Granular Matter 9, 465 (2007)).  Gravity acts throughout.

The arXiv abstract of Müller & Pöschel (arXiv:1009.6153) speaks of balls of a
viscoelastic material, i.e. Hertz contacts with a Kuwabara-Kono dashpot:
:class:`~twoball.modal.lumped.hertz.HertzViscoelastic` with
``law="kuwabara-kono"`` is that reading.
"""

from __future__ import annotations

from dataclasses import dataclass

from twoball._common.errors import bounded
from twoball.modal.lumped.drop import TwoContacts
from twoball.modal.lumped.fitting import check_linear_e, fit_linear
from twoball.modal.lumped.laws import LinearLaw
from twoball.modal.lumped.pair_inputs import pair_contacts
from twoball.modal.pairs import Pair
from twoball.modal.scalings import MASS_RANGE

DURATION_RANGE = (1e-9, 1e3)  # s


@dataclass(frozen=True)
class TwoSpringDashpot(TwoContacts):
    """Linear spring and dashpot at the floor and between the bodies.

    Inputs and where they come from (:meth:`from_pair` for a Table 1 pair):

    * ``m1``, ``m2`` [kg]: body ``mu m2`` (Table 1's mu) and the lower ball's
      preset mass;
    * ``e2``, ``e12``: Table 1, measured by the paper (§4(a));
    * ``tau2`` [s]: the lower ball's floor contact time, ``pi sqrt(m2 / k2)``
      with ``k2 = 2 pi R P`` (Cross 1999), i.e. ``pi / c`` of eq. (3.8);
    * ``tau12`` [s]: the body-ball contact time ``pi sqrt(m12 / k12)``,
      ``k12 = 2 pi R* P`` (:mod:`twoball.modal.lumped.pair_inputs`).

    Each contact's (k, c) reproduces its (tau, e) in an isolated, gravity-free
    contact; a contact opens when its force vanishes.

    Parameters
    ----------
    m1, m2 : float
        Masses [kg] of the body and the lower ball, in [1e-12, 1e12].
    e2, e12 : float
        Restitutions of the floor and body-ball contacts, in (exp(-2), 1].
    tau2, tau12 : float
        Durations of the isolated floor and body-ball contacts [s], > 0.
    source : str, optional
        Where the inputs come from.

    Examples
    --------
    >>> from twoball.modal.pairs import PAIRS
    >>> model = TwoSpringDashpot.from_pair(PAIRS["basketball-tennis"])
    >>> r = model.run(v0=4.1, dx=0.2)
    >>> r.pair_contacts, r.body_left_first
    (1, False)
    >>> model = TwoSpringDashpot(0.01, 1.0, 1.0, 1.0, 0.01, 0.002)
    >>> round(model.run(v0=1.0, dx=1.0, g=0.0).v1_ratio, 6)  # (2.5), mu = 0.01
    2.960396
    """

    m1: float
    m2: float
    e2: float
    e12: float
    tau2: float
    tau12: float
    source: str = ""

    def __post_init__(self) -> None:
        for name in ("m1", "m2"):
            bounded(name, getattr(self, name), *MASS_RANGE, "kg")
        for name in ("tau2", "tau12"):
            bounded(name, getattr(self, name), *DURATION_RANGE, "s")
        check_linear_e("e2", self.e2, tensile=False)
        check_linear_e("e12", self.e12, tensile=False)

    @classmethod
    def from_pair(cls, pair: Pair) -> TwoSpringDashpot:
        """The model of a Table 1 pair with the pressure rule's contact times.

        Parameters
        ----------
        pair : Pair
            A preset of :data:`twoball.modal.pairs.PAIRS`.

        Returns
        -------
        TwoSpringDashpot
            Masses, restitutions and contact times of the pair.

        Examples
        --------
        >>> from twoball.modal.pairs import PAIRS
        >>> round(TwoSpringDashpot.from_pair(PAIRS["tennis-coin"]).tau2 * 1e3, 2)
        5.72
        """
        c = pair_contacts(pair)
        return cls(c.m1, c.m2, c.e2, c.e12, c.tau2, c.tau12, source=c.source)

    @property
    def floor_law(self) -> LinearLaw:
        """The floor contact's spring and dashpot (reduced mass m2)."""
        return fit_linear(self.m2, self.tau2, self.e2, tensile=False)

    @property
    def pair_law(self) -> LinearLaw:
        """The body-ball contact's spring and dashpot (reduced mass ``m1 m2 / (m1 + m2)``)."""
        reduced = self.m1 * self.m2 / (self.m1 + self.m2)
        return fit_linear(reduced, self.tau12, self.e12, tensile=False)

    @property
    def label(self) -> str:
        """The model's name in the results."""
        return "two-spring-dashpot"
