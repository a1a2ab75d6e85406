"""The one definition of the command-line mesh and time options of the finite elements.

Every subcommand that takes a mesh (``liftoff --backend fem``, ``eigen``,
``export``, ``render``, ``plot``) adds its options here and hands them, unchanged
and None when not given, to the public function, whose
:class:`twoball.mesh_options.MeshOptions` supplies the defaults and refuses an
option that does not apply (``--level`` with ``--mesh axisym``, ``--elements``
on a sphere, ``--dt`` with ``--time modal``, any of them with ``--backend legendre``).
"""

from __future__ import annotations

import argparse
from typing import Any

from twoball.mesh_options import (
    DEFAULT_ELEMENTS,
    DEFAULT_LEVEL,
    DEFAULT_ORDER,
    MESH_KINDS,
    SPHERE_KINDS,
)

VALID_RANGES: dict[str, str] = {
    "--level": "an integer >= 0",
    "--elements": "an integer >= 2",
    "--order": "1 or 2",
    "--dt": "a time step > 0 [s]",
}
_KIND_HELP = {
    "sphere": "sphere (icosphere)",
    "ring": "ring (latitude rows, one at phi_a)",
    "axisym": "axisym (line x = cos phi)",
}


def add_mesh_options(
    parser: argparse.ArgumentParser,
    kinds: tuple[str, ...] = MESH_KINDS,
    *,
    initial: bool = False,
) -> None:
    """``--mesh``, ``--level`` (and ``--elements`` if ``axisym`` is a kind), ``--order``.

    Defaults are None here: the public API fills them in (level 3, 400
    elements, order 2) and refuses options that do not apply.
    """
    group = parser.add_argument_group("finite-element mesh")
    group.add_argument(
        "--mesh",
        help=", ".join(_KIND_HELP[k] for k in kinds) + "; default sphere",
    )
    sizes = group.add_mutually_exclusive_group()
    sizes.add_argument(
        "--level", type=int, help=f"sphere refinement level >= 0 (default {DEFAULT_LEVEL})"
    )
    if "axisym" in kinds:
        sizes.add_argument(
            "--elements",
            type=int,
            help=f"axisymmetric line elements >= 2 (default {DEFAULT_ELEMENTS})",
        )
    group.add_argument(
        "--order", type=int, help=f"element and geometry order 1 or 2 (default {DEFAULT_ORDER})"
    )
    if initial:
        group.add_argument(
            "--initial",
            default="projection",
            help="initial displacement (3.10) in the FE space: projection (default) "
            "or interpolation",
        )


def add_time_options(parser: argparse.ArgumentParser) -> None:
    """``--time``, ``--damping-model``, ``--dt`` and ``--route`` of the finite-element lift-off."""
    group = parser.add_argument_group("finite-element time integration")
    group.add_argument("--time", help="modal (superposition, default) or alpha (generalized-alpha)")
    group.add_argument(
        "--damping-model", help="alpha only: modal (ratio D per mode, default) or rayleigh"
    )
    group.add_argument(
        "--dt",
        type=float,
        metavar="SECONDS",
        help="alpha only: time step [s] (default: omega_cut dt = 0.2)",
    )
    group.add_argument(
        "--route",
        help="modal eigen route: full (every pair below the cutoff), krylov (rational "
        "Krylov, pole motion exact to 1e-10 relative) or auto (krylov from 2000 DOFs; default)",
    )


def mesh_arguments(args: argparse.Namespace) -> dict[str, Any]:
    """The mesh options given on the command line, as keyword arguments of the API."""
    names = ("mesh", "level", "elements", "order", "initial")
    return {n: getattr(args, n) for n in names if hasattr(args, n)}


def time_arguments(args: argparse.Namespace) -> dict[str, Any]:
    """The time options given on the command line, as keyword arguments of the API."""
    return {n: getattr(args, n) for n in ("time", "dt", "route", "damping_model")}


__all__ = [
    "SPHERE_KINDS",
    "VALID_RANGES",
    "add_mesh_options",
    "add_time_options",
    "mesh_arguments",
    "time_arguments",
]
