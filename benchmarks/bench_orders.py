"""Sphere lift-off at P1 to P4 near 41k unknowns: error, seconds and peak memory.

Run from the repository root::

    python benchmarks/bench_orders.py                 # P1 L6, P2 L5, P3 L4, P4 L4 (+ P4 exact)
    python benchmarks/bench_orders.py --cases 4:4 2:5 --geometry exact

Each case runs end to end through the public API (:func:`twoball.liftoff` with a
:class:`twoball.Superposition` solver: mesh, assembly, load, Krylov route,
lift-off search) in a fresh subprocess, so that its peak resident set size
(``resource.getrusage(RUSAGE_SELF).ru_maxrss`` of that child) is its own; the
time is the child's wall clock around the call (imports excluded).  t_l and v_l
are compared with the Legendre series of the same case, N = 30 and the same
filter (:func:`twoball.liftoff`), the limit of the finite elements as h -> 0.
P1 L6, P2 L5 and P4 L4 have exactly 40 962 DOFs; P3 L4 has 23 042 (P3 L5 would
have 92 162).  The last columns are the ratios of seconds and of errors to the
P2 row of the same run (same DOFs).
Basketball case (phi_a = 2.6, D = 0.13), Lanczos filter.
"""

from __future__ import annotations

import argparse
import json
import os
import resource
import subprocess
import sys
import time

DEFAULT_CASES = [(1, 6, "isoparametric"), (2, 5, "isoparametric"), (3, 4, "isoparametric"),
                 (4, 4, "isoparametric"), (4, 4, "exact")]  # fmt: skip


def worker(order: int, level: int, geometry: str) -> dict[str, object]:
    """One case in this process: the public API end to end, and the peak memory."""
    import twoball

    case = twoball.Case.preset("basketball")
    mesh = twoball.MeshOptions("sphere", level=level, order=order, geometry=geometry)
    start = time.perf_counter()
    report = twoball.liftoff(case, solver=twoball.Superposition(mesh, route="krylov"))
    seconds = time.perf_counter() - start
    peak = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 2**20  # kB -> GB (Linux)
    exact = twoball.liftoff(case)  # Legendre N = 30, same filter
    return {
        "order": order,
        "level": level,
        "geometry": geometry,
        "dofs": report.extra["dofs"],
        "seconds": seconds,
        "peak_gb": peak,
        "t_error": abs(report.t_liftoff_s / exact.t_liftoff_s - 1.0),
        "v_error": abs(report.v_liftoff_m_s / exact.v_liftoff_m_s - 1.0),
    }


def run_child(order: int, level: int, geometry: str) -> dict[str, object]:
    """Run :func:`worker` in a fresh interpreter from the repository root."""
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    env = {**os.environ, "PYTHONPATH": root + os.pathsep + os.environ.get("PYTHONPATH", "")}
    command = [sys.executable, os.path.abspath(__file__), "--worker",
               f"{order}:{level}:{geometry}"]  # fmt: skip
    output = subprocess.run(command, check=True, capture_output=True, text=True, cwd=root, env=env)
    return json.loads(output.stdout.strip().splitlines()[-1])


def table(rows: list[dict[str, object]]) -> str:
    """Markdown table with the ratios to the P2 row."""
    p2 = next((r for r in rows if r["order"] == 2), None)
    lines = [
        "| case | DOFs | seconds | peak GB | t_l rel. error | v_l rel. error "
        "| seconds / P2 | t_l error / P2 | v_l error / P2 |",
        "|---|---|---|---|---|---|---|---|---|",
    ]
    for r in rows:
        ratios = ["-", "-", "-"]
        if p2 is not None:
            ratios = [f"{r['seconds'] / p2['seconds']:.2f}", f"{r['t_error'] / p2['t_error']:.2e}",
                      f"{r['v_error'] / p2['v_error']:.2e}"]  # fmt: skip
        exact = " exact" if r["geometry"] == "exact" else ""
        lines.append(
            f"| P{r['order']} L{r['level']}{exact} | {r['dofs']} | {r['seconds']:.1f} | "
            f"{r['peak_gb']:.2f} | {r['t_error']:.2e} | {r['v_error']:.2e} | "
            + " | ".join(ratios)
            + " |"
        )
    return "\n".join(lines)


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--worker", help=argparse.SUPPRESS)
    parser.add_argument("--cases", nargs="*", metavar="P:L", help="order:level pairs")
    parser.add_argument("--geometry", default=None, help="isoparametric or exact for --cases")
    parser.add_argument("--json", action="store_true", help="print the rows as JSON")
    args = parser.parse_args(argv)
    if args.worker:
        order, level, geometry = args.worker.split(":")
        print(json.dumps(worker(int(order), int(level), geometry)))
        return 0
    if args.cases:
        geometry = args.geometry or "isoparametric"
        cases = [(int(c.split(":")[0]), int(c.split(":")[1]), geometry) for c in args.cases]
    else:
        cases = DEFAULT_CASES
    rows = []
    for order, level, geometry in cases:
        rows.append(run_child(order, level, geometry))
        print(f"P{order} L{level} {geometry}: {rows[-1]}", file=sys.stderr, flush=True)
    print(json.dumps(rows, indent=1) if args.json else table(rows))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
