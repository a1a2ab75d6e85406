"""``twoball reproduce``: the paper's figures and numbers recomputed, in one directory."""

from __future__ import annotations

import argparse
import shlex

from twoball.cli.console import console
from twoball.verify.reproduce.driver import (
    DEFAULT_OUT,
    PARTS,
    REPORT,
    check_output,
    parse_only,
)
from twoball.verify.reproduce.driver import reproduce as run_reproduction
from twoball.verify.sweeps.parallel import VALID_RANGES as PARALLEL_RANGES
from twoball.verify.sweeps.parallel import Runner, check_workers

VALID_RANGES = dict(PARALLEL_RANGES)


def run(args: argparse.Namespace) -> int:
    """Run ``twoball reproduce``."""
    names = parse_only(args.only)
    workers = check_workers(args.workers) if not args.scheduler else args.workers
    check_output(args.out)  # fail before any work
    from twoball._common.progress import Reporter

    with Runner(workers, args.scheduler) as runner:  # the pool starts before the bar's thread
        with Reporter("reproduce") as bar:
            target, sections = run_reproduction(
                args.out, names, runner, bar.task, command_line(args)
            )
    out = console()
    out.print(f"wrote {target / REPORT} and {sum(len(s.figures) for s in sections)} figures")
    for s in sections:
        out.print(f"  {s.key:<11} {s.seconds:6.1f} s  {len(s.comparisons):3d} numbers compared")
    return 0


def command_line(args: argparse.Namespace) -> str:
    """The options of this run, spelled as a command (for the report's header)."""
    words = ["twoball", "reproduce", "--out", args.out]
    for flag, value in (("--only", args.only), ("--workers", args.workers)):
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
        "reproduction.json into --out.  The directory is replaced only when everything is "
        "written; an existing one must be empty or an earlier reproduction."
    )
    parser.add_argument(
        "--out",
        default=DEFAULT_OUT,
        metavar="DIR",
        help=f"output directory (default ./{DEFAULT_OUT}); its parent must exist",
    )
    parser.add_argument(
        "--only",
        metavar="PARTS",
        help="comma-separated subset of: " + ",".join(PARTS),
    )
    parser.add_argument(
        "--workers",
        type=int,
        metavar="N",
        help="local worker processes for the sweeps (default: all cores; 1 = serial)",
    )
    parser.add_argument(
        "--scheduler",
        metavar="ADDRESS",
        help="run the sweeps on an existing dask.distributed scheduler",
    )
    parser.set_defaults(run=run)
