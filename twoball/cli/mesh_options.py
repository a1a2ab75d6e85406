"""The one definition of the command-line mesh and time options of the finite elements.

Every subcommand that takes a mesh (``liftoff --backend fem``, ``eigen``,
``export``, ``render``, ``plot``) adds its options here and hands them, unchanged
and None when not given, to the public function, whose
:class:`twoball.fem_membrane.options.MeshOptions` supplies the defaults and refuses an
option that does not apply (``--level`` with ``--mesh axisym``, ``--elements``
on a sphere, ``--dt`` with ``--scheme modal``, any of them with ``--backend legendre``).
"""

from __future__ import annotations

import argparse
from pathlib import Path
from typing import Any

from twoball.fem_membrane.options import (
    DEFAULT_ELEMENTS,
    DEFAULT_LEVEL,
    DEFAULT_ORDER,
    MESH_KINDS,
    SPHERE_KINDS,
)

VALID_RANGES: dict[str, str] = {
    "--level": "an integer >= 0",
    "--elements": "an integer >= 2",
    "--order": "1, 2, 3 or 4",
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
    files: bool = True,
    geometry: bool = False,
) -> None:
    """``--mesh`` | ``--mesh-file`` (with ``--pole``), ``--level`` | ``--elements``, ``--order``.

    Defaults are None here: the public API fills them in (level 3, 400
    elements, order 2) and refuses options that do not apply.  ``--elements``
    exists if ``axisym`` is a kind, ``--mesh-file`` and ``--pole`` if ``files``,
    ``--geometry`` if ``geometry``.
    """
    group = parser.add_argument_group("finite-element mesh")
    which = group.add_mutually_exclusive_group()
    which.add_argument(
        "--mesh",
        help=", ".join(_KIND_HELP[k] for k in kinds) + "; default sphere",
    )
    if files:
        which.add_argument(
            "--mesh-file",
            metavar="PATH",
            help="your own sphere mesh: any file meshio reads (.msh, .vtu, .stl, ...), "
            "any radius and centre, 3- or 6-node triangles",
        )
        group.add_argument(
            "--pole",
            metavar="X,Y,Z",
            help="with --mesh-file: direction of the pole in the file's frame (default 0,0,1)",
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
        "--order",
        type=int,
        help=f"element and geometry order 1, 2, 3 or 4 (default {DEFAULT_ORDER})",
    )
    if geometry:
        group.add_argument(
            "--geometry",
            help="discrete sphere: isoparametric (order-p interpolant, default) or exact "
            "(radial projection of the flat triangles; sphere and --mesh-file only)",
        )
    if initial:
        group.add_argument(
            "--initial",
            default="projection",
            help="initial displacement (3.10) in the FE space: projection (default) "
            "or interpolation",
        )


ROUTE_HELP = (
    "FE mode shapes of the fields: full (every eigenpair below the cutoff), krylov "
    "(Ritz pairs of the rational Krylov route, converged on the whole field) or auto "
    "(krylov from 2000 DOFs; default)"
)


def add_route_option(parser: argparse.ArgumentParser) -> None:
    """``--route`` of the field commands (export, render, plot waterfall|pole)."""
    parser.add_argument("--route", help=ROUTE_HELP)


def route_arguments(args: argparse.Namespace) -> dict[str, Any]:
    """``route`` for the API when ``--route`` was given (else the API's default)."""
    return {} if getattr(args, "route", None) is None else {"route": args.route}


def add_time_options(parser: argparse.ArgumentParser) -> None:
    """``--scheme``, ``--damping-model``, ``--dt``, ``--route`` of the finite-element lift-off."""
    group = parser.add_argument_group("finite-element time integration")
    group.add_argument(
        "--scheme",
        help="time integration: modal (superposition, default) or alpha (generalized-alpha)",
    )
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
    """The mesh options given on the command line, as keyword arguments of the API.

    ``--mesh-file PATH`` becomes ``mesh=Path(PATH)`` (a path, never a kind name).
    """
    names = ("mesh", "level", "elements", "order", "pole", "geometry", "initial")
    options = {n: getattr(args, n) for n in names if hasattr(args, n)}
    if getattr(args, "mesh_file", None) is not None:
        options["mesh"] = Path(args.mesh_file)
    return options


def time_arguments(args: argparse.Namespace) -> dict[str, Any]:
    """The time options given on the command line, as keyword arguments of the API."""
    return {n: getattr(args, n) for n in ("scheme", "dt", "route", "damping_model")}


__all__ = [
    "SPHERE_KINDS",
    "VALID_RANGES",
    "add_mesh_options",
    "add_time_options",
    "mesh_arguments",
    "time_arguments",
]
