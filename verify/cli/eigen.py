"""``twoball eigen``: finite-element eigenvalues beside the exact l (l + 1)."""

from __future__ import annotations

import argparse

from rich.table import Table
from twoball.fem_membrane.eigen import eigen_table
from twoball.verify.cli.console import console, print_json
from twoball.verify.cli.fem_options import VALID_RANGES, add_mesh_options

__all__ = ["VALID_RANGES", "register", "run"]


def run(args: argparse.Namespace) -> int:
    """Run ``twoball eigen``."""
    from twoball.budget import check, fem_dofs, fem_estimate, options

    dofs = fem_dofs(args.mesh, args.level, args.elements, args.order)  # refuse absurd meshes
    size = options(level=args.level, elements=args.elements, order=args.order)
    check(size, fem_estimate(dofs, 30, "krylov"))
    rows = eigen_table(
        mesh=args.mesh, level=args.level, elements=args.elements, order=args.order, count=args.count
    )
    if args.json:
        print_json(rows)
        return 0
    if args.mesh == "axisym":
        size = f"{400 if args.elements is None else args.elements} elements"
    else:
        size = f"level {3 if args.level is None else args.level}"
    table = Table(title=f"Eigenvalues of -Laplace-Beltrami: {args.mesh}, P{args.order}, {size}")
    for name in ("#", "l", "lambda (FE)", "l(l+1)", "rel. error", "cluster", "expected"):
        table.add_column(name, justify="right")
    for r in rows:
        table.add_row(
            str(r["index"]),
            str(r["l"]),
            f"{r['value']:.10g}",
            f"{r['exact']:g}",
            f"{r['relative_error']:.3e}",
            str(r["multiplicity"]),
            str(r["expected_multiplicity"]),
        )
    console().print(table)
    return 0


def register(parser: argparse.ArgumentParser) -> None:
    """The options of ``twoball eigen``."""
    add_mesh_options(parser)
    parser.add_argument(
        "--count", type=int, default=25, help="nonzero eigenvalues listed (default 25)"
    )
    parser.add_argument("--json", action="store_true", help="print a JSON list")
    parser.set_defaults(run=run)
