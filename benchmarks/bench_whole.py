"""Wall-time benchmark of the whole two-ball bounce (``twoball.bounce(pair=...)``) and its sweep.

Run from the repository root (not a timed test: speed is measured, not asserted)::

    python benchmarks/bench_whole.py            # 5 repeats per task
    python benchmarks/bench_whole.py --quick    # 3 repeats, a 16-point sweep

Tasks: the basketball with the tennis ball on top, touching (Delta x = 0: the
body rattles on the cap, about 45 contacts, the costliest case), at the defaults
of each backend -- Legendre modes N = 192 (target <= 2 s) and axisymmetric P2 with
96 elements (target <= 20 s) -- after one untimed warm-up (imports, the Hertz
fits of the lumped baselines), with the closed-form lift-off as the same-run
baseline; then a 50-point sweep of Delta x in [0, 250] mm
(``twoball.sweep({"gap": ...}, drop=Drop(), pair=...)``) in one process, on
the local process pool (all cores) and on a Dask ``LocalCluster`` of as many
worker processes (its start-up and the warm-up of its workers, one point
each, timed apart), once each, with the speed-ups and
whether the numbers are those of one process.  The machine's load average is
printed before and after: on a shared machine the wall times follow it.
Exit status 0.
"""

from __future__ import annotations

import os

for _name in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_name, "1")

import argparse  # noqa: E402
import platform  # noqa: E402
import sys  # noqa: E402
import time  # noqa: E402
from collections.abc import Callable  # noqa: E402
from pathlib import Path  # noqa: E402

import numpy as np  # noqa: E402

ROOT = Path(__file__).resolve().parent.parent
if str(ROOT) not in sys.path:
    sys.path.insert(0, str(ROOT))

from timing import timed  # noqa: E402

PAIR = "basketball-tennis"


def main(argv: list[str] | None = None) -> int:
    """Time the whole bounces and the sweep; print medians, IQRs, ratios and the speed-up."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="3 repeats, a 16-point sweep")
    args = parser.parse_args(argv)
    repeats = 3 if args.quick else 5
    import twoball
    from twoball.verify.sweeps.parallel import default_workers

    tasks: list[tuple[str, Callable[[], object], float | None]] = [
        ("baseline: twoball.liftoff()", lambda: twoball.liftoff(), None),
        ("whole bounce, legendre N = 192", lambda: twoball.bounce(pair=PAIR), 2.0),
        (
            "whole bounce, fem axisym 96 P2",
            lambda: twoball.bounce(pair=PAIR, solver=twoball.MoreauJean(twoball.FEBall())),
            20.0,
        ),
    ]
    print(
        f"twoball {twoball.__version__}, Python {platform.python_version()}, "
        f"{os.cpu_count()} CPUs, load {os.getloadavg()[0]:.2f}"
    )
    base = None
    for name, task, target in tasks:
        samples, cpu_samples = timed(task, repeats)
        cpu = float(np.median(cpu_samples))
        median = float(np.median(samples))
        q25, q75 = np.percentile(samples, [25, 75])
        base = median if base is None else base
        verdict = "" if target is None else ("PASS" if median <= target else "FAIL")
        print(
            f"{name:34s} median {median:8.4f} s  IQR {q75 - q25:7.4f} s  CPU {cpu:7.3f} s  "
            f"x baseline {median / base:8.1f}  {verdict} "
            + ("" if target is None else f"(target <= {target:g} s)")
        )
    count = 16 if args.quick else 50
    gaps = list(np.linspace(0.0, 0.25, count))
    workers = default_workers()
    times = {}
    results = {}
    for label, w in (("one process", 1), (f"process pool ({workers})", workers)):
        start = time.perf_counter()
        results[label] = twoball.sweep({"gap": gaps}, drop=twoball.Drop(), pair=PAIR, workers=w)
        times[label] = time.perf_counter() - start
        print(f"sweep of {count} gaps, {label:22s} {times[label]:8.2f} s")
    try:
        from distributed import LocalCluster
    except ImportError:  # pragma: no cover - the dask extra is not installed
        LocalCluster = None
    if LocalCluster is not None:
        start = time.perf_counter()
        with LocalCluster(
            n_workers=workers, threads_per_worker=1, processes=True, dashboard_address=None
        ) as cluster:
            started = time.perf_counter() - start
            # one point per worker first (untimed apart): the workers import twoball and
            # build the lumped baselines' fits once, as the forked pool inherits them
            start = time.perf_counter()
            twoball.sweep(
                {"gap": gaps[:workers]},
                drop=twoball.Drop(),
                pair=PAIR,
                workers=cluster.scheduler_address,
            )
            warmed = time.perf_counter() - start
            label = f"Dask LocalCluster ({workers})"
            start = time.perf_counter()
            results[label] = twoball.sweep(
                {"gap": gaps}, drop=twoball.Drop(), pair=PAIR, workers=cluster.scheduler_address
            )
            times[label] = time.perf_counter() - start
        print(
            f"sweep of {count} gaps, {label:22s} {times[label]:8.2f} s "
            f"(cluster start {started:.1f} s, warm-up of the workers {warmed:.1f} s)"
        )
    one = results["one process"]
    for label, result in results.items():
        if label == "one process":
            continue
        same = all(
            a.v1_ratio == b.v1_ratio and a.v2_ratio == b.v2_ratio
            for a, b in zip(one.reports, result.reports, strict=True)
        )
        speed = times["one process"] / times[label]
        print(f"{label}: speed-up {speed:.2f}; same numbers as one process: {same}")
    print(f"load after: {os.getloadavg()[0]:.2f}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
