"""The independent collision model of §2 as a lumped baseline with the common result type.

Wraps :func:`twoball.modal.icm.icm` (eqs. (2.1), (2.2), (2.5)): the floor impact
and the body-ball impact are instantaneous, at t = 0 and at ``dt`` of eq. (2.2).
Nothing is recomputed here but the bookkeeping of :class:`LumpedResult`
(events, impulses, energy).
"""

from __future__ import annotations

from dataclasses import dataclass

from twoball._common.errors import bounded
from twoball.modal.icm import icm
from twoball.modal.icm.inputs import check_mu, check_restitution
from twoball.modal.lumped.drop import check_gap, impact_speed
from twoball.modal.lumped.result import ContactEvent, EnergyBudget, LumpedResult
from twoball.modal.pairs import Pair
from twoball.modal.scalings import MASS_RANGE, STANDARD_GRAVITY


@dataclass(frozen=True)
class ICMBaseline:
    """The ICM (§2) with mass ratio mu and restitutions e2, e12 (Table 1 for a pair).

    Parameters
    ----------
    mu : float
        ``m1 / m2``, >= 0.
    e2, e12 : float
        Restitutions of the floor and body-ball impacts, in [0, 1].
    m2 : float, optional
        Mass of the lower ball [kg]; sets only the impulses and energies.

    Examples
    --------
    >>> r = ICMBaseline(mu=0.062, e2=0.83, e12=0.46).run(v0=4.1)  # Table 1, row 1
    >>> round(r.v1_ratio, 3), round(r.v2_ratio, 3)
    (1.516, 0.674)
    """

    mu: float
    e2: float
    e12: float
    m2: float = 1.0

    def __post_init__(self) -> None:
        check_mu(self.mu)
        check_restitution("e2", self.e2)
        check_restitution("e12", self.e12)
        bounded("m2", self.m2, *MASS_RANGE, "kg")

    @classmethod
    def from_pair(cls, pair: Pair) -> ICMBaseline:
        """The ICM of a Table 1 pair (mu, e2, e12 of its row; m2 of its lower ball).

        Parameters
        ----------
        pair : Pair
            A preset of :data:`twoball.modal.pairs.PAIRS`.

        Returns
        -------
        ICMBaseline
            The model.

        Examples
        --------
        >>> from twoball.modal.pairs import PAIRS
        >>> ICMBaseline.from_pair(PAIRS["tennis-nut"]).mu
        0.035
        """
        return cls(mu=pair.mu, e2=pair.e2, e12=pair.e12, m2=pair.m2)

    def run(
        self,
        v0: float | None = None,
        *,
        drop_height: float | None = None,
        dx: float = 0.0,
        g: float = STANDARD_GRAVITY,
    ) -> LumpedResult:
        """One drop by eqs. (2.1), (2.2), (2.5).

        Parameters
        ----------
        v0 : float, optional
            Impact velocity [m/s] (sign ignored); or give ``drop_height``.
        drop_height : float, optional
            Fall height of the lower ball [m].
        dx : float, optional
            Gap at the impact [m], in ``[0, 4 e2 (1 + e2) H]`` (see
            :func:`twoball.modal.icm.max_separation`).
        g : float, optional
            Gravitational acceleration [m/s^2], > 0.

        Returns
        -------
        LumpedResult
            Instantaneous events at 0 and ``dt``; ``t_liftoff = dt``.

        Examples
        --------
        >>> r = ICMBaseline(mu=0.0, e2=1.0, e12=1.0).run(v0=1.0)
        >>> r.v1_ratio, r.v2_ratio  # eq. (2.7): three times the impact speed
        (3.0, 1.0)
        """
        speed = impact_speed(v0, drop_height, g)
        height = speed * speed / (2.0 * g)
        out = icm(self.mu, self.e2, self.e12, dx=check_gap(dx), drop_height=height, g=g)
        m2 = self.m2
        m1 = self.mu * m2
        kinetic = lambda a, b: 0.5 * (m1 * a * a + m2 * b * b)  # noqa: E731
        before_pair = kinetic(out.u1, out.u2)
        after_pair = kinetic(out.v1, out.v2)
        initial = kinetic(out.v0, out.v0)
        floor_loss = 0.5 * m2 * out.v0**2 * (1.0 - self.e2**2)
        energy = EnergyBudget(
            initial=initial,
            final_kinetic=after_pair,
            potential_change=kinetic(out.v0, out.u0) - before_pair,
            stored=0.0,
            dissipated_floor=floor_loss,
            dissipated_pair=before_pair - after_pair,
            released_floor=0.0,
            released_pair=0.0,
            residual=0.0,
            rebound_kinetic=after_pair,
        )
        events = (
            ContactEvent("floor", "touch", 0.0, out.v0, out.v0, 0.0),
            ContactEvent("floor", "release", 0.0, out.v0, out.u0, 0.0),
            ContactEvent("pair", "touch", out.dt, out.u1, out.u2, 0.0),
            ContactEvent("pair", "release", out.dt, out.v1, out.v2, 0.0),
        )
        return LumpedResult(
            model="icm",
            v0=out.v0,
            dx=out.dx,
            g=g,
            m1=m1,
            m2=m2,
            v1=out.v1,
            v2=out.v2,
            t_liftoff=out.dt,
            t_floor_release=0.0,
            events=events,
            energy=energy,
            floor_impulse=m2 * (out.u0 - out.v0),
            pair_impulse=m1 * (out.v1 - out.u1),
            t_end=out.dt,
            v1_end=out.v1,
            v2_end=out.v2,
        )
