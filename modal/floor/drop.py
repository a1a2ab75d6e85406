"""One drop of the lower ball on the rigid floor: the shared runner and its result.

Dimensionless (R, 1/c, m2).  :func:`drop` starts the ball undeformed with its
south pole touching the floor, its centre falling at ``|v0|``, integrates
(F1)-(F3) of :mod:`twoball.modal.floor.system` with the contact core
(:class:`~twoball.modal.nonsmooth.MoreauJean`, theta = 1/2, touches localised)
and stops as soon as the ball is known to have left the floor:

``flight``
    No floor impulse in the last step, the centre moving up, and every floor
    point higher than the membrane's vibration can reach: with E the membrane's
    energy (kinetic, elastic and gas; it cannot grow in flight), ``|u(phi_i)| <=
    b_i sqrt(2 E)`` (:meth:`~twoball.modal.floor.ball.ModalBall.amplitude_bound`),
    and while the centre rises no point can come back to the floor.
``apex``
    The centre reached the top of its flight without touching again.
``window``
    The modelled window ended first (a warning for the caller: the ball has not
    left the floor, or has not been seen to).

Every quantity of :class:`DropResult` is measured as in
:mod:`twoball.modal.floor.measure`.
"""

from __future__ import annotations

import math
import time
from dataclasses import dataclass, field

import numpy as np
from twoball.modal.floor.measure import (
    ContactInterval,
    contact_edge,
    contact_intervals,
    hermite_peak,
    smoothed_minimum,
)
from twoball.modal.floor.system import FloorSystem
from twoball.modal.nonsmooth import MoreauJean, Trajectory

from twoball._common.errors import NumericalError, ParameterError, real_number

__all__ = ["DropResult", "DropSettings", "FloorEvent", "run_drop"]

#: Moving-average window of the contact edge, as a fraction of the contact time.
EDGE_WINDOW = 0.05
#: A floor point whose gap is at most this (units R) counts as touching.
GAP_TOLERANCE = 1e-10


@dataclass(frozen=True)
class DropSettings:
    """The drop's numbers (dimensionless).

    Parameters
    ----------
    v0 : float
        Impact speed ``|v0| / (R c)`` > 0.
    gamma : float
        ``g / (R c^2)`` >= 0.
    dt : float
        Time step (units 1/c) > 0.
    t_end : float
        The window: the run stops there if the ball has not left (> dt).
    """

    v0: float
    gamma: float
    dt: float
    t_end: float

    def __post_init__(self) -> None:
        for name, low in (("v0", 0.0), ("dt", 0.0), ("t_end", 0.0)):
            value = real_number(name, getattr(self, name), "a finite number > 0")
            if not (value > low and math.isfinite(value)):
                raise ParameterError(name, "a finite number > 0", value)
        gamma = real_number("gamma", self.gamma, "a finite number >= 0")
        if not (gamma >= 0.0 and math.isfinite(gamma)):
            raise ParameterError("gamma", "a finite number >= 0", gamma)
        if self.t_end <= self.dt:
            raise ParameterError("t_end", f"longer than the time step {self.dt:g}", self.t_end)


@dataclass(frozen=True)
class FloorEvent:
    """A touch of the floor or a separation from it (dimensionless).

    Attributes
    ----------
    kind : {"touch", "separation"}
    t : float
        Time from the first touch.
    velocity : float
        The centre's velocity Z' (upward positive).
    points : int
        Floor points struck at a touch, in contact just before a separation.
    """

    kind: str
    t: float
    velocity: float
    points: int


@dataclass(frozen=True, eq=False)
class DropResult:
    """A drop measured (dimensionless: length R, time 1/c, mass m2, energy m2 (R c)^2).

    Attributes
    ----------
    settings : DropSettings
    left : bool
        The ball left the floor and moves up (stop ``flight`` or ``apex``).
    stop : {"flight", "apex", "window"}
        Why the run ended (see the module documentation).
    contact_time : float or None
        First touch to the last separation (None if the ball has not left).
    v2, e2 : float or None
        The centre's velocity when it leaves (upward positive), and ``v2 / |v0|``.
    phi_a_max : float
        Contact angle of the largest contact [rad]: the smallest edge angle
        (:func:`~twoball.modal.floor.measure.contact_edge`), averaged over a
        window of :data:`EDGE_WINDOW` of the contact time.
    phi_a_extreme : float
        The smallest edge angle of any step end (no averaging).
    t_phi_a_max : float
        When the averaged edge is smallest.
    flattening_max, t_max_compression : float
        Largest ``1 - Z`` (the centre's drop below R) and when.
    impulse : float
        Total floor impulse.
    impulse_balance : float
        ``|impulse - (v2 + |v0| + gamma t_c)| / impulse`` (momentum; NaN if not left).
    events : tuple of FloorEvent
    intervals : tuple of ContactInterval
    point_events : int
        Touches and releases of single floor points.
    energy : dict
        Final energy parts (:meth:`FloorSystem.energies`), ``initial`` (kinetic
        plus gravity), ``damped`` and ``impacts`` (the works, <= 0), ``contact``
        (work of slow arrivals held by the step, ~0), ``vibration`` (membrane
        kinetic + elastic + gas at the end) and ``balance`` (the largest
        ``|E - E_0 - works|`` over the run: rounding).
    edge_t, edge : ndarray
        Step ends in contact and the contact edge there [rad].
    trajectory : Trajectory
        The states, impulses and energies of every step.
    system : FloorSystem
    wall_s : float
        Wall time of the run [s].
    """

    settings: DropSettings
    left: bool
    stop: str
    contact_time: float | None
    v2: float | None
    e2: float | None
    phi_a_max: float
    phi_a_extreme: float
    t_phi_a_max: float
    flattening_max: float
    t_max_compression: float
    impulse: float
    impulse_balance: float
    events: tuple[FloorEvent, ...]
    intervals: tuple[ContactInterval, ...]
    point_events: int
    energy: dict[str, float]
    edge_t: np.ndarray = field(repr=False)
    edge: np.ndarray = field(repr=False)
    trajectory: Trajectory = field(repr=False)
    system: FloorSystem = field(repr=False)
    wall_s: float = 0.0

    @property
    def steps(self) -> int:
        """Steps taken (localised touches shorten some)."""
        return int(self.trajectory.t.size - 1)

    @property
    def force(self) -> tuple[np.ndarray, np.ndarray]:
        """Mid-step times and the floor force of each step (step impulse / step length)."""
        tr = self.trajectory
        h = np.diff(tr.t)
        step = (tr.impulse - tr.impact_impulse).sum(axis=1)
        return 0.5 * (tr.t[1:] + tr.t[:-1]), step / h

    @property
    def impacts(self) -> tuple[np.ndarray, np.ndarray]:
        """Times of the impacts and their total impulses (Newton's law at touches)."""
        tr = self.trajectory
        total = tr.impact_impulse.sum(axis=1)
        k = np.flatnonzero(total > 0.0)
        return tr.t[k], total[k]


def _membrane_energy(system: FloorSystem, q: np.ndarray, v: np.ndarray) -> float:
    b = system.ball
    a, da = q[system.membrane], v[system.membrane]
    return 0.5 * float(b.masses @ (da * da + b.omega_squared * a * a))


def run_drop(system: FloorSystem, settings: DropSettings, **core: object) -> DropResult:
    """Drop the ball of ``system`` on the floor and measure the bounce (dimensionless).

    Parameters
    ----------
    system : FloorSystem
    settings : DropSettings
    **core
        Options of :class:`~twoball.modal.nonsmooth.MoreauJean` (``theta``,
        ``localise``, tolerances), for studies.
    """
    if not isinstance(system, FloorSystem):
        raise ParameterError("system", "a FloorSystem", type(system).__name__)
    ball = system.ball
    x = np.cos(ball.phi)
    bound = np.abs(x) * ball.amplitude_bound()
    stepper = MoreauJean(system.problem, settings.dt, **core)
    q0, v0 = system.falling(settings.v0)
    flags = {"stop": "window", "rising": False}

    def stop(state, record) -> bool:
        if record.impact_impulse.any() or record.step_impulse.any():
            flags["rising"] = False
            return False
        rising = state.v[system.centre] > 0.0
        if flags["rising"] and not rising:
            flags["stop"] = "apex"
            return True
        flags["rising"] = rising
        if not rising or not np.isfinite(bound).all():
            return False
        reach = math.sqrt(2.0 * _membrane_energy(system, state.q, state.v))
        if np.min(system.floor_gaps(state.q) - reach * bound) > 0.0:
            flags["stop"] = "flight"
            return True
        return False

    start = time.perf_counter()
    tr = stepper.run(q0, v0, settings.t_end, stop=stop, keep_states=True)
    wall = time.perf_counter() - start
    return _measure(system, settings, tr, flags["stop"], wall)


def _measure(
    system: FloorSystem, settings: DropSettings, tr: Trajectory, stop: str, wall: float
) -> DropResult:
    gamma, v0 = settings.gamma, settings.v0
    impulses = tr.impulse.sum(axis=1)
    intervals = contact_intervals(tr.t, impulses, settings.dt)
    if not intervals:
        raise NumericalError("the ball never touched the floor")
    events: list[FloorEvent] = []
    for iv in intervals:
        struck = int(np.count_nonzero(tr.impact_impulse[iv.first] > 0.0))
        events.append(FloorEvent("touch", iv.start, float(tr.v[iv.first, 0]), struck))
        carrying = int(np.count_nonzero(tr.impulse[iv.last] > 0.0))
        speed = float(tr.v[iv.last + 1, 0] + gamma * (tr.t[iv.last + 1] - iv.end))
        events.append(FloorEvent("separation", iv.end, speed, carrying))
    point_events = len(tr.events)
    left = stop in ("flight", "apex")
    last = intervals[-1]
    total = float(impulses.sum())
    if left:
        contact_time = last.end - intervals[0].start
        v2 = float(tr.v_final[0] + gamma * (tr.t[-1] - last.end))
        e2 = v2 / v0
        balance = abs(total - (v2 + v0 + gamma * last.end)) / total
    else:
        contact_time = v2 = e2 = None
        balance = math.nan
    # the contact edge at every step end that closes a step with floor impulse
    gaps = system.floor_gaps(tr.q)
    carried = np.flatnonzero(impulses > 0.0)
    ends = carried + 1
    edge = np.array([contact_edge(system.ball.phi, gaps[k], GAP_TOLERANCE) for k in ends])
    edge_t = tr.t[ends]
    window = EDGE_WINDOW * (last.end - intervals[0].start)
    phi_a_max, t_phi = smoothed_minimum(edge_t, edge, window)
    flattening, t_compression = hermite_peak(tr.t, 1.0 - tr.q[:, 0], -tr.v[:, 0])
    parts = system.energies(tr.q[-1], tr.v[-1])
    final = {name: float(value[0]) for name, value in parts.items()}
    energy = {
        "initial": 0.5 * v0 * v0 + gamma * float(tr.q[0, 0]),
        **final,
        "damped": float(tr.damping_work[-1]),
        "impacts": float(tr.impact_work[-1]),
        "contact": float(tr.contact_work[-1]),
        "vibration": final["membrane_kinetic"] + final["membrane_elastic"] + final["gas"],
        "balance": float(np.max(np.abs(tr.balance))),
    }
    return DropResult(
        settings=settings,
        left=left,
        stop=stop,
        contact_time=contact_time,
        v2=v2,
        e2=e2,
        phi_a_max=phi_a_max,
        phi_a_extreme=float(edge.min()) if edge.size else math.pi,
        t_phi_a_max=t_phi,
        flattening_max=flattening,
        t_max_compression=t_compression,
        impulse=total,
        impulse_balance=balance,
        events=tuple(events),
        intervals=tuple(intervals),
        point_events=point_events,
        energy=energy,
        edge_t=edge_t,
        edge=edge,
        trajectory=tr,
        system=system,
        wall_s=wall,
    )
