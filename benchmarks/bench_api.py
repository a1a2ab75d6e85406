"""Cost of the public API and of the CLI layer over the closed-form lift-off.

Run from the repository root::

    python benchmarks/bench_api.py            # full run
    python benchmarks/bench_api.py --quick    # fewer repeats

Each task is timed over repeated runs after one untimed warm-up; the report gives
the median and its ratio to the baseline measured in the same process, the direct
solver call :func:`twoball.modal.report.legendre_liftoff` on the basketball preset.
Nothing is asserted: speed is measured here, not in the test suite.
"""

from __future__ import annotations

import os

for _name in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_name, "1")

import argparse  # noqa: E402
import contextlib  # noqa: E402
import io  # noqa: E402
import statistics  # noqa: E402
import sys  # noqa: E402
import time  # noqa: E402
from collections.abc import Callable  # noqa: E402
from pathlib import Path  # noqa: E402

ROOT = Path(__file__).resolve().parent.parent
if str(ROOT) not in sys.path:
    sys.path.insert(0, str(ROOT))


def median_time(task: Callable[[], object], repeats: int, inner: int) -> float:
    """Median over ``repeats`` of the mean wall time [s] of ``inner`` calls."""
    task()  # warm-up
    samples = []
    for _ in range(repeats):
        start = time.perf_counter()
        for _ in range(inner):
            task()
        samples.append((time.perf_counter() - start) / inner)
    return statistics.median(samples)


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="fewer repeats")
    repeats = 5 if parser.parse_args().quick else 21

    import twoball
    from twoball.cli.main import main as cli
    from twoball.modal.report import legendre_liftoff

    case = twoball.Case.preset("basketball")
    slower = case.derive(v0=3.0)

    def cli_json() -> None:
        with contextlib.redirect_stdout(io.StringIO()):
            cli(["liftoff", "--json"])

    tasks: list[tuple[str, Callable[[], object], int]] = [
        ("legendre_liftoff(case) [baseline]", lambda: legendre_liftoff(case), 20),
        ("twoball.liftoff(case)", lambda: twoball.liftoff(case), 20),
        ("twoball liftoff --json (in process)", cli_json, 20),
        ("Case.preset().derive(damping=0.2)", lambda: case.derive(damping=0.2), 2000),
        ("derive(damping) of an eq. (3.7) case", lambda: slower.derive(damping=0.2), 2000),
        ("Case.preset().derive(v0=3.0) [eq. (3.7)]", lambda: case.derive(v0=3.0), 2000),
    ]
    baseline = None
    print(f"{'task':44s} {'median':>12s} {'ratio':>8s}")
    for name, task, inner in tasks:
        t = median_time(task, repeats, inner)
        baseline = t if baseline is None else baseline
        print(f"{name:44s} {t * 1e6:9.1f} us {t / baseline:8.3f}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
