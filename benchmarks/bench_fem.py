"""Convergence and timing studies of the finite-element backend (dimensionless).

Run from the repository root, e.g.::

    python benchmarks/bench_fem.py eigen            # eigenvalue orders, sphere and line
    python benchmarks/bench_fem.py liftoff          # FE modal lift-off against Legendre
    python benchmarks/bench_fem.py alpha            # generalized-alpha against modal, by dt
    python benchmarks/bench_fem.py liftoff --levels 2 3 4 5 --orders 1 2
    python benchmarks/bench_fem.py timing           # wall-clock of fem_pole_motion runs

Prints plain-text tables; the numbers quoted in docs/method.rst come from here.
"""

from __future__ import annotations

import argparse
import math
import time

import numpy as np

from twoball.fem_membrane.build import build_space
from twoball.fem_membrane.eigen import lowest_eigenpairs
from twoball.fem_membrane.solve import alpha_motion, modal_model
from twoball.modal.filters import SpectralFilter
from twoball.modal.legendre import legendre_series
from twoball.modal.liftoff import find_liftoff
from twoball.modal.parameters import Case

PHI_A = 2.6
DAMPING = 0.13


def exact_sphere(count: int) -> np.ndarray:
    """l (l + 1) with multiplicity 2 l + 1, the first ``count`` values."""
    degrees = range(int(math.isqrt(count)) + 2)
    values = [d * (d + 1.0) for d in degrees for _ in range(2 * d + 1)]
    return np.array(values[:count])


def eigen_study(levels: list[int], elements: list[int], count: int = 25) -> None:
    """Largest relative error of the lowest ``count`` nonzero eigenvalues and observed order."""
    print(f"lowest {count} nonzero eigenvalues, max relative error; order from h ~ dofs^(-1/d)")
    for kind, sizes, dim in (("sphere", levels, 2), ("ring", levels, 2), ("axisym", elements, 1)):
        for order in (1, 2):
            previous = None
            for size in sizes:
                key = {"elements": size} if kind == "axisym" else {"level": size}
                space = build_space(kind, order=order, phi_a=PHI_A, **key)
                start = time.perf_counter()
                wanted = count + 1 if kind == "axisym" else (math.isqrt(count) + 1) ** 2
                pairs = lowest_eigenpairs(space.stiffness, space.mass, min(wanted, space.dofs))
                seconds = time.perf_counter() - start
                n = np.arange(count + 1)
                exact = n * (n + 1.0) if kind == "axisym" else exact_sphere(count + 1)
                error = float(np.max(np.abs(pairs.values[1 : count + 1] / exact[1:] - 1)))
                rate = ""
                if previous is not None:
                    ratio = (space.dofs / previous[1]) ** (1.0 / dim)
                    rate = f"{math.log(previous[0] / error) / math.log(ratio):6.2f}"
                print(
                    f"{kind:7s} P{order} {size:5d} dofs {space.dofs:6d}  "
                    f"err {error:9.3e}  order {rate:>6s}  {seconds:6.2f}s"
                )
                previous = (error, space.dofs)


def liftoff_study(
    kinds: list[str], levels: list[int], elements: list[int], orders: list[int]
) -> None:
    """Relative lift-off differences FE modal vs Legendre (lanczos, N = 30, D = 0.13)."""
    gamma = Case().gamma
    filt = SpectralFilter("lanczos", 30)
    ref = find_liftoff(legendre_series(PHI_A, DAMPING, filt), gamma)
    print(f"Legendre: t_l = {ref.t:.10f}, v_l = {ref.velocity:.10f}, gamma = {gamma:.6g}")
    for kind in kinds:
        sizes = elements if kind == "axisym" else levels
        for order in orders:
            for size in sizes:
                key = {"elements": size} if kind == "axisym" else {"level": size}
                for initial in ("projection", "interpolation"):
                    start = time.perf_counter()
                    model = modal_model(
                        PHI_A, DAMPING, filt, mesh=kind, order=order, initial=initial, **key
                    )
                    result = find_liftoff(model.series, gamma)
                    total = time.perf_counter() - start
                    dt = abs(result.t / ref.t - 1.0)
                    dv = abs(result.velocity / ref.velocity - 1.0)
                    print(
                        f"{kind:7s} P{order} {size:5d} {initial[:6]:6s} dofs {model.space.dofs:6d} "
                        f"modes {len(model.pairs):4d}  dt_l {dt:9.2e}  dv_l {dv:9.2e}  "
                        f"eig {model.seconds['eigen']:6.2f}s total {total:6.2f}s",
                        flush=True,
                    )


def alpha_study(kind: str, size: int, order: int, steps: list[int], rho_inf: float) -> None:
    """Generalized-alpha against modal superposition on the same mesh, by dt."""
    gamma = Case().gamma
    key = {"elements": size} if kind == "axisym" else {"level": size}
    model = modal_model(PHI_A, DAMPING, "lanczos", mesh=kind, order=order, **key)
    ref = find_liftoff(model.series, gamma)
    print(f"{model.space.name}: modal t_l = {ref.t:.10f}, v_l = {ref.velocity:.10f}")
    previous = None
    for count in steps:
        start = time.perf_counter()
        motion, info = alpha_motion(model, dt=4 * np.pi / count, rho_inf=rho_inf)
        seconds = time.perf_counter() - start
        exact = model.series.pole(motion.times)
        diff = np.array(
            [
                np.abs(motion.pole(motion.times).u - exact.u).max(),
                np.abs(motion.pole(motion.times).u_tt - exact.u_tt).max(),
            ]
        )
        result = find_liftoff(motion, gamma)
        lift = np.array([abs(result.t - ref.t), abs(result.velocity - ref.velocity)])
        rates = "" if previous is None else np.array2string(np.log2(previous / diff), precision=2)
        print(
            f"dt {info['dt']:9.3e} |du| {diff[0]:9.2e} |du_tt| {diff[1]:9.2e} "
            f"|dt_l| {lift[0]:9.2e} |dv_l| {lift[1]:9.2e} order {rates} {seconds:6.2f}s",
            flush=True,
        )
        previous = diff


TIMING_RUNS = (
    {"mesh": "axisym", "elements": 400, "order": 2, "scheme": "modal"},
    {"mesh": "axisym", "elements": 400, "order": 2, "scheme": "alpha"},
    {"mesh": "sphere", "level": 3, "order": 2, "scheme": "modal"},
    {"mesh": "sphere", "level": 4, "order": 1, "scheme": "modal"},
    {"mesh": "sphere", "level": 3, "order": 2, "scheme": "alpha"},
    {"mesh": "sphere", "level": 4, "order": 2, "scheme": "modal"},
    {"mesh": "sphere", "level": 4, "order": 2, "scheme": "alpha"},
)


def timing_study() -> None:
    """Wall-clock seconds of :func:`fem_pole_motion` (plus the lift-off search)."""
    from twoball.fem_membrane.solve import fem_pole_motion

    gamma = Case().gamma
    ref = find_liftoff(legendre_series(PHI_A, DAMPING, SpectralFilter("lanczos", 30)), gamma)
    for options in TIMING_RUNS:
        start = time.perf_counter()
        motion, info = fem_pole_motion(PHI_A, DAMPING, "lanczos", **options)
        result = find_liftoff(motion, gamma)
        total = time.perf_counter() - start
        parts = " ".join(f"{k} {v:6.2f}s" for k, v in info["seconds"].items())
        dt = abs(result.t / ref.t - 1.0)
        dv = abs(result.velocity / ref.velocity - 1.0)
        print(
            f"{info['mesh']:38s} {options['scheme']:5s} dofs {info['dofs']:6d} "
            f"modes {info['modes_computed']:4d}  dt_l {dt:8.2e} dv_l {dv:8.2e}  "
            f"{parts}  total {total:6.2f}s",
            flush=True,
        )


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("study", choices=("eigen", "liftoff", "alpha", "timing"))
    parser.add_argument("--levels", type=int, nargs="+", default=[2, 3, 4])
    parser.add_argument("--elements", type=int, nargs="+", default=[50, 100, 200, 400])
    parser.add_argument("--orders", type=int, nargs="+", default=[1, 2])
    parser.add_argument("--kinds", nargs="+", default=["axisym", "sphere", "ring"])
    parser.add_argument("--steps", type=int, nargs="+", default=[2000, 4000, 8000, 16000])
    parser.add_argument("--rho-inf", type=float, default=1.0)
    args = parser.parse_args()
    if args.study == "eigen":
        eigen_study(args.levels, args.elements)
    elif args.study == "timing":
        timing_study()
    elif args.study == "liftoff":
        liftoff_study(args.kinds, args.levels, args.elements, args.orders)
    else:
        alpha_study(args.kinds[0], args.elements[0], args.orders[0], args.steps, args.rho_inf)


if __name__ == "__main__":
    main()
