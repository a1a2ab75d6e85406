"""Export benchmark: whole-process time of ``twoball export`` with and without a body.

Run from anywhere::

    python benchmarks/bench_exports.py                      # 5 runs of each command
    python benchmarks/bench_exports.py --runs 3 --baseline /path/to/older/checkout

Each command is ``python -m twoball export ... --out FILE.xdmf`` (default mesh:
icosphere level 3, P2) started as a fresh process with ``PYTHONPATH`` set to a
checkout, timed from just before it starts to just after it exits; the CPU time
(user + system of the child) is printed beside, as it hardly depends on what
else runs on the machine.  The commands take turns (A B C D A B C D ...), so a
change of the machine's load hits all of them alike, and every median is also
given as a multiple of the plain export (``fem``, no body) of the same checkout
in the same run: the yardstick.  With ``--baseline`` the same commands of an
older checkout take their turns too, and the table shows both.

Targets (multiples of the plain export of the same checkout): the export with a
body (``--mass-ratio 0.101``) at most 3; the closed form (``--backend
legendre``, with or without the body) at most 0.5, the fast one.  They are printed as
PASS/FAIL; the script always exits with status 0: speed is measured here, not
asserted by the test suite.
"""

from __future__ import annotations

import argparse
import os
import resource
import statistics
import subprocess
import sys
import tempfile
import time
from dataclasses import dataclass, field
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent

#: name -> (export arguments, target as a multiple of the plain export or None)
COMMANDS: dict[str, tuple[list[str], float | None]] = {
    "export (fem)": ([], None),
    "export --backend legendre": (["--backend", "legendre"], 0.5),
    "export --mass-ratio 0.101": (["--mass-ratio", "0.101"], 3.0),
    "export --backend legendre --mass-ratio 0.101": (
        ["--backend", "legendre", "--mass-ratio", "0.101"],
        0.5,
    ),
}


@dataclass
class Run:
    """One command of one checkout and its samples."""

    checkout: str
    name: str
    argv: list[str]
    target: float | None
    wall: list[float] = field(default_factory=list)
    cpu: list[float] = field(default_factory=list)


def timed(argv: list[str], env: dict[str, str], cwd: str) -> tuple[float, float]:
    """Wall and CPU seconds (user + system of the child) of one process."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.perf_counter()
    done = subprocess.run(argv, env=env, cwd=cwd, capture_output=True, text=True)
    wall = time.perf_counter() - start
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    if done.returncode not in (0, 1):
        raise SystemExit(f"{' '.join(argv)} failed ({done.returncode}): {done.stderr.strip()}")
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    return wall, cpu


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--runs", type=int, default=5, help="timed runs of each command")
    parser.add_argument("--baseline", help="another checkout to time in the same run")
    args = parser.parse_args(argv)
    checkouts = {"this": str(ROOT)}
    if args.baseline:
        checkouts["baseline"] = str(Path(args.baseline).resolve())
    runs = [
        Run(label, name, extra, target)
        for label in checkouts
        for name, (extra, target) in COMMANDS.items()
    ]
    with tempfile.TemporaryDirectory() as folder:
        env0 = dict(os.environ, OPENBLAS_NUM_THREADS="1", MPLBACKEND="Agg")
        for k in range(args.runs + 1):  # the first round warms the caches, not counted
            for j, run in enumerate(runs):
                env = dict(env0, PYTHONPATH=checkouts[run.checkout])
                out = Path(folder) / f"x{j}.xdmf"
                command = [sys.executable, "-m", "twoball", "export", "-q", *run.argv]
                wall, cpu = timed([*command, "--out", str(out)], env, folder)
                if k > 0:
                    run.wall.append(wall)
                    run.cpu.append(cpu)
    print(f"# twoball export, default mesh (icosphere level 3, P2); {args.runs} runs each")
    print()
    print("| checkout | command | wall median [s] | CPU median [s] | x plain | target |")
    print("|---|---|---|---|---|---|")
    for run in runs:
        plain = next(r for r in runs if r.checkout == run.checkout and not r.argv)
        ratio = statistics.median(run.wall) / statistics.median(plain.wall)
        verdict = ""
        if run.target is not None and run.checkout == "this":
            verdict = f"<= {run.target:g}: " + ("PASS" if ratio <= run.target else "FAIL")
        print(
            f"| {run.checkout} | {run.name} | {statistics.median(run.wall):.2f} "
            f"| {statistics.median(run.cpu):.2f} | {ratio:.2f} | {verdict} |"
        )
    return 0


if __name__ == "__main__":
    sys.exit(main())
