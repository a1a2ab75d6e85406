"""The refusals before work: the cost models' estimates against the budget in force.

The cost models sit with the numerics they estimate and only estimate
(:mod:`twoball.modal.cost`, :mod:`twoball.modal.contact.cost`,
:mod:`twoball.fem_membrane.cost`): each names a piece of work by the options
that set its size and gives its :class:`~twoball._common.estimate.Estimate`.
Whether it fits is the edge's decision: the verbs call these functions before
they hand the work to the numerics, which refuse nothing themselves, and
:func:`twoball._common.budget.check` raises
:class:`~twoball._common.budget.BudgetError` (exit status 2) above the limits::

    modes 100000 needs ~15 GiB of memory; limit 11.7 GiB (raise the memory limit, max_memory)

The verification layer, which cannot import the face, checks the same
descriptions with :func:`twoball._common.budget.check_all`.
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING, Any

from twoball._common.budget import check, check_all
from twoball._common.estimate import Estimate

if TYPE_CHECKING:
    from twoball.modal.parameters import Case
    from twoball.modal.stiffness import Stiffness

__all__ = [
    "check_bounce_cost",
    "check_contact",
    "check_fem",
    "check_fem_contact",
    "check_legendre_contact",
    "check_legendre_liftoff",
    "check_series",
    "check_stepped_contact",
]


def check_series(
    modes: int,
    t_end: float,
    t_end_s: float | None = None,
    damping: float = 0.13,
    stiffness: Stiffness | None = None,
) -> Estimate:
    """Refuse a closed-form lift-off (N modes, window ``t_end`` dimensionless) that cannot fit.

    The truncation guard's converged reference over the same window is included;
    ``stiffness`` as in :func:`twoball.modal.cost.reference_estimate`
    (:func:`twoball.modal.cost.liftoff_work`).
    """
    from twoball.modal.cost import liftoff_work

    return check(*liftoff_work(modes, t_end, t_end_s, damping, stiffness))


def check_legendre_liftoff(case: Case, t_end_s: float | None = None) -> Estimate:
    """:func:`check_series` of :func:`twoball.modal.report.legendre_liftoff` on ``case``.

    ``t_end_s`` the window [s] (None: 4 pi / c), refused first if out of range.
    """
    from twoball.modal.cost import case_liftoff_work

    return check(*case_liftoff_work(case, t_end_s))


def check_contact(
    modes_kept: int,
    omega_max: float,
    t_end: float,
    *,
    modes: int | None = None,
    mass_ratio: float | None = None,
    samples_per_period: int = 32,
) -> Estimate:
    """Refuse a contact run that cannot fit, naming the options that set its size.

    ``modes`` (the case's N) and ``mass_ratio`` only name the work in the message
    (:func:`twoball.modal.contact.cost.contact_work`).
    """
    from twoball.modal.contact.cost import contact_work

    return check(
        *contact_work(
            modes_kept,
            omega_max,
            t_end,
            modes=modes,
            mass_ratio=mass_ratio,
            samples_per_period=samples_per_period,
        )
    )


def check_legendre_contact(
    case: Case,
    body: Any,
    t_end_s: float | None = None,
    *,
    samples_per_period: int = 32,
    reference: bool = True,
) -> Estimate | None:
    """Refuse :func:`twoball.modal.contact.report.legendre_contact` if a solve cannot fit.

    The contact solution and, with ``reference``, its closed-form reference
    (:func:`twoball.modal.contact.cost.legendre_contact_work`).
    """
    from twoball.modal.contact.cost import legendre_contact_work

    work = legendre_contact_work(
        case, body, t_end_s, samples_per_period=samples_per_period, reference=reference
    )
    return check_all(work)


def check_fem(
    mesh: Any,
    level: int | None,
    elements: int | None,
    order: int | None,
    modes: int,
    route: str,
    *,
    scheme: str = "modal",
    dt: float | None = None,
    t_end: float = 4.0 * math.pi,
    step_accuracy: float = 0.2,
    time_unit_s: float | None = None,
) -> Estimate:
    """Refuse a finite-element run (mesh, eigen solve, and stepping for ``alpha``) that cannot fit.

    ``dt`` and ``t_end`` are dimensionless; ``time_unit_s`` (1/c in seconds) only
    turns dt back into seconds, as the user gave it, for the message
    (:func:`twoball.fem_membrane.cost.fem_work`).
    """
    from twoball.fem_membrane.cost import fem_work

    work = fem_work(
        mesh,
        level,
        elements,
        order,
        modes,
        route,
        scheme=scheme,
        dt=dt,
        t_end=t_end,
        step_accuracy=step_accuracy,
        time_unit_s=time_unit_s,
    )
    estimate = check_all(work)
    assert estimate is not None
    return estimate


def check_fem_contact(
    case: Case, body: Any, mesh: Any = None, t_end_s: float | None = None
) -> Estimate | None:
    """Refuse :func:`twoball.fem_membrane.contact.fem_contact_solution` if a stage cannot fit.

    The mesh and eigen solve, the contact solver on the modes below the cutoff,
    and the closed-form reference (:func:`twoball.fem_membrane.cost.fem_contact_work`).
    """
    from twoball.fem_membrane.cost import fem_contact_work

    return check_all(fem_contact_work(case, body, mesh, t_end_s))


def check_stepped_contact(
    coordinates: int, window: float, dt: float | None, *, modes: int | None = None
) -> Estimate:
    """Refuse a body's stepped contact (``coordinates`` modes, window and step in 1/c).

    The steps of the contact core over the whole window, each with the body's
    one row (:func:`twoball.modal.floor.cost.drop_estimate` with one point).
    """
    from twoball._common.estimate import options
    from twoball.modal.contact.stepped import DEFAULT_DT
    from twoball.modal.floor.cost import drop_estimate

    step = DEFAULT_DT if dt is None else dt
    steps = window / step + 10.0
    return check(options(modes=modes), drop_estimate(coordinates + 1, 1, steps))


def check_bounce_cost(problem: Any) -> None:
    """Refuse, before any work, a drop that cannot fit the budget (memory and time).

    The likely cost of :func:`~twoball.modal.floor.cost.likely_drop` from the
    problem's size; the run's monitor stops it at the deadline beyond that.  A
    ball that cannot say its size before it is built is not refused here.
    """
    from twoball._common.budget import check
    from twoball._common.estimate import options
    from twoball.modal.floor.cost import expected_span, likely_drop

    work = problem.work()
    if work["size"] is None:
        return
    dofs, points = work["size"]
    case = problem.case
    ball = problem.ball
    asked: dict[str, Any] = {}
    if getattr(ball, "modes", None) is not None:
        asked["modes"] = ball.modes
    mesh = getattr(ball, "mesh", None)
    if mesh is not None and getattr(mesh, "elements", None) is not None:
        asked["elements"] = mesh.elements
    asked |= {"dt": work["dt"] / case.wave_speed, "t_end": work["t_end"] / case.wave_speed}
    estimate = likely_drop(
        dofs,
        points,
        work["t_end"],
        work["dt"],
        work["dense"],
        span=expected_span(work["body"], work["gap"], work["v0"]),
        v0=work["v0"],
        runs=work["runs"],
    )
    check(options(**asked), estimate)
