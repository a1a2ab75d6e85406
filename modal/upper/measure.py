"""What an elastic body's part of the whole bounce is measured by (dimensionless: R, 1/c, m2).

Beside the body's contacts, lift-off, v1 and ``e12_effective`` of
:mod:`twoball.modal.floor.body` (the same code for every kind), an elastic body
reports:

Contact
    ``contact_time``: its first touch to its last separation (the intervals of
    :func:`~twoball.modal.floor.measure.contact_intervals` on the body's rows),
    ``first_contact``: the first interval's length, ``main_contact``: the length
    of the interval with the largest impulse; ``peak_force``: the largest
    step-mean force of its rows (impacts excluded: a ball body's rows strike
    with Newton's e = 0, reported as ``impacts``, the impulse they took).
Contact disc
    ``disc_max``: the lumped body's largest disc radius ``sqrt(f R* delta)``
    while it carries force; the ball body's largest horizontal radius of a row
    that carried impulse (to the spacing of its points).
Energy books
    ``internal``: the body's own energy at the end (the lumped body's stored
    ``Phi``, the ball body's vibration); ``dissipated``: its own dissipation
    (the lumped body's dashpot, the ball body's modal damping, from the states:
    ``h v_mid^T C v_mid`` per step, the scheme's own booking at theta = 1/2).
    The drop's ``contact`` (held arrivals) and ``damped`` then leave the body's
    share out, so that ``initial = final parts + gravity gained + internal +
    dissipated (ball and body) + impacts + held`` closes to rounding.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np

__all__ = ["ElasticResult", "ball_measures", "lumped_measures"]


@dataclass(frozen=True)
class ElasticResult:
    """An elastic body's own measures (dimensionless; see the module documentation).

    Attributes
    ----------
    kind : {"lumped", "ball"}
    contact_time, first_contact : float or None
    main_contact : float or None
        The contact interval that carried the largest impulse (the collision).
    peak_force : float
        Units ``m2 R c^2``.
    impacts : float
        Impulse of Newton's impacts at the body's rows (0 for a lumped body).
    disc_max : float
        Units R.
    peak_compression : float or None
        The lumped body's largest compression (units R).
    internal, dissipated : float
        Units ``m2 (R c)^2``.
    drift : float
        The lumped body's gap zero moved by its disc's changes (units R).
    """

    kind: str
    contact_time: float | None
    first_contact: float | None
    main_contact: float | None
    peak_force: float
    impacts: float
    disc_max: float
    peak_compression: float | None
    internal: float
    dissipated: float
    drift: float = 0.0


def _times(result: Any) -> tuple[float | None, float | None, float | None]:
    """First touch to last separation, the first interval, the interval of the largest impulse."""
    body = result.body
    if body is None or not body.intervals:
        return None, None, None
    first, last = body.intervals[0], body.intervals[-1]
    main = max(body.intervals, key=lambda iv: iv.impulse)
    return last.end - first.start, first.end - first.start, main.end - main.start


def lumped_measures(system: Any, stepper: Any, result: Any) -> tuple[ElasticResult, dict]:
    """A lumped body's measures and books from the compliant stepper's records."""
    books = stepper.final_books()
    force = books["force"][:, 0]
    radius = books["radius"][:, 0]
    carrying = force > 0.0
    disc = float(np.nanmax(radius[carrying])) if carrying.any() else 0.0
    internal = float(books["stored"][-1])
    dissipated = float(books["dissipated"][-1])
    work = float(books["work"][-1])
    span, first, main = _times(result)
    elastic = ElasticResult(
        kind="lumped",
        contact_time=span,
        first_contact=first,
        main_contact=main,
        peak_force=float(force.max(initial=0.0)),
        impacts=0.0,
        disc_max=disc if math.isfinite(disc) else 0.0,
        peak_compression=float(books["compression"][:, 0].max()),
        internal=internal,
        dissipated=dissipated,
        drift=float(books["drift"][0]),
    )
    energy = {
        "body_internal": internal,
        "body_dissipated": dissipated,
        "body_work": work,
        "contact": float(result.energy["contact"]) - work,
    }
    return elastic, energy


def ball_measures(system: Any, stepper: Any, result: Any) -> tuple[ElasticResult, dict]:
    """A ball body's measures and books from the run's states and impulses."""
    tr = result.trajectory
    rows = system.body_rows
    h = np.diff(tr.t)
    step = tr.impulse[:, rows] - tr.impact_impulse[:, rows]
    force = step.sum(axis=1) / h
    touched = np.any(tr.impulse[:, rows] > 0.0, axis=0)
    radii = system.top_ball.radii
    d = system.body_deformation()
    c = system.problem.damping.diagonal[d]
    mid = 0.5 * (tr.v[1:, d] + tr.v[:-1, d])
    dissipated = float(np.sum(h * ((mid * mid) @ c)))
    internal = float(result.energy["body_vibration"])
    span, first, main = _times(result)
    elastic = ElasticResult(
        kind="ball",
        contact_time=span,
        first_contact=first,
        main_contact=main,
        peak_force=float(force.max(initial=0.0)),
        impacts=float(tr.impact_impulse[:, rows].sum()),
        disc_max=float(radii[touched].max()) if touched.any() else 0.0,
        peak_compression=None,
        internal=internal,
        dissipated=dissipated,
    )
    energy = {
        "body_internal": internal,
        "body_dissipated": dissipated,
        "damped": float(result.energy["damped"]) + dissipated,
    }
    return elastic, energy
