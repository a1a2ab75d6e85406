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
    b_i sqrt(2 E)`` (:meth:`~twoball.modal.balls.description.ModalBall.floor_reach`),
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
from dataclasses import dataclass, field, replace
from typing import TYPE_CHECKING, Any

import numpy as np

from twoball.modal.floor.measure import (
    ContactInterval,
    contact_edge,
    contact_intervals,
    edge_law,
    hermite_peak,
    smoothed_minimum,
)
from twoball.modal.floor.system import FloorSystem
from twoball.modal.nonsmooth import Trajectory

if TYPE_CHECKING:
    from twoball.modal.floor.body import BodyResult

from twoball._common.errors import NumericalError, ParameterError, real_number
from twoball._common.monitor import Monitor

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
        (:func:`~twoball.modal.floor.measure.contact_edge` with the points and
        power of :func:`~twoball.modal.floor.measure.edge_law`), averaged over a
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
    body : BodyResult, optional
        The upper body's measures (:mod:`twoball.modal.floor.body`); then
        ``v2``/``e2`` are the centre's velocity at its last floor release and
        ``impulse_balance`` is the whole system's momentum books.
    elastic : ElasticResult, optional
        An elastic body's own measures (:mod:`twoball.modal.upper.measure`).
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
    body: BodyResult | None = None
    elastic: Any = None

    @property
    def steps(self) -> int:
        """Steps taken (localised touches shorten some)."""
        return int(self.trajectory.t.size - 1)

    @property
    def has_history(self) -> bool:
        """The states and impulses of every step are kept (False: :meth:`light`)."""
        return self.trajectory.q is not None

    def light(self) -> DropResult:
        """The same measures without the history of states and impulses (for sweeps).

        Every number of the result is kept; the force histories, figures and
        fields need the history and refuse a light result.
        """
        tr = self.trajectory
        empty = np.zeros((tr.impulse.shape[0], 0))
        stripped = replace(tr, q=None, v=None, impulse=empty, impact_impulse=empty)
        # the modes' samplers are closures: left out, so that the result pickles
        ball = self.system.ball.without_samplers()
        return replace(
            self,
            trajectory=stripped,
            edge_t=self.edge_t[:0],
            edge=self.edge[:0],
            system=replace(self.system, ball=ball),
        )

    def _history(self) -> Trajectory:
        if not self.has_history:
            raise ParameterError(
                "result",
                "one with its history for its forces, figure and fields (a sweep point "
                "keeps none: run it alone)",
                "a light drop result",
            )
        return self.trajectory

    @property
    def force(self) -> tuple[np.ndarray, np.ndarray]:
        """Mid-step times and the floor force of each step (step impulse / step length)."""
        tr = self._history()
        h = np.diff(tr.t)
        rows = self.system.floor
        step = (tr.impulse[:, rows] - tr.impact_impulse[:, rows]).sum(axis=1)
        return 0.5 * (tr.t[1:] + tr.t[:-1]), step / h

    @property
    def body_force(self) -> tuple[np.ndarray, np.ndarray]:
        """Mid-step times and the body's contact force of each step (zeros without a body)."""
        tr = self._history()
        h = np.diff(tr.t)
        if self.system.body is None:
            return 0.5 * (tr.t[1:] + tr.t[:-1]), np.zeros(h.size)
        rows = self.system.body_rows
        step = (tr.impulse[:, rows] - tr.impact_impulse[:, rows]).sum(axis=1)
        return 0.5 * (tr.t[1:] + tr.t[:-1]), step / h

    @property
    def impacts(self) -> tuple[np.ndarray, np.ndarray]:
        """Times of the floor's impacts and their total impulses (Newton's law at touches)."""
        tr = self._history()
        total = tr.impact_impulse[:, self.system.floor].sum(axis=1)
        k = np.flatnonzero(total > 0.0)
        return tr.t[k], total[k]


def _membrane_energy(system: FloorSystem, q: np.ndarray, v: np.ndarray) -> float:
    """The ball's vibration energy (kinetic, elastic and gas; the translation left out)."""
    b = system.ball
    d = system.membrane
    a, da = q[d], v[d]
    return 0.5 * float(b.masses[d] @ (da * da + b.omega_squared[d] * a * a))


def _cap_bound(system: FloorSystem) -> float:
    """``|<u>_cap| <= b sqrt(2 E)``: ``b^2 = sum_k b_k^2 / (m_k omega_k^2)`` (inf if unstable)."""
    if system.body is None:
        return math.nan
    return float(system.ball.bound(system.body.cap)[0])


def run_drop(
    system: FloorSystem,
    settings: DropSettings,
    label: str = "the drop",
    *,
    monitor: Monitor | None = None,
    **core: object,
) -> DropResult:
    """Drop the ball of ``system`` on the floor and measure the bounce (dimensionless).

    Parameters
    ----------
    system : FloorSystem
    settings : DropSettings
    label : str
        What the monitor is told the run is (``"the ball alone"``).
    monitor : Monitor, optional
        Told of every step (:class:`~twoball._common.monitor.Monitor`; it may stop
        the run by raising).
    **core
        Options of :class:`~twoball.modal.nonsmooth.MoreauJean` (``theta``,
        ``localise``, tolerances), for studies.
    """
    if not isinstance(system, FloorSystem):
        raise ParameterError("system", "a FloorSystem", type(system).__name__)
    ball = system.ball
    x = np.cos(ball.phi)
    bound = ball.floor_reach()
    floor = system.floor
    body = system.body
    stepper = system.integrator(settings.dt, **core)
    q0, v0 = system.falling(settings.v0)
    flags = {"stop": "window", "rising": False, "off": False}
    top_bound = _cap_bound(system)

    def floor_clear(state, record) -> bool:
        """The ball is off the floor and cannot come back while its centre rises."""
        if record.impact_impulse[floor].any() or record.step_impulse[floor].any():
            flags["rising"] = flags["off"] = False
            return False
        rising = state.v[system.centre] > 0.0
        if flags["rising"] and not rising:
            flags["stop"] = "apex"
            flags["off"] = True
            return True
        flags["rising"] = rising
        if not rising or not np.isfinite(bound).all():
            return False
        reach = math.sqrt(2.0 * _membrane_energy(system, state.q, state.v))
        # a point's gap is Z + x_i + (its vertical vibration) with the vibration at most
        # r_i sqrt(2 E) from now on (ModalBall.floor_reach), and Z only grows while the
        # centre rises: Z + x_i - r_i sqrt(2 E) > 0
        lowest = state.q[system.centre] + x - reach * bound
        if np.min(lowest) > 0.0:
            flags["stop"] = "flight"
            flags["off"] = True
            return True
        return False

    def body_clear(state, record) -> bool:
        """The body moves away from the ball's centre beyond what the membrane can reach.

        In free flight both fall alike, so ``s - Z`` grows linearly; the cap's mean
        displacement is at most ``b sqrt(2 E)`` (Cauchy-Schwarz, E the membrane's
        energy, which cannot grow in flight).
        """
        own = system.body_apart(state, record, stepper)
        if own is not None:  # an elastic body's own rule (modal/upper/system.py)
            return own
        row = system.body_row
        if record.impact_impulse[row] > 0.0 or record.step_impulse[row] > 0.0:
            return False
        k = system.body_coordinate
        if state.v[k] - state.v[system.centre] <= 0.0 or not math.isfinite(top_bound):
            return False
        reach = math.sqrt(2.0 * _membrane_energy(system, state.q, state.v))
        return state.q[k] - state.q[system.centre] - 1.0 - reach * top_bound > 0.0

    def stop(state, record) -> bool:
        clear = floor_clear(state, record)
        if body is None or not clear:
            return clear
        if body_clear(state, record):
            return True
        flags["stop"] = "window"  # the body may still come back: go on
        return False

    from threadpoolctl import threadpool_limits

    start = time.perf_counter()
    # thin products with G and small solves: BLAS threads only contend on a loaded
    # machine (measured 11x slower steps for 1200 unknowns with both cores busy)
    with threadpool_limits(limits=1, user_api="blas"):
        tr = stepper.run(
            q0, v0, settings.t_end, stop=stop, keep_states=True, label=label, monitor=monitor
        )
    wall = time.perf_counter() - start
    result = _measure(system, settings, tr, flags["stop"], wall, bool(flags["off"]))
    extra = system.body_measures(stepper, result)
    if extra is None:
        return result
    elastic, books = extra
    return replace(result, elastic=elastic, energy={**result.energy, **books})


def _measure(
    system: FloorSystem,
    settings: DropSettings,
    tr: Trajectory,
    stop: str,
    wall: float,
    off: bool = False,
) -> DropResult:
    gamma, v0 = settings.gamma, settings.v0
    centre = system.centre
    impulses = tr.impulse[:, system.floor].sum(axis=1)
    intervals = contact_intervals(tr.t, impulses, settings.dt)
    if not intervals:
        raise NumericalError("the ball never touched the floor")
    events: list[FloorEvent] = []
    for iv in intervals:
        struck = int(np.count_nonzero(tr.impact_impulse[iv.first, system.floor] > 0.0))
        events.append(FloorEvent("touch", iv.start, float(tr.v[iv.first, centre]), struck))
        carrying = int(np.count_nonzero(tr.impulse[iv.last, system.floor] > 0.0))
        speed = float(tr.v[iv.last + 1, centre] + gamma * (tr.t[iv.last + 1] - iv.end))
        events.append(FloorEvent("separation", iv.end, speed, carrying))
    point_events = len(tr.events)
    # the ball has left the floor for good (with a body, the run may go on for it)
    left = stop in ("flight", "apex") or off
    apart = stop in ("flight", "apex")
    last = intervals[-1]
    total = float(impulses.sum())
    body = None
    if system.body is not None:
        from twoball.modal.floor.body import measure_body, momentum_balance

        body = measure_body(system, tr, intervals, apart, settings.dt)
    if left and system.body is not None:
        contact_time = last.end - intervals[0].start
        # the centre at its floor release: free flight from the next step end back to it
        v2 = float(tr.v[last.last + 1, centre] + gamma * (tr.t[last.last + 1] - last.end))
        e2 = v2 / v0
        balance = momentum_balance(system, tr)
    elif left:
        contact_time = last.end - intervals[0].start
        v2 = float(tr.v_final[centre] + gamma * (tr.t[-1] - last.end))
        e2 = v2 / v0
        balance = abs(total - (v2 + v0 + gamma * last.end)) / total
    else:
        contact_time = v2 = e2 = None
        balance = math.nan
    # the contact edge at every step end that closes a step with floor impulse
    gaps = system.floor_gaps(tr.q)
    carried = np.flatnonzero(impulses > 0.0)
    ends = carried + 1
    law = edge_law(system.ball.bending)
    edge = np.array([contact_edge(system.ball.phi, gaps[k], GAP_TOLERANCE, **law) for k in ends])
    edge_t = tr.t[ends]
    window = EDGE_WINDOW * (last.end - intervals[0].start)
    phi_a_max, t_phi = smoothed_minimum(edge_t, edge, window)
    flattening, t_compression = hermite_peak(tr.t, 1.0 - tr.q[:, centre], -tr.v[:, centre])
    parts = system.energies(tr.q[-1], tr.v[-1])
    final = {name: float(value[0]) for name, value in parts.items()}
    initial = 0.5 * v0 * v0 + gamma * float(tr.q[0, centre])
    body_start = {}
    if system.body is not None:
        start = system.energies(tr.q[0], tr.v[0])
        initial += float(start["body_kinetic"][0] + start["body_gravity"][0])
        body_start = {
            "body_kinetic_start": float(start["body_kinetic"][0]),
            "body_gravity_start": float(start["body_gravity"][0]),
        }
    energy = {
        "initial": initial,
        **final,
        "damped": float(tr.damping_work[-1]),
        "impacts": float(tr.impact_work[-1]),
        "contact": float(tr.contact_work[-1]),
        "vibration": final["membrane_kinetic"] + final["membrane_elastic"] + final["gas"],
        "balance": float(np.max(np.abs(tr.balance))),
        **body_start,
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
        body=body,
    )
