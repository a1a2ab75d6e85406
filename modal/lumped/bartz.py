"""The damped-oscillator model of the two-ball bounce after Bartz (2020), in dimensionless form.

Source: S. P. Bartz, "Delayed rebounds in the two-ball bounce problem",
arXiv:2007.15005 (2020).  Only its abstract and introduction could be
consulted here.  What the abstract states: the independent contact model
(ICM) is reviewed and found accurate for a wide variety of cases, even when
the collisions are not truly independent; the dynamical model is based on the
solution of the damped harmonic oscillator; its equations of motion are made
dimensionless to reduce the number of parameters and initial conditions; a
"delayed rebound effect" -- a small first bounce followed by a higher second
bounce -- is found for a range of parameters, most commonly where the first
bounce is lower than the ICM's prediction.

What is this module's choice, not the abstract's:

* each contact is a linear spring and dashpot, the damped harmonic
  oscillator read as a contact law;
* a contact lasts while the bodies overlap (``tensile=True`` of
  :class:`~twoball.modal.lumped.laws.LinearLaw`), so the dashpot may pull at
  its end: the rule under which an isolated contact restitutes
  ``e = exp(-pi zeta / sqrt(1 - zeta^2))``, the textbook damped oscillator's.
  This is what tells the model from
  :class:`~twoball.modal.lumped.spring_dashpot.TwoSpringDashpot`, whose
  contacts open when their force vanishes (Schwager & Pöschel 2007); with the
  same springs and dashpots the two give different restitutions and rebounds
  when damped, and the same motion when elastic (tested);
* the units and the five groups below, and the inputs of a Table 1 pair
  (:meth:`Bartz2020.from_pair`).

The paper's own dimensionless groups and worked examples could not be
consulted: no number of that paper is claimed to be reproduced.  The
abstract's qualitative claim is: with ``zeta`` from e2 = 0.8, e12 = 0.6,
``g = 0``, ``mu = 0.01``, ``kappa = 1`` and a gap of 0.5 ``|v0| / w2`` the
body leaves the lower ball at 0.68 ``|v0|``, is caught again and leaves at
0.87 ``|v0|``, both below the ICM's 1.85 (tested).

Dimensionless units: mass m2, impact speed ``|v0|``, time ``1 / w2`` with
``w2 = sqrt(k2 / m2)`` (the floor contact's undamped frequency; for a
pressurised ball ``w2 = c`` of eq. (3.8)), length ``|v0| / w2``.  With
``y = z / (|v0| / w2)`` and ``s = w2 t`` the equations read

    y2'' = -gamma + F_floor - F_pair,          mu y1'' = -mu gamma + F_pair,
    F_floor = d + 2 zeta2 d'  (d = -y2 > 0),
    F_pair = kappa d12 + 2 zeta12 sqrt(kappa mu / (1 + mu)) d12'  (d12 = y2 - y1 > 0),

with five groups: mass ratio ``mu = m1 / m2``, stiffness ratio ``kappa = k12 / k2``,
damping ratios ``zeta2`` and ``zeta12`` (each isolated contact has restitution
``exp(-pi zeta / sqrt(1 - zeta^2))``), gravity ``gamma = g / (w2 |v0|)`` and,
as the initial condition, the gap ``dx w2 / |v0|``.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from twoball._common.errors import bounded
from twoball.modal.lumped.drop import check_gap, check_gravity, impact_speed
from twoball.modal.lumped.fitting import linear_restitution
from twoball.modal.lumped.laws import LinearLaw
from twoball.modal.lumped.pair_inputs import pair_contacts
from twoball.modal.lumped.result import LumpedResult
from twoball.modal.lumped.solver import simulate
from twoball.modal.pairs import Pair
from twoball.modal.scalings import MASS_RANGE, STANDARD_GRAVITY

MU_RANGE = (1e-12, 1e6)
KAPPA_RANGE = (1e-9, 1e9)
ZETA_RANGE = (0.0, 0.999)


def zeta_from_restitution(e: float) -> float:
    """Damping ratio zeta of a damped-oscillator contact: ``e = exp(-pi zeta / sqrt(1 - zeta^2))``.

    Parameters
    ----------
    e : float
        Restitution in (0, 1].

    Returns
    -------
    float
        zeta in [0, 1).

    Examples
    --------
    >>> round(zeta_from_restitution(0.8), 5)
    0.07085
    """
    e = bounded("e", e, 0.0, 1.0, low_open=True)
    a = -math.log(e) / math.pi
    return a / math.sqrt(1.0 + a * a)


@dataclass(frozen=True)
class Bartz2020:
    """Two damped-oscillator contacts in Bartz's (2020) dimensionless form (module docstring).

    Inputs (:meth:`from_pair` for a Table 1 pair): ``mu`` (Table 1), ``kappa =
    k12 / k2`` with ``k = 2 pi R P`` and ``2 pi R* P`` (Cross 1999, see
    :mod:`twoball.modal.lumped.pair_inputs`), ``zeta2``, ``zeta12`` from Table
    1's e2, e12 through ``e = exp(-pi zeta / sqrt(1 - zeta^2))``; the SI scales
    ``m2`` (preset) and ``omega2 = sqrt(k2 / m2)`` (= c of eq. (3.8)).

    Parameters
    ----------
    mu : float
        ``m1 / m2``, in [1e-12, 1e6].
    kappa : float
        ``k12 / k2``, > 0.
    zeta2, zeta12 : float
        Damping ratios of the floor and body-ball contacts, in [0, 0.999].
    m2 : float, optional
        Mass unit [kg] (the lower ball's mass) for SI results.
    omega2 : float, optional
        ``sqrt(k2 / m2)`` [1/s] for SI results.
    source : str, optional
        Where the inputs come from.

    Examples
    --------
    >>> model = Bartz2020(mu=0.01, kappa=0.01, zeta2=0.0, zeta12=0.0)
    >>> r = model.run_dimensionless(gap=10.0, gamma=0.0)
    >>> round(r.v1, 6), round(r.v2, 6)  # elastic (2.5) with mu = 0.01
    (2.960396, 0.960396)
    """

    mu: float
    kappa: float
    zeta2: float
    zeta12: float
    m2: float = 1.0
    omega2: float = 1.0
    source: str = ""

    def __post_init__(self) -> None:
        bounded("mu", self.mu, *MU_RANGE)
        bounded("kappa", self.kappa, *KAPPA_RANGE)
        bounded("zeta2", self.zeta2, *ZETA_RANGE)
        bounded("zeta12", self.zeta12, *ZETA_RANGE)
        bounded("m2", self.m2, *MASS_RANGE, "kg")
        bounded("omega2", self.omega2, 1e-6, 1e9, "1/s")

    @classmethod
    def from_stiffness(
        cls, m1: float, m2: float, k2: float, k12: float, e2: float, e12: float, source: str = ""
    ) -> Bartz2020:
        """The model from SI masses [kg], spring constants [N/m] and restitutions.

        Parameters
        ----------
        m1, m2 : float
            Masses of the body and the lower ball [kg].
        k2, k12 : float
            Floor and body-ball spring constants [N/m].
        e2, e12 : float
            Isolated-contact restitutions, in (0, 1].
        source : str, optional
            Where they come from.

        Returns
        -------
        Bartz2020
            ``mu = m1 / m2``, ``kappa = k12 / k2``, zetas from the e's,
            ``omega2 = sqrt(k2 / m2)``.

        Examples
        --------
        >>> m = Bartz2020.from_stiffness(0.0573, 0.567, 58207.4, 12703.2, 0.8, 0.89)
        >>> round(m.omega2, 1), round(m.kappa, 4)
        (320.4, 0.2182)
        """
        m1 = bounded("m1", m1, *MASS_RANGE, "kg")
        m2 = bounded("m2", m2, *MASS_RANGE, "kg")
        k2 = bounded("k2", k2, 1e-9, 1e15, "N/m")
        k12 = bounded("k12", k12, 1e-9, 1e15, "N/m")
        return cls(
            mu=m1 / m2,
            kappa=k12 / k2,
            zeta2=zeta_from_restitution(e2),
            zeta12=zeta_from_restitution(e12),
            m2=m2,
            omega2=math.sqrt(k2 / m2),
            source=source,
        )

    @classmethod
    def from_pair(cls, pair: Pair) -> Bartz2020:
        """The model of a Table 1 pair with the pressure rule's spring constants.

        Parameters
        ----------
        pair : Pair
            A preset of :data:`twoball.modal.pairs.PAIRS`.

        Returns
        -------
        Bartz2020
            See :meth:`from_stiffness`.

        Examples
        --------
        >>> from twoball.modal.pairs import PAIRS
        >>> round(Bartz2020.from_pair(PAIRS["basketball-tissue"]).omega2, 1)
        320.4
        """
        c = pair_contacts(pair)
        return cls.from_stiffness(c.m1, c.m2, c.k2, c.k12, c.e2, c.e12, source=c.source)

    @property
    def e2(self) -> float:
        """Restitution of the isolated floor contact, ``exp(-pi zeta2 / sqrt(1 - zeta2^2))``."""
        return linear_restitution(self.zeta2 / math.sqrt(1.0 - self.zeta2**2), tensile=True)[0]

    @property
    def e12(self) -> float:
        """Restitution of the isolated body-ball contact."""
        return linear_restitution(self.zeta12 / math.sqrt(1.0 - self.zeta12**2), tensile=True)[0]

    def run_dimensionless(self, gap: float, gamma: float) -> LumpedResult:
        """One drop in the units m2, ``|v0|``, ``1 / omega2`` (module docstring).

        Parameters
        ----------
        gap : float
            ``dx omega2 / |v0|``, >= 0.
        gamma : float
            ``g / (omega2 |v0|)``, >= 0.

        Returns
        -------
        LumpedResult
            In the dimensionless units (``m2 = 1``, ``v0 = -1``).

        Examples
        --------
        >>> r = Bartz2020(mu=0.01, kappa=0.01, zeta2=0.0, zeta12=0.0).run_dimensionless(0.0, 0.0)
        >>> r.pair_contacts
        1
        """
        gap = bounded("gap", gap, 0.0, 1e9)
        gamma = bounded("gamma", gamma, 0.0, 1e9)
        reduced = self.mu / (1.0 + self.mu)
        floor = LinearLaw(stiffness=1.0, damping=2.0 * self.zeta2, tensile=True)
        pair = LinearLaw(
            stiffness=self.kappa,
            damping=2.0 * self.zeta12 * math.sqrt(self.kappa * reduced),
            tensile=True,
        )
        pair_time = math.pi * math.sqrt(reduced / self.kappa)
        return simulate(
            "bartz2020", self.mu, 1.0, floor, pair, 1.0, gap, gamma, (math.pi, pair_time)
        )

    def run(
        self,
        v0: float | None = None,
        *,
        drop_height: float | None = None,
        dx: float = 0.0,
        g: float = STANDARD_GRAVITY,
    ) -> LumpedResult:
        """One drop in SI (scales ``m2`` and ``omega2``): see :meth:`run_dimensionless`.

        Parameters
        ----------
        v0 : float, optional
            Impact velocity [m/s] (sign ignored); or give ``drop_height``.
        drop_height : float, optional
            Fall height of the lower ball [m].
        dx : float, optional
            Gap at the impact [m], >= 0.
        g : float, optional
            Gravitational acceleration [m/s^2], >= 0.

        Returns
        -------
        LumpedResult
            In SI.

        Examples
        --------
        >>> from twoball.modal.pairs import PAIRS
        >>> r = Bartz2020.from_pair(PAIRS["basketball-tissue"]).run(v0=4.1)
        >>> round(r.t_floor_release * 1e3, 2)  # ms: about pi / (omega2 sqrt(1 - zeta2^2))
        9.88
        """
        g = check_gravity(g)
        speed = impact_speed(v0, drop_height, g)
        dx = check_gap(dx)
        result = self.run_dimensionless(dx * self.omega2 / speed, g / (self.omega2 * speed))
        return result.rescaled(self.m2, speed, 1.0 / self.omega2)
