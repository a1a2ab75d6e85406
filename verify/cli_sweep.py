"""``twoball sweep``: the closed-form lift-off over a range of one parameter."""

from __future__ import annotations

import argparse

from rich.table import Table

from modal.report import LiftoffReport, legendre_liftoff

from .case_options import add_case_options, case_from_options
from .console import console, number, print_json
from .sweeps import SWEEP_PARAMETERS, parse_range, run_sweep, sweep_cases


def print_sweep(parameter: str, reports: list[LiftoffReport]) -> None:
    """Print one row per swept value."""
    field = SWEEP_PARAMETERS[parameter]
    table = Table(title=f"Sweep of {parameter} ({len(reports)} values)")
    for name in (parameter, "phi_a [rad]", "lifted", "t_l [ms]", "v_l [m/s]", "v_l/|v0|"):
        table.add_column(name, justify="right")
    for r in reports:
        table.add_row(
            f"{getattr(r.case, field):g}",
            f"{r.case.phi_a:.5f}",
            "yes" if r.result.lifted else "no",
            number(r.t_liftoff_s, 1e3),
            number(r.v_liftoff_m_s),
            number(r.ratio),
        )
    console().print(table)


def run(args: argparse.Namespace) -> int:
    """Run ``twoball sweep``."""
    base = case_from_options(args)
    cases = sweep_cases(base, args.param, parse_range(args.values))

    def solve(case):
        return legendre_liftoff(case, args.sigma, args.recontact, args.t_end)

    if args.json or len(cases) < 50:
        reports = run_sweep(cases, solve)
    else:
        from rich.progress import Progress

        with Progress(transient=True) as bar:
            task = bar.add_task(f"sweep {args.param}", total=len(cases))
            reports = run_sweep(cases, solve, lambda k: bar.update(task, completed=k))
    if args.json:
        print_json([r.as_dict() for r in reports])
    else:
        print_sweep(args.param, reports)
    return 0


def register(sub: argparse._SubParsersAction) -> argparse.ArgumentParser:
    """Add the ``sweep`` subcommand."""
    parser = sub.add_parser("sweep", help="lift-off over a range of one parameter")
    parser.add_argument("--param", required=True, choices=tuple(SWEEP_PARAMETERS))
    parser.add_argument("--values", required=True, metavar="START:STOP:COUNT")
    add_case_options(parser)
    parser.add_argument("--json", action="store_true", help="print a JSON list")
    parser.set_defaults(run=run)
    return parser
