"""Fields and eigen listings: today's route against the fast route, side by side.

Run from the repository root::

    python benchmarks/bench_fields.py                  # levels 3-5, 3 repeats
    python benchmarks/bench_fields.py --levels 3 -n 1  # quick
    python benchmarks/bench_fields.py --old /path/to/other/checkout

For each sphere P2 level and task the two commands run as child processes, in
turn (old, new, old, new, ...), and the table gives the median CPU seconds
(user + system of the child, which also counts Python start-up and imports) and
median wall seconds of each, and their ratio.  Tasks (the public API, defaults
otherwise):

``export``   ``twoball.export("f.xdmf", solver=Superposition(MeshOptions(level=L)))``
             (25 frames plus the lift-off)
``render``   ``twoball.render("f.png", solver=...)`` (the lift-off instant)
``pole``     ``twoball.plot("pole", "f.png", solver=...)``
``eigen900`` ``twoball.fem.eigen(MeshOptions(level=L, order=2), count=900)``

"old" is ``--route full`` of this checkout by default (every eigenpair below the
cutoff), or, with ``--old PATH``, the
same calls in another checkout (e.g. the main branch: today's code); eigen900 has
no route and is only compared with ``--old``.  "new" is this checkout's default
(``--route auto``: the Krylov Ritz fields from 2000 unknowns on).  A run longer
than ``--cap`` seconds is stopped and shown as ``>cap``.  Speed is measured here,
not asserted by the tests.  The machine is shared: the load average is printed
before and after.
"""

from __future__ import annotations

import argparse
import os
import platform
import resource
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
TASKS = ("export", "render", "pole", "eigen900")
SOLVER = "solver=twoball.Superposition(twoball.MeshOptions(level={level}){route})"
CALLS = {
    "export": "twoball.export({out!r} + '/f.xdmf', " + SOLVER + ")",
    "render": "twoball.render({out!r} + '/f.png', " + SOLVER + ")",
    "pole": "twoball.plot('pole', {out!r} + '/f.png', " + SOLVER + ")",
    "eigen900": "twoball.fem.eigen(twoball.MeshOptions(level={level}, order=2), count=900)",
}


def _child(checkout: Path, code: str, cap: float) -> tuple[float, float, int]:
    """CPU seconds (user + sys), wall seconds and exit status of one child run."""
    env = dict(os.environ, OPENBLAS_NUM_THREADS="1", PYTHONPATH=str(checkout))
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.perf_counter()
    try:
        done = subprocess.run(
            [sys.executable, "-c", code],
            cwd=checkout,
            env=env,
            timeout=cap,
            capture_output=True,
            check=False,
        )
        status = done.returncode
    except subprocess.TimeoutExpired:
        status = -1
    wall = time.perf_counter() - start
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    return cpu, wall, status


def _code(task: str, level: int, out: str, route: str | None) -> str:
    call = CALLS[task].format(out=out, level=level, route="" if route is None else route)
    return f"import twoball, twoball.fem; {call}"


def _format(values: list[float], statuses: list[int], cap: float) -> str:
    if any(s == -1 for s in statuses):
        return f">{cap:.0f}"
    text = f"{statuses and statuses[0] and 'exit ' + str(statuses[0]) + ' ' or ''}"
    return text + f"{statistics.median(values):.2f}"


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--levels", default="3,4,5", help="sphere levels (P2), default 3,4,5")
    parser.add_argument("--tasks", default=",".join(TASKS), help="subset of " + ",".join(TASKS))
    parser.add_argument("-n", type=int, default=3, help="runs of each command (median)")
    parser.add_argument("--cap", type=float, default=120.0, help="seconds before a run stops")
    parser.add_argument("--old", type=Path, help="checkout with today's code (default: route full)")
    args = parser.parse_args()
    levels = [int(v) for v in args.levels.split(",")]
    tasks = [t for t in args.tasks.split(",") if t]
    print(f"{platform.node()} {platform.processor() or platform.machine()}, {os.cpu_count()} CPUs")
    print(f"load average before: {os.getloadavg()}")
    old_label = f"old ({args.old})" if args.old else "old (--route full)"
    header = f"{'task':10} {'level':>5} | {old_label:>24} | {'new (auto)':>14} | {'cpu ratio':>9}"
    print(header + "\n" + "-" * len(header))
    with tempfile.TemporaryDirectory() as out:
        for level in levels:
            for task in tasks:
                if task == "eigen900" and args.old is None:
                    old_checkout, old_route = None, None
                elif args.old is not None:
                    old_checkout, old_route = args.old, None
                else:
                    old_checkout, old_route = ROOT, ", route='full'"
                samples: dict[str, list[tuple[float, float, int]]] = {"old": [], "new": []}
                for _ in range(args.n):
                    if old_checkout is not None:
                        code = _code(task, level, out, old_route)
                        samples["old"].append(_child(old_checkout, code, args.cap))
                    samples["new"].append(_child(ROOT, _code(task, level, out, None), args.cap))
                cells = {}
                for name, runs in samples.items():
                    if not runs:
                        cells[name] = "-"
                        continue
                    cpu = [r[0] for r in runs]
                    wall = [r[1] for r in runs]
                    status = [r[2] for r in runs]
                    cells[name] = (
                        f"{_format(cpu, status, args.cap)} cpu {_format(wall, status, args.cap)} w"
                    )
                ratio = "-"
                good = [r for r in samples["old"] if r[2] == 0]
                if good and all(r[2] == 0 for r in samples["new"]):
                    old_cpu = statistics.median(r[0] for r in good)
                    ratio = f"{old_cpu / statistics.median(r[0] for r in samples['new']):.1f}x"
                print(
                    f"{task:10} {level:5d} | {cells['old']:>24} | {cells['new']:>14} | {ratio:>9}"
                )
                sys.stdout.flush()
    print(f"load average after: {os.getloadavg()}")


if __name__ == "__main__":
    main()
