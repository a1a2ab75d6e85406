"""Start-up benchmark: whole-process wall time of short ``twoball`` commands.

Run from the repository root::

    python benchmarks/bench_startup.py            # 15 runs of each command
    python benchmarks/bench_startup.py --quick    # 5 runs

Each command is started as a fresh process, its output thrown away, and timed
from just before it starts to just after it exits.  The commands take turns
(A B C D A B C D ...) so that a change of the machine's load hits all of them
alike.  The yardstick is ``python -c "import numpy"``, measured in the same run:
every median is also given as a multiple of it, and the targets are multiples of
it (``twoball --help`` no slower than importing numpy, ``twoball liftoff --json``
at most twice that).  The median CPU time (user + system) of each process is
printed beside: it hardly depends on what else runs on the machine.  Targets
are printed as PASS/FAIL; the script always exits with status 0: speed is
measured here, not asserted by the test suite.

``twoball`` is the venv's console script when that script runs this checkout
(an editable install of it); otherwise ``python -m twoball`` from the
repository root, which imports this checkout's code.  The header says which.
"""

from __future__ import annotations

import argparse
import os
import platform
import resource
import shutil
import statistics
import subprocess
import sys
import tempfile
import time
from dataclasses import dataclass, field
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent


@dataclass
class Command:
    """One command line to time, with its target as a multiple of the yardstick."""

    name: str
    argv: list[str]
    target: float | None = None  # median / yardstick median must be <= this
    samples: list[float] = field(default_factory=list)  # wall seconds
    cpu: list[float] = field(default_factory=list)  # user + system seconds of the child

    @property
    def median(self) -> float:
        return statistics.median(self.samples)

    @property
    def cpu_median(self) -> float:
        return statistics.median(self.cpu)


def twoball_launcher() -> tuple[list[str], str]:
    """How to start ``twoball`` for this checkout, and a sentence saying which way."""
    script = Path(sys.executable).parent / "twoball"
    if not script.exists():
        found = shutil.which("twoball")
        script = Path(found) if found else script
    if script.exists():
        # The script's own interpreter, from a neutral directory: where does it find twoball?
        probe = "import twoball.cli.main as m; print(m.__file__)"
        with tempfile.TemporaryDirectory() as neutral:
            done = subprocess.run(
                [_interpreter(script), "-c", probe],
                cwd=neutral,
                capture_output=True,
                text=True,
                check=False,
            )
        where = Path(done.stdout.strip()).resolve() if done.returncode == 0 else None
        if where == ROOT / "verify" / "cli" / "main.py":
            return [str(script)], f"console script {script} (runs this checkout)"
        elsewhere = f"runs {where.parent.parent.parent}" if where else "does not start"
        reason = f"the console script {script} {elsewhere}"
    else:
        reason = "no twoball console script found"
    return [sys.executable, "-m", "twoball"], f"python -m twoball from {ROOT} ({reason})"


def _interpreter(script: Path) -> str:
    """The interpreter named on a console script's ``#!`` line (else this one)."""
    with open(script, "rb") as handle:
        first = handle.readline().decode(errors="replace").strip()
    return first[2:].split()[0] if first.startswith("#!") else sys.executable


def commands(twoball: list[str]) -> list[Command]:
    """The yardstick first, then the twoball commands."""
    return [
        Command('python -c "import numpy"', [sys.executable, "-c", "import numpy"]),
        Command("twoball --help", [*twoball, "--help"], target=1.0),
        Command("twoball liftoff --json", [*twoball, "liftoff", "--json"], target=2.0),
        Command(
            "twoball liftoff --backend fem --mesh axisym --json",
            [*twoball, "liftoff", "--backend", "fem", "--mesh", "axisym", "--json"],
        ),
    ]


def run_once(command: Command) -> tuple[float, float]:
    """Wall and CPU (user + system) seconds of one fresh process of ``command``."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.perf_counter()
    done = subprocess.run(
        command.argv, cwd=ROOT, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, check=False
    )
    seconds = time.perf_counter() - start
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    if done.returncode != 0:
        message = done.stderr.decode(errors="replace").strip().splitlines()
        raise RuntimeError(
            f"{command.name} exited with {done.returncode}: {message[-1] if message else ''}"
        )
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    return seconds, cpu


def measure(all_commands: list[Command], runs: int) -> None:
    """One untimed round (warms the file cache), then ``runs`` interleaved rounds."""
    for command in all_commands:
        run_once(command)
    for _ in range(runs):
        for command in all_commands:
            wall, cpu = run_once(command)
            command.samples.append(wall)
            command.cpu.append(cpu)


def report(all_commands: list[Command]) -> str:
    """The result table as text; ratios are to the first command's medians.

    The targets apply to wall time; CPU time (user + system, median) is shown
    beside it because it is far less sensitive to other processes on the machine.
    """
    yardstick, yardstick_cpu = all_commands[0].median, all_commands[0].cpu_median
    width = max(len(c.name) for c in all_commands)
    header = (
        f"{'command':{width}s} {'runs':>4s} {'median':>8s} {'min':>8s} {'max':>8s} "
        f"{'x numpy':>8s} {'target':>8s}  {'result':6s} {'cpu':>7s} {'x numpy':>8s}"
    )
    lines = ["wall time (median, min, max) and CPU time (median)", header, "-" * len(header)]
    for c in all_commands:
        ratio = c.median / yardstick
        if c.target is None:
            target, verdict = "-", "-"
        else:
            target = f"<= {c.target:g}"
            verdict = "PASS" if ratio <= c.target else "FAIL"
        lines.append(
            f"{c.name:{width}s} {len(c.samples):4d} {c.median:7.3f}s {min(c.samples):7.3f}s "
            f"{max(c.samples):7.3f}s {ratio:8.2f} {target:>8s}  {verdict:6s} "
            f"{c.cpu_median:6.3f}s {c.cpu_median / yardstick_cpu:8.2f}"
        )
    return "\n".join(lines)


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--runs", type=int, default=15, help="timed runs of each command")
    parser.add_argument("--quick", action="store_true", help="same as --runs 5")
    args = parser.parse_args(argv)
    runs = 5 if args.quick else max(args.runs, 1)

    twoball, how = twoball_launcher()
    load = os.getloadavg()[0] if hasattr(os, "getloadavg") else float("nan")
    print(
        f"twoball start-up benchmark -- Python {platform.python_version()}, "
        f"{os.cpu_count()} CPUs, load average {load:.2f} at the start, "
        f"OPENBLAS_NUM_THREADS={os.environ.get('OPENBLAS_NUM_THREADS', 'unset')}"
    )
    print(f"twoball: {how}")
    all_commands = commands(twoball)
    try:
        measure(all_commands, runs)
    except RuntimeError as error:
        print(f"cannot time: {error}")
        return 0
    print(report(all_commands))
    yardstick = all_commands[0].median
    failed = [c.name for c in all_commands if c.target and c.median / yardstick > c.target]
    if failed:
        print("targets missed (not an error; timings depend on the machine and its load):")
        for name in failed:
            print("  " + name)
    else:
        print("all targets met")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
