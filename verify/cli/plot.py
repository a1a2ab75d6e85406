"""``twoball plot waterfall|pole|eigen``: PNG figures of the solution and of the FE spectrum."""

from __future__ import annotations

import argparse

from twoball.fem_membrane.export import check_output_path
from twoball.modal.errors import ParameterError
from twoball.verify.cli.case_options import add_case_options
from twoball.verify.cli.console import console, key_value_table
from twoball.verify.cli.export import add_mesh_options, mesh_notes, model_from_options
from twoball.verify.cli.main import warn
from twoball.verify.output.fields import BACKENDS, MAX_FRAMES
from twoball.verify.output.plots import (
    PLOT_KINDS,
    WATERFALL_INSTANTS,
    eigen_figure,
    eigen_table,
    pole_figure,
    save_figure,
    waterfall_figure,
)

VALID_RANGES: dict[str, str] = {
    "--instants": f"an integer in [2, {MAX_FRAMES}]",
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
    """Run ``twoball plot``."""
    if args.kind not in PLOT_KINDS:
        raise ParameterError("plot kind", "one of " + ", ".join(PLOT_KINDS), args.kind)
    if not str(args.out).lower().endswith(".png"):
        raise ParameterError("--out", "a file name ending in .png", args.out)
    out = check_output_path(args.out)
    rows: list[tuple[str, str]] = [("file", str(out)), ("plot", args.kind)]
    if args.kind == "eigen":
        levels = parse_list(args.levels, "--levels", "comma-separated levels >= 0, e.g. 1,2")
        orders = parse_list(args.orders, "--orders", "comma-separated orders 1 or 2", {1, 2})
        tables = [
            eigen_table(level, order, args.max_degree) for order in orders for level in levels
        ]
        figure = eigen_figure(tables)
        rows += [(t.label, f"l <= {t.degrees[-1]}, worst {t.errors[1:].max():.2e}") for t in tables]
    else:
        if isinstance(args.instants, int) and not 2 <= args.instants <= MAX_FRAMES:
            raise ParameterError("--instants", VALID_RANGES["--instants"], args.instants)
        model = model_from_options(args, parse_backends(args.backends))
        for backend in model.backends.values():
            notes = mesh_notes(args, model.case, backend.report.backend)
            for text in backend.report.warnings + tuple(notes):
                warn(f"{backend.report.backend}: {text}")
        if args.kind == "waterfall":
            figure = waterfall_figure(model, args.instants)
        else:
            figure = pole_figure(model)
        for name, backend in model.backends.items():
            report = backend.report
            if report.result.lifted:
                text = f"{report.t_liftoff_s * 1e3:.3f} ms, {report.v_liftoff_m_s:.4f} m/s"
            else:
                text = "no lift-off"
            rows.append((f"lift-off ({name})", text))
    save_figure(figure, out)
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
    add_mesh_options(parser, backend_choice=False)
    parser.add_argument(
        "--backends", default="fem,legendre", help="solvers drawn (default fem,legendre)"
    )
    parser.add_argument(
        "--instants",
        type=int,
        default=WATERFALL_INSTANTS,
        help=f"curves of the waterfall (default {WATERFALL_INSTANTS})",
    )
    parser.add_argument("--levels", default="1,2,3", help="eigen: mesh levels (default 1,2,3)")
    parser.add_argument("--orders", default="1,2", help="eigen: element orders (default 1,2)")
    parser.add_argument(
        "--max-degree", type=int, help="eigen: largest degree l (default: half the unknowns)"
    )
    parser.add_argument("--out", required=True, metavar="FILE.png", help="output PNG")
    parser.set_defaults(run=run)
