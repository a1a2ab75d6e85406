"""Cost model of sweeps and worker pools: many closed-form solves on one or more processes."""

from __future__ import annotations

import os

from twoball._common.budget import BASE_MEMORY, Estimate, KiB, MiB, check
from twoball._common.errors import ParameterError
from twoball.modal.cost import reference_estimate, series_estimate

__all__ = ["check_count", "check_sweep", "check_worker_budget", "sweep_estimate"]

MAX_WORKERS_PER_CORE = 4
WORKER_MEMORY = 150 * MiB  # one pool worker (a forked interpreter with the solver loaded)
POINT_OVERHEAD_SECONDS = 3e-3  # one sweep point besides its series (case, report, reference)
POINT_BYTES = 8 * KiB  # one kept sweep point (case, report, candidates)


def sweep_estimate(points: int, per_point: Estimate, workers: int = 1) -> Estimate:
    """``points`` solves of ``per_point`` each, on ``workers`` processes (limited by the cores)."""
    parallel = max(1, min(int(workers), os.cpu_count() or 1))
    seconds = points * (per_point.seconds + POINT_OVERHEAD_SECONDS) / parallel
    memory = per_point.memory + (parallel - 1) * WORKER_MEMORY + POINT_BYTES * points
    return Estimate(memory, seconds)


def check_worker_budget(workers: int | None) -> None:
    """Refuse more than four workers per core (they only contend) or more than memory allows."""
    if workers is None:
        return
    cores = os.cpu_count() or 1
    if workers > MAX_WORKERS_PER_CORE * cores:
        raise ParameterError(
            "workers",
            f"an integer in [1, {MAX_WORKERS_PER_CORE * cores}] "
            f"({MAX_WORKERS_PER_CORE} per core, {cores} cores)",
            workers,
        )
    check(f"workers {workers}", Estimate(BASE_MEMORY + workers * WORKER_MEMORY, 0.0))


def check_sweep(
    points: int,
    modes: int,
    t_end: float,
    workers: int | None = None,
    reference: bool = False,
    per_point: Estimate | None = None,
) -> Estimate:
    """Refuse a sweep of ``points`` closed-form solves (N ``modes``, window ``t_end``).

    Workers: at most four per core, each ~150 MiB.  Per point: the series (and,
    with ``reference``, the truncation guard's converged series) plus ~3 ms of
    bookkeeping; or ``per_point`` when the solve is another (the contact solver,
    :func:`twoball.modal.contact.cost.contact_estimate`, or a stiffened series).
    """
    check_worker_budget(workers)
    cores = os.cpu_count() or 1
    per_point = series_estimate(modes, t_end) if per_point is None else per_point
    if reference:
        per_point = per_point + reference_estimate(t_end, modes)
    estimate = sweep_estimate(points, per_point, cores if workers is None else workers)
    return check(f"values ({points} points)", estimate)


def check_count(option: str, count: float, bytes_each: float = 8.0) -> Estimate:
    """Refuse an array of ``count`` items (e.g. the swept values) that cannot fit."""
    return check(option, Estimate(BASE_MEMORY + bytes_each * count, 0.0))
