"""The full modal state of the coupled problem at any times, in closed form (dimensionless).

:func:`twoball.modal.contact.trajectory.sample` gives the body and the cap
average; exports and pictures of the membrane need every modal coordinate.
Between events the state is ``z(t) = exp(A (t - t_e)) z_e`` (A the flight or the
contact matrix of :class:`~twoball.modal.contact.system.ContactSystem`, ``z_e``
the state right after the event that starts the phase), and its rate is
``A z(t)``: the membrane's acceleration ``q''`` includes the contact force
``-b Lambda / m`` of eq. (C1) while the body is on.  The membrane field is then
``u = sum_k q_k phi_k`` with the backend's mode shapes (docs/contact.rst).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from twoball.modal.contact.events import _DENSE_EXPM_MAX, ContactHistory, grid_step, make_phases
from twoball.modal.contact.system import ContactSystem
from twoball.modal.contact.trajectory import phases

#: Above this many times in one phase, evenly spaced times are reached by repeated
#: multiplication with ``exp(A dt)`` (one exponential per phase) instead of one each.
_STEP_FROM = 64


@dataclass(frozen=True)
class ModalStates:
    """The augmented state ``z = (q, q', s, s', 1)`` and its rate at T times.

    Attributes
    ----------
    times : ndarray, shape (T,)
        Dimensionless times (unit 1/c).
    state, rate : ndarray, shape (T, 2K + 3)
        ``z`` and ``dz/dt = A z`` (A of the phase the time falls in; at an event
        time, the phase the event starts).
    contact : ndarray of bool, shape (T,)
        True while the body is on the membrane.
    size : int
        Number of modes K.
    """

    times: np.ndarray
    state: np.ndarray
    rate: np.ndarray
    contact: np.ndarray
    size: int

    def modal(self, derivative: int = 0) -> np.ndarray:
        """``q``, ``q'`` or ``q''``, shape (T, K) (dimensionless)."""
        k = self.size
        if derivative == 0:
            return self.state[:, :k]
        if derivative == 1:
            return self.state[:, k : 2 * k]
        if derivative == 2:
            return self.rate[:, k : 2 * k]
        raise ValueError("derivative must be 0, 1 or 2")

    @property
    def body_height(self) -> np.ndarray:
        """The body's height ``s`` above the undeformed pole (unit R)."""
        return self.state[:, 2 * self.size]

    @property
    def body_velocity(self) -> np.ndarray:
        """The body's velocity ``s'`` (unit R c)."""
        return self.state[:, 2 * self.size + 1]

    @property
    def body_acceleration(self) -> np.ndarray:
        """The body's acceleration ``s''`` (unit R c^2): ``-gamma`` in flight."""
        return self.rate[:, 2 * self.size + 1]


def modal_states(system: ContactSystem, history: ContactHistory, times: np.ndarray) -> ModalStates:
    """``z`` and ``A z`` at ``times`` (dimensionless, within [0, ``history.t_end``]).

    Each time is evaluated from the start of its phase in closed form; many
    evenly spaced times in one phase share one matrix exponential.  Large
    systems (finite-element spheres, state size above 200) walk the phase on the
    event grid of :func:`~twoball.modal.contact.events.integrate`, each step and
    the rest of a step a local Taylor series
    (:class:`~twoball.modal.contact.events.LocalSeries`, O(n) products ``A z``)
    instead of one ``expm_multiply`` over the whole offset per time.
    """
    times = np.atleast_1d(np.asarray(times, dtype=float))
    segments = phases(system, history)
    starts = np.array([s[0] for s in segments])
    matrices = {"flight": system.flight_matrix, "contact": system.contact_matrix}
    size = 2 * system.size + 3
    state = np.empty((times.size, size))
    rate = np.empty((times.size, size))
    touching = np.zeros(times.size, dtype=bool)
    which = np.maximum(np.searchsorted(starts, times, side="right") - 1, 0)
    walkers = make_phases(system, grid_step(system))
    for j in np.unique(which):
        t0, z0, mode = segments[j]
        index = np.flatnonzero(which == j)
        offsets = times[index] - t0
        if size > _DENSE_EXPM_MAX:  # large: grid steps, then a local series
            state[index] = walkers[mode].far(z0, np.maximum(offsets, 0.0))
        else:
            state[index] = _propagate(matrices[mode], z0, offsets)
        rate[index] = state[index] @ matrices[mode].T
        touching[index] = mode == "contact"
    return ModalStates(times, state, rate, touching, system.size)


def _at(matrix: np.ndarray, z0: np.ndarray, offsets: np.ndarray) -> np.ndarray:
    """``exp(A tau) z0`` for each offset: dense ``expm`` for small systems, else
    ``expm_multiply`` (as the event search of :mod:`twoball.modal.contact.events`)."""
    if matrix.shape[0] <= _DENSE_EXPM_MAX:
        from scipy.linalg import expm

        return np.array([expm(matrix * tau) @ z0 for tau in offsets])
    from scipy.sparse.linalg import expm_multiply

    return np.array([expm_multiply(matrix * tau, z0) for tau in offsets])


def _propagate(matrix: np.ndarray, z0: np.ndarray, offsets: np.ndarray) -> np.ndarray:
    """States at ``offsets`` from ``z0``: one exponential each, or steps of one ``exp(A dt)``."""
    steps = np.diff(offsets)
    even = offsets.size > _STEP_FROM and np.allclose(steps, steps[0], rtol=1e-9, atol=0.0)
    if not even or steps[0] <= 0.0:
        return _at(matrix, z0, offsets)
    from scipy.linalg import expm

    out = np.empty((offsets.size, z0.size))
    out[0] = _at(matrix, z0, offsets[:1])[0]
    step = expm(matrix * steps[0])
    for j in range(1, offsets.size):
        out[j] = step @ out[j - 1]
    return out
