"""``twoball sweep``: the closed-form lift-off over one parameter or a grid of two."""

from __future__ import annotations

import argparse
import math

from rich.table import Table
from twoball.modal.report import t_end_dimensionless
from twoball.verify.cli.case_options import add_case_options, case_from_options
from twoball.verify.cli.console import console, number, print_json
from twoball.verify.sweeps.parallel import MIN_PARALLEL_ITEMS, Runner, check_workers
from twoball.verify.sweeps.parallel import VALID_RANGES as PARALLEL_RANGES
from twoball.verify.sweeps.sweeps import (
    SWEEP_PARAMETERS,
    SweepGrid,
    SweepPoint,
    SweepSolver,
    check_plot_path,
    make_grid,
    plot_sweep,
    run_sweep,
)

from twoball.budget import check_sweep

VALID_RANGES = dict(PARALLEL_RANGES)
#: Sweeps at least this long show a progress bar (on stderr, never with --json).
PROGRESS_FROM = 50


def print_sweep(grid: SweepGrid, points: list[SweepPoint]) -> None:
    """Print one row per grid point (an ``error`` column appears only if a point failed)."""
    fields = [SWEEP_PARAMETERS[p] for p in grid.parameters]
    shape = " x ".join(str(n) for n in grid.shape)
    title = f"Sweep of {' x '.join(grid.parameters)} ({shape} values)"
    table = Table(title=title)
    columns = [*grid.parameters, "phi_a [rad]", "lifted", "t_l [ms]", "v_l [m/s]", "v_l/|v0|"]
    failed = any(p.error for p in points)
    if failed:
        columns.append("error")
    for name in columns:
        table.add_column(name, justify="left" if name == "error" else "right")
    for p in points:
        r = p.report
        cells = [f"{getattr(p.case, f):g}" for f in fields]
        cells.append(f"{p.case.phi_a:.5f}")
        if r is None:
            cells += ["error", "-", "-", "-"]
        else:
            cells += [
                "yes" if r.result.lifted else "no",
                number(r.t_liftoff_s, 1e3),
                number(r.v_liftoff_m_s),
                number(r.ratio),
            ]
        if failed:
            cells.append(p.error or "")
        table.add_row(*cells)
    console(wide=failed).print(table)


def run(args: argparse.Namespace) -> int:
    """Run ``twoball sweep``."""
    base = case_from_options(args)  # first: it sets the resource budget
    grid = make_grid(args.param, args.values)
    workers = check_workers(args.workers)
    plot = None if args.plot is None else check_plot_path(args.plot)
    modes = (
        int(max(grid.values[grid.parameters.index("modes")]))
        if "modes" in grid.parameters
        else base.modes
    )
    check_sweep(math.prod(grid.shape), modes, t_end_dimensionless(base, args.t_end), args.workers)
    cases = grid.cases(base)
    solver = SweepSolver(args.sigma, args.recontact, args.t_end)
    if len(cases) < MIN_PARALLEL_ITEMS:
        workers = 1  # would run in process anyway; do not start a pool
    with Runner(workers, args.scheduler) as runner:
        if args.json or len(cases) < PROGRESS_FROM:
            points = run_sweep(cases, solver, runner=runner, indices=grid.indices())
        else:
            from rich.progress import Progress

            label = f"sweep {' x '.join(grid.parameters)} [{runner.describe()}]"
            err = console_err()
            with Progress(console=err, transient=True, disable=not err.is_terminal) as bar:
                task = bar.add_task(label, total=len(cases))
                points = run_sweep(
                    cases,
                    solver,
                    lambda k: bar.update(task, completed=k),
                    runner=runner,
                    indices=grid.indices(),
                )
    flagged = [p for p in points if p.report is not None and p.report.warnings]
    if flagged:
        from twoball.verify.cli.main import warn

        warn(
            f"{len(flagged)} of {len(points)} points carry warnings (see --json), the first "
            f"at {flagged[0].index}: {flagged[0].report.warnings[0]}"
        )
    if plot is not None:
        plot_sweep(grid, points, plot)
    if args.json:
        print_json([p.as_dict() for p in points])
    else:
        print_sweep(grid, points)
        if plot is not None:
            console().print(f"plot written to {plot}")
    return 0


def console_err():
    """A console on standard error, for progress bars."""
    from rich.console import Console

    return Console(stderr=True)


def register(parser: argparse.ArgumentParser) -> None:
    """The options of ``twoball sweep``."""
    parser.description = (
        "Closed-form lift-off over a range of one parameter, or over a grid of "
        "two (give --param and --values twice, in the same order; the first parameter "
        "varies slowest).  v0, wave-speed and radius re-derive phi_a from eq. (3.7).  "
        "A point whose solve fails is reported with its parameters and an error."
    )
    parser.add_argument(
        "--param",
        required=True,
        action="append",
        choices=tuple(SWEEP_PARAMETERS),
        help="swept parameter; give twice for a 2-D grid",
    )
    parser.add_argument(
        "--values",
        required=True,
        action="append",
        metavar="START:STOP:COUNT",
        help="values of the matching --param (same order)",
    )
    parser.add_argument(
        "--plot",
        metavar="FILE.png",
        help="also write a PNG: v_l/|v0| and t_l against the parameter (1-D) "
        "or as two heat maps (2-D)",
    )
    run_group = parser.add_argument_group("execution")
    run_group.add_argument(
        "--workers",
        type=int,
        metavar="N",
        help="local worker processes (default: all cores; 1 = strictly serial)",
    )
    run_group.add_argument(
        "--scheduler",
        metavar="ADDRESS",
        help="run on an existing dask.distributed scheduler (needs the 'dask' extra)",
    )
    add_case_options(parser)
    parser.add_argument("--json", action="store_true", help="print a JSON list")
    parser.set_defaults(run=run)
