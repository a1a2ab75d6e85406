"""``twoball plot waterfall|pole|eigen|precursor``: figures of the solution and of the FE spectrum.

A thin layer over :func:`twoball.plot`.
"""

from __future__ import annotations

import argparse
from typing import Any

import twoball
from twoball._common import choices as _choices
from twoball._common.errors import ParameterError
from twoball.cli.case_options import (
    add_case_options,
    apply_limits,
    case_from_options,
    first_case_option,
)
from twoball.cli.console import console, key_value_table, print_notes, print_warnings
from twoball.cli.contact_options import add_contact_options, body_options
from twoball.cli.mesh_options import (
    add_mesh_options,
    add_route_option,
    refuse_mesh_flags,
)
from twoball.cli.solver_options import closed_form, field_solver
from twoball.cli.values import integer, number

__all__ = ["register", "run"]


def parse_list(text: str, flag: str, valid: str, allowed: set[int] | None = None) -> list[int]:
    """Integers in the one list syntax (e.g. ``--levels 2,3`` or ``--levels 1:3``)."""
    from twoball._common.ranges import parse_values

    values = parse_values(text, flag, integer=True, valid=valid)
    if any(v < 0 for v in values) or (allowed and any(v not in allowed for v in values)):
        raise ParameterError(flag, valid, text)
    return sorted(set(int(v) for v in values))


def parse_backends(text: str) -> tuple[str, ...]:
    """``--backend``: one of fem, legendre, or both comma-separated."""
    names = tuple(dict.fromkeys(p.strip() for p in str(text).split(",")))
    if not names or any(n not in _choices.FIELD_BACKENDS for n in names):
        raise ParameterError("backends", "fem, legendre or fem,legendre", text)
    return names


def _plot_solver(args: argparse.Namespace) -> Any:
    """The plot's solver: none for ``eigen``, the closed form for ``precursor``, else the
    fields' (:func:`~twoball.cli.solver_options.field_solver`)."""
    if args.kind == "eigen":
        why = "left out with kind eigen (use --levels, --orders)"
        for name in ("t_end", "sigma", "recontact", "route"):
            if getattr(args, name, None) is not None:
                raise ParameterError(name, why, getattr(args, name))
        return None
    if args.kind == "precursor":
        refuse_mesh_flags(args, "with kind precursor (the closed form only)")
        if getattr(args, "route", None) is not None:
            valid = "left out with kind precursor (the closed form)"
            raise ParameterError("route", valid, args.route)
        return closed_form(args)
    return field_solver(args)


def run(args: argparse.Namespace) -> int:
    """Run ``twoball plot``: :func:`twoball.plot` with the options."""
    from twoball._common.progress import Reporter

    levels = None
    if args.levels is not None:
        levels = parse_list(args.levels, "levels", "comma-separated levels >= 0, e.g. 1,2")
    orders = None
    if args.orders is not None:
        orders = parse_list(args.orders, "orders", "comma-separated orders 1 to 4", {1, 2, 3, 4})
    if args.kind == "eigen":  # no case: every case option given is refused by its flag
        refuse_mesh_flags(args, "with kind eigen (use --levels, --orders)")
        apply_limits(args)
        given = first_case_option(args)
        if given is not None:
            valid = "left out with kind eigen (use --levels, --orders)"
            raise ParameterError(given[0], valid, given[1])
        case = None
        steps = len(levels or (1, 2, 3)) * len(orders or (1, 2)) + 1
    else:
        case = case_from_options(args)
        steps = 2
    solver = _plot_solver(args)
    with Reporter(f"plot {args.kind}", total=steps) as progress:
        result = twoball.plot(
            args.kind,
            args.out,
            case,
            solver=solver,
            body=body_options(args),
            figure=twoball.PlotOptions(
                dpi=args.dpi,
                instants=args.instants,
                levels=levels,
                orders=orders,
                max_degree=args.max_degree,
                backends=None if args.backend is None else parse_backends(args.backend),
            ),
            progress=progress,
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
        "pole: u, u_t, u_tt of the pole against time with lift-off (and the difference "
        "finite elements - closed form); eigen: FE eigenvalue errors against l(l+1) per "
        "level and order.  The suffix of --out chooses the format (.pdf, .svg, .eps, .png, ...)."
    )
    parser.add_argument("kind", metavar="KIND", help="waterfall, pole, eigen or precursor")
    add_case_options(parser)
    add_mesh_options(parser, _choices.SPHERE_KINDS, initial=True, geometry=True)
    # None when not given: the API fills in the defaults and refuses what the kind does not use
    parser.set_defaults(initial=None)
    add_route_option(parser)
    parser.add_argument(
        "--backend", help="solvers drawn: fem, legendre or both (default fem,legendre)"
    )
    parser.add_argument(
        "--instants",
        type=integer,
        help=f"curves of the waterfall (default {_choices.WATERFALL_INSTANTS})",
    )
    parser.add_argument("--levels", help="eigen: mesh levels (default 1,2,3)")
    parser.add_argument("--orders", help="eigen: element orders (default 1,2)")
    parser.add_argument(
        "--max-degree", type=integer, help="eigen: largest degree l (default: half the unknowns)"
    )
    parser.add_argument(
        "--out",
        required=True,
        metavar="FILE",
        help="output figure; the suffix chooses the format: .pdf, .svg, .eps, .png, ...",
    )
    parser.add_argument(
        "--dpi",
        type=number,
        help=f"resolution of raster formats (.png, ...) in dots per inch, "
        f"50 to 1200 (default {_choices.DPI})",
    )
    add_contact_options(
        parser, "pole: m1/m2 in (0, 100], the cap and the body's path with every event"
    )
    parser.set_defaults(run=run)
