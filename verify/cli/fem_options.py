"""Command-line options of the finite-element backend (``liftoff --backend fem``, ``eigen``).

SI at the edge: ``--dt`` is in seconds and becomes ``dt c`` for the solver.
"""

from __future__ import annotations

import argparse
import time
from typing import Any

from twoball.fem_membrane.checks import check_dt
from twoball.fem_membrane.solve import fem_pole_motion
from twoball.modal.filters import SpectralFilter
from twoball.modal.parameters import Case
from twoball.modal.report import LiftoffReport, report_liftoff, t_end_dimensionless

from twoball.budget import check_fem

VALID_RANGES: dict[str, str] = {
    "--level": "an integer >= 0",
    "--elements": "an integer >= 2",
    "--order": "1 or 2",
    "--dt": "a time step > 0 [s]",
    "--count": "an integer >= 1",
}
MESHES = ("sphere", "ring", "axisym")


def add_mesh_options(parser: argparse.ArgumentParser) -> None:
    """``--mesh``, ``--level`` | ``--elements`` and ``--order``."""
    group = parser.add_argument_group("finite-element mesh")
    group.add_argument(
        "--mesh",
        default="sphere",
        help="sphere (icosphere), ring (latitude rows, one at phi_a) or axisym (x = cos phi)",
    )
    sizes = group.add_mutually_exclusive_group()
    sizes.add_argument("--level", type=int, help="sphere refinement level >= 0 (default 3)")
    sizes.add_argument("--elements", type=int, help="axisymmetric line elements >= 2 (default 400)")
    group.add_argument("--order", type=int, default=2, help="element order 1 or 2 (default 2)")


def add_time_options(parser: argparse.ArgumentParser) -> None:
    """``--time``, ``--damping-model`` and ``--dt`` of the finite-element lift-off."""
    group = parser.add_argument_group("finite-element time integration")
    group.add_argument(
        "--time", default="modal", help="modal (superposition) or alpha (generalized-alpha)"
    )
    group.add_argument(
        "--damping-model", default="modal", help="modal (ratio D per mode) or rayleigh"
    )
    group.add_argument(
        "--dt", type=float, metavar="SECONDS", help="time step [s] (default: omega_cut dt = 0.2)"
    )
    group.add_argument(
        "--route",
        default="auto",
        help="modal eigen route: full (every pair below the cutoff), krylov (rational "
        "Krylov, pole motion exact to 1e-10 relative) or auto (krylov from 2000 DOFs; default)",
    )


def fem_liftoff(case: Case, args: argparse.Namespace) -> LiftoffReport:
    """The shared lift-off of the finite-element pole motion for the options' mesh (SI)."""
    dt_s = check_dt(args.dt)
    check_fem(
        args.mesh,
        args.level,
        args.elements,
        args.order,
        case.modes,
        args.route,
        time=args.time,
        dt=None if dt_s is None else dt_s / case.scalings.time,
        t_end=t_end_dimensionless(case, args.t_end),
        time_unit_s=case.scalings.time,
    )
    started = time.perf_counter()
    motion, info = fem_pole_motion(
        case.phi_a,
        case.damping,
        SpectralFilter(args.sigma, case.modes),
        mesh=args.mesh,
        level=args.level,
        elements=args.elements,
        order=args.order,
        time=args.time,
        damping_model=args.damping_model,
        dt=None if dt_s is None else dt_s / case.scalings.time,
        t_end=t_end_dimensionless(case, args.t_end),
        route=args.route,
    )
    extra: dict[str, Any] = {
        "dofs": info["dofs"],
        "modes_used": info["modes_used"],
        "mesh": info["mesh"],
        "order": info["order"],
        "time_scheme": info["time_scheme"],
        "route": info["route"],
        "damping_model": info.get("damping_model", args.damping_model),
        "seconds": time.perf_counter() - started,
    }
    if "dt" in info:
        extra["dt_s"] = info["dt"] * case.scalings.time
    if "rayleigh" in info:
        extra["rayleigh"] = info["rayleigh"]
    from twoball.fem_membrane.guards import fem_warnings

    notes = fem_warnings(
        info,
        SpectralFilter(args.sigma, case.modes),
        level=args.level,
        elements=args.elements,
        time_unit_s=case.scalings.time,
    )
    return report_liftoff(
        case,
        motion,
        backend="fem",
        sigma=args.sigma,
        recontact=args.recontact,
        t_end_s=args.t_end,
        extra=extra,
        warnings=notes,
    )
