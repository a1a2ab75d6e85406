"""``twoball eigen``: FE eigenvalues beside the exact l (l + 1), by :func:`twoball.fem.eigen`."""

from __future__ import annotations

import argparse

from twoball.cli.console import console, print_json
from twoball.cli.mesh_options import VALID_RANGES as MESH_RANGES
from twoball.cli.mesh_options import add_mesh_options, mesh_arguments

VALID_RANGES = {**MESH_RANGES, "--count": "an integer >= 1"}

__all__ = ["VALID_RANGES", "register", "run"]


def run(args: argparse.Namespace) -> int:
    """Run ``twoball eigen``."""
    from rich.table import Table

    from twoball._common.progress import QUICK, Reporter
    from twoball._common.provenance import attach, block
    from twoball.fem import eigen
    from twoball.fem_membrane.options import MeshOptions

    options = mesh_arguments(args)
    with Reporter("eigen", delay=QUICK) as progress:
        rows = eigen(**options, count=args.count, progress=progress)
    if args.json:
        print_json(attach(rows, block(None, "twoball.fem.eigen", {**options, "count": args.count})))
        return 0
    spec = MeshOptions.resolve(**options)
    table = Table(title=f"Eigenvalues of -Laplace-Beltrami: {spec.label}")
    names = ("#", "l", "lambda (FE)", "l(l+1)", "rel. error", "cluster", "expected", "residual")
    for name in names:
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
            f"{r['residual']:.1e}",
        )
    if rows:
        table.caption = (
            f"residual = |K x - lambda M x| / |K x| (|M x| for lambda = 0); "
            f"M-orthonormality error max |X^T M X - I| = {rows[0]['orthonormality']:.1e}"
        )
    console().print(table)
    return 0


def register(parser: argparse.ArgumentParser) -> None:
    """The options of ``twoball eigen``."""
    add_mesh_options(parser, geometry=True)
    parser.add_argument(
        "--count", type=int, default=25, help="nonzero eigenvalues listed (default 25)"
    )
    parser.add_argument(
        "--json",
        action="store_true",
        help='print JSON: {"results": [one object per eigenvalue], "provenance": {...}}',
    )
    parser.set_defaults(run=run)
