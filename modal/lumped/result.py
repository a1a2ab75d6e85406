"""What every lumped model returns: :class:`LumpedResult`, its contact events and energy budget.

SI units; velocities positive upwards; times measured from the lower ball's
impact on the floor (t = 0), when both bodies move at ``v0 < 0``.
"""

from __future__ import annotations

from dataclasses import dataclass, fields, replace

#: The two contacts of the two-ball bounce.
CONTACTS = ("floor", "pair")


@dataclass(frozen=True)
class ContactEvent:
    """One touch or release of a contact.

    Attributes
    ----------
    contact : str
        ``"floor"`` (lower ball on the floor) or ``"pair"`` (body on the lower ball).
    kind : str
        ``"touch"`` (the contact closes) or ``"release"`` (it opens).
    time : float
        Time after the floor impact [s].
    v1, v2 : float
        Velocities of the body (1) and the lower ball (2) [m/s].
    overlap : float
        Overlap of this contact [m] (> 0 compressed); a release with the force
        rule leaves a positive overlap.
    """

    contact: str
    kind: str
    time: float
    v1: float
    v2: float
    overlap: float


@dataclass(frozen=True)
class EnergyBudget:
    """Where the kinetic energy at the floor impact went, in joules.

    ``initial = final_kinetic + potential_change + stored + dissipated_floor +
    dissipated_pair + released_floor + released_pair + residual``, from the
    impact to the end of the run (``t_end``).

    Attributes
    ----------
    initial : float
        ``(m1 + m2) v0^2 / 2`` at the floor impact.
    final_kinetic : float
        Kinetic energy at ``t_end``.
    potential_change : float
        Gain of gravitational energy from the impact to ``t_end``.
    stored : float
        Elastic energy still held in closed contacts at ``t_end`` (0 when all are open).
    dissipated_floor, dissipated_pair : float
        Work of the dashpots (or the energy an instantaneous impact loses).
    released_floor, released_pair : float
        Elastic energy left in a contact when it opens with a positive overlap
        (force rule), net of energy taken back when such a contact closes again.
    residual : float
        What the balance misses: the integration error.
    rebound_kinetic : float
        ``(m1 v1^2 + m2 v2^2) / 2`` with the rebound velocities of the result.
    """

    initial: float
    final_kinetic: float
    potential_change: float
    stored: float
    dissipated_floor: float
    dissipated_pair: float
    released_floor: float
    released_pair: float
    residual: float
    rebound_kinetic: float

    def scaled(self, energy: float) -> EnergyBudget:
        """Every term multiplied by ``energy`` (a unit change)."""
        return EnergyBudget(**{f.name: getattr(self, f.name) * energy for f in fields(self)})

    @property
    def lost(self) -> float:
        """Energy that left the mechanical system [J]: dashpots plus releases."""
        return (
            self.dissipated_floor + self.dissipated_pair + self.released_floor + self.released_pair
        )


@dataclass(frozen=True)
class LumpedResult:
    """The outcome of one lumped model for one drop, SI units.

    Attributes
    ----------
    model : str
        Which model (``"icm"``, ``"two-spring-dashpot"``, ``"bartz2020"``,
        ``"hertz-viscoelastic"``).
    v0 : float
        Velocity of both bodies at the floor impact [m/s], < 0.
    dx : float
        Gap between the body and the lower ball's top at that instant [m].
    g : float
        Gravitational acceleration [m/s^2].
    m1, m2 : float
        Masses of the body and the lower ball [kg].
    v1, v2 : float
        Rebound velocities [m/s]: each body's velocity at the instant of its
        last release (the body from the lower ball; the lower ball from the
        floor or the body, whichever is later).
    t_liftoff : float
        Time from the floor impact to the body's last release [s].
    t_floor_release : float
        Time from the floor impact to the lower ball's last release from the floor [s].
    events : tuple of ContactEvent
        Every touch and release, in time order.
    energy : EnergyBudget
        The energy budget from the impact to ``t_end``.
    floor_impulse, pair_impulse : float
        Time integrals of the floor force on the lower ball and of the contact
        force on the body [N s].
    t_end : float
        End of the run [s]: every contact open and no further contact possible.
    v1_end, v2_end : float
        Velocities at ``t_end`` [m/s] (for the momentum balance
        ``m1 v1_end + m2 v2_end - (m1 + m2) v0 = floor_impulse - (m1 + m2) g t_end``).
    """

    model: str
    v0: float
    dx: float
    g: float
    m1: float
    m2: float
    v1: float
    v2: float
    t_liftoff: float
    t_floor_release: float
    events: tuple[ContactEvent, ...]
    energy: EnergyBudget
    floor_impulse: float
    pair_impulse: float
    t_end: float
    v1_end: float
    v2_end: float

    @property
    def mu(self) -> float:
        """Mass ratio ``m1 / m2``."""
        return self.m1 / self.m2

    @property
    def v1_ratio(self) -> float:
        """``v1 / |v0|`` (Table 1's upper-ball column)."""
        return self.v1 / abs(self.v0)

    @property
    def v2_ratio(self) -> float:
        """``v2 / |v0|`` (Table 1's lower-ball column)."""
        return self.v2 / abs(self.v0)

    @property
    def body_left_first(self) -> bool:
        """Whether the body lifted off before the lower ball left the floor."""
        return self.t_liftoff < self.t_floor_release

    def count(self, contact: str, kind: str = "touch") -> int:
        """How many events of ``kind`` the ``contact`` had."""
        return sum(1 for e in self.events if e.contact == contact and e.kind == kind)

    @property
    def pair_contacts(self) -> int:
        """Number of separate contacts between the body and the lower ball."""
        return self.count("pair")

    @property
    def first_release_v1(self) -> float:
        """The body's velocity at its first release from the lower ball [m/s]."""
        return next(e.v1 for e in self.events if e.contact == "pair" and e.kind == "release")

    @property
    def delayed_rebound(self) -> bool:
        """A second contact that sends the body off faster than the first (Bartz 2020)."""
        return self.pair_contacts > 1 and self.v1 > self.first_release_v1

    def summary(self) -> dict[str, float | int | bool | str]:
        """The scalar outcome, JSON-ready, units in the keys."""
        return {
            "model": self.model,
            "v0_m_s": self.v0,
            "dx_m": self.dx,
            "mu": self.mu,
            "v1_m_s": self.v1,
            "v2_m_s": self.v2,
            "v1_ratio": self.v1_ratio,
            "v2_ratio": self.v2_ratio,
            "t_liftoff_s": self.t_liftoff,
            "t_floor_release_s": self.t_floor_release,
            "body_left_first": self.body_left_first,
            "pair_contacts": self.pair_contacts,
            "energy_lost_J": self.energy.lost,
            "energy_residual_J": self.energy.residual,
        }

    def rescaled(
        self, mass: float, speed: float, time: float, model: str | None = None
    ) -> LumpedResult:
        """The same result in other units (a dimensionless run turned into SI).

        Masses are multiplied by ``mass``, velocities by ``speed``, times by ``time``.

        Parameters
        ----------
        mass, speed, time : float
            The units [kg], [m/s], [s] of the present numbers.
        model : str, optional
            A new model name.

        Returns
        -------
        LumpedResult
            Lengths scale with ``speed * time``, impulses with ``mass * speed``,
            energies with ``mass * speed**2``, g with ``speed / time``.
        """
        length = speed * time
        events = tuple(
            replace(
                e, time=e.time * time, v1=e.v1 * speed, v2=e.v2 * speed, overlap=e.overlap * length
            )
            for e in self.events
        )
        return LumpedResult(
            model=self.model if model is None else model,
            v0=self.v0 * speed,
            dx=self.dx * length,
            g=self.g * speed / time,
            m1=self.m1 * mass,
            m2=self.m2 * mass,
            v1=self.v1 * speed,
            v2=self.v2 * speed,
            t_liftoff=self.t_liftoff * time,
            t_floor_release=self.t_floor_release * time,
            events=events,
            energy=self.energy.scaled(mass * speed * speed),
            floor_impulse=self.floor_impulse * mass * speed,
            pair_impulse=self.pair_impulse * mass * speed,
            t_end=self.t_end * time,
            v1_end=self.v1_end * speed,
            v2_end=self.v2_end * speed,
        )
