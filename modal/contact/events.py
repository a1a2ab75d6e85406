"""Event-driven integration of the contact problem on the closed-form modal motion.

Between events the state follows ``z(t) = exp(A t) z(t_0)`` exactly (A the flight
or the contact matrix of :class:`~twoball.modal.contact.system.ContactSystem`).
Events are located on a grid of ``samples_per_period`` points per shortest modal
period and refined to ``TIME_TOLERANCE``:

* in contact, the force ``Lambda`` reaches zero from above: separation;
* in flight, the gap ``g`` reaches zero: an impact, resolved by Newton's law with
  restitution e (default 0, inelastic).  After an inelastic impact the body stays
  (contact phase) if the contact force is positive, else it flies on at once.

Both signals are checked at the grid points and at every local minimum between
them (zeros of their rate crossed from below), so a short excursion below zero
between two grid points is not missed.  Dimensionless throughout.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass, field
from functools import cached_property
from typing import Any

import numpy as np
from scipy.linalg import expm

from twoball._common.errors import NumericalError, ParameterError
from twoball._common.monitor import Monitor
from twoball.modal.contact.system import ContactSystem
from twoball.modal.roots import bracketed_roots

TIME_TOLERANCE = 1e-12
MAX_EVENTS = 10000
_DENSE_EXPM_MAX = 200  # state size up to which exp(A t) is formed densely for each root step
_DENSE_WALK_MAX = 600  # state size up to which the grid is walked with a dense exp(A step)
_TAYLOR_MAX_TERMS = 80  # beyond this the local Taylor series gives way to expm_multiply
_UNIT_ROUNDOFF = 2.0**-53
_ZENO_RATE = 1e-6  # |g'| (units R c) below which an impact is plastic: ends Zeno chains


@dataclass(frozen=True)
class ContactEvent:
    """One event: ``kind`` is ``impact`` or ``separation`` (dimensionless).

    ``velocity`` is the body's velocity right after the event, ``impulse`` the
    impulse of an impact (0 for a separation), ``energy_loss`` the energy lost in
    it, ``approach`` the gap rate just before an impact.
    """

    kind: str
    t: float
    height: float
    velocity: float
    impulse: float = 0.0
    approach: float = 0.0
    energy_loss: float = 0.0
    energy_before: float = 0.0
    state_before: np.ndarray | None = field(default=None, repr=False, compare=False)
    state_after: np.ndarray | None = field(default=None, repr=False, compare=False)


@dataclass(frozen=True)
class ContactHistory:
    """All events on [0, t_end] and the final separation (dimensionless).

    ``lifted`` is True if the body is in flight at ``t_end`` after a last
    separation (lift-off or rebound) with an upward velocity; then ``t`` and
    ``velocity`` are the time and that velocity, ``displacement`` its height
    there.  A body that separated moving down (v1 <= 0) is falling with the
    membrane and will land again: not lifted.
    """

    events: tuple[ContactEvent, ...]
    t_end: float
    lifted: bool
    t: float | None
    velocity: float | None
    displacement: float | None
    final_state: np.ndarray = field(repr=False, compare=False)
    restitution: float = 0.0

    @property
    def impacts(self) -> tuple[ContactEvent, ...]:
        """The impacts, in order."""
        return tuple(e for e in self.events if e.kind == "impact")

    @property
    def separations(self) -> tuple[ContactEvent, ...]:
        """Every separation (lift-off from persistent contact or rebound), in order."""
        return tuple(e for e in self.events if e.kind == "separation")


def grid_step(system: ContactSystem, samples_per_period: int = 32) -> float:
    """The event grid's step: ``samples_per_period`` points per shortest modal period."""
    return 2.0 * math.pi / (max(system.max_frequency, 1.0) * samples_per_period)


class LocalSeries:
    """``exp(A tau) z`` for every ``tau`` in [0, h] from one truncated Taylor series.

    ``c_j = (h A)^j z / j!`` is summed until two successive terms are below the
    unit round-off of the largest term (the stopping rule of Al-Mohy and Higham's
    ``expm_multiply``, Alg. 3.2, which scipy uses); ``exp(A tau) z = sum_j (tau/h)^j
    c_j`` then costs one Horner sweep per time, and a scalar ``r . z(tau)`` a
    polynomial in ``tau`` of the numbers ``r . c_j``.  On the event grid ``h`` is 1/32
    of the shortest modal period, so ``|omega h| < 0.2`` and some 10-20 terms
    suffice.  ``apply(z)`` is ``A z`` (:meth:`ContactSystem.apply`: O(n), not a
    dense product).
    """

    def __init__(self, apply: Callable[[np.ndarray], np.ndarray], z: np.ndarray, h: float) -> None:
        terms = [np.asarray(z, dtype=float)]
        scale = float(np.abs(terms[0]).max(initial=0.0))
        for j in range(1, _TAYLOR_MAX_TERMS + 1):
            terms.append(apply(terms[-1]) * (h / j))
            size = float(np.abs(terms[-1]).max(initial=0.0))
            scale = max(scale, size)
            if size + float(np.abs(terms[-2]).max(initial=0.0)) <= _UNIT_ROUNDOFF * scale:
                break
        else:  # pragma: no cover - |A h| is small on the event grid
            raise NumericalError("contact: the local Taylor series did not converge")
        self.terms = np.array(terms)
        self.h = h

    def at(self, tau: np.ndarray) -> np.ndarray:
        """States at ``tau`` (shape (T,), each in [0, h]): shape (T, n)."""
        s = np.atleast_1d(np.asarray(tau, dtype=float)) / self.h
        out = np.repeat(self.terms[-1][None, :], s.size, axis=0)
        for term in self.terms[-2::-1]:
            out *= s[:, None]
            out += term
        return out

    def scalar(self, row: np.ndarray) -> LocalScalar:
        """``row . z(tau)`` as a polynomial in ``tau``."""
        return LocalScalar(self.terms @ row, self.h)


@dataclass(frozen=True)
class LocalScalar:
    """``sum_j (tau / h)^j a_j``: a scalar observable of a :class:`LocalSeries`."""

    coefficients: np.ndarray
    h: float

    def __call__(self, tau: np.ndarray, _i: np.ndarray | None = None) -> np.ndarray:
        s = np.atleast_1d(np.asarray(tau, dtype=float)) / self.h
        out = np.full(s.shape, self.coefficients[-1])
        for a in self.coefficients[-2::-1]:
            out = out * s + a
        return out


class _Phase:
    """Closed-form propagation ``exp(A t) z`` of one phase, with its grid step.

    Small systems (state size up to :data:`_DENSE_EXPM_MAX`) form ``exp(A t)``
    densely: ``grid_map = exp(A step)`` for the grid and ``expm`` at any offset.
    Larger ones (``apply`` given) evaluate inside a step with a
    :class:`LocalSeries` of ``A z`` products, O(n) each; they walk the grid with
    the dense ``grid_map`` up to :data:`_DENSE_WALK_MAX` (one O(n^2) product a
    step beats a dozen small products there) and with the local series beyond,
    where forming ``exp(A step)`` (O(n^3)) and applying it would dominate the
    export (finite-element spheres, n ~ 1600 at level 3, P2).
    """

    def __init__(
        self,
        matrix: np.ndarray,
        step: float,
        apply: Callable[[np.ndarray], np.ndarray] | None = None,
    ) -> None:
        self.matrix = matrix
        self.step = step
        self.apply = apply if matrix.shape[0] > _DENSE_EXPM_MAX else None
        self.walks_dense = self.apply is None or matrix.shape[0] <= _DENSE_WALK_MAX

    @cached_property
    def grid_map(self) -> np.ndarray:
        """``exp(A step)`` (small systems)."""
        return expm(self.matrix * self.step)

    def local(self, z: np.ndarray) -> LocalSeries | None:
        """The local series from ``z`` over one step (None for small systems)."""
        return None if self.apply is None else LocalSeries(self.apply, z, self.step)

    def next(self, z: np.ndarray, local: LocalSeries | None = None) -> np.ndarray:
        """The state one grid step after ``z``."""
        if self.walks_dense:
            return self.grid_map @ z
        local = self.local(z) if local is None else local
        return local.at(np.array([self.step]))[0]  # type: ignore[union-attr]

    def at(self, z: np.ndarray, tau: np.ndarray, local: LocalSeries | None = None) -> np.ndarray:
        """States at offsets ``tau`` from ``z`` (each in [0, step] for large systems;
        use :meth:`far` beyond)."""
        if self.apply is None:
            return np.array([expm(self.matrix * t) @ z for t in np.atleast_1d(tau)])
        local = self.local(z) if local is None else local
        return local.at(tau)  # type: ignore[union-attr]

    def far(self, z: np.ndarray, offsets: np.ndarray) -> np.ndarray:
        """States at any ``offsets`` >= 0 from ``z``: small systems one ``expm`` each,
        large ones whole grid steps (:meth:`next`, as :func:`_advance`) and the rest
        of a step from its local series."""
        offsets = np.atleast_1d(np.asarray(offsets, dtype=float))
        if self.apply is None:
            return self.at(z, offsets)
        out = np.empty((offsets.size, z.size))
        cells = np.floor(offsets / self.step).astype(np.int64)
        state, cell = z, 0
        for i in np.argsort(offsets, kind="stable"):
            while cell < cells[i]:
                state, cell = self.next(state), cell + 1
            out[i] = self.at(state, np.array([offsets[i] - cell * self.step]))[0]
        return out


def make_phases(system: ContactSystem, step: float) -> dict[str, _Phase]:
    """The flight and the contact phase of ``system`` on the grid ``step``."""
    return {
        mode: _Phase(matrix, step, lambda z, mode=mode: system.apply(z, mode))
        for mode, matrix in (("flight", system.flight_matrix), ("contact", system.contact_matrix))
    }


def integrate(
    system: ContactSystem,
    t_end: float,
    restitution: float = 0.0,
    samples_per_period: int = 32,
    monitor: Monitor | None = None,
) -> ContactHistory:
    """Integrate the body on the membrane from rest in contact to ``t_end``.

    Parameters
    ----------
    system : ContactSystem
        Modes, contact vector, body (``body_mass > 0``).
    t_end : float
        End of the modelled window (dimensionless).
    restitution : float
        Newton's coefficient e in [0, 1] at every impact.
    samples_per_period : int
        Event-detection grid points per shortest modal period (>= 16).
    monitor : Monitor, optional
        Told at every event and every 64 grid steps of the search between them
        (:class:`~twoball._common.monitor.Monitor`; it may stop the run by raising).

    Returns
    -------
    ContactHistory
    """
    if not (0.0 <= restitution <= 1.0):
        raise ParameterError("restitution", "in [0, 1]", restitution)
    if not (system.body_mass > 0):
        raise ParameterError("mass_ratio", "> 0 for the contact solver", system.body_mass)
    if not (math.isfinite(t_end) and t_end > 0):
        raise ParameterError("t_end", "a finite time > 0", t_end)
    if samples_per_period < 16:
        raise ParameterError("samples_per_period", "an integer >= 16", samples_per_period)
    omega = max(system.max_frequency, 1.0)
    step = grid_step(system, samples_per_period)
    phases = make_phases(system, step)
    skip = 1e-3 / omega  # round-off zone right after an event
    force = system.force_row
    events: list[ContactEvent] = []
    z, t = system.start(), 0.0
    mode = "contact" if float(force @ z) > 0.0 else "flight"
    if mode == "flight":
        events.append(_separation(system, 0.0, z))
    while True:
        if monitor is not None:
            monitor(f"the contact event loop at t = {t:.4g} of {t_end:.4g} (units 1/c)")
        phase = phases[mode]
        if mode == "contact":
            signal = force
        else:
            k = system.size
            signal = np.zeros_like(force)
            signal[2 * k] = 1.0
            signal[:k] = -system.contact
        found = _next_event(phase, signal, z, t, t_end, skip, monitor)
        if found is None:
            z = _advance(phase, z, t_end - t, monitor)
            break
        tau, z_event = found
        t += tau
        if len(events) >= MAX_EVENTS:
            raise NumericalError(f"contact: more than {MAX_EVENTS} events (a Zeno sequence?)")
        if mode == "contact":
            z = z_event
            events.append(_separation(system, t, z))
            mode = "flight"
            continue
        # impact
        approach = float(system.gap_rate(z_event))
        e = restitution if abs(approach) > _ZENO_RATE else 0.0
        if e > 0.0 and _unresolved_bounce(system, signal, z_event, e, skip):
            e = 0.0  # the rebound would land again within the round-off zone: plastic
        before = float(system.energy(z_event))
        z, impulse = system.impact(z_event, e)
        z[2 * system.size] = float(system.contact @ z[: system.size])  # g = 0 exactly
        after = float(system.energy(z))
        events.append(
            ContactEvent(
                "impact",
                t,
                *_body(system, z),
                impulse,
                approach,
                before - after,
                before,
                z_event,
                z.copy(),
            )
        )
        if e > 0.0:
            events.append(_separation(system, t, z))
            mode = "flight"
        elif float(force @ z) > 0.0:
            mode = "contact"
        else:
            events.append(_separation(system, t, z))
            mode = "flight"
    final = events[-1] if events and events[-1].kind == "separation" else None
    # a body that left the membrane moving down is falling with it, not lifting off
    # (criterion (ii) of §3(a): no negative lift-off velocity); it lands again later
    lifted = mode == "flight" and final is not None and final.velocity > 0.0
    return ContactHistory(
        tuple(events),
        t_end,
        lifted,
        final.t if lifted else None,
        final.velocity if lifted else None,
        final.height if lifted else None,
        z,
        restitution,
    )


def _unresolved_bounce(
    system: ContactSystem, gap_row: np.ndarray, z: np.ndarray, e: float, skip: float
) -> bool:
    """True if a rebound with coefficient ``e`` would touch again within ``2 skip``.

    The flight time of a bounce is about ``2 g'+ / |g''|`` (g'' the relative
    acceleration in flight); shorter than the resolved time it is the tail of a Zeno
    sequence, whose limit (the body staying on) is taken at once.
    """
    bounced, _ = system.impact(z, e)
    rate = float(system.gap_rate(bounced))
    accel = float(gap_row @ system.flight_matrix @ system.flight_matrix @ bounced)
    return accel < 0.0 and 2.0 * rate / -accel < 2.0 * skip


def _body(system: ContactSystem, z: np.ndarray) -> tuple[float, float]:
    k = system.size
    return float(z[2 * k]), float(z[2 * k + 1])


def _separation(system: ContactSystem, t: float, z: np.ndarray) -> ContactEvent:
    energy = float(system.energy(z))
    return ContactEvent(
        "separation", t, *_body(system, z), energy_before=energy, state_after=z.copy()
    )


def _advance(
    phase: _Phase, z: np.ndarray, duration: float, monitor: Monitor | None = None
) -> np.ndarray:
    steps = int(duration // phase.step)
    for k in range(steps):
        if k % 64 == 0 and monitor is not None:
            monitor(f"the contact solver's last flight, step {k} of {steps}")
        z = phase.next(z)
    rest = duration - steps * phase.step
    return phase.at(z, np.array([rest]))[0] if rest > 0 else z


def _next_event(
    phase: _Phase,
    signal: np.ndarray,
    z0: np.ndarray,
    t0: float,
    t_end: float,
    skip: float,
    monitor: Monitor | None = None,
) -> tuple[float, np.ndarray] | None:
    """First time after ``skip`` at which ``signal . z`` reaches zero from above.

    Returns the offset from ``t0`` and the state there, or None before ``t_end``.
    """
    rate = signal @ phase.matrix  # d/dt (signal . z) = signal . A z
    z, tau = z0, 0.0
    duration = t_end - t0
    steps = 0
    while tau < duration:
        steps += 1
        if steps % 64 == 0 and monitor is not None:
            monitor(f"the contact event search at t = {t0 + tau:.4g} of {t_end:.4g}")
        h = min(phase.step, duration - tau)
        local = None if phase.walks_dense else phase.local(z)  # the step's and its search's
        if h == phase.step:
            z_next = phase.next(z, local)
        else:
            z_next = phase.at(z, np.array([h]), local)[0]
        lo = max(skip - tau, 0.0)  # offset inside this step where the search begins
        if lo < h:
            hit = _in_step(phase, signal, rate, z, h, lo, z_next, local)
            if hit is not None:
                return tau + hit, phase.at(z, np.array([hit]), local)[0]
        z, tau = z_next, tau + h
    return None


def _in_step(
    phase: _Phase,
    signal: np.ndarray,
    rate: np.ndarray,
    z: np.ndarray,
    h: float,
    lo: float,
    z_next: np.ndarray,
    local: LocalSeries | None = None,
) -> float | None:
    """First zero of ``signal . z(tau)`` crossed downwards in ``[lo, h]``, if any.

    With a :class:`LocalSeries` of the step (systems above
    :data:`_DENSE_EXPM_MAX`, built here when first needed) the signal and its
    rate are polynomials in ``tau``; otherwise each value is a dense ``expm``.
    """
    found: dict[str, Any] = {}

    def series() -> LocalSeries | None:
        if "series" not in found:
            found["series"] = local if local is not None else phase.local(z)
        return found["series"]

    def observable(row: np.ndarray, name: str) -> Callable[..., np.ndarray]:
        def evaluate(tau: np.ndarray, _i: np.ndarray | None = None) -> np.ndarray:
            near = series()
            if near is None:
                return phase.at(z, tau) @ row
            if name not in found:
                found[name] = near.scalar(row)
            return found[name](tau)

        return evaluate

    value, slope = observable(signal, "value"), observable(rate, "slope")

    if lo > 0.0:
        z_lo = phase.at(z, np.array([lo]), series())[0]
        start, s0 = float(signal @ z_lo), float(rate @ z_lo)
    else:
        start, s0 = float(signal @ z), float(rate @ z)
    end, s1 = float(signal @ z_next), float(rate @ z_next)
    if start > 0.0 and end <= 0.0:
        return float(_root(value, lo, h))
    if start <= 0.0 and end <= 0.0:
        return lo  # already below zero and staying there: touching at once
    # start <= 0 alone is round-off right after an event (the signal leaves zero
    # like (t - t_event)^2 or ^3); then only a later minimum below zero counts.
    # both ends positive: look for a local minimum below zero in between
    if not (s0 < 0.0 and s1 > 0.0):
        return None
    t_min = float(_root(slope, lo, h))
    if float(value(np.array([t_min]))[0]) > 0.0:
        return None
    if start <= 0.0:
        return lo  # it never opened beyond round-off: touching again at once
    return float(_root(value, lo, t_min))


def _root(f, a: float, b: float) -> float:
    return float(bracketed_roots(f, np.array([a]), np.array([b]), xtol=TIME_TOLERANCE)[0])
