"""``twoball eigen``: FE eigenvalues beside the exact l (l + 1), by :func:`twoball.fem.eigen`."""

from __future__ import annotations

import argparse

from twoball.cli.console import console, print_json
from twoball.cli.mesh_options import add_mesh_options, mesh_options
from twoball.cli.values import integer

__all__ = ["register", "run"]


def run(args: argparse.Namespace) -> int:
    """Run ``twoball eigen``."""
    from rich.table import Table

    import twoball
    from twoball._common.progress import QUICK, Reporter
    from twoball._common.provenance import attach, block

    mesh = mesh_options(args)
    membrane = "paper" if args.membrane is None else args.membrane
    with Reporter("eigen", delay=QUICK) as progress:
        rows = twoball.fem.eigen(mesh, count=args.count, membrane=membrane, progress=progress)
    spec = twoball.MeshOptions() if mesh is None else mesh
    pressurised = twoball.Membrane.of(membrane).pressurised
    if args.json:
        arguments = {"mesh": spec.as_dict(), "count": args.count}
        if args.membrane is not None:
            arguments["membrane"] = args.membrane
        print_json(attach(rows, block(None, "twoball.fem.eigen", arguments)))
        return 0
    operator = "-Laplace-Beltrami - 2 (pressurised)" if pressurised else "-Laplace-Beltrami"
    table = Table(title=f"Eigenvalues of {operator}: {spec.label}")
    exact = "(l-1)(l+2)" if pressurised else "l(l+1)"
    names = ("#", "l", "lambda (FE)", exact, "rel. error", "cluster", "expected", "residual")
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
        "--count", type=integer, default=25, help="nonzero eigenvalues listed (default 25)"
    )
    parser.add_argument(
        "--membrane",
        help="membrane operator: paper (K, beside l(l+1); default) or pressurised "
        "(K - 2M, beside (l-1)(l+2))",
    )
    parser.add_argument(
        "--json",
        action="store_true",
        help='print JSON: {"results": [one object per eigenvalue], "provenance": {...}}',
    )
    parser.set_defaults(run=run)
