"""What the whole two-ball bounce is measured by: the body's contacts, lift-off and restitution.

Dimensionless (R, 1/c, m2).  The run of :func:`~twoball.modal.floor.drop.run_drop`
with a body on the ball (:class:`~twoball.modal.floor.system.BodyOnTop`) is
measured here:

Body contact intervals
    Stretches of steps in which the body's row (B2) carries impulse, ended where
    its force vanishes (:func:`~twoball.modal.floor.measure.contact_intervals`,
    the same rule as the floor's).
Lift-off
    The body's last separation: ``t_liftoff`` (from the first floor touch) and
    ``v1``, the body's velocity there (free flight after it: the velocity at the
    next step end plus ``gamma`` times the time back to the separation).
    ``t_liftoff_from_max_compression = t_liftoff - t_max_compression`` (the
    paper's ``t_l`` of Fig. 9 and Table 2).
Rebound of the ball
    ``v2``: the centre's velocity at the ball's last release, from the floor or
    from the body, whichever is later (the ICM's "just after the impact").
Sequence
    ``independent`` when the ball has left the floor for good before the body
    first touches it (the ICM's order of events, eq. (2.2)), else
    ``overlapping``.  ``body_left_first``: the body's last separation comes
    before the ball's last floor separation.
Effective restitution
    Between the centres, eq. (2.4) with the velocities before the body's first
    touch and after its last separation: ``e12_eff = (v2 - v1) / (u1 - u2)``.
    Both bodies fall freely between the contacts, so the relative velocity is
    constant there and gravity drops out; the value is None when the collisions
    overlap (the floor then pushes during the body's contact).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from twoball.modal.floor.measure import ContactInterval, contact_intervals
from twoball.modal.floor.system import FloorSystem
from twoball.modal.nonsmooth import Trajectory

__all__ = ["BodyEvent", "BodyResult", "measure_body"]


@dataclass(frozen=True)
class BodyEvent:
    """A touch or separation of either contact (dimensionless).

    Attributes
    ----------
    contact : {"floor", "body"}
    kind : {"touch", "separation"}
    t : float
        Time from the first floor touch.
    ball_velocity, body_velocity : float
        Z' and s' there (upward positive).
    """

    contact: str
    kind: str
    t: float
    ball_velocity: float
    body_velocity: float


@dataclass(frozen=True)
class BodyResult:
    """The body's part of a whole bounce (dimensionless; see the module documentation).

    Attributes
    ----------
    touched : bool
        The body touched the ball at all.
    left : bool
        The body has separated for good (the run ended with both apart).
    v1 : float or None
        The body's velocity at its last separation.
    v2 : float or None
        The centre's velocity at the ball's last release (floor or body).
    t_liftoff : float or None
        The body's last separation, from the first floor touch.
    t_floor_release : float or None
        The ball's last separation from the floor.
    sequence : {"independent", "overlapping"} or None
    body_left_first : bool or None
    e12_effective : float or None
    contacts : int
        Separate contacts of the body with the ball.
    impulse : float
        Total impulse of the body's contact (on the body, upward).
    intervals : tuple of ContactInterval
    events : tuple of BodyEvent
        Every touch and separation of both contacts, in time order.  A body
        started touching (``gap = 0``) that the top leaves at once, with no
        impulse, has a touch and a separation at t = 0 (not counted in
        ``contacts``): the top moves down at the first floor force (the
        radial membrane's degree-1 response, docs/whole_bounce.rst).
    before, after : tuple of float or None
        ``(u1, u2)`` before the first touch and ``(v1, v2)`` after the last
        separation (body, centre): the velocities behind ``e12_effective``.
    """

    touched: bool
    left: bool
    v1: float | None
    v2: float | None
    t_liftoff: float | None
    t_floor_release: float | None
    sequence: str | None
    body_left_first: bool | None
    e12_effective: float | None
    contacts: int
    impulse: float
    intervals: tuple[ContactInterval, ...]
    events: tuple[BodyEvent, ...]
    before: tuple[float, float] | None
    after: tuple[float, float] | None


def _free_velocity(tr: Trajectory, column: int, k: int, t: float, gamma: float) -> float:
    """Velocity at time t of a coordinate that falls freely from t to the step end ``t[k]``."""
    return float(tr.v[k, column] + gamma * (tr.t[k] - t))


def measure_body(
    system: FloorSystem,
    tr: Trajectory,
    floor: list[ContactInterval],
    left: bool,
    dt: float,
) -> BodyResult:
    """The body's measures of a finished run (``floor``: the floor's contact intervals)."""
    body = system.body
    assert body is not None
    gamma = system.gamma
    weight = gamma if body.weight else 0.0
    s, z = system.body_coordinate, system.centre
    impulses = tr.impulse[:, system.body_rows].sum(axis=1)
    intervals = contact_intervals(tr.t, impulses, dt)
    steps = tr.impulse.shape[0]

    def closed(iv: ContactInterval) -> bool:
        """A contact still carried in the window's last step has not ended."""
        return iv.last < steps - 1

    events: list[BodyEvent] = []
    if body.gap == 0.0 and not (intervals and intervals[0].first == 0):
        # started touching, the top dropped away at once with no impulse (the degree-1
        # response of the radial membrane): a touch and a separation at t = 0
        events.append(BodyEvent("body", "touch", float(tr.t[0]), *_pair(tr, z, s, 0)))
        events.append(BodyEvent("body", "separation", float(tr.t[0]), *_pair(tr, z, s, 0)))
    for iv in floor:
        events.append(BodyEvent("floor", "touch", iv.start, *_pair(tr, z, s, iv.first)))
        if closed(iv):
            events.append(BodyEvent("floor", "separation", iv.end, *_at(tr, z, s, iv.end)))
    for iv in intervals:
        events.append(BodyEvent("body", "touch", iv.start, *_pair(tr, z, s, iv.first)))
        if closed(iv):
            body_v = _free_velocity(tr, s, iv.last + 1, iv.end, weight)
            at = _at(tr, z, s, iv.end)[0]
            events.append(BodyEvent("body", "separation", iv.end, at, body_v))
    events.sort(key=lambda e: (e.t, e.contact != "floor", e.kind != "touch"))
    t_floor = floor[-1].end if floor and closed(floor[-1]) else None
    if not intervals:
        return BodyResult(
            False,
            left,
            None,
            None,
            None,
            t_floor,
            None,
            None,
            None,
            0,
            0.0,
            (),
            tuple(events),
            None,
            None,
        )
    first, last = intervals[0], intervals[-1]
    k = last.last + 1
    v1 = _free_velocity(tr, s, k, last.end, weight)
    # the ball's last release: the floor's or the body's, whichever is later
    if t_floor is not None and t_floor > last.end:
        v2 = _free_velocity(tr, z, floor[-1].last + 1, t_floor, gamma)
    else:
        v2 = _free_velocity(tr, z, k, last.end, gamma)
    sequence = "independent" if t_floor is not None and t_floor <= first.start else "overlapping"
    before = (float(tr.v[first.first, s]), float(tr.v[first.first, z]))
    after_ball = _free_velocity(tr, z, k, last.end, gamma) if sequence == "independent" else None
    after = (v1, after_ball) if after_ball is not None else None
    e12 = None
    if left and after is not None and before[0] - before[1] < 0.0:
        # eq. (2.4) with the relative velocity at the step ends around the contact:
        # both fall freely there, so gravity drops out of it
        e12 = (after[1] - after[0]) / (before[0] - before[1])
    return BodyResult(
        touched=True,
        left=left,
        v1=v1 if left else None,
        v2=v2 if left else None,
        t_liftoff=last.end if left else None,
        t_floor_release=t_floor,
        sequence=sequence,
        body_left_first=None if (not left or t_floor is None) else bool(last.end < t_floor),
        e12_effective=e12,
        contacts=len(intervals),
        impulse=float(impulses.sum()),
        intervals=tuple(intervals),
        events=tuple(events),
        before=before,
        after=after,
    )


def _pair(tr: Trajectory, z: int, s: int, k: int) -> tuple[float, float]:
    """(Z', s') at step end k (before an impact there)."""
    return float(tr.v[k, z]), float(tr.v[k, s])


def _at(tr: Trajectory, z: int, s: int, t: float) -> tuple[float, float]:
    """(Z', s') at time t, linear between the step ends (kept inside the run)."""
    t = min(max(t, tr.t[0]), tr.t[-1])
    return float(np.interp(t, tr.t, tr.v[:, z])), float(np.interp(t, tr.t, tr.v[:, s]))


def momentum_balance(system: FloorSystem, tr: Trajectory) -> float:
    """Relative error of the whole system's momentum books over the run.

    ``J_floor = (Z' + mu s')_end - (Z' + mu s')_0 + (1 + mu) gamma t_end``
    (the body's weight only if it has one); relative to ``J_floor``.
    """
    body = system.body
    mu = 0.0 if body is None else body.mass
    weight = system.gamma * (1.0 + (mu if body is not None and body.weight else 0.0))
    s, z = system.body_coordinate, system.centre
    start = tr.v[0, z] + (mu * tr.v[0, s] if body is not None else 0.0)
    end = tr.v_final[z] + (mu * tr.v_final[s] if body is not None else 0.0)
    floor = float(tr.impulse[:, system.floor].sum())
    change = end - start + weight * (tr.t[-1] - tr.t[0])
    return abs(floor - change) / max(abs(floor), math.ulp(1.0))
