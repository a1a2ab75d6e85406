"""``twoball.sweep``: the lift-off over a grid of cases, in SI.

The command line (``twoball sweep``) calls exactly this function, so the same
inputs give bit-identical numbers in Python and in a shell.
"""

from __future__ import annotations

import math
import os
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from twoball._common.budget import BudgetError, timed
from twoball._common.errors import ParameterError
from twoball._common.keywords import checked
from twoball._common.ranges import real
from twoball.modal.parameters import Case

__all__ = ["SweepResult", "sweep"]


@checked
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
    warnings : tuple of str
        The sweep's own: swept values far outside any ball (unit slips), checked on the
        values before any point ran (:func:`twoball.modal.guards.sweep_slips`).

    Examples
    --------
    >>> import twoball
    >>> result = twoball.sweep({"v0": [3.0, 4.1]})
    >>> result.parameters, result.shape, [p.case.phi_a_source for p in result.points]
    (('v0',), (2,), ['eq. (3.7)', 'eq. (3.7)'])
    >>> result.phi_a_rule
    'eq. (3.7) at every point (from |v0|, R, c)'
    """

    parameters: tuple[str, ...]
    shape: tuple[int, ...]
    points: list[Any]
    provenance: dict[str, Any] | None = field(default=None, compare=False, repr=False)
    values: tuple[Any, ...] = field(default=(), compare=False, repr=False)
    warnings: tuple[str, ...] = ()
    #: the points' own warnings that repeat the swept values' slips (said once, in warnings)
    point_slips: frozenset[str] = field(default=frozenset(), compare=False, repr=False)

    @checked
    def plot(self, out: str | os.PathLike[str], *, measured: Any = None) -> Path:
        r"""Write the figure of the sweep: v_l / \|v0\| and t_l against the parameter, or heat maps.

        ``out``'s suffix chooses the format (``.png``, ``.pdf``, ``.svg``, ...).
        ``measured`` (a CSV path or a mapping of columns, as :func:`twoball.fit`
        reads them) draws the user's points over a one-parameter sweep: ``v1_m_s``
        over ``|v0|`` on the ratio's panel, ``t_liftoff_s`` on the time's (at
        their ``v0_m_s`` in a v0 sweep, else as lines).
        """
        from twoball._plot import check_figure_path
        from twoball.verify.output.figures.sweep import plot_sweep
        from twoball.verify.sweeps.sweeps import SweepGrid

        target = check_figure_path(out, "out")
        grid = SweepGrid(self.parameters, tuple(self.values))
        if measured is None:
            return plot_sweep(grid, self.points, target)
        from twoball._fit import read_measured
        from twoball.verify.output.figures import REPORT_DPI, save_figure
        from twoball.verify.output.figures.measured import draw_overlay, overlay_for
        from twoball.verify.output.figures.sweep import sweep_figure

        if len(self.parameters) != 1:
            valid = "given with a sweep of one parameter (a grid of two draws heat maps)"
            raise ParameterError("measured", valid, "a grid of " + " x ".join(self.parameters))
        data = read_measured(measured, "measured")
        figure = sweep_figure(grid, self.points)
        draw_overlay(figure, overlay_for(self, data))
        return save_figure(figure, target, "plot", dpi=REPORT_DPI)

    @checked
    def to_csv(self, path: str | os.PathLike[str]) -> Path:
        """Write the table as CSV: one row per point, SI columns with the unit in the name.

        The swept parameters first, then ``v0_m_s``, ``radius_m``,
        ``wave_speed_1_s``, ``damping``, ``modes``, ``phi_a_rad``, ``phi_a_source``,
        ``lifted``, ``t_liftoff_s``, ``v_liftoff_m_s``, ``ratio``, ``warnings``,
        ``error`` (blank: no value).  Returns the path written.
        """
        from twoball.verify.sweeps.table import liftoff_table, write_table

        header, rows = liftoff_table(self.points, self.parameters)
        return write_table(header, rows, path, "path")

    @property
    def phi_a_rule(self) -> str:
        """How phi_a was chosen: one rule for every point (eq. (3.7) when v0, c or R is
        swept, else the base case's angle)."""
        from twoball.verify.sweeps.sweeps import phi_a_rule

        return phi_a_rule([p.case for p in self.points])

    @property
    def phi_a_note(self) -> str | None:
        """The sweep's one note on phi_a when its rule replaced a preset's measured angle
        (eq. (3.7) at every point, the preset's own point included), else None."""
        from twoball.verify.sweeps.sweeps import phi_a_note

        return phi_a_note([p.case for p in self.points])

    def as_dict(self) -> dict[str, Any]:
        """JSON-ready: parameters, shape, the phi_a rule, the points (SI) and the provenance."""
        return {
            "parameters": list(self.parameters),
            "shape": list(self.shape),
            "phi_a_rule": self.phi_a_rule,
            "warnings": list(self.warnings),
            "points": [p.as_dict() for p in self.points],
            "provenance": self.provenance,
        }


def _point_cost(case: Case, grid: Any, body: Any, modes: int, window: float) -> Any:
    """The estimate of the costliest point: the contact solver with a body, else the series
    at the stiffest bending swept (None: the membrane's series, the sweep's default)."""
    from twoball.modal.cost import legendre_omega, series_estimate

    stiff = case
    if "bending" in grid.parameters:
        stiff = case.derive(bending=float(max(grid.values[grid.parameters.index("bending")])))
    top = float(stiff.stiffness.legendre_omega(float(modes))) if stiff.stiff else None
    masses = [0.0 if body is None else body.mass_ratio]
    if "mass-ratio" in grid.parameters:
        masses = list(grid.values[grid.parameters.index("mass-ratio")])
    if max(masses) > 0.0:
        from twoball.modal.contact.cost import contact_estimate

        return contact_estimate(modes + 1, legendre_omega(modes), window)
    return None if top is None else series_estimate(modes, window, omega_max=top)


def _sweep_name(name: str) -> str:
    return name.replace("_", "-")


def where(verb: str, workers: Any) -> tuple[Any, str | None]:
    """``workers`` as (process count, None) or (None, scheduler address), the address
    checked (named ``workers``)."""
    from twoball.verify.sweeps.parallel import check_scheduler

    if isinstance(workers, str):
        try:
            return None, check_scheduler(workers)
        except ParameterError as error:
            valid = "an integer >= 1 (local processes) or " + error.valid
            raise ParameterError("workers", valid, error.got) from None
    return workers, None


@checked
@timed
def sweep(
    values: Mapping[str, Sequence[float]],
    case: Case | None = None,
    *,
    solver: Any = None,
    body: Any = None,
    damping: Any = None,
    workers: int | str | None = None,
    progress: Callable[[int], None] | None = None,
    drop: Any = None,
    pair: str | None = None,
) -> SweepResult | Any:
    """Lift-off over one parameter or a grid of two (Fig. 11(b), Fig. 12), or drops over one.

    Parameters
    ----------
    values : mapping
        ``{"v0": [2.0, 4.0, 8.0]}`` or two entries for a grid; keys among
        ``damping``, ``v0``, ``wave_speed``, ``radius``, ``modes``,
        ``mass_ratio``, ``bending``.  v0, c and R re-apply the phi_a rule of
        :class:`~twoball.Case`.
    case : Case, optional
        The base case (default the basketball preset).
    solver : ClosedForm or MoreauJean, optional
        The closed form of every point (:class:`~twoball.ClosedForm`: its filter,
        re-contact horizon and window; the default), or, with a body of finite
        mass on the points (``body`` or a ``mass_ratio`` sweep), the stepped
        contact on the Legendre modes (:class:`~twoball.MoreauJean`: its step,
        window and the start's filter; the default there).  A sweep of the drop
        takes a :class:`~twoball.MoreauJean` with its ball.
    body : Body, optional
        An upper body on every point (docs/contact.rst); a ``mass_ratio`` sweep
        takes its other fields from it (default: contact radius R/10, no
        restitution, the ball's energy).  With ``drop`` also an elastic body
        (:class:`~twoball.LumpedBody`, :class:`~twoball.BallBody`) or, with
        ``pair``, a kind name (``"rigid"``, ``"lumped"``, ``"ball"``: the pair's
        preset body of that kind), as :func:`~twoball.bounce` takes it
        (docs/bodies.rst); a ``mass_ratio`` sweep takes a rigid body only.
    damping : ModalRatio or Rayleigh, optional
        The damping law of every point, as in :func:`~twoball.liftoff` (a
        Rayleigh law with alpha, beta of its own refuses a ``damping`` sweep).
    workers : int or str, optional
        Local processes (default 1: serial), or the address of a
        dask.distributed scheduler (``"tcp://host:8786"``) whose workers run
        the points; the numbers do not depend on where.
    progress : callable, optional
        Called with the number of points done (e.g. :meth:`twoball.Reporter.update`).
    drop : Drop, optional
        Sweep the drop on the floor, or the whole bounce with ``body`` or
        ``pair``, instead (:func:`twoball.bounce` at every point): one
        parameter, ``v0``, ``drop_height``, ``gap``, ``mass_ratio`` or
        ``damping``; returns a :class:`~twoball.BounceSweep`.
    pair : str, optional
        With ``drop``: a Table 1 pair (:func:`twoball.bounce`'s ``pair``).

    Returns
    -------
    SweepResult

    Examples
    --------
    >>> import twoball
    >>> result = twoball.sweep({"damping": [0.1, 0.13, 0.2]})
    >>> [round(p.ratio, 3) for p in result.points]
    [1.354, 0.935, 0.417]
    """
    from twoball._solvers import ClosedForm, MoreauJean
    from twoball.modal.contact.body import Body
    from twoball.modal.damping import with_damping

    workers, scheduler = where("twoball.sweep", workers)
    if body is not None and drop is None and not isinstance(body, Body):
        raise ParameterError("body", "a twoball.Body", type(body).__name__)
    if drop is not None:  # the body of every drop checked as twoball.bounce checks it
        from twoball._common.watch import Watch
        from twoball.verify.sweeps.bounce import bounce_sweep

        if solver is not None and not isinstance(solver, MoreauJean):
            raise ParameterError("solver", "a twoball.MoreauJean for a sweep of the drop", solver)
        return bounce_sweep(
            values,
            case,
            drop,
            body=body,
            pair=pair,
            solver=solver,
            damping=damping,
            workers=workers,
            scheduler=scheduler,
            progress=progress,
            monitor=Watch(),
        )
    if pair is not None:
        raise ParameterError("pair", "given only with drop (a sweep of the whole bounce)", pair)
    import numpy as np

    from twoball._common.progress import check_progress
    from twoball._common.watch import Watch
    from twoball.modal.report import t_end_dimensionless
    from twoball.verify.sweeps.cost import check_sweep
    from twoball.verify.sweeps.parallel import (
        MIN_PARALLEL_ITEMS,
        Runner,
        check_workers,
    )
    from twoball.verify.sweeps.sweeps import SWEEP_PARAMETERS, SweepGrid, SweepSolver, run_sweep

    check_progress(progress)
    case = Case.preset("basketball") if case is None else case
    if not isinstance(case, Case):
        raise ParameterError("case", "a twoball.Case", type(case).__name__)
    case = with_damping(case, damping)
    if not isinstance(values, Mapping):
        raise ParameterError("values", "a mapping of one or two parameters to values", values)
    stepped = (body is not None and body.mass_ratio > 0.0) or any(
        _sweep_name(k) == "mass-ratio" for k in values
    )
    if solver is None:
        solver = MoreauJean() if stepped else ClosedForm()
    if stepped and not isinstance(solver, MoreauJean):
        valid = "twoball.MoreauJean with a body of finite mass on the points (its contacts)"
        raise ParameterError("solver", valid, type(solver).__name__)
    if not stepped and not isinstance(solver, ClosedForm):
        raise ParameterError("solver", "a twoball.ClosedForm for a lift-off sweep", solver)
    if isinstance(solver, MoreauJean) and solver.ball is not None:
        from twoball.modal.balls.membrane import LegendreBall

        if not isinstance(solver.ball, LegendreBall) or solver.ball.modes is not None:
            valid = "the case's Legendre modes in a sweep (N is the case's, or swept: modes)"
            raise ParameterError("ball", valid, solver.ball.label)
    sigma = solver.sigma or "lanczos"
    recontact = getattr(solver, "recontact", "window")
    t_end = solver.t_end
    workers = 1 if workers is None and not scheduler else workers
    if workers is not None:
        check_workers(workers)  # its type and range, before the budget compares it
    call: dict[str, Any] = {"workers": workers, "scheduler": scheduler}
    call["solver"] = solver.as_dict()
    if body is not None:
        call["body"] = body.as_dict()
    if damping is not None:
        call["damping"] = damping.as_dict()
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
        valid = f"a non-empty list of finite numbers for {name}"
        if isinstance(items, (str, bytes)):
            raise ParameterError("values", valid, items)
        try:  # numbers only: a string ("0_01" is 1.0 to float) or a bool is refused
            array = np.array([real(v) for v in np.atleast_1d(np.asarray(items, dtype=object))])
        except (TypeError, ValueError):
            raise ParameterError("values", valid, items) from None
        if array.ndim != 1 or array.size < 1 or not np.all(np.isfinite(array)):
            raise ParameterError("values", valid, items)
        arrays.append(array)
    rule = [p for p in parameters if p in ("v0", "wave-speed", "radius")]
    if rule and case.phi_a_source == "given":
        valid = (
            f"left out when {rule[0].replace('-', '_')} is swept (phi_a then follows |v0|, "
            "c and R by eq. (3.7) at every point)"
        )
        raise ParameterError("phi_a", valid, case.phi_a)
    grid = SweepGrid(parameters, tuple(arrays))
    if "mass-ratio" in parameters and body is not None and body.energy == "both":
        # mu > 0 takes eq. (3.7) at |v0| sqrt(1 + mu): so does mu = 0 (one rule per sweep)
        case = case.derive(phi_a="eq. (3.7)")
    modes = int(max(arrays[parameters.index("modes")])) if "modes" in parameters else case.modes
    window = t_end_dimensionless(case, t_end)
    slips = _slips(grid, case)  # on the values, before the budget and any point
    try:
        check_sweep(
            math.prod(grid.shape),
            modes,
            window,
            workers,
            per_point=_point_cost(case, grid, body, modes, window),
        )
    except BudgetError as error:  # the slips are said with the refusal: it may be their cost
        if not slips:
            raise
        raise BudgetError(error.name, "; ".join([error.valid, *slips])) from None
    cases = grid.cases(case)
    workers = None if scheduler else check_workers(workers)
    if len(cases) < MIN_PARALLEL_ITEMS and not scheduler:
        workers = 1  # would run in process anyway; do not start a pool
    if "mass-ratio" in parameters or body is not None:
        from dataclasses import replace

        from twoball.modal.contact.body import Body
        from twoball.modal.contact.report import check_contact_options

        template = Body(0.0) if body is None else body
        swept = parameters.index("mass-ratio") if "mass-ratio" in parameters else None
        for mu in [template.mass_ratio] if swept is None else arrays[swept]:
            check_contact_options(case, replace(template, mass_ratio=float(mu)))
        step = None if solver.dt is None else solver.dt * case.wave_speed
        task = SweepSolver(sigma, recontact, t_end, body=template, dt=step, monitor=Watch())
    else:
        task = SweepSolver(sigma, recontact, t_end, monitor=Watch())
    with Runner(workers, scheduler) as runner:
        points = run_sweep(cases, task, progress, runner=runner, indices=grid.indices())
    from dataclasses import replace as with_rule

    from twoball.verify.sweeps.sweeps import phi_a_rule

    rule = phi_a_rule(cases)  # one rule per sweep: said beside every point
    points = [with_rule(p, phi_a_rule=rule) for p in points]
    from twoball._common.provenance import block

    arguments = {"values": {k: arrays[i] for i, k in enumerate(values)}, **call}
    provenance = block(case, "twoball.sweep", arguments)
    repeated = _point_slips(points, parameters) if slips else frozenset()
    return SweepResult(
        parameters, grid.shape, points, provenance, tuple(arrays), tuple(slips), repeated
    )


def _point_slips(points: Sequence[Any], parameters: Sequence[str]) -> frozenset[str]:
    """The points' warnings of their own swept values' slips (already said for the sweep)."""
    from twoball.modal.guards import value_slip
    from twoball.verify.sweeps.sweeps import SWEEP_PARAMETERS

    fields = [SWEEP_PARAMETERS[name] for name in parameters]
    said = (
        value_slip(f, float(getattr(p.case, f)), p.case)
        for p in points
        for f in fields
        if f not in ("mass_ratio", "modes")
    )
    return frozenset(text for text in said if text is not None)


def _slips(grid: Any, case: Case) -> list[str]:
    """One warning per swept parameter whose values lie far outside any ball (unit slips)."""
    from twoball.modal.guards import sweep_slips
    from twoball.verify.sweeps.sweeps import SWEEP_PARAMETERS

    said = (
        sweep_slips(SWEEP_PARAMETERS[name], name, values, case)
        for name, values in zip(grid.parameters, grid.values, strict=True)
    )
    return [text for text in said if text is not None]
