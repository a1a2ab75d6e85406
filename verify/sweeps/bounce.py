"""Sweeps of the drop on the floor and of the whole bounce: one run per value (SI).

:func:`bounce_points` turns a base case, drop and body and one swept parameter
into the (case, drop, body) triples that :func:`bounce_sweep` runs one by one
(:class:`BounceTask`, the run of :mod:`twoball.modal.floor.bounce`) in process,
on the process pool or on Dask
(:class:`~twoball.verify.sweeps.parallel.Runner`): the impact speed ``v0``
[m/s], the drop height ``drop-height`` [m], the gap ``gap`` [m] (Fig. 3, Fig. 8)
and the mass ratio ``mass-ratio`` of the upper body.  The figures are
:func:`twoball.verify.output.figures.bounce.speeds_figure` and
:func:`~twoball.verify.output.figures.bounce.gap_figure`.
"""

from __future__ import annotations

import os
from collections.abc import Sequence
from dataclasses import dataclass, field, replace
from pathlib import Path
from typing import Any

import numpy as np

from twoball._common.errors import ParameterError
from twoball._common.keywords import checked
from twoball.modal.floor.options import Drop
from twoball.modal.floor.report import BounceReport
from twoball.modal.parameters import Case
from twoball.verify.sweeps.sweeps import parse_range

__all__ = [
    "BOUNCE_PARAMETERS",
    "BounceSweep",
    "BounceTask",
    "bounce_points",
    "bounce_sweep",
    "bounce_values",
    "check_point",
]

#: Parameters of a drop sweep (CLI names) and the field each sets.
BOUNCE_PARAMETERS: dict[str, str] = {
    "v0": "v0",
    "drop-height": "drop_height",
    "gap": "gap",
    "mass-ratio": "mass_ratio",
    "damping": "damping",
}


def bounce_values(parameters: Sequence[str], values: Sequence[object]) -> tuple[str, np.ndarray]:
    """The one swept parameter of a drop sweep and its values (``START:STOP:COUNT`` or a list)."""
    parameters = [p.replace("_", "-") for p in parameters]
    if len(parameters) != 1 or parameters[0] not in BOUNCE_PARAMETERS:
        valid = "one of " + ", ".join(BOUNCE_PARAMETERS) + " (a drop sweep has one axis)"
        raise ParameterError("param", valid, ",".join(parameters))
    if len(values) != 1:
        raise ParameterError("values", "given once, for the one parameter", list(values))
    items = values[0]
    valid = "a non-empty list of finite numbers"
    if isinstance(items, str):
        array = np.atleast_1d(parse_range(items)).astype(float)
    else:
        from twoball._common.ranges import real

        try:  # numbers only: float("0_01") and bools would pass as other values
            array = np.array([real(v) for v in np.atleast_1d(np.asarray(items, dtype=object))])
        except (TypeError, ValueError):
            raise ParameterError("values", valid, items) from None
    if array.ndim != 1 or array.size < 1 or not np.all(np.isfinite(array)):
        raise ParameterError("values", valid, items)
    return parameters[0], array


def bounce_points(
    case: Case, drop: Drop, parameter: str, values: np.ndarray, body: Any = None
) -> list[tuple[Case, Drop, Any]]:
    """One (case, drop, body) per value of ``parameter`` (validated by the options' classes).

    ``gap`` needs a body (or a pair, which the face resolves: ``body`` is then
    None and the gap is the drop's); ``mass-ratio`` replaces the body's mu (a
    body of that mu with the default contact radius and no restitution when
    none is given); ``damping`` the case's ratio D (refused with a Rayleigh law
    of its own alpha and beta, which has no D).
    """
    if parameter == "damping":
        law = case.rayleigh
        if law is not None and not law.fitted:
            valid = "a parameter the case's damping law reads (a Rayleigh law of its own alpha, "
            raise ParameterError("param", valid + "beta has no D)", "damping")
        return [(case.derive(damping=float(v)), drop, body) for v in values]
    if parameter == "v0":
        for name in ("drop_height", "centre_height"):  # a height sets |v0|
            if getattr(drop, name) is not None:
                raise ParameterError(name, "left out when v0 is swept", getattr(drop, name))
        return [(case.derive(v0=float(v)), drop, body) for v in values]
    if parameter == "drop-height":
        from twoball.modal.floor.inputs import check_drop_height

        if drop.centre_height is not None:  # the swept heights are the lowest point's
            valid = "left out when drop_height is swept"
            raise ParameterError("centre_height", valid, drop.centre_height)
        points = [(case, replace(drop, drop_height=float(v)), body) for v in values]
        for _, point, _ in points:  # a height below the case's radius: before the first run
            check_drop_height(case, point.drop_height)
        return points
    if parameter == "gap":
        if drop.gap != 0.0:
            raise ParameterError("gap", "left out when the gap is swept", drop.gap)
        return [(case, replace(drop, gap=float(v)), body) for v in values]
    from twoball.modal.contact.body import Body

    if body is not None and not isinstance(body, Body):  # an elastic body's mu is its own
        valid = "a twoball.Body (rigid) when the mass ratio is swept"
        raise ParameterError("body", valid, body if isinstance(body, str) else type(body).__name__)
    if body is not None and body.mass_ratio != 0.0:
        raise ParameterError("mass_ratio", "left out when the mass ratio is swept", body.mass_ratio)
    base = Body(0.0) if body is None else body
    return [(case, drop, replace(base, mass_ratio=float(v))) for v in values]


@checked
@dataclass(frozen=True)
class BounceSweep:
    """Drops over one parameter (``v0``, ``drop-height``, ``gap``, ``mass-ratio``, ``damping``).

    Attributes
    ----------
    parameter : str
        ``v0``, ``drop-height``, ``gap``, ``mass-ratio`` or ``damping``.
    values : tuple of float
        Its values (m/s, m, m or none).
    reports : list of BounceReport or None
        One run per value without its history
        (:meth:`~twoball.modal.floor.report.BounceReport.light`; None where it
        failed; ``errors`` says why).
    errors : list of str or None
    provenance : dict
    slips : tuple of tuple of str
        Each point's unit slips (:func:`twoball.modal.guards.case_warnings`), found
        before any point ran: kept in the JSON of a point that failed too.
    warnings : tuple of str
        The sweep's own: swept values far outside any ball
        (:func:`twoball.modal.guards.sweep_slips`), checked before any point ran.

    Examples
    --------
    >>> import twoball
    >>> solver = twoball.MoreauJean(twoball.LegendreBall(32))
    >>> result = twoball.sweep({"v0": [2.0, 4.1]}, drop=twoball.Drop(), solver=solver)
    >>> [round(r.flattening_max_m * 1e3, 1) for r in result.reports]
    [12.0, 20.5]
    """

    parameter: str
    values: tuple[float, ...]
    reports: list[Any]
    errors: list[str | None]
    provenance: dict[str, Any] | None = field(default=None, compare=False, repr=False)
    slips: tuple[tuple[str, ...], ...] = field(default=(), compare=False, repr=False)
    warnings: tuple[str, ...] = ()

    def as_dict(self) -> dict[str, Any]:
        """JSON-ready: the parameter and one drop per value (SI), with the provenance and
        the sweep's own ``warnings``; a point that failed keeps its unit slips."""
        points = []
        slips = self.slips or ((),) * len(self.values)
        for value, report, error, slip in zip(
            self.values, self.reports, self.errors, slips, strict=True
        ):
            data = {"parameter": self.parameter, "value": value, "error": error}
            if report is not None:
                data |= {k: v for k, v in report.as_dict().items() if k != "provenance"}
            else:
                data["warnings"] = list(slip)
            points.append(data)
        return {
            "parameter": self.parameter,
            "warnings": list(self.warnings),
            "points": points,
            "provenance": self.provenance,
        }

    @checked
    def plot(
        self, out: str | os.PathLike[str], *, dpi: float | None = None, measured: Any = None
    ) -> Path:
        """phi_a,max and the flattening against |v0|, with eq. (3.7), pressure x area and the
        measurements (Table 2; 3.07 mm per m/s); for a gap or mass-ratio sweep (or a damping
        sweep with a body), v1/|v0|, v2/|v0| and the lift-off time against it with the ICM
        and the lumped baselines; for a damping sweep of the ball alone, e2, the contact time
        and phi_a,max against D.

        ``measured`` (a CSV path or a mapping of columns, as :func:`twoball.fit` reads
        them) draws the user's points on the panels of the same quantities
        (:mod:`twoball.verify.output.figures.measured`).
        """
        from twoball._common.staging import check_path_type
        from twoball.verify.output.figures import figure_format, save_figure
        from twoball.verify.output.figures.bounce import speeds_figure

        figure_format(Path(check_path_type(out)), "out")  # before the figure is drawn
        done = [r for r in self.reports if r is not None]
        if not done:
            raise ParameterError("values", "at least one drop that ran, to plot", None)
        data = None
        if measured is not None:
            from twoball.verify.fit.data import as_measurements

            data = as_measurements(measured, "measured")
        pairs = [(v, r) for v, r in zip(self.values, self.reports, strict=True) if r]
        if self.parameter in ("gap", "mass-ratio") or any(r.has_body for r in done):
            from twoball.verify.output.figures.bounce import gap_figure

            figure = gap_figure(pairs, self.parameter)
            if self.parameter not in ("gap", "mass-ratio"):
                from twoball.verify.output.figures.drop_sweep import sweep_axis_label

                figure.axes[-1].set_xlabel(sweep_axis_label(self.parameter))
        elif self.parameter in ("v0", "drop-height"):
            rows = [(r.case.v0, r.phi_a_max_rad, r.flattening_max_m) for r in done]
            figure = speeds_figure(rows, done[0].case)
        else:
            from twoball.verify.output.figures.drop_sweep import drop_sweep_figure

            figure = drop_sweep_figure(pairs, self.parameter)
        if data is not None:
            from twoball.verify.output.figures.measured import draw_overlay, overlay_for

            draw_overlay(figure, overlay_for(self, data))
        return save_figure(figure, out, "plot", dpi)

    @checked
    def to_csv(self, path: str | os.PathLike[str]) -> Path:
        """Write the table as CSV: one row per value, SI columns with the unit in the name.

        The swept value first (``v0_m_s``, ``drop_height_m``, ``gap_m``,
        ``mass_ratio`` or ``damping``), then ``v0_m_s``, ``drop_height_m``,
        ``left_floor``, ``contact_time_s``, ``v2_m_s``, ``e2``, ``phi_a_max_rad``,
        ``flattening_max_m``, ``t_max_compression_s``; with a body also
        ``gap_m``, ``mass_ratio``, ``v1_m_s``, ``v1_ratio``, ``v2_ratio``,
        ``t_liftoff_s``, ``t_liftoff_from_max_compression_s``,
        ``body_left_first``, ``sequence``, ``e12_effective``, ``caveats`` (the
        answer's tags, ``artefact | overlap``); then ``warnings``
        and ``error`` (blank: no value).  Returns the path written.
        """
        from twoball.verify.sweeps.table import bounce_table, write_table

        header, rows = bounce_table(self.parameter, self.values, self.reports, self.errors)
        return write_table(header, rows, path, "path")


def check_point(
    case: Case | None, drop: Drop, body: Any, pair: str | None, *, solver: Any = None
) -> Any:
    """The checks a drop makes before its work (:func:`~twoball.modal.floor.bounce.bounce_problem`),
    for one point of a sweep; returns the resolved problem."""
    from twoball.modal.floor.bounce import bounce_problem

    return bounce_problem(case, drop, body=body, pair=pair, **_solver_options(solver))


def _solver_options(solver: Any) -> dict[str, Any]:
    """A Moreau-Jean solver's ball, step and window as the drop's arguments."""
    if solver is None:
        return {}
    return {"ball": solver.ball, "dt": solver.dt, "t_end": solver.t_end}


def bounce_sweep(
    values: Any,
    case: Case | None,
    drop: Drop,
    *,
    body: Any = None,
    pair: str | None = None,
    solver: Any = None,
    damping: Any = None,
    workers: int | None = None,
    scheduler: str | None = None,
    progress: Any = None,
    monitor: Any = None,
) -> BounceSweep:
    """Drops over ``values`` (``{"v0": [...]}``, ``drop_height``, ``gap``, ``mass_ratio`` or
    ``damping``), SI.

    The points run in this process (``workers`` 1 or None), on a local process
    pool or on a Dask scheduler (:class:`~twoball.verify.sweeps.parallel.Runner`):
    the numbers do not depend on where.  Each point is kept without its history
    (:meth:`BounceReport.light`).  ``solver`` is the Moreau-Jean solver of every
    point (its ball, step and window); ``monitor`` is handed to each run.
    """
    from twoball.modal.floor.inputs import check_drop_case, resolve_pair, v0_set
    from twoball.verify.sweeps.parallel import Runner, check_workers

    if case is not None and not isinstance(case, Case):
        raise ParameterError("case", "a twoball.Case", type(case).__name__)
    if not isinstance(drop, Drop):
        raise ParameterError("drop", "a twoball.Drop", type(drop).__name__)
    if not hasattr(values, "items") or not values:
        raise ParameterError(
            "values", "a mapping of v0, drop_height, gap or mass_ratio to values", values
        )
    parameter, array = bounce_values(list(values), list(values.values()))
    if (
        parameter == "damping"
        and damping is not None
        and not (
            getattr(damping, "fitted", False)  # Rayleigh() fitted to each point's D
        )
    ):
        valid = "left out when damping is swept (the law would replace the swept D)"
        raise ParameterError("damping", valid, damping.as_dict())
    if pair is not None and parameter == "mass-ratio":
        raise ParameterError("pair", "left out when the mass ratio is swept (it fixes mu)", pair)
    if parameter == "gap" and body is None and pair is None:
        raise ParameterError("gap", "swept only with an upper body (body or pair)", None)
    if scheduler and workers is not None:
        raise ParameterError("workers", "left out with scheduler (the cluster decides)", workers)
    workers = 1 if workers is None and not scheduler else workers
    if workers is not None:
        check_workers(workers)
    base, _, _ = resolve_pair(case, None, pair) if pair is not None else (case, None, None)
    base = Case.preset("basketball") if base is None else base
    if parameter == "drop-height" and v0_set(base):
        speed = base.v0 if base.v0_given is None else base.v0_given
        valid = "left out when drop_height is swept (each height sets |v0| = sqrt(2 g H))"
        raise ParameterError("v0", valid, speed)
    check_drop_case(base, drop)  # a given phi_a: a v0 sweep would drop it unsaid
    points = [(*point, pair) for point in bounce_points(base, drop, parameter, array, body)]
    # every point's values refused here, before the first run, and its unit slips found
    slips = tuple(check_point(*point, solver=solver).slips for point in points)
    from twoball.modal.guards import sweep_slips

    field = BOUNCE_PARAMETERS[parameter]
    swept = sweep_slips(field, parameter, array, base)
    warnings = () if swept is None else (swept,)
    task = BounceTask(solver=solver, damping=damping, monitor=monitor)
    reports: list[Any] = []
    errors: list[str | None] = []
    with Runner(workers=workers, scheduler=scheduler) as runner:
        outcomes = runner.map(task, points, progress=progress, min_parallel=2, chunk=1)
        where = runner.describe()
    for outcome in outcomes:
        reports.append(outcome.value if outcome.ok else None)
        errors.append(None if outcome.ok else _short(outcome.error))
    arguments: dict[str, Any] = {"values": {parameter: array}, "drop": drop.as_dict()}
    if body is not None:  # a kind name with the pair: the pair's preset body of that kind
        arguments["body"] = body if isinstance(body, str) else body.as_dict()
    if pair is not None:
        arguments["pair"] = pair
    if solver is not None:
        arguments["solver"] = solver.as_dict()
    if damping is not None:
        arguments["damping"] = damping.as_dict()
    arguments["runner"] = where
    from twoball._common.provenance import block

    provenance = block(base, "twoball.sweep", arguments)
    values_ = tuple(float(v) for v in array)
    return BounceSweep(parameter, values_, reports, errors, provenance, slips, warnings)


def _short(error: str | None) -> str | None:
    """``ParameterError: gap must be ...`` -> the message (the type only for other errors)."""
    if error is None:
        return None
    kind, _, text = error.partition(": ")
    return text if kind in ("ParameterError", "NumericalError") else error


@dataclass(frozen=True)
class BounceTask:
    """One drop or whole bounce, picklable for the process pool or Dask.

    Called with ``(case, drop, body, pair)``, it resolves and runs the drop
    (:func:`~twoball.modal.floor.bounce.bounce_problem`,
    :func:`~twoball.modal.floor.bounce.simulate`) with the task's solver (a
    Moreau-Jean solver's ball, step and window), damping law and monitor, and
    returns the report without its history (:meth:`BounceReport.light`, about
    0.1 MB) or provenance.
    """

    solver: Any = None
    damping: Any = None
    monitor: Any = None

    def __call__(self, item: tuple[Any, Any, Any, Any]) -> BounceReport:
        from twoball.modal.floor.bounce import bounce_problem, simulate

        case, drop, body, pair = item
        problem = bounce_problem(
            case, drop, body=body, pair=pair, damping=self.damping, **_solver_options(self.solver)
        )
        return simulate(problem, self.monitor).light()
