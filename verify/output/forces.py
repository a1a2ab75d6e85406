"""The drop's contact forces as impulse per window: what figures, files and pictures show.

The integrator (Moreau-Jean, :mod:`twoball.modal.nonsmooth.moreau_jean`) gives
each step's contact impulse, the impact part acting at the step's start and the
rest over the step.  A step cut short at a touch (localised) holds only an
impact or nothing, so the impulse of each step over its length
(:attr:`~twoball.modal.floor.drop.DropResult.force`) drops to 0 N at every
such step although the contact carries its load throughout.  Shown here
instead: the impulse over fixed windows of :data:`FORCE_WINDOW_S` (at least two
steps) divided by their length, the impacts included, so that the areas under
the curve are the run's impulse.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

#: Length of the windows over which the contact forces are averaged [s] (at least two
#: time steps): the localised steps of the touches are too short to show a force alone.
FORCE_WINDOW_S = 1e-4


def mean_force(
    t: np.ndarray, impulse: np.ndarray, impact: np.ndarray, window: float
) -> tuple[np.ndarray, np.ndarray]:
    """Centres and mean forces of consecutive windows of length ``window``: impulse / length.

    ``t`` are the step ends (K + 1), ``impulse`` the total impulse of each step
    (K) and ``impact`` its impact part, which acts at the step's start ``t[k]``;
    the rest of a step's impulse is spread evenly over the step (Moreau-Jean:
    the step impulse over ``(t[k], t[k+1]]``).  Every impulse falls in exactly
    one window (the last may be shorter), so the areas under the curve add up to
    the total impulse.  A step localised at a touch, whose own impulse is all
    impact or nothing, no longer shows a force of zero: it shares its window
    with the full steps around it.
    """
    t = np.asarray(t, dtype=float)
    spread = np.concatenate([[0.0], np.cumsum(impulse - impact)])  # at each t[k]
    count = max(1, int(math.floor((t[-1] - t[0]) / window * (1.0 + 1e-12))))
    edges = t[0] + window * np.arange(count + 1)
    if t[-1] - edges[-1] > 1e-9 * window:
        edges = np.append(edges, t[-1])
    edges[-1] = min(edges[-1], t[-1])
    struck = np.concatenate([[0.0], np.cumsum(impact)])
    before = np.searchsorted(t[:-1], edges, side="left")  # impacts strictly before an edge
    before[-1] = impact.size  # the last edge closes every window
    total = np.interp(edges, t, spread) + struck[before]
    return 0.5 * (edges[1:] + edges[:-1]), np.diff(total) / np.diff(edges)


def contact_forces(r: Any, case: Any) -> tuple[float, dict[str, tuple[Any, Any]]]:
    """The window [s] and the mean forces (:func:`mean_force`, dimensionless) of the floor
    and, with a body, of the ball on the body: ``{"floor": (t, F), "body": (t, F)}``."""
    tr = r.trajectory
    window = max(FORCE_WINDOW_S * case.wave_speed, 2.0 * r.settings.dt)
    forces = {}
    rows = {"floor": r.system.floor}
    if r.system.body is not None:
        rows["body"] = r.system.body_rows
    for name, index in rows.items():
        impulse = tr.impulse[:, index].sum(axis=1)
        impact = tr.impact_impulse[:, index].sum(axis=1)
        forces[name] = mean_force(tr.t, impulse, impact, window)
    return window / case.wave_speed, forces
