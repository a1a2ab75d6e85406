"""``twoball render``: a picture (PNG) or an animation (GIF, MP4) of the bouncing ball.

A thin layer over :func:`twoball.render`.
"""

from __future__ import annotations

import argparse

import twoball
from twoball._common import choices as _choices
from twoball.cli.case_options import add_case_options, case_from_options
from twoball.cli.console import console, key_value_table, print_notes, print_warnings
from twoball.cli.contact_options import add_contact_options, body_options
from twoball.cli.export import add_backend_option
from twoball.cli.mesh_options import (
    add_mesh_options,
    add_route_option,
)
from twoball.cli.solver_options import field_solver
from twoball.cli.values import integer, number

__all__ = ["register", "run"]


def run(args: argparse.Namespace) -> int:
    """Run ``twoball render``: :func:`twoball.render` with the options."""
    from twoball._common.progress import Reporter

    if args.time is not None and not str(args.out).lower().endswith(".png"):
        valid = "used with .png only (--frames for an animation)"
        raise twoball.ParameterError("time", valid, args.time)
    frames = args.frames if args.time is None else [args.time]
    view = twoball.RenderOptions(warp=args.warp, size=args.size, fps=args.fps, frames=frames)
    solver = field_solver(args)
    with Reporter("render") as progress:
        result = twoball.render(
            args.out,
            case_from_options(args),
            backend=args.backend,
            solver=solver,
            body=body_options(args),
            view=view,
            progress=progress,
        )
    times = result.times_s
    print_notes(result.report.notes)
    print_warnings(result.warnings)
    rows = [
        ("file", str(result.file)),
        ("frames", str(len(times))),
        ("times [ms]", f"{times[0] * 1e3:.3f} .. {times[-1] * 1e3:.3f}"),
        ("size [px]", f"{result.size[0]}x{result.size[1]}"),
        ("warp", f"{result.warp:.4g}"),
        ("backend", result.backend),
        ("phi_a from", str(result.report.case.phi_a_source)),
    ]
    console().print(key_value_table("Rendered", rows))
    return 0


def register(parser: argparse.ArgumentParser) -> None:
    """The options of ``twoball render``."""
    parser.description = (
        "Off-screen pyvista rendering: the ball warped by its radial displacement "
        "and coloured by u [mm], the upper body on the pole and in free flight after lift-off."
    )
    add_case_options(parser)
    add_mesh_options(parser, _choices.SPHERE_KINDS, initial=True, geometry=True)
    add_route_option(parser)
    add_backend_option(parser)
    parser.add_argument("--out", required=True, metavar="FILE", help="FILE.png, .gif or .mp4")
    group = parser.add_mutually_exclusive_group()
    group.add_argument(
        "--time", type=number, metavar="SECONDS", help="instant of a PNG (default: the lift-off)"
    )
    group.add_argument(
        "--frames",
        type=integer,
        metavar="K",
        help="frames of an animation over [0, t_end] "
        f"(default {_choices.DEFAULT_ANIMATION_FRAMES})",
    )
    parser.add_argument(
        "--warp",
        type=number,
        default="auto",
        metavar="SCALE",
        help="displacement magnification; auto (default): the largest displacement drawn "
        "at 15%% of R, never less than true scale",
    )
    parser.add_argument(
        "--size",
        default=f"{_choices.DEFAULT_SIZE[0]}x{_choices.DEFAULT_SIZE[1]}",
        metavar="WxH",
        help="image size in pixels (MP4: rounded up to multiples of 16)",
    )
    parser.add_argument(
        "--fps", type=number, help="frames per second of a .gif or .mp4 (default 20)"
    )
    parser.set_defaults(initial=None)  # the API's default; refused with --backend legendre
    add_contact_options(
        parser, "m1/m2 in (0, 100]: the body over the coupled membrane, in contact or not"
    )
    parser.set_defaults(run=run)
