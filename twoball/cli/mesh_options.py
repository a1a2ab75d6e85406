"""The one definition of the command-line mesh and time options of the finite elements.

Every subcommand that takes a mesh (``liftoff --backend fem``, ``eigen``,
``export``, ``render``, ``plot``) adds its options here and hands them, unchanged
and None when not given, to the public function, whose
:class:`twoball.fem_membrane.options.MeshOptions` supplies the defaults and refuses an
option that does not apply (``--level`` with ``--mesh axisym``, ``--elements``
on a sphere); the solver they feed is built by :mod:`twoball.cli.solver_options`.
"""

from __future__ import annotations

import argparse
from pathlib import Path

import twoball
from twoball._common import choices as _choices
from twoball.cli.values import integer, number

_KIND_HELP = {
    "sphere": "sphere (icosphere)",
    "ring": "ring (latitude rows, one at phi_a)",
    "axisym": "axisym (line x = cos phi)",
}


def add_mesh_options(
    parser: argparse.ArgumentParser,
    kinds: tuple[str, ...] | None = None,
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
    kinds = _choices.MESH_KINDS if kinds is None else kinds
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
        "--level",
        type=integer,
        help=f"sphere refinement level >= 0 (default {_choices.DEFAULT_LEVEL})",
    )
    if "axisym" in kinds:
        sizes.add_argument(
            "--elements",
            type=integer,
            help=f"axisymmetric line elements >= 2 (default {_choices.DEFAULT_ELEMENTS})",
        )
    group.add_argument(
        "--order",
        type=integer,
        help=f"element and geometry order 1, 2, 3 or 4 (default {_choices.DEFAULT_ORDER})",
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


def add_time_options(parser: argparse.ArgumentParser) -> None:
    """``--scheme``, ``--damping-model``, ``--dt``, ``--route`` of the lift-off's solvers."""
    group = parser.add_argument_group("finite-element time integration")
    group.add_argument(
        "--scheme",
        help="time integration: modal (superposition, default) or alpha (generalized-alpha)",
    )
    group.add_argument(
        "--damping-model",
        help="damping law: modal (ratio D on every mode, default) or rayleigh "
        "(C = alpha M + beta K fitted to D at the lowest mode and omega_N); any backend",
    )
    group.add_argument(
        "--dt",
        type=number,
        metavar="SECONDS",
        help="time step [s] of --scheme alpha (default: omega_cut dt = 0.2), or of the "
        "Moreau-Jean steps with --mass-ratio (default 0.005 / c)",
    )
    group.add_argument(
        "--route",
        help="modal eigen route: full (every pair below the cutoff), krylov (rational "
        "Krylov, pole motion exact to 1e-10 relative) or auto (krylov from 2000 DOFs; default)",
    )


def mesh_options(args: argparse.Namespace) -> twoball.MeshOptions | None:
    """The mesh options given on the command line as :class:`~twoball.MeshOptions` (or None).

    ``--mesh-file PATH`` becomes ``MeshOptions(file=Path(PATH))`` (a path,
    never a kind name).
    """
    names = ("level", "elements", "order", "pole", "geometry", "initial")
    fields = {n: getattr(args, n) for n in names if getattr(args, n, None) is not None}
    kind = getattr(args, "mesh", None)
    path = getattr(args, "mesh_file", None)
    if kind is None and path is None and not fields:
        return None
    if path is not None:
        return twoball.MeshOptions(file=Path(path), **fields)
    return twoball.MeshOptions(kind, **fields)


def refuse_mesh_flags(args: argparse.Namespace, why: str) -> None:
    """Refuse the first mesh option given, by its own name (``--level``, not ``--mesh``)."""
    names = ("mesh", "mesh_file", "pole", "level", "elements", "order", "geometry", "initial")
    for name in names:
        value = getattr(args, name, None)
        if value is not None:
            raise twoball.ParameterError(name, f"left out {why}", value)


def damping_options(args: argparse.Namespace) -> twoball.ModalRatio | twoball.Rayleigh | None:
    """``--damping-model`` as a damping law: ``rayleigh`` fitted to D, ``modal`` the paper's.

    Refused beside ``--rayleigh ALPHA,BETA`` (a law of its own).
    """
    law = getattr(args, "damping_model", None)
    if law is not None and getattr(args, "rayleigh", None) is not None:
        raise twoball.ParameterError(
            "damping_model", "left out with --rayleigh ALPHA,BETA (one damping law)", law
        )
    if law is None or law == "modal":
        return None
    if law == "rayleigh":
        return twoball.Rayleigh()
    raise twoball.ParameterError("damping_model", "one of modal, rayleigh", law)


__all__ = [
    "refuse_mesh_flags",
    "add_mesh_options",
    "add_route_option",
    "add_time_options",
    "damping_options",
    "mesh_options",
]
