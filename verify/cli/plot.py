"""``twoball plot waterfall|pole|eigen``: PNG figures of the solution and of the FE spectrum.

A thin layer over :func:`twoball.plot`.
"""

from __future__ import annotations

import argparse

from twoball.modal.errors import ParameterError
from twoball.verify.cli.case_options import add_case_options, case_from_options
from twoball.verify.cli.console import console, key_value_table, print_notes, print_warnings
from twoball.verify.cli.mesh_options import (
    SPHERE_KINDS,
    add_mesh_options,
    add_route_option,
    mesh_arguments,
    route_arguments,
)
from twoball.verify.cli.mesh_options import VALID_RANGES as MESH_RANGES
from twoball.verify.output.fields import BACKENDS
from twoball.verify.output.figures.waterfall import WATERFALL_INSTANTS

VALID_RANGES: dict[str, str] = {
    **MESH_RANGES,
    "--instants": "an integer >= 2",
    "--max-degree": "an integer >= 1",
}


def parse_list(text: str, flag: str, valid: str, allowed: set[int] | None = None) -> list[int]:
    """Comma-separated integers (e.g. ``--levels 2,3``)."""
    try:
        values = [int(p) for p in str(text).split(",")]
    except ValueError:
        raise ParameterError(flag, valid, text) from None
    if (
        not values
        or any(v < 0 for v in values)
        or (allowed and any(v not in allowed for v in values))
    ):
        raise ParameterError(flag, valid, text)
    return sorted(set(values))


def parse_backends(text: str) -> tuple[str, ...]:
    """``--backends``: comma-separated names among fem, legendre."""
    names = tuple(dict.fromkeys(p.strip() for p in str(text).split(",")))
    if not names or any(n not in BACKENDS for n in names):
        raise ParameterError("--backends", "a comma-separated list of fem, legendre", text)
    return names


def run(args: argparse.Namespace) -> int:
    """Run ``twoball plot``: :func:`twoball.plot` with the options."""
    from twoball.files import plot

    options = {**mesh_arguments(args), **route_arguments(args)}
    if args.kind == "eigen":
        levels = parse_list(args.levels, "--levels", "comma-separated levels >= 0, e.g. 1,2")
        orders = parse_list(args.orders, "--orders", "comma-separated orders 1 or 2", {1, 2})
        result = plot(
            "eigen", args.out, levels=levels, orders=orders, max_degree=args.max_degree, **options
        )
    else:
        result = plot(
            args.kind,
            args.out,
            case_from_options(args),
            backends=parse_backends(args.backends),
            instants=args.instants,
            sigma=args.sigma,
            recontact=args.recontact,
            t_end=args.t_end,
            **options,
        )
    rows = [("file", str(result.file)), ("plot", result.kind), *result.rows]
    if result.reports:
        case = next(iter(result.reports.values())).case
        print_notes(next(iter(result.reports.values())).notes)
        rows.append(("phi_a from", str(case.phi_a_source)))
    print_warnings(result.warnings)
    console().print(key_value_table("Plot", rows))
    return 0


def register(parser: argparse.ArgumentParser) -> None:
    """The options of ``twoball plot``."""
    parser.description = (
        "waterfall: u(phi) at 24 instants, closed form (lines) and FE nodes (dots); "
        "pole: u, u_t, u_tt of the pole against time with lift-off; eigen: FE eigenvalue "
        "errors against l(l+1) per level and order."
    )
    parser.add_argument("kind", metavar="KIND", help="waterfall, pole or eigen")
    add_case_options(parser)
    add_mesh_options(parser, SPHERE_KINDS, initial=True, files=False)
    add_route_option(parser)
    parser.add_argument(
        "--backends", default="fem,legendre", help="solvers drawn (default fem,legendre)"
    )
    parser.add_argument(
        "--instants",
        type=int,
        help=f"curves of the waterfall (default {WATERFALL_INSTANTS})",
    )
    parser.add_argument("--levels", default="1,2,3", help="eigen: mesh levels (default 1,2,3)")
    parser.add_argument("--orders", default="1,2", help="eigen: element orders (default 1,2)")
    parser.add_argument(
        "--max-degree", type=int, help="eigen: largest degree l (default: half the unknowns)"
    )
    parser.add_argument("--out", required=True, metavar="FILE.png", help="output PNG")
    parser.set_defaults(run=run)
