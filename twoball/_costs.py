"""Refusals before work: each verb's cost estimate against the budget in force (the edge).

The cost models sit beside what they estimate and only estimate
(:mod:`twoball.modal.cost`, :mod:`twoball.fem_membrane.cost`,
:mod:`twoball.modal.floor.cost`); whether the work fits is decided here, by
the verbs, before anything is allocated (:func:`twoball._common.budget.check`:
a :class:`~twoball._common.budget.BudgetError` names the work as it was asked
for, ``modes 100000 t_end 1e+06``).  The deadline while the work runs is the
monitor's (:class:`twoball._common.watch.Watch`).
"""

from __future__ import annotations

import math
from typing import Any

from twoball._common.budget import check
from twoball._common.estimate import Estimate, options

__all__ = ["check_fem", "check_series", "check_stepped_contact"]


def check_series(
    modes: int,
    t_end: float,
    t_end_s: float | None = None,
    damping: float = 0.13,
    stiffness: Any = None,
) -> Estimate:
    """Refuse a closed-form lift-off (N modes, window ``t_end`` in units of 1/c) that cannot fit.

    The truncation guard's converged reference over the same window is included;
    ``stiffness`` (bending, gas) as in :func:`twoball.modal.cost.reference_estimate`.
    """
    from twoball.modal.cost import legendre_top, reference_estimate, series_estimate

    top = legendre_top(modes, stiffness)
    estimate = series_estimate(modes, t_end, omega_max=top) + reference_estimate(
        t_end, modes, damping, stiffness
    )
    return check(options(modes=int(modes), t_end=t_end_s), estimate)


def check_fem(
    mesh: str,
    level: int | None,
    elements: int | None,
    order: int,
    modes: int,
    route: str,
    *,
    scheme: str = "modal",
    dt: float | None = None,
    t_end: float = 4.0 * math.pi,
    step_accuracy: float = 0.2,
    time_unit_s: float | None = None,
) -> Estimate:
    """Refuse finite elements (mesh, route, time scheme) that cannot fit the budget.

    ``dt`` and ``t_end`` are dimensionless; ``time_unit_s`` (1/c in seconds) only
    turns dt back into seconds, as the user gave it, for the message.
    """
    from twoball.fem_membrane.cost import alpha_estimate, fem_dofs, fem_estimate
    from twoball.modal.cost import legendre_omega

    dofs = fem_dofs(mesh, level, elements, order)
    dimension = 1 if mesh == "axisym" else 2
    if route == "auto":
        route = "krylov" if dofs >= 2000 else "full"
    if scheme == "alpha":
        route = "full"
    size = options(level=level, elements=elements, order=order) or "the finite-element mesh"
    fe_order = order if order is not None else getattr(mesh, "order", 2)
    estimate = check(size, fem_estimate(dofs, modes, route, dimension, fe_order))
    if scheme != "alpha":
        return estimate
    omega_cut = 0.5 * (legendre_omega(modes) + legendre_omega(modes + 1))
    step = dt if dt is not None else step_accuracy / omega_cut
    pairs = (modes + 1) ** 2 if dimension == 2 else modes + 1
    if dt is None:
        option = "scheme alpha"
    elif time_unit_s is None:
        option = f"dt (dt c = {dt:.3g})"
    else:
        option = options(dt=dt * time_unit_s)
    return check(option, estimate + alpha_estimate(dofs, pairs, t_end, step))


def check_stepped_contact(
    coordinates: int, window: float, dt: float | None, *, modes: int | None = None
) -> Estimate:
    """Refuse a body's stepped contact (``coordinates`` modes, window and step in 1/c).

    The steps of the contact core over the whole window, each with the body's
    one row (:func:`twoball.modal.floor.cost.drop_estimate` with one point).
    """
    from twoball.modal.contact.stepped import DEFAULT_DT
    from twoball.modal.floor.cost import drop_estimate

    step = DEFAULT_DT if dt is None else dt
    steps = window / step + 10.0
    return check(options(modes=modes), drop_estimate(coordinates + 1, 1, steps))
