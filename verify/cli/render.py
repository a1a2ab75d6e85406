"""``twoball render``: a picture (PNG) or an animation (GIF, MP4) of the bouncing ball."""

from __future__ import annotations

import argparse
import math

import numpy as np
from twoball.fem_membrane.render import DEFAULT_SIZE, check_size, check_warp, image_kind
from twoball.modal.errors import ParameterError
from twoball.verify.cli.case_options import add_case_options, case_from_options
from twoball.verify.cli.console import console, key_value_table
from twoball.verify.cli.export import (
    add_mesh_options,
    check_backend,
    check_mesh_options,
    model_from_options,
)
from twoball.verify.output.fields import (
    MAX_FRAMES,
    ball_scene,
    check_frames,
    check_times,
    liftoff_frame,
    window_s,
)

from twoball.staging import check_file

DEFAULT_ANIMATION_FRAMES = 60
VALID_RANGES: dict[str, str] = {
    "--time": "a time >= 0 in seconds within the modelled window",
    "--frames": f"an integer in [1, {MAX_FRAMES}]",
    "--fps": "a number > 0",
}


def parse_warp(text: str | None) -> float | None:
    """``--warp``: ``auto`` (None) or a finite number >= 0."""
    if text is None or str(text).strip().lower() == "auto":
        return None
    try:
        value = float(text)
    except ValueError:
        raise ParameterError("--warp", "a finite number >= 0 or auto", text) from None
    return check_warp(value)


def run(args: argparse.Namespace) -> int:
    """Run ``twoball render``."""
    kind = image_kind(args.out)
    out = check_file(args.out)
    size = check_size(args.size)
    warp = parse_warp(args.warp)
    check_backend(args.backend)
    if not (math.isfinite(args.fps) and args.fps > 0):
        raise ParameterError("--fps", "a number > 0", args.fps)
    if kind == ".png" and args.frames is not None:
        raise ParameterError("--frames", "used with .gif or .mp4 only (use --time for .png)")
    if kind != ".png" and args.time is not None:
        raise ParameterError("--time", "used with .png only (use --frames for animations)")
    frames = None if args.frames is None else check_frames(args.frames)
    check_mesh_options(args)
    case = case_from_options(args)
    times = None
    if args.time is not None:
        times = check_times(window_s(case, args.t_end), [args.time], "--time")
    model = model_from_options(args, (args.backend,), case)
    if kind == ".png":
        times = liftoff_frame(model, args.backend) if times is None else times
    else:
        count = DEFAULT_ANIMATION_FRAMES if frames is None else frames
        times = np.linspace(0.0, model.t_end_s, count)
    scene = ball_scene(model, times, args.backend)
    from twoball.fem_membrane.render import render_scene, round_size

    render_scene(out, scene, warp=warp, size=size, fps=args.fps)
    shown = round_size(size) if kind == ".mp4" else size
    rows = [
        ("file", str(out)),
        ("frames", str(times.size)),
        ("times [ms]", f"{times[0] * 1e3:.3f} .. {times[-1] * 1e3:.3f}"),
        ("size [px]", f"{shown[0]}x{shown[1]}"),
        ("warp", f"{scene.auto_warp() if warp is None else warp:.4g}"),
        ("backend", args.backend),
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
    add_mesh_options(parser)
    parser.add_argument("--out", required=True, metavar="FILE", help="FILE.png, .gif or .mp4")
    group = parser.add_mutually_exclusive_group()
    group.add_argument(
        "--time", type=float, metavar="SECONDS", help="instant of a PNG (default: the lift-off)"
    )
    group.add_argument(
        "--frames",
        type=int,
        metavar="K",
        help=f"frames of an animation over [0, t_end] (default {DEFAULT_ANIMATION_FRAMES})",
    )
    parser.add_argument(
        "--warp",
        default="auto",
        metavar="SCALE",
        help="displacement magnification; auto (default): the largest displacement drawn "
        "at 15%% of R, never less than true scale",
    )
    parser.add_argument(
        "--size",
        default=f"{DEFAULT_SIZE[0]}x{DEFAULT_SIZE[1]}",
        metavar="WxH",
        help="image size in pixels (MP4: rounded up to multiples of 16)",
    )
    parser.add_argument("--fps", type=float, default=20.0, help="frames per second (animations)")
    parser.set_defaults(run=run)
