"""Calibration of the closed form's and the finite elements' cost models against measurement.

The estimates are those of :mod:`twoball.modal.cost` and
:mod:`twoball.fem_membrane.cost`, which the guard of :mod:`twoball._common.budget`
compares with the limits.

Run from the repository root::

    python benchmarks/bench_budget.py           # series N = 1000, 3000; FE P1 L4, P2 L3
    python benchmarks/bench_budget.py --quick   # series N = 1000; FE P2 L3

Each run is one fresh interpreter: peak RSS from ``resource.getrusage`` (it
includes the interpreter and imports, ~90 MiB, which the estimates include as
their base) and the CPU time (user + system) of the work alone -- on a shared
machine the wall time of a single-threaded run grows with the others' load, the
CPU time does not.  Prints estimate / measured for both; the estimates are meant
to be right within a factor of 2-3.
"""

from __future__ import annotations

import argparse
import math
import os
import subprocess
import sys
import textwrap
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
if str(ROOT) not in sys.path:
    sys.path.insert(0, str(ROOT))

WRAPPER = textwrap.dedent(
    """
    import resource, sys
    import numpy, scipy.sparse.linalg, skfem
    def cpu():
        usage = resource.getrusage(resource.RUSAGE_SELF)
        return usage.ru_utime + usage.ru_stime
    start = cpu()
    exec(sys.argv[1])
    print(resource.getrusage(resource.RUSAGE_SELF).ru_maxrss * 1024, cpu() - start)
    """
)


def measure(code: str) -> tuple[float, float]:
    """Peak RSS [bytes] and CPU seconds of ``code`` in a fresh interpreter."""
    env = dict(os.environ, OPENBLAS_NUM_THREADS="1")
    done = subprocess.run(
        [sys.executable, "-c", WRAPPER, code],
        cwd=ROOT,
        env=env,
        capture_output=True,
        text=True,
        check=True,
    )
    peak, seconds = done.stdout.split()[-2:]
    return float(peak), float(seconds)


def twoball_case(name: str, modes: int) -> object:
    """A preset with ``modes``."""
    import twoball

    return twoball.Case.preset(name, modes=modes)


def check_series_estimate(modes: int, stiffness: object) -> object:
    """The closed form's estimate with the converged reference, as the guard makes it."""
    from twoball.modal.cost import reference_estimate, series_estimate

    top = float(stiffness.legendre_omega(float(modes)))
    return series_estimate(modes, 4 * math.pi, omega_max=top) + reference_estimate(
        4 * math.pi, modes, 0.13, stiffness
    )


def main() -> None:
    """Print the table."""
    from twoball._common import budget
    from twoball.fem_membrane.cost import fem_dofs, fem_estimate
    from twoball.modal.contact.cost import contact_estimate
    from twoball.modal.cost import legendre_omega, reference_estimate, series_estimate

    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true")
    quick = parser.parse_args().quick
    rows = []
    for modes in [1000] if quick else [1000, 3000]:
        code = (
            "from twoball.modal.parameters import preset\n"
            "from twoball.modal.report import legendre_liftoff\n"
            f"legendre_liftoff(preset('basketball').derive(modes={modes}))\n"
        )
        estimate = series_estimate(modes, 4 * math.pi) + reference_estimate(4 * math.pi, modes)
        rows.append((f"series N = {modes}", estimate, *measure(code)))
    code = "import twoball\ntwoball.liftoff(twoball.Case.preset('tennis', modes=240))\n"
    tennis = twoball_case("tennis", 240)
    estimate = check_series_estimate(240, tennis.stiffness)
    rows.append(("series tennis N = 240", estimate, *measure(code)))
    code = (
        "import twoball\n"
        "twoball.liftoff(twoball.Case.preset('basketball', modes=120), body=twoball.Body(0.1))\n"
    )
    estimate = contact_estimate(121, legendre_omega(120), 4 * math.pi)
    rows.append(("contact N = 120", estimate, *measure(code)))
    for level, order in [(3, 2)] if quick else [(4, 1), (3, 2)]:
        code = (
            "from twoball.fem_membrane.solve import fem_pole_motion\n"
            f"fem_pole_motion(2.6, 0.13, 'lanczos', level={level}, order={order})\n"
        )
        dofs = fem_dofs("sphere", level, None, order)
        rows.append((f"FE P{order} level {level}", fem_estimate(dofs), *measure(code)))
    print(f"{'run':22s} {'memory est':>11s} {'measured':>11s} {'ratio':>6s}"
          f" {'time est':>9s} {'CPU':>9s} {'ratio':>6s}")  # fmt: skip
    for name, estimate, peak, seconds in rows:
        print(
            f"{name:22s} {budget.format_bytes(estimate.memory):>11s} "
            f"{budget.format_bytes(peak):>11s} {estimate.memory / peak:6.2f} "
            f"{estimate.seconds:8.2f}s {seconds:8.2f}s {estimate.seconds / seconds:6.2f}"
        )


if __name__ == "__main__":
    main()
