"""The finite-mass body on the paper's start, stepped by the contact core (dimensionless).

The same physics as :mod:`twoball.modal.contact.system` (eqs. (C1)-(C3) of
docs/contact.rst: the filtered start of eq. (3.10) at rest, a rigid body resting
on the cap, the membrane's modes about a centre that does not move, no floor),
run by the one nonsmooth integrator of the drop and the whole bounce
(:class:`~twoball.modal.nonsmooth.MoreauJean` through
:func:`~twoball.modal.floor.restitution.body_on_start`): the ball is a
:class:`~twoball.modal.balls.description.ModalBall` built from the backend's
:class:`~twoball.modal.series.ModalSeries` (:func:`series_ball`), the body one
more coordinate and one more row.  The event-driven matrix exponential of
:mod:`twoball.modal.contact.events` stays as the exact reference of the
verification studies.

:func:`stepped_contact` returns a :class:`SteppedMotion`: the events in the
units of :mod:`twoball.modal.contact.system` (impulse ``T R / c``, energy ``T
R^2``, so that :class:`~twoball.modal.contact.report.ContactReport` reports
them as before) and the state at any time, for the figures and fields.
Between step ends the coordinates are the cubic through the step ends' values
and rates, the rates linear, the accelerations the step's mean.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from twoball._common.errors import ParameterError
from twoball._common.monitor import Monitor
from twoball.modal.balls.description import ModalBall
from twoball.modal.balls.membrane import mode_decay
from twoball.modal.contact.events import ContactEvent, ContactHistory
from twoball.modal.contact.states import ModalStates
from twoball.modal.damping import ModalRatio
from twoball.modal.nonsmooth.moreau_jean import ZENO_VELOCITY
from twoball.modal.series import ModalSeries

__all__ = ["DEFAULT_DT", "ExactMotion", "SteppedMotion", "series_ball", "stepped_contact"]

#: Time step of the body's contact in units of 1/c (the drop's step).
DEFAULT_DT = 0.005
#: The contact core's units against the contact system's: the membrane's mass is
#: ``m2 = 4 pi rho R^2``, so impulses and energies in units of m2 are 4 pi times
#: fewer than in units of rho R^2 (:mod:`twoball.modal.contact.system`).
SPHERE = 4.0 * math.pi


def series_ball(series: ModalSeries, contact: np.ndarray) -> tuple[ModalBall, np.ndarray]:
    """The modes of a backend's series as a ball held at its centre, and its filtered start.

    Masses ``m_k = int phi_k^2 dS / (4 pi)`` in units of m2 (the series'
    ``mode_norms`` over the unit sphere's area), frequencies and damping of the
    series (the ratio D: ``2 D omega_k``, eq. (3.14)), the pole values as the top,
    ``contact`` (the modes averaged over the body's cap) as the cap; no floor.
    The start is ``sigma_k q_k(0)`` at rest (eq. (3.16)).
    """
    if not isinstance(series.damping, float):
        raise ParameterError("damping", "the modal ratio D with a body of finite mass", "law")
    contact = np.asarray(contact, dtype=float)
    w2 = series.omega**2
    k = series.omega.size
    ball = ModalBall(
        masses=series.mode_norms / SPHERE,
        omega_squared=w2,
        gas_squared=np.zeros(k),
        decay=mode_decay(ModalRatio(series.damping), w2),
        centre=None,
        phi=np.zeros(0),
        floor_rows=np.zeros((0, k)),
        top=series.pole_values,
        label="the series' modes",
        averager=lambda theta: contact,
    )
    return ball, series.weights * series.coefficients


@dataclass(frozen=True, eq=False)
class SteppedMotion:
    """A body on the start, stepped: its events and the state at any time (dimensionless).

    Attributes
    ----------
    history : ContactHistory
        The impacts and separations (units of :mod:`twoball.modal.contact.system`).
    contact : ndarray, shape (K,)
        The cap averages ``b_k`` of the modes.
    times, q, v : ndarray
        Step ends, the modal coordinates and their rates there, shape (T,) and (T, K).
    s, w : ndarray, shape (T,)
        The body's height above the undeformed pole and its velocity at the step ends.
    touching : ndarray of bool, shape (T - 1,)
        Steps in which the body's contact carries impulse.
    trajectory : Trajectory
        The contact core's record (states, impulses, energy books).
    """

    history: ContactHistory
    contact: np.ndarray
    times: np.ndarray = field(repr=False)
    q: np.ndarray = field(repr=False)
    v: np.ndarray = field(repr=False)
    s: np.ndarray = field(repr=False)
    w: np.ndarray = field(repr=False)
    touching: np.ndarray = field(repr=False)
    trajectory: Any = field(default=None, repr=False)

    @property
    def size(self) -> int:
        """Number of modes K."""
        return int(self.contact.size)

    def states(self, times: np.ndarray) -> ModalStates:
        """``z = (q, q', s, s', 1)`` and its rate at ``times`` (within the run)."""
        t = np.clip(np.atleast_1d(np.asarray(times, dtype=float)), self.times[0], self.times[-1])
        k = self.size
        step = np.clip(np.searchsorted(self.times, t, side="right") - 1, 0, self.times.size - 2)
        t0, t1 = self.times[step], self.times[step + 1]
        h = t1 - t0
        x = np.where(h > 0.0, (t - t0) / np.where(h > 0.0, h, 1.0), 0.0)
        coords = np.column_stack([self.q, self.s])
        rates = np.column_stack([self.v, self.w])
        a0, a1, r0, r1 = coords[step], coords[step + 1], rates[step], rates[step + 1]
        xx = x[:, None]
        hh = h[:, None]
        h00 = 2 * xx**3 - 3 * xx**2 + 1
        h10 = xx**3 - 2 * xx**2 + xx
        h01 = -2 * xx**3 + 3 * xx**2
        h11 = xx**3 - xx**2
        value = h00 * a0 + h10 * hh * r0 + h01 * a1 + h11 * hh * r1
        rate = (1.0 - xx) * r0 + xx * r1
        accel = (r1 - r0) / np.where(hh > 0.0, hh, 1.0)
        state = np.empty((t.size, 2 * k + 3))
        state[:, :k], state[:, k : 2 * k] = value[:, :k], rate[:, :k]
        state[:, 2 * k], state[:, 2 * k + 1], state[:, -1] = value[:, k], rate[:, k], 1.0
        out = np.zeros_like(state)
        out[:, :k], out[:, k : 2 * k] = rate[:, :k], accel[:, :k]
        out[:, 2 * k], out[:, 2 * k + 1] = rate[:, k], accel[:, k]
        return ModalStates(t, state, out, self.touching[step], k)

    def sample(self, times: np.ndarray) -> dict[str, np.ndarray]:
        """Body height and velocity, cap-averaged displacement and velocity, contact flag."""
        states = self.states(times)
        q, v = states.modal(0), states.modal(1)
        return {
            "t": states.times,
            "body_height": states.body_height,
            "body_velocity": states.body_velocity,
            "cap_displacement": q @ self.contact,
            "cap_velocity": v @ self.contact,
            "contact": states.contact,
        }


def stepped_contact(
    series: ModalSeries,
    contact: np.ndarray,
    mass_ratio: float,
    gamma: float,
    t_end: float,
    restitution: float = 0.0,
    *,
    dt: float = DEFAULT_DT,
    theta: float | None = None,
    monitor: Monitor | None = None,
) -> SteppedMotion:
    """Step a body of mass ratio mu resting on the start of ``series`` to ``t_end``.

    Parameters
    ----------
    series : ModalSeries
        The backend's modes and filtered start (the ratio D on every mode).
    contact : ndarray, shape (K,)
        The modes averaged over the body's cap.
    mass_ratio : float
        mu = m1 / m2 > 0.
    gamma : float
        ``g / (R c^2)``.
    t_end, dt : float
        Window and time step (units 1/c).
    restitution : float
        Newton's e12 at the body's impacts.
    theta : float, optional
        The cap's half-angle [rad] (for the record only).
    monitor : Monitor, optional
        Told of every step.
    """
    from twoball.modal.floor.measure import contact_intervals
    from twoball.modal.floor.restitution import body_on_start
    from twoball.modal.floor.system import BodyOnTop

    if not (math.isfinite(mass_ratio) and mass_ratio > 0.0):
        raise ParameterError("mass_ratio", "> 0 for the stepped contact", mass_ratio)
    ball, q0 = series_ball(series, contact)
    body = BodyOnTop(
        float(mass_ratio), np.asarray(contact, dtype=float), theta or 0.0, float(restitution)
    )
    zeno = ZENO_VELOCITY if restitution > 0.0 else None
    run = body_on_start(ball, q0, gamma, dt, body, t_end=t_end, monitor=monitor, zeno_velocity=zeno)
    system, tr = run.system, run.trajectory
    k, row, j = ball.modes, system.body_row, system.body_coordinate
    q, v = tr.q[:, :k], tr.v[:, :k]
    s, w = tr.q[:, j] - 1.0, tr.v[:, j]
    impulses = tr.impulse[:, row]
    intervals = contact_intervals(tr.t, impulses, dt)
    events: list[ContactEvent] = []
    steps = tr.t.size - 1
    if not intervals or intervals[0].first > 0:  # the start's cap leaves the body at once
        events.append(ContactEvent("separation", float(tr.t[0]), float(s[0]), float(w[0])))
    for iv in intervals:
        impact = float(tr.impact_impulse[iv.first, row])
        if impact > 0.0:
            loss = -(tr.impact_work[iv.first + 1] - tr.impact_work[iv.first])
            before = float(tr.v[iv.first, j] - tr.v[iv.first, :k] @ contact)
            events.append(
                ContactEvent(
                    "impact",
                    float(tr.t[iv.first]),
                    float(s[iv.first]),
                    float(w[iv.first] + impact / mass_ratio),  # the impulse on the body alone
                    impulse=SPHERE * impact,
                    approach=before,
                    energy_loss=SPHERE * float(loss),
                )
            )
        if iv.last + 1 < steps:  # the contact ended within the run: a separation
            after = iv.last + 1  # free flight under g from the separation to t[after]
            back = tr.t[after] - iv.end
            velocity = float(w[after] + gamma * back)
            height = float(s[after] - w[after] * back - 0.5 * gamma * back**2)
            events.append(ContactEvent("separation", iv.end, height, velocity))
    last = events[-1] if events else None
    in_flight = not intervals or intervals[-1].last + 1 < steps
    lifted = bool(
        last is not None and last.kind == "separation" and in_flight and last.velocity > 0.0
    )
    history = ContactHistory(
        tuple(events),
        float(tr.t[-1]),
        lifted,
        last.t if lifted else None,
        last.velocity if lifted else None,
        last.height if lifted else None,
        np.concatenate([q[-1], v[-1], [s[-1], w[-1], 1.0]]),
        float(restitution),
    )
    return SteppedMotion(
        history, np.asarray(contact, dtype=float), tr.t, q, v, s, w, impulses > 0.0, tr
    )


@dataclass(frozen=True, eq=False)
class ExactMotion:
    """The event-driven solution in closed form (the verification studies' exact reference).

    The same interface as :class:`SteppedMotion`: ``history``, ``contact``,
    :meth:`states` and :meth:`sample` (:mod:`twoball.modal.contact.states`,
    :mod:`twoball.modal.contact.trajectory`).
    """

    history: ContactHistory
    system: Any = field(repr=False)

    @property
    def contact(self) -> np.ndarray:
        """The cap averages ``b_k``."""
        return self.system.contact

    @property
    def size(self) -> int:
        """Number of modes K."""
        return int(self.system.size)

    def states(self, times: np.ndarray) -> ModalStates:
        """``z`` and ``A z`` at ``times`` (:func:`~twoball.modal.contact.states.modal_states`)."""
        from twoball.modal.contact.states import modal_states

        return modal_states(self.system, self.history, times)

    def sample(self, times: np.ndarray) -> dict[str, np.ndarray]:
        """As :meth:`SteppedMotion.sample` (:func:`~twoball.modal.contact.trajectory.sample`)."""
        from twoball.modal.contact.trajectory import sample

        return sample(self.system, self.history, times)
