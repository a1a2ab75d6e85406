"""Eigenpairs of the elastic ball in finite elements against Lamb's roots: time, memory, error.

Run from anywhere with the package installed, e.g.::

    OPENBLAS_NUM_THREADS=1 python benchmarks/bench_solid.py            # both routes
    python benchmarks/bench_solid.py 3d --sizes 0.35,0.2 0.3,0.15     # (size, surface) pairs
    python benchmarks/bench_solid.py axisym --sizes 0.04,0.01

Each case runs in a child process, so its peak memory (``resource.getrusage``,
maximum resident set size) is its own.  Times are wall-clock and include meshing,
assembly, the shift-invert eigensolve and the classification.  Dimensionless:
eta = omega R / c_s, nu = 1/4.

3-D: every eigenpair below the first root of degree ``--degree`` (all azimuthal
orders, torsional and spheroidal, the six rigid modes) on a P2 tetrahedral ball
from gmsh graded to the surface.  Axisymmetric: every m = 0 eigenpair below the
same cut (degree 30 by default) on a gmsh half disc graded to the arc.

Columns: "err k=1" is the largest relative error of the first spheroidal
multiplet of each degree <= ``--degree`` (the lowest 2n + 1 modes labelled
spheroidal of degree n, every azimuthal order; one mode in (r, z)) against Lamb's
first root, "miss" the copies of those multiplets not found; "err all" the largest
relative error of every mode below the cut against the exact value of its label
(Lamb's roots; torsional ones against (n - 1) j_n(y) = y j_{n+1}(y)), and "unlab"
the modes whose label has no exact value within 10 % (classification failures).

Measured on the project's 2-core machine (one BLAS thread; other sessions were
running, load average 6-8, so the times are upper bounds), nu = 1/4:

    route    size  surf   elems    dofs modes  time s peak GB   err k=1 miss   err all unlab
    3d        0.4  0.25     932    5340   324    28.1    0.51  1.49e-01   31  9.94e-02    35
    3d        0.3  0.18    2136   11622   324    51.1    0.77  6.02e-02   21  6.02e-02    11
    3d       0.25  0.14    3734   19875   324   107.5    0.94  4.14e-02    0  3.44e-02     2
    3d        0.2  0.11    6961   35607   324   262.9    1.23  2.15e-02    0  1.61e-02     3
    axisym   0.08  0.02    1720    7262   157     8.3    0.16  1.32e-03    0  6.93e-03     0
    axisym   0.05 0.012    4373   18120   157    20.1    0.26  2.01e-04    0  1.21e-03     0
    axisym   0.04  0.01    6461   26604   157    26.0    0.34  9.03e-05    0  5.26e-04     0

The axisymmetric route meets 1e-4 for the first root of every degree up to 30 in
26 s and 0.34 GB.  The 3-D P2 route does not meet 1e-4 up to degree 10 in 60 s:
its worst mode (a degree-10 multiplet) is still pre-asymptotic at 35k unknowns
(2.2e-2; the m = 0 copy of the same mesh size in (r, z) is 5.4e-3).  With the
asymptotic h^4 it would need about 3.8x smaller elements, some 2 million unknowns,
far beyond SuperLU's fill in 4 GB.  What would be needed: higher-order tetrahedra
(the error falls as h^(2p)), a nested-dissection sparse Cholesky with spectrum
slicing, or one (r, z) problem per azimuthal order m (the ball is axisymmetric).
"""

from __future__ import annotations

import argparse
import json
import resource
import subprocess
import sys
import time

import numpy as np
from scipy.optimize import brentq
from scipy.special import spherical_jn

NU = 0.25


def torsional_roots(n: int, top: float) -> list[float]:
    """Roots of (n - 1) j_n(y) - y j_{n+1}(y) below ``top`` (Lamb 1882, the torsional family)."""

    def f(y):
        return (n - 1) * spherical_jn(n, y) - y * spherical_jn(n + 1, y)

    grid = np.arange(0.3, top, 0.005)
    v = f(grid)
    return [
        brentq(f, grid[i], grid[i + 1], xtol=1e-14)
        for i in np.flatnonzero(np.sign(v[:-1]) != np.sign(v[1:]))
    ]


def reference(degree: int, three_d: bool) -> tuple[float, dict, int]:
    """The cut eta, the exact value of each (kind, n, k), and the number of modes below the cut."""
    from twoball.modal.solid.lamb import lamb_roots

    top = float(lamb_roots(degree, NU, 1)[0]) * (1.0 + 1e-3)
    exact: dict[tuple[str, int, int], float] = {}
    count = 3 if three_d else 1  # translations (3-D: and below, rotations)
    for n in range(0, 3 * degree + 10):
        roots = lamb_roots(n, NU, 1 + int(top))
        for k, eta in enumerate(roots, start=1):
            exact[("spheroidal", n, k)] = float(eta)
            if eta < top:
                count += (2 * n + 1) if three_d else 1
        if three_d and n >= 1:
            for k, eta in enumerate(torsional_roots(n, top + 3.0), start=1):
                exact[("torsional", n, k)] = float(eta)
                if eta < top:
                    count += 2 * n + 1
    if three_d:
        count += 3  # rotations
    return top, exact, count


def run_case(route: str, size: float, surface: float, degree: int) -> dict:
    """One case in this process: mesh, eigenpairs, classification, errors, time, peak memory."""
    from twoball.fem_solid.eigen import axisymmetric_eigen, ball_eigen
    from twoball.fem_solid.mesh import ball_gmsh, half_disc_gmsh

    three_d = route == "3d"
    top, exact, count = reference(degree, three_d)
    start = time.perf_counter()
    if three_d:
        mesh = ball_gmsh(size, surface)
        e = ball_eigen(mesh, NU, count + 10, max_degree=degree + 4)
    else:
        mesh = half_disc_gmsh(size, surface)
        e = axisymmetric_eigen(mesh, NU, count + 5, max_degree=degree + 10)
    seconds = time.perf_counter() - start
    kinds = np.array(e.kind)
    # the k = 1 multiplet of each degree <= `degree`: the lowest 2n + 1 (3-D) or 1 (m = 0)
    # modes labelled spheroidal of that degree, against Lamb's first root
    first, missing = 0.0, 0
    for n in range(degree + 1):
        copies = (2 * n + 1) if three_d else 1
        found = np.sort(e.eta[(kinds == "spheroidal") & (e.degree == n) & ~e.rigid])[:copies]
        missing += copies - len(found)
        if len(found):
            first = max(first, float(np.max(np.abs(found / exact[("spheroidal", n, 1)] - 1))))
    # every labelled mode below the cut against the exact value of its label
    every, unlabelled = 0.0, 0
    for i in np.flatnonzero(~e.rigid & (e.eta < top * (1 - 2e-3))):
        key = (e.kind[i], int(e.degree[i]), int(e.radial_order[i]))
        if key not in exact or abs(e.eta[i] / exact[key] - 1) > 0.1:
            unlabelled += 1
            continue
        every = max(every, abs(e.eta[i] / exact[key] - 1))
    peak = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss * 1024  # kB on Linux
    return {
        "route": route,
        "size": size,
        "surface": surface,
        "elements": int(mesh.nelements),
        "dofs": int(e.basis.N),
        "modes": int(len(e.eta)),
        "rigid": int(e.rigid.sum()),
        "seconds": seconds,
        "peak_gb": peak / 2**30,
        "max_rel_error_first": first,
        "missing_first": missing,
        "max_rel_error_all": every,
        "unlabelled": unlabelled,
    }


def main(argv: list[str] | None = None) -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("route", nargs="?", choices=["3d", "axisym", "both"], default="both")
    parser.add_argument("--sizes", nargs="*", help="size,surface pairs (units of R)")
    parser.add_argument("--degree", type=int, help="highest degree (3-D 10, axisym 30)")
    parser.add_argument("--child", action="store_true", help=argparse.SUPPRESS)
    args = parser.parse_args(argv)
    if args.child:
        size, surface = (float(v) for v in args.sizes[0].split(","))
        print(json.dumps(run_case(args.route, size, surface, args.degree)))
        return
    plan = []
    if args.route in ("3d", "both"):
        sizes = args.sizes or ["0.4,0.25", "0.3,0.18", "0.25,0.14"]
        plan += [("3d", s, args.degree or 10) for s in sizes]
    if args.route in ("axisym", "both"):
        sizes = args.sizes or ["0.08,0.02", "0.05,0.012", "0.04,0.01"]
        plan += [("axisym", s, args.degree or 30) for s in sizes]
    header = (
        f"{'route':7} {'size':>5} {'surf':>5} {'elems':>7} {'dofs':>7} {'modes':>5} "
        f"{'time s':>7} {'peak GB':>7} {'err k=1':>9} {'miss':>4} {'err all':>9} {'unlab':>5}"
    )
    print(f"nu = {NU}; modes below the first root of the highest degree")
    print(header)
    for route, sizes, degree in plan:
        child = [sys.executable, __file__, route, "--child", "--sizes", sizes, "--degree"]
        out = subprocess.run([*child, str(degree)], capture_output=True, text=True, check=True)
        r = json.loads(out.stdout.strip().splitlines()[-1])
        print(
            f"{r['route']:7} {r['size']:5.3g} {r['surface']:5.3g} {r['elements']:7d} "
            f"{r['dofs']:7d} {r['modes']:5d} {r['seconds']:7.1f} {r['peak_gb']:7.2f} "
            f"{r['max_rel_error_first']:9.2e} {r['missing_first']:4d} "
            f"{r['max_rel_error_all']:9.2e} {r['unlabelled']:5d}",
            flush=True,
        )


if __name__ == "__main__":
    main()
