"""The body's path and the cap's motion between the events, in closed form (dimensionless).

Rebuilds the phases from a :class:`~twoball.modal.contact.events.ContactHistory`
(each event's state after it, and whether the body stays on) and evaluates
``exp(A (t - t_event)) z`` at any times: for plots and exported data.
"""

from __future__ import annotations

import numpy as np

from twoball.modal.contact.events import ContactHistory, grid_step, make_phases
from twoball.modal.contact.system import ContactSystem


def phases(system: ContactSystem, history: ContactHistory) -> list[tuple[float, np.ndarray, str]]:
    """(start time, start state, ``contact`` or ``flight``) of every phase, in order."""
    out: list[tuple[float, np.ndarray, str]] = [(0.0, system.start(), "contact")]
    events = history.events
    for j, event in enumerate(events):
        nxt = events[j + 1] if j + 1 < len(events) else None
        if event.kind == "separation":
            mode = "flight"
        elif nxt is not None and nxt.kind == "separation" and nxt.t == event.t:
            continue  # an impact the body leaves at once: the separation starts the phase
        else:
            mode = "contact"
        if event.t == out[-1][0]:
            out[-1] = (event.t, event.state_after, mode)
        else:
            out.append((event.t, event.state_after, mode))
    return out


def sample(
    system: ContactSystem, history: ContactHistory, times: np.ndarray
) -> dict[str, np.ndarray]:
    """Body height, velocity, cap-averaged displacement, velocity, contact flag at ``times``."""
    times = np.asarray(times, dtype=float)
    segments = phases(system, history)
    starts = np.array([s[0] for s in segments])
    mats = make_phases(system, grid_step(system))
    k = system.size
    states = np.empty((times.size, 2 * k + 3))
    touching = np.zeros(times.size, dtype=bool)
    which = np.maximum(np.searchsorted(starts, times, side="right") - 1, 0)
    for j in np.unique(which):  # one walk per phase (large systems), expm per time (small)
        t0, z0, mode = segments[j]
        index = np.flatnonzero(which == j)
        states[index] = mats[mode].far(z0, times[index] - t0)
        touching[index] = mode == "contact"
    cap, cap_rate = system.cap_motion(states)
    return {
        "t": times,
        "body_height": states[:, 2 * k],
        "body_velocity": states[:, 2 * k + 1],
        "cap_displacement": cap,
        "cap_velocity": cap_rate,
        "contact": touching,
    }
