"""Wall-time benchmark of one drop of the lower ball on the floor (``twoball.bounce``).

Run from the repository root (not a timed test: speed is measured, not asserted)::

    python benchmarks/bench_bounce.py            # 7 repeats per task
    python benchmarks/bench_bounce.py --quick    # 3 repeats

Tasks: the basketball at 4.1 m/s at the defaults of each backend -- Legendre
modes N = 192 (target <= 1 s) and axisymmetric P2 with 96 elements (target
<= 10 s) -- after one untimed warm-up (imports).  Each task is reported as the
median and interquartile range of its wall times, and as a ratio to a baseline
measured in the same run (the closed-form lift-off ``twoball.liftoff()``, ~10
ms), so that a busy machine shows as a slower baseline rather than a slower
drop.  Exit status 0 always.
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


def timed(task: Callable[[], object], repeats: int) -> np.ndarray:
    """Wall times [s] of ``repeats`` runs after one untimed warm-up."""
    task()
    samples = []
    for _ in range(repeats):
        start = time.perf_counter()
        task()
        samples.append(time.perf_counter() - start)
    return np.array(samples)


def main(argv: list[str] | None = None) -> int:
    """Time the drops and print medians, interquartile ranges and baseline ratios."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="3 repeats instead of 7")
    args = parser.parse_args(argv)
    repeats = 3 if args.quick else 7
    import twoball

    tasks: list[tuple[str, Callable[[], object], float | None]] = [
        ("baseline: twoball.liftoff()", lambda: twoball.liftoff(), None),
        ("bounce, legendre N = 192", lambda: twoball.bounce(), 1.0),
        (
            "bounce, fem axisym 96 P2",
            lambda: twoball.bounce(solver=twoball.MoreauJean(twoball.FEBall())),
            10.0,
        ),
    ]
    print(
        f"twoball {twoball.__version__}, Python {platform.python_version()}, "
        f"{os.cpu_count()} CPUs, load {os.getloadavg()[0]:.2f}"
    )
    base = None
    for name, task, target in tasks:
        samples = timed(task, repeats)
        median = float(np.median(samples))
        q25, q75 = np.percentile(samples, [25, 75])
        base = median if base is None else base
        verdict = "" if target is None else ("PASS" if median <= target else "FAIL")
        print(
            f"{name:32s} median {median:8.4f} s  IQR {q75 - q25:7.4f} s  "
            f"x baseline {median / base:8.1f}  {verdict} "
            + ("" if target is None else f"(target <= {target:g} s)")
        )
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
