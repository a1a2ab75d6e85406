"""``twoball reproduce``: the paper's figures and numbers recomputed, in one directory."""

from __future__ import annotations

import argparse
import shlex

from twoball._common import choices as _choices
from twoball.cli.console import console
from twoball.cli.sweep import workers
from twoball.cli.values import integer

__all__ = ["register", "run"]


def run(args: argparse.Namespace) -> int:
    """Run ``twoball reproduce``."""
    import twoball
    from twoball._common.progress import Reporter
    from twoball.cli.case_options import apply_limits

    apply_limits(args)
    with Reporter("reproduce") as bar:
        done = twoball.reproduce(
            args.out,
            only=args.only,
            workers=workers(args),
            progress=bar.task,
            command=command_line(args),
        )
    out = console()
    out.print(f"wrote {done.directory / _choices.REPRODUCTION_REPORT} and {done.figures} figures")
    for s in done.sections:
        out.print(f"  {s.key:<11} {s.seconds:6.1f} s  {len(s.comparisons):3d} numbers compared")
    return 0


def command_line(args: argparse.Namespace) -> str:
    """The options of this run, spelled as a command (for the report's header)."""
    words = ["twoball", "reproduce", "--out", args.out or _choices.REPRODUCTION_DIR]
    given = (
        ("--only", args.only),
        ("--workers", args.workers),
        ("--max-memory", args.max_memory),
        ("--max-time", args.max_time),
    )
    for flag, value in given:
        if value is not None:
            words += [flag, str(value)]
    if args.scheduler:
        words += ["--scheduler", args.scheduler]
    return " ".join(shlex.quote(w) for w in words)


def register(parser: argparse.ArgumentParser) -> None:
    """The options of ``twoball reproduce``."""
    parser.description = (
        "Recompute Figs. 3, 6, 8, 10, 11, 12, Tables 1 and 2 and the §5 "
        "thresholds; write PNG figures, reproduction.md (paper value, ours, difference) and "
        "reproduction.json into --out.  As each part finishes, the directory is replaced by "
        "every part finished so far; a run stopped (--max-time, Ctrl-C, SIGTERM) keeps them, "
        "and reproduction.md names the missing parts.  An existing directory must be empty "
        "or an earlier reproduction."
    )
    parser.add_argument(
        "--out",
        default=None,
        metavar="DIR",
        help=f"output directory (default ./{_choices.REPRODUCTION_DIR}); its parent must exist",
    )
    parser.add_argument(
        "--only",
        metavar="PARTS",
        help="comma-separated subset of: " + ",".join(_choices.REPRODUCTION_PARTS),
    )
    parser.add_argument(
        "--workers",
        type=integer,
        metavar="N",
        help="local worker processes for the sweeps (default: all cores; 1 = serial)",
    )
    parser.add_argument(
        "--scheduler",
        metavar="ADDRESS",
        help="run the sweeps on an existing dask.distributed scheduler",
    )
    from twoball.cli.case_options import add_limit_options

    add_limit_options(
        parser,
        "default: off -- the full reproduction takes 2 min on an idle two-core machine "
        "and over 10 min on a shared one",
    )
    parser.set_defaults(run=run)
