"""Wall time of the sweeps behind Fig. 12: 1,200 closed-form lift-offs, one process and two.

Run from the repository root (not a timed test: speed is measured, not asserted)::

    python benchmarks/bench_sweeps.py            # 3 repeats per runner
    python benchmarks/bench_sweeps.py --runs 1

The 1,200 cases are those of ``twoball reproduce --only fig12`` (three axes times
the damping ratios times the values).  Each runner does one untimed warm-up and
then ``--runs`` timed sweeps, alternating, so both see the same load; the table
gives medians and the speed-up.  The target of the reproduction is 30 s on two
workers.  Exit status 0.
"""

from __future__ import annotations

import os

for _name in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_name, "1")

import argparse  # noqa: E402
import platform  # noqa: E402
import statistics  # noqa: E402
import sys  # noqa: E402
import time  # noqa: E402
from pathlib import Path  # noqa: E402

ROOT = Path(__file__).resolve().parent.parent
if str(ROOT) not in sys.path:
    sys.path.insert(0, str(ROOT))


def main(argv: list[str] | None = None) -> int:
    """Time the Fig. 12 sweeps on one and on two workers; print medians and the speed-up."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--runs", type=int, default=3, help="timed runs per runner (default 3)")
    args = parser.parse_args(argv)
    from twoball.verify.reproduce.cem.fig12 import fig12_cases
    from twoball.verify.sweeps.parallel import Runner
    from twoball.verify.sweeps.sweeps import SweepSolver, run_sweep

    _, cases = fig12_cases()

    def sweep(workers: int) -> float:
        start = time.perf_counter()
        with Runner(workers=workers) as runner:
            points = run_sweep(cases, SweepSolver(), runner=runner)
        assert all(p.error is None for p in points)
        return time.perf_counter() - start

    times: dict[int, list[float]] = {1: [], 2: []}
    for workers in times:
        sweep(workers)
    for _ in range(args.runs):
        for workers in times:
            times[workers].append(sweep(workers))
    print(
        f"# {len(cases)} lift-offs, {platform.node()}, {os.cpu_count()} CPUs, "
        f"load {os.getloadavg()[0]:.2f}"
    )
    print("| workers | median [s] | runs [s] |")
    print("|---|---|---|")
    for workers, samples in times.items():
        runs = ", ".join(f"{s:.2f}" for s in samples)
        print(f"| {workers} | {statistics.median(samples):.2f} | {runs} |")
    print(f"speed-up: {statistics.median(times[1]) / statistics.median(times[2]):.2f}x")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
