"""Wall-time benchmark of the closed-form lift-off solver.

Run from the repository root::

    python benchmarks/bench_liftoff.py            # full run
    python benchmarks/bench_liftoff.py --quick    # fewer repeats

Each task is timed over repeated runs (after one untimed warm-up) and reported as
the median and the interquartile range (IQR).  Every median is also divided by the
median of a fixed baseline measured in the same process -- ``np.exp`` of a
1000 x 31 complex array, the kind of table the series evaluation builds -- so that
the ratios can be compared across machines.  Targets are printed as PASS/FAIL but
the script always exits with status 0: speed is measured here, not asserted by
the test suite.
"""

from __future__ import annotations

import os

# The solver's matrices are tiny (31 columns at N = 30), so a multi-threaded BLAS only
# adds scheduling overhead -- several-fold on a busy machine.  Pin it to one thread
# unless the caller chose otherwise; this must happen before numpy is imported.
for _name in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_name, "1")

import argparse  # noqa: E402
import platform  # noqa: E402
import sys  # noqa: E402
import time  # noqa: E402
from collections.abc import Callable  # noqa: E402
from dataclasses import dataclass  # noqa: E402
from pathlib import Path  # noqa: E402

import numpy as np  # noqa: E402

# Let ``python benchmarks/bench_liftoff.py`` work from a fresh clone without installing.
ROOT = Path(__file__).resolve().parent.parent
if str(ROOT) not in sys.path:
    sys.path.insert(0, str(ROOT))


@dataclass(frozen=True)
class Timing:
    """Wall times [s] of repeated runs of one task."""

    name: str
    samples: np.ndarray
    target: float | None = None

    @property
    def median(self) -> float:
        return float(np.median(self.samples))

    @property
    def iqr(self) -> float:
        q25, q75 = np.percentile(self.samples, [25, 75])
        return float(q75 - q25)

    @property
    def verdict(self) -> str:
        if self.target is None:
            return "-"
        return "PASS" if self.median <= self.target else "FAIL"


def measure(
    name: str, task: Callable[[], object], repeats: int, target: float | None = None
) -> Timing:
    """Run ``task`` once untimed, then ``repeats`` times timed with ``perf_counter``."""
    task()
    samples = np.empty(repeats)
    for k in range(repeats):
        start = time.perf_counter()
        task()
        samples[k] = time.perf_counter() - start
    return Timing(name, samples, target)


def _seconds(value: float) -> str:
    if value >= 1.0:
        return f"{value:8.3f} s "
    if value >= 1e-3:
        return f"{value * 1e3:8.3f} ms"
    return f"{value * 1e6:8.1f} us"


def run(repeats: int) -> list[Timing]:
    """Time the baseline and the five solver tasks; the baseline comes first."""
    from twoball.modal.filters import SpectralFilter
    from twoball.modal.legendre import legendre_series
    from twoball.modal.parameters import preset
    from twoball.modal.report import legendre_liftoff
    from twoball.verify.sweeps.sweeps import sweep_cases

    case = preset("basketball")  # D = 0.13, N = 30, phi_a = 2.6
    fine = case.derive(modes=240)
    sweep = sweep_cases(case, "damping", np.linspace(0.0, 0.6, 121))

    rng = np.random.default_rng(0)
    table = 1j * rng.uniform(0.0, 10.0, (1000, 31)) - rng.uniform(0.0, 1.0, (1000, 31))

    def solve_sweep() -> None:  # as `twoball sweep` runs it: no converged reference
        for c in sweep:
            legendre_liftoff(c, reference=False)

    heavy = max(3, repeats // 20)
    return [
        measure("baseline: np.exp, 1000x31 complex", lambda: np.exp(table), repeats * 4),
        measure(
            "(a) build Legendre series, N = 30",
            lambda: legendre_series(case.phi_a, case.damping, SpectralFilter("lanczos", 30)),
            repeats,
        ),
        measure(
            "(b) lift-off solve, N = 30",
            lambda: legendre_liftoff(case, reference=False),
            repeats,
            2e-3,
        ),
        measure("(c) damping sweep, 121 values of D", solve_sweep, heavy, 1.0),
        measure(
            "(d) lift-off solve, N = 240", lambda: legendre_liftoff(fine, reference=False), heavy
        ),
        measure(
            "(e) lift-off with the converged reference",  # the truncation guard's block
            lambda: legendre_liftoff(case),
            repeats,
        ),
    ]


def report(timings: list[Timing]) -> str:
    """The result table as text."""
    baseline = timings[0].median
    header = (
        f"{'task':38s} {'runs':>5s} {'median':>11s} {'IQR':>11s} "
        f"{'x baseline':>11s} {'target':>11s}  result"
    )
    lines = [header, "-" * len(header)]
    for t in timings:
        target = "-" if t.target is None else "<= " + _seconds(t.target).strip()
        lines.append(
            f"{t.name:38s} {t.samples.size:5d} {_seconds(t.median):>11s} {_seconds(t.iqr):>11s} "
            f"{t.median / baseline:11.3g} {target:>11s}  {t.verdict}"
        )
    return "\n".join(lines)


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--repeats", type=int, default=200, help="runs of the fast tasks")
    parser.add_argument("--quick", action="store_true", help="same as --repeats 40")
    args = parser.parse_args(argv)
    repeats = 40 if args.quick else max(args.repeats, 4)

    load = os.getloadavg()[0] if hasattr(os, "getloadavg") else float("nan")
    print(
        f"twoball lift-off benchmark -- Python {platform.python_version()}, "
        f"numpy {np.__version__}, {os.cpu_count()} CPUs, load average {load:.2f}, "
        f"BLAS threads {os.environ['OPENBLAS_NUM_THREADS']}"
    )
    timings = run(repeats)
    print(report(timings))
    failed = [t.name for t in timings if t.verdict == "FAIL"]
    if failed:
        print("targets missed (not an error; timings depend on the machine and its load):")
        for name in failed:
            print("  " + name)
    else:
        print("all targets met")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
