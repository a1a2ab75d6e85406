"""Large-mesh timing of the finite-element lift-off: full eigen route against Krylov.

Run from the repository root, e.g.::

    python benchmarks/bench_fem_scale.py            # P1 levels 4-6, P2 levels 3-5
    python benchmarks/bench_fem_scale.py --quick    # P1 levels 4-5, P2 levels 3-4
    python benchmarks/bench_fem_scale.py --cases 2:5 1:6 --routes krylov

Each (case, route) runs in a fresh subprocess so that its peak memory is its own:
the peak resident set size from ``resource.getrusage(RUSAGE_SELF).ru_maxrss`` of
that subprocess (it includes scipy's and SuperLU's C allocations, which
tracemalloc does not see; it also includes the interpreter and imports, about
0.1 GB).  Times are wall-clock seconds for assembly (mesh, K, M and the load b),
the solve (all eigenpairs below the cutoff + modal series, or the Krylov series)
and the lift-off search.  Default: Lanczos filter, N = 30, basketball case
D = 0.13, phi_a = 2.6, gamma = 9.81 / (0.12 * 320^2).  Dimensionless results.
"""

from __future__ import annotations

import argparse
import json
import os
import resource
import subprocess
import sys
import time

PHI_A = 2.6
DAMPING = 0.13
GAMMA = 9.81 / (0.12 * 320.0**2)
FULL_CASES = [(1, 4), (1, 5), (1, 6), (2, 3), (2, 4), (2, 5)]
QUICK_CASES = [(1, 4), (1, 5), (2, 3), (2, 4)]
ROUTES = ("full", "krylov")


def worker(order: int, level: int, route: str, kind: str, modes: int) -> dict[str, object]:
    """One case and route in this process; returns timings, peak memory and the lift-off."""
    from twoball.fem_membrane.build import build_space
    from twoball.fem_membrane.eigen import eigenpairs
    from twoball.fem_membrane.initial import initial_moments
    from twoball.fem_membrane.krylov import krylov_modal_series
    from twoball.fem_membrane.modal import modal_series
    from twoball.modal.filters import SpectralFilter
    from twoball.modal.liftoff import find_liftoff

    filter = SpectralFilter(kind, modes)
    start = time.perf_counter()
    space = build_space("sphere", level=level, order=order, phi_a=PHI_A)
    moments = initial_moments(space, PHI_A)
    assembly = time.perf_counter() - start
    start = time.perf_counter()
    extra: dict[str, object] = {}
    if route == "full":
        pairs = eigenpairs(space.stiffness, space.mass, filter.omega_cut**2)
        series = modal_series(pairs, moments, space.pole, DAMPING, filter)
        extra["modes"] = len(pairs)
    else:
        series, info = krylov_modal_series(space, moments, DAMPING, filter)
        extra.update(
            modes=info.modes,
            basis=info.basis_size,
            iterations=info.iterations,
            converged=info.converged,
            change=info.trajectory_change,
        )
    solve = time.perf_counter() - start
    start = time.perf_counter()
    result = find_liftoff(series, GAMMA)
    liftoff = time.perf_counter() - start
    peak = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 2**20  # kB -> GB (Linux)
    return {
        "order": order,
        "level": level,
        "route": route,
        "dofs": space.dofs,
        "assembly": assembly,
        "solve": solve,
        "liftoff": liftoff,
        "total": assembly + solve + liftoff,
        "peak_gb": peak,
        "t_l": result.t,
        "v_l": result.velocity,
        **extra,
    }


def run_case(order: int, level: int, route: str, kind: str, modes: int) -> dict[str, object]:
    """Run :func:`worker` in a fresh interpreter and parse its JSON line."""
    command = [
        sys.executable,
        os.path.abspath(__file__),
        "--worker",
        f"{order}:{level}:{route}",
        "--filter",
        kind,
        "--modes",
        str(modes),
    ]
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    env = dict(os.environ)
    env["PYTHONPATH"] = root + os.pathsep + env.get("PYTHONPATH", "")
    done = subprocess.run(command, capture_output=True, text=True, env=env, check=False)
    if done.returncode != 0:
        return {"order": order, "level": level, "route": route, "error": done.stderr[-2000:]}
    return json.loads(done.stdout.strip().splitlines()[-1])


def relative(a: float | None, b: float | None) -> float:
    """|a / b - 1|, nan when either is missing."""
    if a is None or b is None:
        return float("nan")
    return abs(a / b - 1.0)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--quick", action="store_true", help="P1 levels 4-5, P2 levels 3-4")
    parser.add_argument("--cases", nargs="+", help="ORDER:LEVEL, e.g. 2:5 1:6")
    parser.add_argument("--routes", nargs="+", choices=ROUTES, default=list(ROUTES))
    parser.add_argument("--filter", default="lanczos", choices=("lanczos", "printed", "none"))
    parser.add_argument("--modes", type=int, default=30)
    parser.add_argument("--worker", help=argparse.SUPPRESS)
    args = parser.parse_args()
    if args.worker:
        order, level, route = args.worker.split(":")
        print(json.dumps(worker(int(order), int(level), route, args.filter, args.modes)))
        return
    if args.cases:
        cases = [tuple(int(x) for x in case.split(":")) for case in args.cases]
    else:
        cases = QUICK_CASES if args.quick else FULL_CASES
    print(
        f"filter {args.filter}, N = {args.modes}, D = {DAMPING}, phi_a = {PHI_A}, "
        f"gamma = {GAMMA:.6g}; peak = ru_maxrss of a fresh subprocess per run [GB]; "
        f"load average {os.getloadavg()[0]:.1f} on {os.cpu_count()} cores"
    )
    header = (
        f"{'mesh':8s} {'dofs':>6s} {'route':6s} {'modes':>5s} {'assemb':>7s} {'solve':>8s} "
        f"{'liftoff':>7s} {'total':>8s} {'peak':>6s} {'t_l':>14s} {'v_l':>14s}"
    )
    print(header)
    for order, level in cases:
        rows = {}
        for route in args.routes:
            row = run_case(order, level, route, args.filter, args.modes)
            rows[route] = row
            name = f"P{order} L{level}"
            if "error" in row:
                print(f"{name:8s} {route:6s} FAILED: {row['error']}", flush=True)
                continue
            print(
                f"{name:8s} {row['dofs']:6d} {route:6s} {row['modes']:5d} "
                f"{row['assembly']:7.2f} {row['solve']:8.2f} {row['liftoff']:7.2f} "
                f"{row['total']:8.2f} {row['peak_gb']:6.2f} {row['t_l']:14.10f} "
                f"{row['v_l']:14.10f}",
                flush=True,
            )
        full, fast = rows.get("full"), rows.get("krylov")
        if full and fast and "error" not in full and "error" not in fast:
            print(
                f"{'':8s} full/krylov: time {full['total'] / fast['total']:6.1f}x "
                f"(solve {full['solve'] / fast['solve']:6.1f}x), "
                f"memory {full['peak_gb'] / fast['peak_gb']:5.1f}x; "
                f"|dt_l| rel {relative(fast['t_l'], full['t_l']):8.1e}, "
                f"|dv_l| rel {relative(fast['v_l'], full['v_l']):8.1e}",
                flush=True,
            )


if __name__ == "__main__":
    main()
