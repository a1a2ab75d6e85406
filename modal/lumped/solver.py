"""The one event-driven ODE solver that every contact-based lumped model uses.

Two point masses on a vertical line: the lower ball (mass m2) above a rigid
floor and the body (mass m1) above the lower ball.  Each contact carries a force
law from :mod:`twoball.modal.lumped.laws`; between events the equations are

    m2 z2'' = -m2 g + F_floor - F_pair,      m1 z1'' = -m1 g + F_pair,

with the floor overlap ``-z2`` and the pair overlap ``z2 - z1`` (z2: height of
the lower ball's undeformed underside, z1: height of the body's underside less
the lower ball's diameter).  :func:`scipy.integrate.solve_ivp` (DOP853)
integrates each phase with a fixed set of closed contacts; terminal events
close a contact when its switching function rises through 0 and open it when
the function falls through 0 (the overlap; for a law that never pulls, the
smaller of the overlap and the force expressed as a length).  The phase then
restarts with the contact toggled, so the right-hand side is smooth inside
every phase and each kink of the force is an exact event.

Why not an exact piecewise solution for the linear laws: one solver serves the
linear and the Hertz laws alike, and at rtol 1e-10 the integration error is far
below every tolerance of the tests (the linear isolated contacts are checked
against their closed forms in the tests).

The run starts at the floor impact (t = 0): both bodies move at ``-|v0|``,
the body ``dx`` above the lower ball's top; it ends when both contacts are
open, the lower ball moves up and the body at least as fast (no contact can
follow while both fly freely; the lower ball's next landing is another bounce).
"""

from __future__ import annotations

import math
from collections.abc import Callable
from typing import Protocol

import numpy as np
from scipy.integrate import solve_ivp

from twoball._common.errors import NumericalError
from twoball.modal.lumped.result import ContactEvent, EnergyBudget, LumpedResult

# state vector: z2, v2, z1, v1, floor impulse, pair impulse, floor and pair dashpot work
_Z2, _V2, _Z1, _V1, _JF, _JP, _DF, _DP = range(8)
_FLOOR, _PAIR = 0, 1
_NAMES = ("floor", "pair")
RTOL = 1e-10
MAX_EVENTS = 2000


class ContactLaw(Protocol):
    """What the solver needs of a force law (see :mod:`twoball.modal.lumped.laws`)."""

    tensile: bool

    def force(self, delta: float, rate: float) -> float: ...

    def dissipative_force(self, delta: float, rate: float) -> float: ...

    def elastic_energy(self, delta: float) -> float: ...

    @property
    def length_per_force(self) -> float: ...


def _overlap(y: np.ndarray, which: int) -> tuple[float, float]:
    """Overlap [m] and its rate [m/s] of the floor (0) or pair (1) contact."""
    if which == _FLOOR:
        return -y[_Z2], -y[_V2]
    return y[_Z2] - y[_Z1], y[_V2] - y[_V1]


def switching_value(law: ContactLaw, delta: float, rate: float) -> float:
    """The function whose zeros open and close a contact [m].

    The overlap for a law that may pull; otherwise the smaller of the overlap and
    the force turned into a length, so it rises through 0 when the bodies touch
    (or a recovering contact starts to push again) and falls through 0 when the
    force vanishes (Schwager & Pöschel, Granular Matter 9, 465 (2007)).

    Parameters
    ----------
    law : ContactLaw
        The contact's force law.
    delta, rate : float
        Overlap [m] and overlap rate [m/s].

    Returns
    -------
    float
        The switching value [m].

    Examples
    --------
    >>> from twoball.modal.lumped.laws import LinearLaw
    >>> law = LinearLaw(stiffness=100.0, damping=1.0, tensile=False)
    >>> switching_value(law, 0.01, -2.0)
    -0.01
    """
    if law.tensile:
        return delta
    return min(delta, law.force(max(delta, 0.0), rate) * law.length_per_force)


def _energy(y: np.ndarray, m1: float, m2: float, g: float) -> tuple[float, float]:
    """Kinetic and gravitational energy [J] (potential relative to z = 0)."""
    kinetic = 0.5 * m1 * y[_V1] ** 2 + 0.5 * m2 * y[_V2] ** 2
    return kinetic, g * (m1 * y[_Z1] + m2 * y[_Z2])


def _right_hand_side(
    laws: tuple[ContactLaw, ContactLaw], closed: tuple[bool, bool], m1: float, m2: float, g: float
) -> Callable[[float, np.ndarray], np.ndarray]:
    floor_law, pair_law = laws
    floor_closed, pair_closed = closed

    def rhs(_t: float, y: np.ndarray) -> np.ndarray:
        ff = fp = df = dp = 0.0
        if floor_closed:
            d, r = -y[_Z2], -y[_V2]
            ff = floor_law.force(d, r)
            df = floor_law.dissipative_force(d, r) * r
        if pair_closed:
            d, r = y[_Z2] - y[_Z1], y[_V2] - y[_V1]
            fp = pair_law.force(d, r)
            dp = pair_law.dissipative_force(d, r) * r
        return np.array(
            [y[_V2], -g + (ff - fp) / m2, y[_V1], -g + fp / m1, ff, fp, df, dp], dtype=float
        )

    return rhs


def _event(law: ContactLaw, which: int, closing: bool) -> Callable[[float, np.ndarray], float]:
    def event(_t: float, y: np.ndarray) -> float:
        return switching_value(law, *_overlap(y, which))

    event.terminal = True  # type: ignore[attr-defined]
    event.direction = 1.0 if closing else -1.0  # type: ignore[attr-defined]
    return event


def simulate(
    model: str,
    m1: float,
    m2: float,
    floor_law: ContactLaw,
    pair_law: ContactLaw,
    speed: float,
    dx: float,
    g: float,
    time_scales: tuple[float, float],
) -> LumpedResult:
    """Integrate one two-ball bounce from the floor impact to the final releases.

    Parameters
    ----------
    model : str
        Name stored in the result.
    m1, m2 : float
        Masses of the body and the lower ball [kg], > 0.
    floor_law, pair_law : ContactLaw
        Force laws of the floor contact and of the body-ball contact.
    speed : float
        Impact speed ``|v0|`` of both bodies [m/s], > 0.
    dx : float
        Gap between the body and the lower ball's top at the impact [m], >= 0;
        0 means resting in contact.
    g : float
        Gravitational acceleration [m/s^2], >= 0.
    time_scales : tuple of float
        Durations of the floor and pair contacts [s], > 0.  While contacts are
        closed the step is capped at 1/40 of the shortest closed one, so its
        release is not stepped over.  An open contact cannot be stepped over:
        without its force its overlap grows monotonically once it is positive,
        so the sign change is seen at the end of the step.  With both contacts
        open the motion is a polynomial in time and the step is free.

    Returns
    -------
    LumpedResult
        Rebound velocities, every contact event, impulses and the energy budget.

    Raises
    ------
    NumericalError
        If the integration fails, more than :data:`MAX_EVENTS` events occur, or
        the bodies have not parted by a generous time limit.

    Examples
    --------
    >>> from twoball.modal.lumped.laws import LinearLaw
    >>> floor = LinearLaw(stiffness=1.0e4, damping=0.0, tensile=False)
    >>> pair = LinearLaw(stiffness=1.0e3, damping=0.0, tensile=False)
    >>> r = simulate("demo", 0.01, 1.0, floor, pair, 1.0, 0.5, 0.0, (0.03, 0.003))
    >>> round(r.v1_ratio, 6), round(r.v2_ratio, 6)  # elastic (2.5) with mu = 0.01
    (2.960396, 0.960396)
    """
    laws = (floor_law, pair_law)
    y = np.zeros(8)
    y[_V2] = y[_V1] = -speed
    y[_Z1] = dx
    closed = [True, dx == 0.0]
    events = [ContactEvent("floor", "touch", 0.0, -speed, -speed, 0.0)]
    if closed[_PAIR]:
        events.append(ContactEvent("pair", "touch", 0.0, -speed, -speed, 0.0))
    released = [0.0, 0.0]
    kinetic0, potential0 = _energy(y, m1, m2, g)

    approach = dx / speed
    longest = max(time_scales)
    horizon = 40.0 * longest + 2.0 * approach
    t_limit = 400.0 * longest + 20.0 * approach + (20.0 * speed / g if g > 0.0 else 0.0)
    scale_x = speed * min(time_scales)
    mass = m1 + m2
    atol = 1e-12 * np.array(
        [scale_x, speed, scale_x, speed, mass * speed, mass * speed] + 2 * [mass * speed**2]
    )
    t = 0.0
    while not _parted(y, closed):
        if len(events) > MAX_EVENTS:
            raise NumericalError(f"{model}: more than {MAX_EVENTS} contact events")
        if t > t_limit:
            raise NumericalError(f"{model}: the bodies had not parted after {t:.3g} s")
        state = (closed[_FLOOR], closed[_PAIR])
        sol = solve_ivp(
            _right_hand_side(laws, state, m1, m2, g),
            (t, t + horizon),
            y,
            method="DOP853",
            events=[_event(laws[i], i, not closed[i]) for i in (_FLOOR, _PAIR)],
            rtol=RTOL,
            atol=atol,
            max_step=min((time_scales[i] / 40.0 for i in (0, 1) if closed[i]), default=np.inf),
        )
        if sol.status < 0:
            raise NumericalError(f"{model}: {sol.message}")
        t, y = float(sol.t[-1]), sol.y[:, -1].copy()
        if not np.all(np.isfinite(y)):
            raise NumericalError(f"{model}: the state is not finite at t = {t:.6g} s")
        if sol.status != 1:
            continue
        fired = [i for i in (_FLOOR, _PAIR) if sol.t_events[i].size]
        which = min(fired, key=lambda i: sol.t_events[i][0])
        delta = float(_overlap(y, which)[0])
        stored = float(laws[which].elastic_energy(max(delta, 0.0)))
        released[which] += stored if closed[which] else -stored
        closed[which] = not closed[which]
        kind = "touch" if closed[which] else "release"
        events.append(ContactEvent(_NAMES[which], kind, t, float(y[_V1]), float(y[_V2]), delta))
    return _result(model, m1, m2, laws, speed, dx, g, events, y, t, released, kinetic0, potential0)


def _parted(y: np.ndarray, closed: list[bool]) -> bool:
    """Both contacts open, the lower ball rising and the body not slower."""
    return not any(closed) and y[_V2] >= 0.0 and y[_V1] >= y[_V2]


def _result(
    model: str,
    m1: float,
    m2: float,
    laws: tuple[ContactLaw, ContactLaw],
    speed: float,
    dx: float,
    g: float,
    events: list[ContactEvent],
    y: np.ndarray,
    t_end: float,
    released: list[float],
    kinetic0: float,
    potential0: float,
) -> LumpedResult:
    pair_releases = [e for e in events if e.contact == "pair" and e.kind == "release"]
    floor_releases = [e for e in events if e.contact == "floor" and e.kind == "release"]
    if not pair_releases or not floor_releases:
        raise NumericalError(f"{model}: a contact never opened")
    lift, leave = pair_releases[-1], floor_releases[-1]
    v2 = lift.v2 if lift.time > leave.time else leave.v2
    kinetic, potential = (float(e) for e in _energy(y, m1, m2, g))
    kinetic0, potential0 = float(kinetic0), float(potential0)
    stored = 0.0  # both contacts are open at the end of a run
    dissipated_floor, dissipated_pair = float(y[_DF]), float(y[_DP])
    residual = (
        kinetic0
        + potential0
        - (kinetic + potential + stored + dissipated_floor + dissipated_pair + sum(released))
    )
    budget = EnergyBudget(
        initial=kinetic0,
        final_kinetic=kinetic,
        potential_change=potential - potential0,
        stored=stored,
        dissipated_floor=dissipated_floor,
        dissipated_pair=dissipated_pair,
        released_floor=released[_FLOOR],
        released_pair=released[_PAIR],
        residual=residual,
        rebound_kinetic=0.5 * m1 * lift.v1**2 + 0.5 * m2 * v2**2,
    )
    if not math.isfinite(residual):
        raise NumericalError(f"{model}: the energy budget is not finite")
    return LumpedResult(
        model=model,
        v0=-speed,
        dx=dx,
        g=g,
        m1=m1,
        m2=m2,
        v1=lift.v1,
        v2=v2,
        t_liftoff=lift.time,
        t_floor_release=leave.time,
        events=tuple(events),
        energy=budget,
        floor_impulse=float(y[_JF]),
        pair_impulse=float(y[_JP]),
        t_end=t_end,
        v1_end=float(y[_V1]),
        v2_end=float(y[_V2]),
    )
