"""Wall-time benchmark of the whole bounce with each kind of upper body, beside the rigid one.

Run from outside the checkout with the package installed (not a timed test:
speed is measured, not asserted)::

    python benchmarks/bench_bodies.py            # 3 repeats, a 50-point sweep per kind
    python benchmarks/bench_bodies.py --quick    # 1 repeat, a 16-point sweep

Tasks, all on the basketball and the tennis ball (Table 1's row 4), touching
(Delta x = 0), at the defaults of each backend -- Legendre modes N = 192 and
axisymmetric P2 with 96 elements -- after one untimed warm-up: the rigid body
(Newton's e12 on a cap, today's, the same-run baseline), the lumped body (its
compliant row: substeps of a hundredth of its own contact time while it is
compressed, a Newton iteration per substep) and the ball body (the tennis
membrane on N = 64 Legendre modes, 22 rows); then a sweep of Delta x in
[0, 250] mm with each kind on the Legendre modes, one process (a loop of
``twoball.bounce``), and the tennis ball's coin (Hertz, the stiffest law: its
substeps are a quarter of a microsecond) at Delta x = 0 and 150 mm.  The
machine's load average is printed before and after: on a shared machine the
wall times follow it.  Exit status 0.
"""

from __future__ import annotations

import os

for _name in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_name, "1")

import argparse  # noqa: E402
import platform  # noqa: E402
import time  # noqa: E402
from collections.abc import Callable  # noqa: E402

import numpy as np  # noqa: E402
from timing import timed  # noqa: E402

PAIR = "basketball-tennis"
KINDS = ("rigid", "lumped", "ball")


def main(argv: list[str] | None = None) -> int:
    """Time one whole bounce per kind and backend, the sweeps and the coin; print the table."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="1 repeat, a 16-point sweep")
    args = parser.parse_args(argv)
    repeats = 1 if args.quick else 3
    import twoball

    backends = {"legendre N = 192": twoball.LegendreBall, "fem axisym 96 P2": twoball.FEBall}
    print(
        f"twoball {twoball.__version__}, Python {platform.python_version()}, "
        f"{os.cpu_count()} CPUs, load {os.getloadavg()[0]:.2f}"
    )
    print("| task | wall median [s] | CPU [s] | steps | x rigid | v1/abs(v0) |")
    print("|---|---|---|---|---|---|")
    for label, make in backends.items():
        base = None
        for kind in KINDS:
            out: dict[str, object] = {}

            def task(kind: str = kind, make: Callable = make, out: dict = out) -> None:
                out["report"] = twoball.bounce(
                    pair=PAIR, body=kind, solver=twoball.MoreauJean(make())
                )

            wall, cpu = timed(task, repeats)
            median = float(np.median(wall))
            base = median if base is None else base
            report = out["report"]
            print(
                f"| {kind} body, {label} | {median:.2f} | {float(np.median(cpu)):.2f} | "
                f"{report.result.steps} | {median / base:.1f} | {report.v1_ratio:.4f} |",
                flush=True,
            )
    count = 16 if args.quick else 50
    gaps = np.linspace(0.0, 0.25, count)
    base = None
    for kind in KINDS:
        start, start_cpu = time.perf_counter(), time.process_time()
        for gap in gaps:
            twoball.bounce(drop=twoball.Drop(gap=float(gap)), pair=PAIR, body=kind)
        wall = time.perf_counter() - start
        base = wall if base is None else base
        print(
            f"| sweep of {count} gaps, {kind} body, legendre N = 192 | {wall:.1f} | "
            f"{time.process_time() - start_cpu:.1f} | - | {wall / base:.1f} | - |",
            flush=True,
        )
    for gap in (0.0, 0.15):
        for kind in ("rigid", "lumped"):
            start = time.perf_counter()
            report = twoball.bounce(drop=twoball.Drop(gap=gap), pair="tennis-coin", body=kind)
            print(
                f"| tennis-coin, {kind}, gap {gap * 1e3:g} mm, legendre N = 192 | "
                f"{time.perf_counter() - start:.2f} | - | {report.result.steps} | - | "
                f"{report.v1_ratio:.4f} |",
                flush=True,
            )
    print(f"load after: {os.getloadavg()[0]:.2f}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
