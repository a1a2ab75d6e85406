"""``twoball icm``: the independent collision model (§2) and Table 1."""

from __future__ import annotations

import argparse
from dataclasses import asdict

import twoball
from twoball._common.errors import ParameterError
from twoball._common.provenance import attach, block
from twoball.cli.console import Table, console, print_json
from twoball.cli.values import number

__all__ = ["register", "run"]


def run(args: argparse.Namespace) -> int:
    """Run ``twoball icm``."""
    out = console()
    if args.table1:
        for flag in ("mu", "e2", "e12", "dx", "drop_height"):
            if getattr(args, flag) is not None:
                raise ParameterError(
                    flag, "left out with --table1 (its rows fix them)", getattr(args, flag)
                )
        checks = twoball.table1()
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
            print_json(attach(rows, block(None, "twoball.table1")))
            return 0
        from rich import box

        table = Table(
            title="Table 1: ICM (eq. (2.6)), printed vs ours",
            box=box.SIMPLE_HEAD,
            show_edge=False,
            pad_edge=False,
            padding=(0, 1, 0, 0),
        )
        for name in ("lower", "upper", "mu", "e2", "e12", "v1\nprinted", "v1\nours"):
            table.add_column(name, justify="left" if name in ("lower", "upper") else "right")
        table.add_column("v2\nprinted", justify="right")
        table.add_column("v2\nours", justify="right")
        for column in table.columns:
            column.no_wrap = True
        differs = False
        for c in checks:
            r = c.row
            differs |= c.v1_differs or c.v2_differs
            table.add_row(
                r.lower,
                r.upper,
                f"{r.mu:g}",
                f"{r.e2:g}",
                f"{r.e12:g}",
                f"{r.icm_v1:g}",
                f"{c.v1:.3f}" + (" *" if c.v1_differs else "  "),
                f"{r.icm_v2:g}",
                f"{c.v2:.3f}" + (" *" if c.v2_differs else "  "),
            )
        out.print(table)
        out.print("Ratios v/|v0|. * DIFFERS from the printed value rounded to its digits.")
        if differs:
            out.print("Why: docs, page 'Independent collision model', 'Table 1 recomputed'.")
        return 0
    missing = [f for f, v in (("mu", args.mu), ("e2", args.e2), ("e12", args.e12)) if v is None]
    if missing:
        raise ParameterError(missing[0], "given (or use --table1)")
    if (args.dx is None) != (args.drop_height is None) and args.dx not in (None, 0.0):
        raise ParameterError("drop_height", "given with --dx")
    result = twoball.icm(
        args.mu,
        args.e2,
        args.e12,
        dx=0.0 if args.dx is None else args.dx,
        drop_height=1.0 if args.drop_height is None else args.drop_height,
    )
    if args.json:
        arguments = {"mu": args.mu, "e2": args.e2, "e12": args.e12}
        arguments |= {"dx": args.dx, "drop_height": args.drop_height}
        print_json(attach(result.as_dict(), block(None, "twoball.icm", arguments)))
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
    out.print(table)
    return 0


def register(parser: argparse.ArgumentParser) -> None:
    """The options of ``twoball icm``."""
    parser.add_argument("--mu", type=number, help="mass ratio m1/m2 >= 0")
    parser.add_argument("--e2", type=number, help="restitution lower ball-floor in [0, 1]")
    parser.add_argument("--e12", type=number, help="restitution between the balls in [0, 1]")
    parser.add_argument("--dx", type=number, help="initial separation [m] (default 0)")
    parser.add_argument("--drop-height", type=number, help="drop height x2 - r2 [m] (default 1)")
    parser.add_argument(
        "--table1", action="store_true", help="recompute Table 1 beside the printed values"
    )
    parser.add_argument(
        "--json",
        action="store_true",
        help='print JSON (an object; --table1: {"results": [rows], "provenance": {...}})',
    )
    parser.set_defaults(run=run)
