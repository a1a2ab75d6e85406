"""What a drop is measured by, between the steps and between the floor points.

Dimensionless.  Each measure is defined so that it converges with the time step
and the resolution instead of sticking to a step end or a floor point:

Contact intervals
    A run of steps in which the floor carries an impulse.  It starts at a touch,
    which the integrator localises exactly (the step ends when a gap reaches
    zero).  It ends when the floor force vanishes: near the end the force falls
    linearly, so the impulse still to come, ``R(t) = J_end - J(t)``, is
    ``~ (t_e - t)^2`` and ``sqrt(R)`` is linear.  :func:`separation_time`
    extrapolates ``sqrt(R)`` from the last two step ends at which it is positive
    (the cumulative impulse, exact at step ends, is insensitive to the short
    steps of localised touches); a last contact that is an impact alone ends at
    that impact.
Contact edge
    The membrane leaves the floor tangentially, so the gap outside the contact
    grows as ``(phi_e - phi)^2`` (as its cube with bending): :func:`contact_edge`
    fits ``sqrt(gap)`` (the cube root) of free points near the contact by a
    straight line and takes its zero; :func:`edge_law` says which points.
Peaks
    :func:`hermite_peak` refines the largest sample of a motion with the cubic
    through the values and rates of the two neighbouring steps.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

__all__ = [
    "ContactInterval",
    "EDGE_POINTS",
    "contact_edge",
    "contact_intervals",
    "edge_law",
    "hermite_peak",
    "separation_time",
    "smoothed_minimum",
]

#: Free floor points whose sqrt(gap) locate the edge (beyond the one next to the contact).
EDGE_POINTS = 3


@dataclass(frozen=True)
class ContactInterval:
    """One stretch of contact with the floor (dimensionless).

    Attributes
    ----------
    start, end : float
        Touch time and separation time (:func:`separation_time`).
    first, last : int
        First and last step (index into the steps) that carry floor impulse.
    impulse : float
        Floor impulse delivered in the interval.
    """

    start: float
    end: float
    first: int
    last: int
    impulse: float


def separation_time(t: np.ndarray, cumulative: np.ndarray, last: int, dt: float) -> float:
    """When the floor force of a contact that ends in step ``last`` vanishes.

    Parameters
    ----------
    t : ndarray, shape (K + 1,)
        Step end times.
    cumulative : ndarray, shape (K + 1,)
        Floor impulse delivered up to each step end (0 at t[0]).
    last : int
        The last step with floor impulse (from ``t[last]`` to ``t[last + 1]``).
    dt : float
        The regular step (a pair of step ends closer than dt/2 is not used to
        take a slope).

    Returns
    -------
    float
        ``t_e``: the zero of the straight line through ``sqrt(J_end - J)`` at the
        last two usable step ends, kept in ``[t[last], t[last + 1] + h]`` (h the
        last step's length: the scheme's last step ends the force at its end,
        while the force it samples runs on to zero within about a step).
    """
    total = cumulative[last + 1]
    b = last
    remaining_b = total - cumulative[b]
    if remaining_b <= 0.0:
        return float(t[last])  # an impact at t[last] and nothing after it
    a = b - 1
    while a >= 0 and t[b] - t[a] < 0.5 * dt:
        a -= 1
    if a < 0:
        return float(t[last + 1])
    ra, rb = math.sqrt(max(total - cumulative[a], 0.0)), math.sqrt(remaining_b)
    if ra <= rb:
        return float(t[last + 1])
    estimate = t[b] + rb * (t[b] - t[a]) / (ra - rb)
    late = t[last + 1] + (t[last + 1] - t[last])
    return float(min(max(estimate, t[last]), late))


def contact_intervals(t: np.ndarray, impulses: np.ndarray, dt: float) -> list[ContactInterval]:
    """The stretches of contact of a run: maximal runs of steps with floor impulse.

    ``impulses[k]`` is the total floor impulse of step k (impacts at ``t[k]``
    plus the step's own).
    """
    carried = impulses > 0.0
    cumulative = np.concatenate([[0.0], np.cumsum(impulses)])
    out: list[ContactInterval] = []
    k, count = 0, impulses.size
    while k < count:
        if not carried[k]:
            k += 1
            continue
        first = k
        while k + 1 < count and carried[k + 1]:
            k += 1
        end = separation_time(t, cumulative, k, dt)
        delivered = float(cumulative[k + 1] - cumulative[first])
        out.append(ContactInterval(float(t[first]), end, first, k, delivered))
        k += 1
    return out


def contact_edge(
    phi: np.ndarray, gap: np.ndarray, tolerance: float, skip: int = 1, power: float = 2.0
) -> float:
    """Polar angle of the contact edge [rad] between the floor points (pi if none touches).

    ``phi`` ascends to pi.  The outermost point with ``gap <= tolerance`` is i.
    Outside the contact the gap grows like ``(phi_e - phi)^power``, so
    ``gap^(1/power)`` of the :data:`EDGE_POINTS` free points beyond the first
    ``skip`` ones, i - 1 - skip ... i - skip - EDGE_POINTS (or as many as there
    are, at least two), is fitted by a straight line in phi and its zero is the
    edge, kept between point ``i - 1`` and point ``i + 1``.

    ``power = 2`` for a membrane, which leaves the floor tangentially; ``power =
    3`` with bending, which keeps the curvature continuous at the edge too (the
    gap then grows like the cube of the distance, as a plate's off a rigid
    foundation).  ``skip = 1`` for a membrane's contact, tens of points wide:
    the free point next to the contact lies within one spacing of a point held
    on the floor, and the discrete membrane hugs the floor over that cell (its
    gap falls below the continuum's tangential parabola by a factor that depends
    on where the edge falls between the points), so its gap carries the points'
    phase, not the edge.  ``skip = 0`` for a contact of a few points (at rest:
    the points further out lie where the profile is no longer the parabola) and
    with bending (which does not let the membrane hug the floor over one cell).
    """
    touching = np.flatnonzero(gap <= tolerance)
    if touching.size == 0:
        return math.pi
    i = int(touching[0])
    high = i - skip
    low = max(high - EDGE_POINTS, 0)
    if high - low < 2:
        return float(phi[i])
    angles = phi[low:high]
    roots = np.maximum(gap[low:high], 0.0) ** (1.0 / power)
    # the least-squares line in closed form (centred sums): its slope and its zero
    da = angles - angles.mean()
    slope = float(da @ (roots - roots.mean())) / float(da @ da)
    if slope >= 0.0:
        return float(phi[i])
    zero = float(angles.mean()) - float(roots.mean()) / slope
    upper = phi[i + 1] if i + 1 < phi.size else phi[i]
    return float(min(max(zero, phi[i - 1]), upper))


def edge_law(bending: bool) -> dict[str, float]:
    """The keywords of :func:`contact_edge` for a drop's contact: ``skip`` and ``power``.

    A membrane: the free points beyond the first one, the gap's square root
    (tangential departure); with bending: from the first free point on, the
    gap's cube root.  Measured on the basketball (no bending) and the tennis
    ball (bending) at N = 96 to 768 (docs/bounce.rst).
    """
    return {"skip": 0, "power": 3.0} if bending else {"skip": 1, "power": 2.0}


def smoothed_minimum(t: np.ndarray, values: np.ndarray, window: float) -> tuple[float, float]:
    """Smallest value of a sampled curve averaged over a moving time window, and its time.

    The average over ``[s - window/2, s + window/2]`` (trapezoid rule on the
    samples, evaluated at every sample time s) smooths the jumps of a measure
    that depends on which discrete points touch; ``window = 0`` returns the
    plain minimum.
    """
    if t.size == 0:
        return math.nan, math.nan
    if window <= 0.0 or t.size < 3:
        k = int(np.argmin(values))
        return float(values[k]), float(t[k])
    area = np.concatenate([[0.0], np.cumsum(0.5 * (values[1:] + values[:-1]) * np.diff(t))])
    lo = np.clip(t - 0.5 * window, t[0], t[-1])
    hi = np.clip(t + 0.5 * window, t[0], t[-1])
    span = hi - lo
    ok = span > 0.5 * window
    if not ok.any():
        k = int(np.argmin(values))
        return float(values[k]), float(t[k])
    mean = (np.interp(hi, t, area) - np.interp(lo, t, area))[ok] / span[ok]
    k = int(np.argmin(mean))
    return float(mean[k]), float(t[ok][k])


def hermite_peak(t: np.ndarray, x: np.ndarray, rate: np.ndarray) -> tuple[float, float]:
    """Largest value of a sampled motion and its time, refined by cubic Hermite interpolation.

    On each interval next to the largest sample where the rate changes sign,
    the cubic through the end values and rates (fourth order) is maximised.
    """
    k = int(np.argmax(x))
    best, when = float(x[k]), float(t[k])
    for a in (k - 1, k):
        if a < 0 or a + 1 >= t.size or rate[a] * rate[a + 1] > 0:
            continue
        h = t[a + 1] - t[a]
        s = np.linspace(0.0, 1.0, 401)
        h00, h10 = (1 + 2 * s) * (1 - s) ** 2, s * (1 - s) ** 2
        h01, h11 = s * s * (3 - 2 * s), s * s * (s - 1)
        values = h00 * x[a] + h10 * h * rate[a] + h01 * x[a + 1] + h11 * h * rate[a + 1]
        j = int(np.argmax(values))
        if values[j] > best:
            best, when = float(values[j]), float(t[a] + s[j] * h)
    return best, when
