"""``twoball export``: the ball's fields over time as XDMF + HDF5, PVD + VTU or one VTU (SI).

A thin layer over :func:`twoball.export`.
"""

from __future__ import annotations

import argparse

from twoball import _lookup
from twoball._common import choices as _choices
from twoball.cli.case_options import add_case_options, case_from_options
from twoball.cli.console import console, key_value_table, number, print_notes, print_warnings
from twoball.cli.contact_options import add_contact_options, body_options
from twoball.cli.mesh_options import (
    add_mesh_options,
    add_route_option,
)
from twoball.cli.solver_options import field_solver
from twoball.cli.values import integer

__all__ = ["add_backend_option", "add_frame_options", "register", "run"]


def add_backend_option(parser: argparse.ArgumentParser) -> None:
    """``--backend`` of the field commands (export, render)."""
    parser.add_argument(
        "--backend",
        default="fem",
        help="which solver gives u, u_t, u_tt and the lift-off: fem (default) or legendre",
    )


def add_frame_options(parser: argparse.ArgumentParser, default: int) -> None:
    """``--frames K`` or ``--times T1,T2,...`` (mutually exclusive)."""
    group = parser.add_mutually_exclusive_group()
    group.add_argument(
        "--frames",
        type=integer,
        metavar="K",
        help=f"K frames evenly spaced over [0, t_end] (default {default}; plus the lift-off)",
    )
    group.add_argument(
        "--times", metavar="LIST", help="frame times in seconds: t1,t2,... or START:STOP:COUNT"
    )


def run(args: argparse.Namespace) -> int:
    """Run ``twoball export``."""
    import twoball
    from twoball._common.progress import Reporter

    frames = args.frames if args.times is None else _lookup.parse_times(args.times)
    if args.format is not None:  # the API takes the suffix of --out; --format must agree
        from twoball._fields import check_export_format

        check_export_format(args.out, args.format)
    solver = field_solver(args)
    with Reporter("export") as progress:
        result = twoball.export(
            args.out,
            case_from_options(args),
            backend=args.backend,
            solver=solver,
            body=body_options(args),
            frames=frames,
            progress=progress,
        )
    files, report, selected = result.files, result.report, result.times_s
    print_notes(report.notes)
    print_warnings(result.warnings)
    rows = [
        ("file", str(files[0])),
        ("beside it", f"{len(files) - 1} file(s)" if len(files) > 1 else "-"),
        ("format", result.format),
        ("frames", str(len(selected))),
        ("times [ms]", f"{selected[0] * 1e3:.3f} .. {selected[-1] * 1e3:.3f}"),
        ("nodes", str(result.nodes)),
        ("cells", f"{result.cells} {result.cell_type}"),
        ("point data", ", ".join(result.point_data)),
        (f"t_l [ms] ({args.backend})", number(report.t_liftoff_s, 1e3)),
        (f"v_l [m/s] ({args.backend})", number(report.v_liftoff_m_s)),
        ("phi_a from", str(report.case.phi_a_source)),
    ]
    console().print(key_value_table("Exported fields (SI)", rows))
    return 0


def register(parser: argparse.ArgumentParser) -> None:
    """The options of ``twoball export``."""
    parser.description = (
        "Write the mesh (m) with point data per frame: u, u_t, u_tt (SI), the "
        "displacement vector u n, and u_fem, u_legendre, u_diff; lift-off in field data."
    )
    add_case_options(parser)
    add_mesh_options(parser, _choices.SPHERE_KINDS, initial=True, geometry=True)
    parser.set_defaults(initial=None)  # the API's default (projection)
    add_route_option(parser)
    add_backend_option(parser)
    parser.add_argument(
        "--format",
        help="xdmf (with NAME.h5), pvd (frames in NAME_frames-ID/) or vtu (one frame); "
        "default: from the suffix of --out (" + ", ".join(_choices.FORMATS) + ")",
    )
    add_frame_options(parser, _choices.DEFAULT_FRAMES)
    parser.add_argument("--out", required=True, metavar="PATH", help="main output file")
    add_contact_options(
        parser, "m1/m2 in (0, 100]: the membrane coupled to the body, its path in field data"
    )
    parser.set_defaults(run=run)
