"""The ``twoball`` command line: SI units in and out, one-line errors, exit status 2."""

from __future__ import annotations

import argparse
import json
import sys
from collections.abc import Sequence
from typing import Any, NoReturn

from modal.errors import NumericalError, ParameterError
from modal.report import LiftoffReport, legendre_liftoff

from .case_options import add_case_options, case_from_options
from .sweeps import SWEEP_PARAMETERS, parse_range, run_sweep, sweep_cases

EXIT_USAGE = 2
EXIT_NUMERICAL = 3


class _Parser(argparse.ArgumentParser):
    """ArgumentParser whose errors are one line (no usage block) and exit status 2."""

    def error(self, message: str) -> NoReturn:
        _fail(message)


def _fail(message: str, status: int = EXIT_USAGE) -> NoReturn:
    sys.stderr.write(f"twoball: error: {message}\n")
    raise SystemExit(status)


def _fmt(value: float | None, scale: float = 1.0, digits: int = 4) -> str:
    return "-" if value is None else f"{value * scale:.{digits}f}"


def _print_liftoff(report: LiftoffReport) -> None:
    from rich.console import Console
    from rich.table import Table

    case = report.case
    table = Table(
        title=f"Lift-off ({report.backend}, sigma={report.sigma}, re-contact={report.recontact})"
    )
    table.add_column("quantity")
    table.add_column("value", justify="right")
    rows = [
        ("R [m]", f"{case.radius:g}"),
        ("c [1/s]", f"{case.wave_speed:g}"),
        ("|v0| [m/s]", f"{case.v0:g}"),
        ("phi_a [rad]", f"{case.phi_a:.6f}"),
        ("D", f"{case.damping:g}"),
        ("N", f"{case.modes}"),
        ("gamma = g/(R c^2)", f"{case.gamma:.4e}"),
        ("lifted", "yes" if report.result.lifted else "no"),
        ("t_l [ms]", _fmt(report.t_liftoff_s, 1e3)),
        ("v_l [m/s]", _fmt(report.v_liftoff_m_s)),
        ("v_l / |v0|", _fmt(report.ratio)),
        ("rejected candidates", str(len(report.result.rejected))),
    ]
    for key, value in report.extra.items():
        if isinstance(value, (int, float, str)):
            rows.append((key, str(value)))
    for name, value in rows:
        table.add_row(name, value)
    Console(markup=False, highlight=False).print(table)


def _print_sweep(parameter: str, reports: list[LiftoffReport]) -> None:
    from rich.console import Console
    from rich.table import Table

    field = SWEEP_PARAMETERS[parameter]
    table = Table(title=f"Sweep of {parameter} ({len(reports)} values)")
    for name in (parameter, "phi_a [rad]", "lifted", "t_l [ms]", "v_l [m/s]", "v_l/|v0|"):
        table.add_column(name, justify="right")
    for r in reports:
        table.add_row(
            f"{getattr(r.case, field):g}",
            f"{r.case.phi_a:.5f}",
            "yes" if r.result.lifted else "no",
            _fmt(r.t_liftoff_s, 1e3),
            _fmt(r.v_liftoff_m_s),
            _fmt(r.ratio),
        )
    Console(markup=False, highlight=False).print(table)


def _cmd_liftoff(args: argparse.Namespace) -> int:
    case = case_from_options(args)
    report = legendre_liftoff(case, args.sigma, args.recontact, args.t_end)
    if args.json:
        print(json.dumps(report.as_dict(), indent=2))
    else:
        _print_liftoff(report)
    return 0


def _cmd_sweep(args: argparse.Namespace) -> int:
    base = case_from_options(args)
    values = parse_range(args.values)
    cases = sweep_cases(base, args.param, values)

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
        print(json.dumps([r.as_dict() for r in reports], indent=2))
    else:
        _print_sweep(args.param, reports)
    return 0


def build_parser() -> argparse.ArgumentParser:
    """The ``twoball`` argument parser (subcommands: liftoff, sweep, icm)."""
    parser = _Parser(
        prog="twoball",
        description="Lift-off of a light body from a vibrating spherical membrane "
        "(two-ball bounce): closed-form Legendre series and finite elements.",
    )
    sub = parser.add_subparsers(dest="command", required=True, parser_class=_Parser)

    liftoff = sub.add_parser("liftoff", help="lift-off time and velocity for one case")
    add_case_options(liftoff)
    liftoff.add_argument("--json", action="store_true", help="print one JSON object")
    liftoff.set_defaults(run=_cmd_liftoff)

    sweep = sub.add_parser("sweep", help="lift-off over a range of one parameter")
    sweep.add_argument("--param", required=True, choices=tuple(SWEEP_PARAMETERS))
    sweep.add_argument("--values", required=True, metavar="START:STOP:COUNT")
    add_case_options(sweep)
    sweep.add_argument("--json", action="store_true", help="print a JSON list")
    sweep.set_defaults(run=_cmd_sweep)
    return parser


def main(argv: Sequence[str] | None = None) -> int:
    """Entry point of the ``twoball`` console script."""
    parser = build_parser()
    args = parser.parse_args(argv)
    try:
        return int(args.run(args))
    except ParameterError as error:
        _fail(str(error))
    except NumericalError as error:
        _fail(f"numerical trouble: {error}", EXIT_NUMERICAL)


def _jsonable(value: Any) -> Any:  # pragma: no cover - helper for subcommands
    return value


if __name__ == "__main__":
    raise SystemExit(main())
