"""Wall-time benchmark of one whole bounce with the shell ball, beside the membrane's.

Run from the repository root (not a timed test: speed is measured, not asserted)::

    python benchmarks/bench_shell.py            # 5 repeats per task
    python benchmarks/bench_shell.py --quick    # 3 repeats

Tasks: the basketball with the tennis ball on top, touching (Table 1's row 4,
``twoball.bounce(pair="basketball-tennis")``), at each ball's defaults: the
membrane on Legendre modes N = 192 and on axisymmetric P2 with 96 elements (the
same-run baselines), the shell (the basketball's wall C/N0 = 4) on Legendre
degrees N = 128 (257 modes; target <= 2 s) and on the meridian's elements, P2
with 64 elements (target <= 20 s); each after one untimed warm-up (imports, the
lumped baselines' fits).  The shell's build (its modes and rows) is timed apart.
The machine's load average is printed before and after: on a shared machine the
wall times follow it.  Exit status 0.
"""

from __future__ import annotations

import os

for _name in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_name, "1")

import argparse  # noqa: E402
import platform  # noqa: E402
import sys  # noqa: E402
from collections.abc import Callable  # noqa: E402
from pathlib import Path  # noqa: E402

import numpy as np  # noqa: E402
from timing import timed  # noqa: E402

ROOT = Path(__file__).resolve().parent.parent
if str(ROOT) not in sys.path:
    sys.path.insert(0, str(ROOT))

PAIR = "basketball-tennis"


def main(argv: list[str] | None = None) -> int:
    """Time the whole bounces; print medians, interquartile ranges and the targets."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="3 repeats")
    args = parser.parse_args(argv)
    repeats = 3 if args.quick else 5

    import twoball
    from twoball.modal.floor.inputs import resolve_drop
    from twoball.modal.floor.options import Drop

    def whole(ball: object) -> Callable[[], object]:
        return lambda: twoball.bounce(pair=PAIR, solver=twoball.MoreauJean(ball))

    case = resolve_drop(twoball.Case.preset("basketball"), Drop()).case
    tasks: list[tuple[str, Callable[[], object], float | None]] = [
        ("membrane, legendre N = 192 (baseline)", whole(twoball.LegendreBall()), None),
        ("membrane, fem axisym 96 P2 (baseline)", whole(twoball.FEBall()), None),
        ("shell build, legendre N = 128", lambda: twoball.ShellBall().describe(case), None),
        ("shell build, meridian 64 P2", lambda: twoball.FEShellBall().describe(case), None),
        ("shell, legendre N = 128", whole(twoball.ShellBall()), 2.0),
        ("shell, meridian 64 P2", whole(twoball.FEShellBall()), 20.0),
    ]
    print(
        f"twoball {twoball.__version__}, Python {platform.python_version()}, "
        f"{os.cpu_count()} CPUs, load {os.getloadavg()[0]:.2f}"
    )
    print()
    print("| task | wall median [s] | wall IQR [s] | CPU median [s] | target [s] |")
    print("|---|---|---|---|---|")
    for label, task, target in tasks:
        wall, cpu = timed(task, repeats)
        q1, q3 = np.percentile(wall, [25, 75])
        shown = "" if target is None else f"{target:g}"
        print(
            f"| {label} | {np.median(wall):.2f} | {q3 - q1:.2f} | {np.median(cpu):.2f} | {shown} |",
            flush=True,
        )
    report = twoball.bounce(pair=PAIR, solver=twoball.MoreauJean(twoball.ShellBall()))
    print()
    print(
        f"shell legendre N = 128: v1/|v0| = {report.v1_ratio:.4f}, v2/|v0| = "
        f"{report.v2_ratio:.4f}, {report.result.steps} steps, "
        f"{report.as_dict()['body_contacts']} body contacts"
    )
    print(f"load at the end {os.getloadavg()[0]:.2f}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
