"""Contact stiffnesses and contact times of a Table 1 pair from the lower ball's pressure.

A pressurised ball pressed a distance x onto a flat surface pushes with its
excess pressure times the flattened area, ``F = P 2 pi R x``: a linear spring
``k = 2 pi R P`` (Cross, Am. J. Phys. 67, 222 (1999), the paper's ref. [14];
Hubbard & Stronge, Sports Eng. 4, 49 (2001), ref. [25]).  Its half period
``pi sqrt(m / k)`` is the contact time on the floor; with ``T = P R / 2`` and
``m = 4 pi R^2 rho`` it equals ``pi / c``, c of eq. (3.8) (basketball: 9.81 ms).

A body pressed onto the top of the lower ball flattens the ball's membrane the
same way over a circle of radius a with ``a^2 = 2 R* x``: ``k12 = 2 pi R* P``
with the contact radius ``R*`` of :mod:`twoball.modal.pairs` (the body taken
rigid; two membranes at equal pressure meeting on a flat disc give the same
``k12``).  Its contact time is ``pi sqrt(m12 / k12)``, ``m12 = m1 m2 / (m1 + m2)``.
These are estimates: wall bending (the tennis ball's rubber) stiffens the
contacts and a soft body (the tissue ball) softens the pair contact.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from twoball._common.errors import ParameterError
from twoball.modal.pairs import Pair


@dataclass(frozen=True)
class PairContacts:
    """Masses, restitutions, stiffnesses and contact times of one pair.

    Attributes
    ----------
    m1, m2 : float
        Body mass ``mu m2`` and lower-ball mass [kg].
    e2, e12 : float
        Restitutions from Table 1.
    k2, k12 : float
        Floor and body-ball spring constants ``2 pi R P``, ``2 pi R* P`` [N/m].
    tau2, tau12 : float
        Undamped contact times ``pi sqrt(m / k)`` [s].
    source : str
        The rule and the lower ball's preset.
    """

    m1: float
    m2: float
    e2: float
    e12: float
    k2: float
    k12: float
    tau2: float
    tau12: float
    source: str

    @property
    def reduced_mass(self) -> float:
        """``m1 m2 / (m1 + m2)`` [kg]."""
        return self.m1 * self.m2 / (self.m1 + self.m2)


def pair_contacts(pair: Pair) -> PairContacts:
    """The pressure rule (module docstring) applied to ``pair``.

    Parameters
    ----------
    pair : Pair
        A preset of :data:`twoball.modal.pairs.PAIRS`.

    Returns
    -------
    PairContacts
        Masses, restitutions, spring constants and contact times.

    Raises
    ------
    ParameterError
        If the lower ball's preset has no pressure.

    Examples
    --------
    >>> from twoball.modal.pairs import PAIRS
    >>> c = pair_contacts(PAIRS["basketball-table-tennis"])
    >>> round(c.tau2 * 1e3, 2), round(c.tau12 * 1e3, 2)  # ms
    (9.81, 1.83)
    """
    ball = pair.ball
    if ball.pressure is None:
        raise ParameterError("pair", "a lower ball with a measured pressure", pair.name)
    k2 = 2.0 * math.pi * ball.radius * ball.pressure
    k12 = 2.0 * math.pi * pair.contact_radius * ball.pressure
    m1, m2 = pair.m1, pair.m2
    reduced = m1 * m2 / (m1 + m2)
    return PairContacts(
        m1=m1,
        m2=m2,
        e2=pair.e2,
        e12=pair.e12,
        k2=k2,
        k12=k12,
        tau2=math.pi * math.sqrt(m2 / k2),
        tau12=math.pi * math.sqrt(reduced / k12),
        source=f"k = 2 pi R P with the {pair.lower} preset (P = {ball.pressure:g} Pa, "
        f"R = {ball.radius:g} m, m = {m2:g} kg), R* = {pair.contact_radius:.5g} m; "
        f"mu, e2, e12 from Table 1 row {pair.row}",
    )
