"""``twoball export``: the ball's fields over time as XDMF + HDF5, PVD + VTU or one VTU (SI).

Also holds the mesh/backend options shared with ``twoball render`` and ``twoball plot``.
"""

from __future__ import annotations

import argparse
from collections.abc import Sequence

from twoball.fem_membrane.build import DEFAULT_LEVEL
from twoball.fem_membrane.checks import INITIAL_METHODS, check_choice, check_level, check_order
from twoball.fem_membrane.export import FORMATS, check_output_path, series_format, write_series
from twoball.modal.errors import ParameterError
from twoball.modal.parameters import Case
from twoball.verify.cli.case_options import add_case_options, case_from_options
from twoball.verify.cli.console import console, key_value_table, number
from twoball.verify.cli.main import warn
from twoball.verify.output.fields import (
    BACKENDS,
    DEFAULT_FRAMES,
    MAX_FRAMES,
    MESH_KINDS,
    BallModel,
    ball_model,
    check_frames,
    check_times,
    field_series,
    frame_times,
    liftoff_frame,
    parse_times,
    window_s,
)

from twoball.budget import check_frames as check_frames_budget

VALID_RANGES: dict[str, str] = {
    "--level": "an integer >= 0",
    "--order": "1 or 2",
    "--frames": f"an integer in [1, {MAX_FRAMES}]",
}
DEFAULT_ORDER = 2  # the finite-element defaults of twoball.fem_membrane.build / solve


def add_mesh_options(parser: argparse.ArgumentParser, backend_choice: bool = True) -> None:
    """Add ``--level``, ``--order``, ``--mesh`` and (optionally) ``--backend``."""
    group = parser.add_argument_group("finite elements")
    group.add_argument(
        "--level",
        type=int,
        default=DEFAULT_LEVEL,
        help=f"sphere mesh refinement level (default {DEFAULT_LEVEL})",
    )
    group.add_argument(
        "--order",
        type=int,
        default=DEFAULT_ORDER,
        help=f"element and geometry order, 1 or 2 (default {DEFAULT_ORDER})",
    )
    group.add_argument(
        "--mesh",
        default="sphere",
        help="icosphere (sphere) or rings of latitude with one at phi_a (ring)",
    )
    group.add_argument(
        "--initial",
        default="projection",
        help="initial displacement (3.10) in the FE space: projection (default) or interpolation",
    )
    if backend_choice:
        group.add_argument(
            "--backend",
            default="fem",
            help="which solver gives u, u_t, u_tt and the lift-off: fem (default) or legendre",
        )


def mesh_notes(args: argparse.Namespace, case: Case, backend: str) -> list[str]:
    """The mesh-resolution warning of the options' mesh (finite-element backend only)."""
    if backend != "fem":
        return []
    from twoball.fem_membrane.guards import mesh_warnings
    from twoball.modal.filters import SpectralFilter

    kind = "ring" if args.mesh == "ring" else "sphere"
    filter = SpectralFilter(args.sigma, case.modes)
    return mesh_warnings(kind, args.level, None, args.order, filter)


def check_backend(name: str) -> str:
    """``--backend`` must be fem or legendre."""
    if name not in BACKENDS:
        raise ParameterError("--backend", "one of " + ", ".join(BACKENDS), name)
    return name


def check_mesh_options(args: argparse.Namespace) -> None:
    """Validate ``--level``, ``--order`` and ``--mesh`` before any work."""
    check_level(args.level)
    check_order(args.order)
    if args.mesh not in MESH_KINDS:
        raise ParameterError("--mesh", "one of " + ", ".join(MESH_KINDS), args.mesh)
    check_choice("--initial", args.initial, INITIAL_METHODS)


def model_from_options(
    args: argparse.Namespace, backends: Sequence[str] = BACKENDS, case: Case | None = None
) -> BallModel:
    """Solve the case of the options with ``backends`` on the mesh of the options."""
    check_mesh_options(args)
    case = case_from_options(args) if case is None else case
    return ball_model(
        case,
        args.level,
        args.order,
        mesh=args.mesh,
        sigma=args.sigma,
        recontact=args.recontact,
        t_end_s=args.t_end,
        backends=backends,
        initial=args.initial,
    )


def add_frame_options(parser: argparse.ArgumentParser, default: int) -> None:
    """``--frames K`` or ``--times T1,T2,...`` (mutually exclusive)."""
    group = parser.add_mutually_exclusive_group()
    group.add_argument(
        "--frames",
        type=int,
        metavar="K",
        help=f"K frames evenly spaced over [0, t_end] (default {default}; plus the lift-off)",
    )
    group.add_argument(
        "--times", metavar="T1,T2,...", help="frame times in seconds, comma-separated"
    )


def run(args: argparse.Namespace) -> int:
    """Run ``twoball export``."""
    fmt = series_format(args.out, args.format)
    out = check_output_path(args.out)
    check_backend(args.backend)
    check_mesh_options(args)
    case = case_from_options(args)
    times = None
    if args.times is not None:
        times = check_times(window_s(case, args.t_end), parse_times(args.times))
        if len(times) > MAX_FRAMES:  # the same cap as --frames
            raise ParameterError("--times", f"at most {MAX_FRAMES} times", f"{len(times)} times")
    frames = None if args.frames is None else check_frames(args.frames)
    if fmt == "vtu" and frames is not None and frames != 1:
        raise ParameterError("--frames", "1 for a single .vtu file (or use --times T)", frames)
    if fmt == "vtu" and times is not None and len(times) != 1:
        raise ParameterError("--times", "exactly one time for a single .vtu file", args.times)
    count = len(times) if times is not None else (frames or DEFAULT_FRAMES)
    flag = "--times" if times is not None else "--frames"
    check_frames_budget(
        f"{flag} ({count} frames)", count, args.mesh, args.level, args.order, case.modes
    )
    model = model_from_options(args, case=case)
    if fmt == "vtu" and times is None and frames is None:
        selected = liftoff_frame(model, args.backend)
    elif fmt == "vtu" and frames == 1:
        selected = frame_times(model, 1, None, args.backend, include_liftoff=False)
    else:
        selected = frame_times(model, frames, times, args.backend)
    series = field_series(model, selected, args.backend)
    files = write_series(out, series, fmt)
    report = model.backend(args.backend).report
    for text in report.warnings + tuple(mesh_notes(args, case, args.backend)):
        warn(text)
    rows = [
        ("file", str(files[0])),
        ("beside it", f"{len(files) - 1} file(s)" if len(files) > 1 else "-"),
        ("format", fmt),
        ("frames", str(len(series))),
        ("times [ms]", f"{selected[0] * 1e3:.3f} .. {selected[-1] * 1e3:.3f}"),
        ("nodes", str(len(series.points))),
        ("cells", f"{len(series.cells)} {series.cell_type}"),
        ("point data", ", ".join(series.point_data)),
        (f"t_l [ms] ({args.backend})", number(report.t_liftoff_s, 1e3)),
        (f"v_l [m/s] ({args.backend})", number(report.v_liftoff_m_s)),
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
    add_mesh_options(parser)
    parser.add_argument(
        "--format",
        help="xdmf (with NAME.h5), pvd (with NAME_0000.vtu ...) or vtu (one frame); "
        "default: from the suffix of --out (" + ", ".join(FORMATS) + ")",
    )
    add_frame_options(parser, DEFAULT_FRAMES)
    parser.add_argument("--out", required=True, metavar="PATH", help="main output file")
    parser.set_defaults(run=run)
