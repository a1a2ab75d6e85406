"""The command line's shell ball: ``--ball shell`` with its wall, and the shell's eigen rows.

``twoball bounce --ball shell`` takes the wall from ``--youngs-modulus E
--thickness h [--poisson NU]`` (SI; for the shell these define the wall, not the
membrane's bending) or from ``--wall-stiffness-ratio C_OVER_N0
[--thickness-ratio H] [--poisson NU]``, else the preset's
(:data:`twoball.modal.balls.shell.WALLS`); the backend's resolution from
``--modes N`` (Legendre) or ``--elements E --order p`` (the meridian's finite
elements).  ``twoball eigen --ball shell`` lists the shell's spectrum
(:func:`twoball.fem.shell_eigen`).  A flag that does not apply is refused by its
own name, with the reason.
"""

from __future__ import annotations

import argparse
from typing import Any

import twoball
from twoball._common.errors import ParameterError
from twoball.cli.values import number

__all__ = [
    "BALLS",
    "WALL_FLAGS",
    "add_ball_option",
    "add_wall_options",
    "shell_ball",
    "shell_case_args",
    "wall_options",
]

#: The kinds of lower ball of ``--ball``.
BALLS = ("membrane", "shell", "solid", "thick")
#: The wall's own flags (``--ball shell`` only), by their argparse names.
WALL_FLAGS = ("wall_stiffness_ratio", "thickness_ratio")
#: The case's flags that define the shell's wall instead of the membrane's bending.
SI_WALL_FLAGS = ("youngs_modulus", "thickness", "poisson")
#: Flags of the membrane that a shell does not take, and why.
MEMBRANE_ONLY = {
    "bending": "with --ball shell (the wall's thickness sets its bending: --youngs-modulus "
    "and --thickness, or --thickness-ratio)",
    "membrane": "with --ball shell (it has no membrane operator: its wall and tension set "
    "its spectrum)",
    "mesh": "with --ball shell (its finite elements are the meridian's: --elements, --order)",
}


def add_ball_option(parser: argparse.ArgumentParser) -> None:
    """``--ball membrane|shell`` (default membrane)."""
    parser.add_argument(
        "--ball",
        default="membrane",
        help="the lower ball: membrane (radial only, the centre a coordinate of its own; "
        "default), shell (radial and meridional displacement, in-plane stiffness and "
        "bending: its translation is a motion of its wall), solid (Lamb's elastic sphere, "
        "--preset superball or a material) or thick (a hollow ball's wall in (r, z) "
        "elasticity, finite elements)",
    )


def add_wall_options(parser: argparse.ArgumentParser) -> None:
    """``--wall-stiffness-ratio`` and ``--thickness-ratio`` (the shell's dimensionless wall)."""
    group = parser.add_argument_group(
        "the shell's wall (--ball shell; or --youngs-modulus E --thickness h --poisson NU)"
    )
    group.add_argument(
        "--wall-stiffness-ratio",
        type=number,
        metavar="C_OVER_N0",
        help="in-plane stiffness C = E h / (1 - nu^2) over the inflation tension N0 = P R / 2 "
        "(default: the preset's wall)",
    )
    group.add_argument(
        "--thickness-ratio",
        type=number,
        metavar="H",
        help="wall thickness over the radius, h / R (with --wall-stiffness-ratio; default 0: "
        "no bending)",
    )


def check_ball_kind(args: argparse.Namespace) -> str:
    """``--ball`` checked: one of :data:`BALLS`."""
    kind = getattr(args, "ball", None) or "membrane"
    if kind not in BALLS:
        raise ParameterError("ball", "one of " + ", ".join(BALLS), kind)
    return kind


def wall_options(args: argparse.Namespace) -> twoball.Wall | None:
    """The wall of the flags (None: the preset's).

    ``--youngs-modulus`` and ``--thickness`` (with ``--poisson``) make an SI wall;
    ``--wall-stiffness-ratio`` (with ``--thickness-ratio`` and ``--poisson``) a
    dimensionless one; mixing the two, or ``--poisson`` / ``--thickness-ratio``
    alone, is refused by name.
    """
    youngs, thickness = getattr(args, "youngs_modulus", None), getattr(args, "thickness", None)
    poisson = getattr(args, "poisson", None)
    ratio = getattr(args, "wall_stiffness_ratio", None)
    thick = getattr(args, "thickness_ratio", None)
    if youngs is None and thickness is None and ratio is None:
        for name, value in (("thickness_ratio", thick), ("poisson", poisson)):
            if value is not None:
                valid = "given with a wall (--youngs-modulus and --thickness, or "
                raise ParameterError(name, valid + "--wall-stiffness-ratio)", value)
        return None
    fields: dict[str, Any] = {} if poisson is None else {"poisson": poisson}
    if youngs is not None or thickness is not None:
        for name, value in (("wall_stiffness_ratio", ratio), ("thickness_ratio", thick)):
            if value is not None:
                valid = "left out with --youngs-modulus and --thickness (one kind of wall)"
                raise ParameterError(name, valid, value)
        return twoball.Wall(youngs_modulus=youngs, thickness=thickness, **fields)
    return twoball.Wall(wall_stiffness_ratio=ratio, thickness_ratio=thick, **fields)


def refuse_wall_flags(args: argparse.Namespace) -> None:
    """A membrane's run refuses the shell's own flags by name."""
    for name in WALL_FLAGS:
        value = getattr(args, name, None)
        if value is not None:
            raise ParameterError(name, "given with --ball shell (the shell's wall)", value)


def shell_case_args(args: argparse.Namespace) -> argparse.Namespace:
    """The options with the wall's SI flags taken out (they define the wall, not a bending).

    The membrane's own flags (``--bending``, ``--membrane``, ``--mesh``) are refused.
    """
    from copy import copy

    for name, why in MEMBRANE_ONLY.items():
        value = getattr(args, name, None)
        if value is not None:
            raise ParameterError(name, f"left out {why}", value)
    out = copy(args)
    for name in SI_WALL_FLAGS:
        setattr(out, name, None)
    return out


def shell_ball(args: argparse.Namespace) -> twoball.ShellBall | twoball.FEShellBall:
    """The shell of ``--backend``: ``--modes`` on Legendre degrees, ``--elements`` and
    ``--order`` on the meridian's finite elements; the wall of :func:`wall_options`."""
    wall = wall_options(args)
    elements, order = getattr(args, "elements", None), getattr(args, "order", None)
    backend = args.backend
    if backend == "legendre":
        for name, value in (("elements", elements), ("order", order)):
            if value is not None:
                valid = "left out with backend legendre (no mesh: --modes sets its resolution)"
                raise ParameterError(name, valid, value)
        return twoball.ShellBall(wall, modes=getattr(args, "modes", None))
    if backend != "fem":
        raise ParameterError("backend", "one of legendre, fem", backend)
    modes = getattr(args, "modes", None)
    if modes is not None:
        raise ParameterError("modes", "left out with backend fem (the mesh sets it)", modes)
    fields = {} if order is None else {"order": order}
    return twoball.FEShellBall(wall, elements=elements, **fields)


def gas_value(text: str | None, si: bool) -> str | float:
    """``--gas`` of the shell's eigen: a law with physical inputs, the number g with ratios."""
    if si:
        return "none" if text is None else text
    if text is None:
        return 0.0
    from twoball._common.ranges import decimal

    try:
        value = decimal(text)
    except ValueError:
        valid = (
            "the dimensionless g = 3 kappa P_abs R / C >= 0 with the ratios (a gas law "
            "needs the physical inputs: --preset or --radius, --mass, --pressure)"
        )
        raise ParameterError("gas", valid, text) from None
    return value


#: The flags of ``twoball eigen --ball shell`` (argparse names), for the membrane's refusal.
SHELL_EIGEN_FLAGS = (
    "backend",
    "poisson",
    "thickness_ratio",
    "prestress_ratio",
    "gas",
    "preset",
    "youngs_modulus",
    "thickness",
    "wall_stiffness_ratio",
    "radius",
    "mass",
    "pressure",
)


def add_shell_eigen_options(parser: argparse.ArgumentParser) -> None:
    """The options of ``twoball eigen --ball shell``: backend, the shell dimensionless or SI."""
    group = parser.add_argument_group(
        "the shell's spectrum (--ball shell): dimensionless, or physical (--preset, or "
        "--radius --mass --pressure with a wall)"
    )
    group.add_argument(
        "--backend", help="legendre (the closed form, default) or fem (the meridian's elements)"
    )
    group.add_argument(
        "--poisson", type=number, metavar="NU", help="Poisson's ratio in (0, 0.5] (default 0.5)"
    )
    group.add_argument(
        "--thickness-ratio", type=number, metavar="H", help="h / R (default 0: no bending)"
    )
    group.add_argument(
        "--prestress-ratio",
        type=number,
        metavar="P",
        help="p = N0 / C, the inflation tension over the in-plane stiffness (default 0)",
    )
    group.add_argument(
        "--gas",
        metavar="G",
        help="the enclosed gas (default none): the dimensionless g = 3 kappa P_abs R / C with "
        "the ratios, a law (isothermal, adiabatic) with physical inputs",
    )
    group.add_argument(
        "--preset", help="physical inputs: a preset's R, m, P and wall (tennis, basketball, ...)"
    )
    group.add_argument("--radius", type=number, metavar="R", help="physical: radius R [m]")
    group.add_argument("--mass", type=number, metavar="M", help="physical: mass m [kg]")
    group.add_argument(
        "--pressure", type=number, metavar="P", help="physical: excess pressure P [Pa]"
    )
    group.add_argument(
        "--youngs-modulus", type=number, metavar="E", help="physical: the wall's E [Pa]"
    )
    group.add_argument("--thickness", type=number, metavar="H", help="physical: the wall's h [m]")
    group.add_argument(
        "--wall-stiffness-ratio",
        type=number,
        metavar="C_OVER_N0",
        help="physical: the wall as C / N0 (with --thickness-ratio)",
    )


def refuse_shell_eigen_flags(args: argparse.Namespace) -> None:
    """``twoball eigen`` of the membrane refuses the shell's flags by name."""
    for name in SHELL_EIGEN_FLAGS:
        value = getattr(args, name, None)
        if value is not None:
            raise ParameterError(name, "given with --ball shell (the shell's spectrum)", value)


def shell_eigen_arguments(args: argparse.Namespace) -> dict[str, Any]:
    """The keywords of :func:`twoball.fem.shell_eigen` from the options.

    Physical inputs (``--preset``, or ``--radius --mass --pressure``) with the wall
    of :func:`wall_options` (default the preset's); else the ratios.  The
    membrane's mesh flags (``--mesh``, ``--level``, ``--mesh-file``, ``--pole``,
    ``--geometry``, ``--membrane``) are refused, and ``--elements``/``--order``
    with the closed form.
    """
    for name in ("mesh", "mesh_file", "pole", "level", "geometry", "membrane"):
        value = getattr(args, name, None)
        if value is not None:
            valid = "left out with --ball shell (its elements are the meridian's: --elements, "
            raise ParameterError(name, valid + "--order)", value)
    backend = args.backend or "legendre"
    if backend not in ("legendre", "fem"):
        raise ParameterError("backend", "one of legendre, fem", backend)
    out: dict[str, Any] = {"backend": backend}
    if args.count is not None:
        out["count"] = args.count
    if backend == "fem":
        if args.elements is not None:
            out["elements"] = args.elements
        if args.order is not None:
            out["order"] = args.order
    else:
        for name in ("elements", "order"):
            if getattr(args, name, None) is not None:
                valid = "left out with backend legendre (the closed form has no mesh)"
                raise ParameterError(name, valid, getattr(args, name))
    trio = (args.radius, args.mass, args.pressure)
    physical = args.preset is not None or any(v is not None for v in trio)
    physical_wall = args.youngs_modulus is not None or args.thickness is not None
    if not physical:
        for name in ("youngs_modulus", "thickness", "wall_stiffness_ratio"):
            if getattr(args, name) is not None:
                valid = "given with physical inputs (--preset, or --radius --mass --pressure)"
                raise ParameterError(name, valid, getattr(args, name))
        out |= {
            "poisson": 0.5 if args.poisson is None else args.poisson,
            # a value given ('' or 0) goes to the API as typed: only a missing one is 0
            "thickness_ratio": 0.0 if args.thickness_ratio is None else args.thickness_ratio,
            "prestress_ratio": 0.0 if args.prestress_ratio is None else args.prestress_ratio,
            "gas": gas_value(args.gas, si=False),
        }
        return out
    if args.prestress_ratio is not None:
        valid = "left out with physical inputs (the wall and the pressure set p = N0 / C)"
        raise ParameterError("prestress_ratio", valid, args.prestress_ratio)
    gas = gas_value(args.gas, si=True)
    if any(v is not None for v in trio):
        if any(v is None for v in trio):
            raise ParameterError("--radius/--mass/--pressure", "given together")
        preset = args.preset or "basketball"
        case = twoball.Case.from_pressure(
            args.pressure, args.mass, preset=preset, radius=args.radius, gas="isothermal"
        )
        if args.preset is None and not physical_wall and args.wall_stiffness_ratio is None:
            raise ParameterError("wall_stiffness_ratio", "given (a wall for this ball)", None)
    else:
        from twoball._lookup import MEASURED

        if args.preset not in MEASURED:
            raise ParameterError("preset", "one of " + ", ".join(MEASURED), args.preset)
        from dataclasses import replace

        # the preset's R, c and P (a gas law carries P; the spectrum takes --gas's)
        case = twoball.Case.preset(args.preset)
        if case.pressure is None:
            pressure = MEASURED[args.preset].pressure
            case = replace(case, pressure=pressure, gas="isothermal")
    out["case"] = case
    out["gas"] = gas  # the law of --gas (none by default), not the case's
    wall = wall_options(args)
    if wall is not None:
        out["wall"] = wall
    return out
