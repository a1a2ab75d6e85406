"""``twoball eigen``: FE eigenvalues beside the exact l (l + 1), by :func:`twoball.fem.eigen`;
with ``--ball shell`` the thin shell's two branches beside their closed form
(:func:`twoball.fem.shell_eigen`)."""

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
    from twoball.cli.shell import check_ball_kind, refuse_shell_eigen_flags

    if check_ball_kind(args) == "shell":
        return run_shell(args)
    refuse_shell_eigen_flags(args)
    mesh = mesh_options(args)
    membrane = "paper" if args.membrane is None else args.membrane
    with Reporter("eigen", delay=QUICK) as progress:
        count = 25 if args.count is None else args.count
        rows = twoball.fem.eigen(mesh, count=count, membrane=membrane, progress=progress)
    spec = twoball.MeshOptions() if mesh is None else mesh
    pressurised = twoball.Membrane.of(membrane).pressurised
    if args.json:
        arguments = {"mesh": spec.as_dict(), "count": count}
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


def run_shell(args: argparse.Namespace) -> int:
    """``twoball eigen --ball shell``: both branches of the shell beside the closed form."""
    from rich.table import Table

    import twoball
    from twoball._common.progress import QUICK, Reporter
    from twoball._common.provenance import attach, block
    from twoball.cli.shell import shell_eigen_arguments

    arguments = shell_eigen_arguments(args)
    with Reporter("eigen", delay=QUICK) as progress:
        rows = twoball.fem.shell_eigen(**arguments, progress=progress)
    if args.json:
        shown = {k: (v.as_dict() if hasattr(v, "as_dict") else v) for k, v in arguments.items()}
        print_json(attach(rows, block(arguments.get("case"), "twoball.fem.shell_eigen", shown)))
        return 0
    physical = "frequency_hz" in rows[0]
    table = Table(title=f"Axisymmetric spectrum of the shell ({arguments['backend']})")
    names = ["n", "branch", "Omega", "closed form", "rel. error"]
    if physical:
        names += ["f [Hz]"]
    for name in names:
        table.add_column(name, justify="right")
    for r in rows:
        cells = [
            str(r["degree"]),
            "lower" if r["branch"] == 1 else "upper",
            "-" if r["value"] is None else f"{r['value']:.10g}",
            f"{r['exact']:.10g}",
            "-" if r["relative_error"] is None else f"{r['relative_error']:.2e}",
        ]
        if physical:
            cells.append("-" if r["frequency_hz"] is None else f"{r['frequency_hz']:.6g}")
        table.add_row(*cells)
    table.caption = "Omega = omega R sqrt(rho_s / C); n = 1 lower is the rigid translation"
    console().print(table)
    return 0


def register(parser: argparse.ArgumentParser) -> None:
    """The options of ``twoball eigen``."""
    from twoball.cli.shell import add_ball_option, add_shell_eigen_options

    add_mesh_options(parser, geometry=True)
    parser.add_argument(
        "--count",
        type=integer,
        default=None,
        help="nonzero eigenvalues listed (default 25); --ball shell: the highest degree "
        "(default 10; 2 count + 1 rows)",
    )
    add_ball_option(parser)
    add_shell_eigen_options(parser)
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
