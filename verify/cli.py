"""The ``twoball`` command line: SI units in and out, one-line errors, exit status 2."""

from __future__ import annotations

import argparse
import json
import sys
from collections.abc import Sequence
from typing import NoReturn

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


def _cmd_icm(args: argparse.Namespace) -> int:
    from dataclasses import asdict

    from rich.console import Console
    from rich.table import Table

    from modal import icm

    console = Console(markup=False, highlight=False, width=max(Console().width, 120))
    if args.table1:
        checks = icm.table1_check()
        if args.json:
            rows = [
                {
                    **asdict(c.row),
                    "ours_v1": c.v1,
                    "ours_v2": c.v2,
                    "ours_v1_rounded": c.v1_rounded,
                    "ours_v2_rounded": c.v2_rounded,
                    "v1_differs": c.v1_differs,
                    "v2_differs": c.v2_differs,
                }
                for c in checks
            ]
            print(json.dumps(rows, indent=2))
            return 0
        table = Table(title="Table 1: ICM (eq. (2.6)) recomputed beside the printed values")
        for name in (
            "lower",
            "upper",
            "mu",
            "e2",
            "e12",
            "v1 printed",
            "v1 ours",
            "",
            "v2 printed",
            "v2 ours",
            " ",
        ):
            table.add_column(name, justify="right")
        for c in checks:
            r = c.row
            table.add_row(
                r.lower,
                r.upper,
                f"{r.mu:g}",
                f"{r.e2:g}",
                f"{r.e12:g}",
                f"{r.icm_v1:g}",
                f"{c.v1:.3f}",
                "DIFFERS" if c.v1_differs else "ok",
                f"{r.icm_v2:g}",
                f"{c.v2:.3f}",
                "DIFFERS" if c.v2_differs else "ok",
            )
        console.print(table)
        console.print("Ratios are v/|v0|; 'ok' means equal after rounding to the printed digits.")
        return 0
    missing = [
        f for f, v in (("--mu", args.mu), ("--e2", args.e2), ("--e12", args.e12)) if v is None
    ]
    if missing:
        raise ParameterError(missing[0], "given (or use --table1)")
    if (args.dx is None) != (args.drop_height is None) and args.dx not in (None, 0.0):
        raise ParameterError("--drop-height", "given with --dx")
    result = icm.icm(
        args.mu,
        args.e2,
        args.e12,
        dx=0.0 if args.dx is None else args.dx,
        drop_height=1.0 if args.drop_height is None else args.drop_height,
    )
    if args.json:
        print(json.dumps(asdict(result), indent=2))
        return 0
    table = Table(title="Independent collision model (§2)")
    table.add_column("quantity")
    table.add_column("value", justify="right")
    for name, value in (
        ("impact velocity v0 [m/s]", result.v0),
        ("lower-ball rebound u0 [m/s] (2.1)", result.u0),
        ("delay to second impact dt [s] (2.2)", result.dt),
        ("upper ball after v1 [m/s] (2.5)", result.v1),
        ("lower ball after v2 [m/s] (2.5)", result.v2),
        ("v1 / |v0|", result.v1_ratio),
        ("v2 / |v0|", result.v2_ratio),
    ):
        table.add_row(name, f"{value:.6g}")
    console.print(table)
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

    collision = sub.add_parser("icm", help="independent collision model (§2), Table 1")
    collision.add_argument("--mu", type=float, help="mass ratio m1/m2 >= 0")
    collision.add_argument("--e2", type=float, help="restitution lower ball-floor in [0, 1]")
    collision.add_argument("--e12", type=float, help="restitution between the balls in [0, 1]")
    collision.add_argument("--dx", type=float, help="initial separation [m] (default 0)")
    collision.add_argument("--drop-height", type=float, help="drop height x2 - r2 [m] (default 1)")
    collision.add_argument(
        "--table1", action="store_true", help="recompute Table 1 beside the printed values"
    )
    collision.add_argument("--json", action="store_true", help="print JSON")
    collision.set_defaults(run=_cmd_icm)
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


if __name__ == "__main__":
    raise SystemExit(main())
