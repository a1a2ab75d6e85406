"""``twoball sweep``: the closed-form lift-off over one parameter or a grid of two."""

from __future__ import annotations

import argparse

from twoball._common.errors import ParameterError
from twoball._common.provenance import attach
from twoball.cli.case_options import add_case_options, case_from_options
from twoball.cli.console import (
    Table,
    console,
    number,
    print_json,
    print_notes,
    print_warnings,
)
from twoball.verify.sweeps.parallel import VALID_RANGES as PARALLEL_RANGES
from twoball.verify.sweeps.parallel import check_workers
from twoball.verify.sweeps.sweeps import (
    SWEEP_PARAMETERS,
    SweepGrid,
    SweepPoint,
    check_plot_path,
    make_grid,
    plot_sweep,
)

VALID_RANGES = dict(PARALLEL_RANGES)


def print_sweep(grid: SweepGrid, points: list[SweepPoint]) -> None:
    """Print one row per grid point (an ``error`` column appears only if a point failed)."""
    fields = [SWEEP_PARAMETERS[p] for p in grid.parameters]
    shape = " x ".join(str(n) for n in grid.shape)
    title = f"Sweep of {' x '.join(grid.parameters)} ({shape} values)"
    table = Table(title=title)
    columns = [
        *grid.parameters,
        "phi_a [rad]",
        "phi_a from",
        "lifted",
        "t_l [ms]",
        "v_l [m/s]",
        "v_l/|v0|",
    ]
    failed = any(p.error for p in points)
    if failed:
        columns.append("error")
    for name in columns:
        table.add_column(name, justify="left" if name == "error" else "right")
    for p in points:
        r = p.report
        cells = [f"{getattr(p.case, f):g}" for f in fields]
        cells.append(f"{p.case.phi_a:.5f}")
        cells.append(str(p.case.phi_a_source))
        if r is None:
            cells += ["error", "-", "-", "-"]
        else:
            cells += [
                "yes" if r.result.lifted else "no",  # ContactReport.result too
                number(r.t_liftoff_s, 1e3),
                number(r.v_liftoff_m_s),
                number(r.ratio),
            ]
        if failed:
            cells.append(p.error or "")
        table.add_row(*cells)
    console(wide=failed).print(table)


def run(args: argparse.Namespace) -> int:
    """Run ``twoball sweep``: :func:`twoball.sweep` with the options' grid and case."""
    from twoball._sweep import sweep

    grid = make_grid(args.param, args.values)
    workers = check_workers(args.workers) if not args.scheduler else args.workers
    for name in grid.parameters:  # the swept parameter's base value would be replaced
        field = SWEEP_PARAMETERS[name]
        if getattr(args, field, None) is not None:
            raise ParameterError(
                field, f"left out when --param {name} is swept", getattr(args, field)
            )
    plot = None if args.plot is None else check_plot_path(args.plot)
    base = case_from_options(args)
    values = dict(zip(grid.parameters, grid.values, strict=True))
    options = {
        "sigma": args.sigma,
        "recontact": args.recontact,
        "t_end": args.t_end,
        "workers": workers,
        "scheduler": args.scheduler,
    }
    if args.contact_radius is not None:
        options["contact_radius"] = args.contact_radius
    from twoball._common.progress import QUICK, Reporter

    total = 1
    for n in grid.shape:
        total *= n
    with Reporter(f"sweep {' x '.join(grid.parameters)}", total=total, delay=QUICK) as bar:
        result = sweep(values, base, progress=bar.update, **options)
    points = result.points
    print_notes(sweep_notes(points))
    print_warnings(sweep_warnings(points))
    if plot is not None:
        plot_sweep(grid, points, plot)
    if args.json:
        print_json(attach([p.as_dict() for p in points], result.provenance))
    else:
        print_sweep(grid, points)
        if plot is not None:
            console().print(f"plot written to {plot}")
    return 0


def sweep_notes(points: list[SweepPoint]) -> list[str]:
    """One note for the whole sweep: at how many points eq. (3.7) replaced a preset's phi_a."""
    notes = [p.report.notes[0] for p in points if p.report is not None and p.report.notes]
    if len(notes) <= 1:
        return notes
    why = notes[0].split("; ", 1)[-1]
    return [f"phi_a from eq. (3.7) at {len(notes)} of {len(points)} points; {why}"]


def sweep_warnings(points: list[SweepPoint]) -> list[str]:
    """One warning for the whole sweep: how many points carry accuracy warnings, the first."""
    flagged = [p for p in points if p.report is not None and p.report.warnings]
    if not flagged:
        return []
    return [
        f"{len(flagged)} of {len(points)} points carry warnings (see --json), the first "
        f"at {flagged[0].index}: {flagged[0].report.warnings[0]}"
    ]


def register(parser: argparse.ArgumentParser) -> None:
    """The options of ``twoball sweep``."""
    parser.description = (
        "Closed-form lift-off over a range of one parameter, or over a grid of "
        "two (give --param and --values twice, in the same order; the first parameter "
        "varies slowest).  v0, wave-speed and radius re-apply the phi_a rule: the "
        "preset's measured angle at its own R, c, |v0|, eq. (3.7) elsewhere.  "
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
        metavar="LIST",
        help="values of the matching --param (same order): START:STOP:COUNT or v1,v2,...",
    )
    parser.add_argument(
        "--plot",
        metavar="FILE",
        help="also write a figure (.png, .pdf, .svg, ... by the suffix): v_l/|v0| and t_l "
        "against the parameter (1-D) or as two heat maps (2-D)",
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
    parser.add_argument(
        "--contact-radius",
        type=float,
        metavar="A",
        help="with --param mass-ratio: contact cap radius a [m] (default R/10)",
    )
    parser.add_argument(
        "--json",
        action="store_true",
        help='print JSON: {"results": [one object per point], "provenance": {...}}',
    )
    parser.set_defaults(run=run)
