"""``twoball.sweep``: the lift-off over a grid of cases, in SI.

The command line (``twoball sweep``) calls exactly this function, so the same
inputs give bit-identical numbers in Python and in a shell.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass, field
from typing import Any

from twoball._common.errors import ParameterError
from twoball.modal.parameters import Case

__all__ = ["SweepResult", "sweep"]


@dataclass(frozen=True)
class SweepResult:
    """Lift-off over a grid of cases (row-major: the first parameter varies slowest).

    Attributes
    ----------
    parameters : tuple of str
        Swept parameters (``v0``, ``damping``, ``wave-speed``, ``radius``, ``modes``).
    shape : tuple of int
        Values per parameter.
    points : list of SweepPoint
        One per grid point: ``index``, ``case``, ``report`` (or ``error``).
    provenance : dict
        Versions, command line or call, UTC time, base case (:mod:`twoball._common.provenance`).
    """

    parameters: tuple[str, ...]
    shape: tuple[int, ...]
    points: list[Any]
    provenance: dict[str, Any] | None = field(default=None, compare=False, repr=False)

    def as_dict(self) -> dict[str, Any]:
        """JSON-ready: parameters, shape, the points (SI) and the provenance."""
        return {
            "parameters": list(self.parameters),
            "shape": list(self.shape),
            "points": [p.as_dict() for p in self.points],
            "provenance": self.provenance,
        }


def _sweep_name(name: str) -> str:
    return name.replace("_", "-")


def sweep(
    values: Mapping[str, Sequence[float]],
    case: Case | None = None,
    *,
    sigma: str = "lanczos",
    recontact: str = "window",
    t_end: float | None = None,
    workers: int | None = None,
    scheduler: str | None = None,
    progress: Callable[[int], None] | None = None,
    contact_radius: float | None = None,
) -> SweepResult:
    """Closed-form lift-off over one parameter or a grid of two (Fig. 11(b), Fig. 12).

    Parameters
    ----------
    values : mapping
        ``{"v0": [2.0, 4.0, 8.0]}`` or two entries for a grid; keys among
        ``damping``, ``v0``, ``wave_speed``, ``radius``, ``modes``.  v0, c and R
        re-apply the phi_a rule of :class:`~twoball.modal.parameters.Case`.
    case : Case, optional
        The base case (default the basketball preset).
    sigma, recontact, t_end
        As in :func:`liftoff` (``t_end`` in seconds).
    workers : int, optional
        Local processes (default 1: serial; the numbers do not depend on it);
        refused with ``scheduler``.
    scheduler : str, optional
        Address of a dask.distributed scheduler.
    progress : callable, optional
        Called with the number of points done (e.g. :meth:`twoball._common.progress.Reporter.update`).
    contact_radius : float, optional
        Contact cap radius a [m] of a ``mass_ratio`` sweep (default R/10): the
        points then run the finite-mass contact solver (docs/contact.rst).

    Returns
    -------
    SweepResult
    """
    import numpy as np

    from twoball._common.budget import check_sweep
    from twoball.modal.report import t_end_dimensionless
    from twoball.verify.sweeps.parallel import MIN_PARALLEL_ITEMS, Runner, check_workers
    from twoball.verify.sweeps.sweeps import SWEEP_PARAMETERS, SweepGrid, SweepSolver, run_sweep

    case = Case.preset("basketball") if case is None else case
    if not isinstance(case, Case):
        raise ParameterError("case", "a twoball.Case", type(case).__name__)
    if scheduler and workers is not None:
        raise ParameterError("workers", "left out with scheduler (the cluster decides)", workers)
    workers = 1 if workers is None and not scheduler else workers
    if workers is not None:
        check_workers(workers)  # its type and range, before the budget compares it
    call = {
        "sigma": sigma,
        "recontact": recontact,
        "t_end": t_end,
        "workers": workers,
        "scheduler": scheduler,
    }
    if not isinstance(values, Mapping) or not 1 <= len(values) <= 2:
        raise ParameterError("values", "a mapping of one or two parameters to values", values)
    parameters = tuple(_sweep_name(k) for k in values)
    for key, name in zip(values, parameters, strict=True):
        if name not in SWEEP_PARAMETERS:
            valid = "keys among " + ", ".join(f.replace("-", "_") for f in SWEEP_PARAMETERS)
            raise ParameterError("values", valid, key)
    if len(set(parameters)) != len(parameters):
        raise ParameterError("values", "two different parameters for a grid", list(values))
    arrays = []
    for name, items in values.items():
        array = np.atleast_1d(np.asarray(items, dtype=float))
        if array.ndim != 1 or array.size < 1 or not np.all(np.isfinite(array)):
            raise ParameterError(f"values[{name!r}]", "a non-empty list of finite numbers", items)
        arrays.append(array)
    grid = SweepGrid(parameters, tuple(arrays))
    modes = int(max(arrays[parameters.index("modes")])) if "modes" in parameters else case.modes
    check_sweep(math.prod(grid.shape), modes, t_end_dimensionless(case, t_end), workers)
    cases = grid.cases(case)
    workers = None if scheduler else check_workers(workers)
    if len(cases) < MIN_PARALLEL_ITEMS and not scheduler:
        workers = 1  # would run in process anyway; do not start a pool
    if contact_radius is not None and "mass-ratio" not in parameters:
        raise ParameterError("contact_radius", "given only with a mass_ratio sweep", contact_radius)
    if "mass-ratio" in parameters:
        from twoball.modal.contact.report import check_contact_options

        for mu in arrays[parameters.index("mass-ratio")]:
            check_contact_options(case, float(mu), contact_radius, 0.0, "ball")
        if recontact != "window":
            raise ParameterError("recontact", "window with mass_ratio", recontact)
    if contact_radius is None:
        solver = SweepSolver(sigma, recontact, t_end)
    else:
        solver = SweepSolver(sigma, recontact, t_end, contact_radius=contact_radius)
    with Runner(workers, scheduler) as runner:
        points = run_sweep(cases, solver, progress, runner=runner, indices=grid.indices())
    from twoball._common.provenance import block

    arguments = {"values": {k: arrays[i] for i, k in enumerate(values)}, **call}
    return SweepResult(parameters, grid.shape, points, block(case, "twoball.sweep", arguments))
