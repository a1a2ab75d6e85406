"""The command line's solid ball and thick wall: ``--ball solid|thick``, and the solid's eigen rows.

``twoball bounce --ball solid`` and ``twoball liftoff --ball solid`` take the
material from ``--youngs-modulus E --poisson NU --density RHO`` (SI; all three)
or from ``--preset superball`` (any of the three then overrides the preset's),
the radius from ``--radius`` (default the preset's), and set the case's wave
speed to ``c = c_s / R`` (docs/solid.rst, eq. (S1)); the resolution from
``--modes N --radial-orders K`` (Lamb's modes, ``--backend legendre``) or
``--level L --pole-levels J`` (the (r, z) half disc, ``--backend fem``).
``twoball bounce --ball thick`` is the hollow ball of the preset (tennis) with
its wall from ``--youngs-modulus --thickness [--poisson] [--density]`` or the
preset's (:data:`twoball.fem_solid.ball.THICK_WALLS`), on ``--elements`` cells
along the half circle and ``--wall-cells`` across (finite elements only).
``twoball eigen --ball solid`` lists Lamb's spectrum (:func:`twoball.fem.solid_eigen`).
A flag that does not apply is refused by its own name, with the reason.
"""

from __future__ import annotations

import argparse
from typing import Any

import twoball
from twoball._common.errors import ParameterError
from twoball.cli.values import integer, number

__all__ = [
    "add_solid_options",
    "solid_ball",
    "solid_case",
    "solid_rows",
    "thick_ball",
]

#: The membrane's flags a solid ball does not take, and why.
NOT_SOLID = {
    "wave_speed": "with --ball solid (c = c_s / R of the material)",
    "pressure": "with --ball solid (a solid ball has no excess pressure)",
    "mass": "with --ball solid (its mass is (4/3) pi R^3 rho)",
    "bending": "with --ball solid (its elasticity is the material's)",
    "gas": "with --ball solid (no enclosed gas)",
    "atmosphere": "with --ball solid (no enclosed gas)",
    "membrane": "with --ball solid (no membrane operator)",
    "mesh": "with --ball solid (its elements are the half disc's: --level, --pole-levels)",
    "thickness": "with --ball solid (a solid ball: --ball thick for a wall)",
    "wall_stiffness_ratio": "with --ball solid (the shell's wall)",
    "thickness_ratio": "with --ball solid (the shell's wall)",
    "pair": "with --ball solid (Table 1's lower balls are a tennis ball and a basketball; a "
    "body on the solid: --mass-ratio)",
}


def add_solid_options(
    parser: argparse.ArgumentParser, *, level: bool = True, view: bool = False
) -> None:
    """``--density``, ``--radial-orders``, ``--pole-levels``, ``--wall-cells`` (and ``--level``,
    ``--view``)."""
    group = parser.add_argument_group(
        "the solid ball and the thick wall (--ball solid|thick; with --youngs-modulus, --poisson)"
    )
    group.add_argument(
        "--density", type=number, metavar="RHO", help="the material's density [kg/m^3]"
    )
    group.add_argument(
        "--radial-orders",
        type=integer,
        metavar="K",
        help="--ball solid, legendre: radial orders per degree (default 8)",
    )
    if level:
        group.add_argument(
            "--level",
            type=integer,
            metavar="L",
            help="--ball solid, fem: uniform refinements of the half disc (default 3)",
        )
    group.add_argument(
        "--pole-levels",
        type=integer,
        metavar="J",
        help="--ball solid, fem: refinements towards the south pole (default 0)",
    )
    group.add_argument(
        "--top-levels",
        type=integer,
        metavar="J",
        help="--ball solid, fem: refinements towards the north pole, a body's cap (default 0)",
    )
    if view:
        group.add_argument(
            "--view",
            metavar="KIND",
            help="--export/--render: surface (default) or cut (the meridian plane through a "
            "solid or thick ball: the wave inside)",
        )
    group.add_argument(
        "--wall-cells",
        type=integer,
        metavar="M",
        help="--ball thick: cells across the wall (default 2; --elements: along it, 96)",
    )


#: The solid's and the thick wall's own flags (argparse names).
SOLID_FLAGS = ("density", "radial_orders", "pole_levels", "top_levels", "wall_cells", "view")


def refuse_solid_flags(args: argparse.Namespace, level: bool = True) -> None:
    """A membrane's or a shell's run refuses the solid's own flags by name."""
    names = (*SOLID_FLAGS, "level") if level else SOLID_FLAGS
    for name in names:
        value = getattr(args, name, None)
        if value is not None and not (name == "view" and value == "surface"):
            raise ParameterError(name, "given with --ball solid or thick", value)


def _refuse(args: argparse.Namespace, table: dict[str, str]) -> None:
    for name, why in table.items():
        value = getattr(args, name, None)
        if value is not None:
            raise ParameterError(name, f"left out {why}", value)


def material(args: argparse.Namespace) -> twoball.SolidMaterial:
    """The material of the flags: all three SI values, or the preset's with overrides."""
    values = {
        "density": getattr(args, "density", None),
        "youngs_modulus": getattr(args, "youngs_modulus", None),
        "poisson": getattr(args, "poisson", None),
    }
    preset = args.preset
    from twoball._lookup import MATERIALS

    if preset in MATERIALS:
        base = MATERIALS[preset]
        given = {k: v for k, v in values.items() if v is not None}
        if not given:
            return base
        fields = {k: getattr(base, k) for k in values} | given
        return twoball.SolidMaterial(**fields)
    missing = [k for k, v in values.items() if v is None]
    if missing:
        valid = "given (a material: --youngs-modulus, --poisson, --density; or --preset superball)"
        raise ParameterError(missing[0], valid, None)
    return twoball.SolidMaterial(**values)


def solid_case(args: argparse.Namespace) -> twoball.Case:
    """The case of ``--ball solid``: the material's ``c = c_s / R``, the radius, ``|v0|``, D.

    Without a material (``--youngs-modulus``, ``--poisson``, ``--density``) the
    superball preset's; ``--preset superball`` with some of them overrides those.
    """
    from twoball._common.choices import STANDARD_GRAVITY
    from twoball._lookup import MATERIALS, SUPERBALL_RADIUS
    from twoball.cli.case_options import apply_limits

    _refuse(args, NOT_SOLID)
    if getattr(args, "phi_a", None) is not None:
        raise ParameterError("phi_a", "left out with --ball solid (no truncated start)", args.phi_a)
    apply_limits(args)
    if args.preset in (None, "basketball"):  # the verbs' defaults: the superball's, if no material
        args.preset = "superball" if _no_material(args) else None
    if args.preset is not None and args.preset not in MATERIALS:
        valid = "superball, or none with --youngs-modulus, --poisson, --density"
        raise ParameterError("preset", valid, args.preset)
    chosen = material(args)
    preset = None if args.preset is None else twoball.Case.preset(args.preset)
    radius = args.radius if args.radius is not None else SUPERBALL_RADIUS
    fields: dict[str, Any] = {
        "radius": radius,
        "wave_speed": chosen.wave_speed(radius),
        "v0": args.v0 if args.v0 is not None else (preset.v0 if preset else 4.1),
        "damping": 0.0 if args.damping is None else args.damping,
        "preset_name": args.preset,
    }
    if args.g != STANDARD_GRAVITY:
        fields["g"] = args.g
    if args.modes is not None and getattr(args, "backend", "legendre") == "legendre":
        fields["modes"] = args.modes
    if getattr(args, "rayleigh", None) is not None:
        from twoball.cli.case_options import rayleigh_option

        if args.damping is not None:
            valid = "left out with --rayleigh ALPHA,BETA (the law has its own coefficients)"
            raise ParameterError("damping", valid, args.damping)
        fields["rayleigh"] = rayleigh_option(args.rayleigh)
    return twoball.Case(**fields)


def _no_material(args: argparse.Namespace) -> bool:
    return all(getattr(args, k, None) is None for k in ("density", "youngs_modulus", "poisson"))


def solid_ball(args: argparse.Namespace) -> Any:
    """The solid of ``--backend``: Lamb's modes or the (r, z) half disc, the flags' material
    when it differs from the preset's."""
    from twoball._lookup import MATERIALS

    chosen = material(args)
    given = None if MATERIALS.get(args.preset or "") == chosen else chosen
    backend = args.backend
    if backend == "legendre":
        for name in ("level", "pole_levels", "top_levels", "elements", "order", "wall_cells"):
            if getattr(args, name, None) is not None:
                valid = "left out with backend legendre (Lamb's modes: --modes, --radial-orders)"
                raise ParameterError(name, valid, getattr(args, name))
        return twoball.SolidBall(given, modes=args.modes, radial_orders=args.radial_orders)
    if backend != "fem":
        raise ParameterError("backend", "one of legendre, fem", backend)
    for name in ("modes", "radial_orders", "elements", "wall_cells"):
        if getattr(args, name, None) is not None:
            valid = "left out with backend fem (the half disc: --level, --pole-levels)"
            raise ParameterError(name, valid, getattr(args, name))
    fields = {}
    if getattr(args, "level", None) is not None:
        fields["level"] = args.level
    if args.pole_levels is not None:
        fields["pole_levels"] = args.pole_levels
    if args.top_levels is not None:
        fields["top_levels"] = args.top_levels
    if getattr(args, "order", None) is not None:
        fields["order"] = args.order
    return twoball.FESolidBall(given, **fields)


def thick_ball(args: argparse.Namespace) -> Any:
    """The thick wall of the flags (``--youngs-modulus --thickness [--poisson] [--density]``,
    else the preset's) on ``--wall-cells`` x ``--elements`` P2 cells."""
    for name in (
        "modes",
        "radial_orders",
        "level",
        "pole_levels",
        "top_levels",
        "wall_stiffness_ratio",
    ):
        if getattr(args, name, None) is not None:
            valid = "left out with --ball thick (the annulus: --elements, --wall-cells)"
            raise ParameterError(name, valid, getattr(args, name))
    if args.backend not in ("legendre", "fem"):
        raise ParameterError("backend", "one of legendre, fem", args.backend)
    youngs, thickness = args.youngs_modulus, args.thickness
    wall = None
    if youngs is not None or thickness is not None or args.thickness_ratio is not None:
        fields: dict[str, Any] = {"youngs_modulus": youngs}
        if args.thickness_ratio is not None:
            fields["thickness_ratio"] = args.thickness_ratio
        else:
            fields["thickness"] = thickness
        if args.poisson is not None:
            fields["poisson"] = args.poisson
        if args.density is not None:
            fields["density"] = args.density
        if youngs is None:
            raise ParameterError("youngs_modulus", "given with the wall's thickness", None)
        wall = twoball.ThickWall(**fields)
    elif args.poisson is not None or args.density is not None:
        name = "poisson" if args.poisson is not None else "density"
        raise ParameterError(name, "given with a wall (--youngs-modulus, --thickness)", None)
    along = 96 if args.elements is None else args.elements
    across = 2 if args.wall_cells is None else args.wall_cells
    try:
        return twoball.ThickBall(wall, cells=(across, along))
    except ParameterError as error:  # the API's one ``cells``: across first, then along
        if error.name != "cells":
            raise
        name = "wall_cells" if repr(error.got) == repr(across) else "elements"  # nan too
        raise ParameterError(name, error.valid, error.got) from None


def thick_case_args(args: argparse.Namespace) -> argparse.Namespace:
    """The options with the wall's flags taken out of the case (they define the wall)."""
    from copy import copy

    out = copy(args)
    for name in ("youngs_modulus", "thickness", "poisson", "density"):
        setattr(out, name, None)
    for name in ("bending", "membrane", "mesh"):
        value = getattr(args, name, None)
        if value is not None:
            raise ParameterError(name, "left out with --ball thick (its wall sets it)", value)
    if out.preset is None:
        out.preset = "tennis"
    return out


def solid_rows(report: Any) -> list[tuple[str, str]]:
    """The rows of a solid's or thick wall's drop that replace the membrane's (SI)."""
    from twoball.cli.console import number

    model = report.model
    rows = [("m2 [kg]", f"{report.mass_kg:.4g}")]
    if model.get("ball") == "solid":
        mat = model["material"]
        hertz = model["hertz"]
        tt, force = report.result.force
        unit = report.mass_kg * report.case.radius * report.case.wave_speed**2
        peak = float(force.max()) * unit if force.size else float("nan")
        rows += [
            (
                "E [MPa], nu, rho [kg/m^3]",
                f"{mat['youngs_modulus_Pa'] / 1e6:.4g}, {mat['poisson']:g}, "
                f"{mat['density_kg_m3']:.4g}",
            ),
            (
                "c_s [m/s], c = c_s/R [1/s]",
                f"{mat['shear_speed_m_s']:.4g}, {report.case.wave_speed:.5g}",
            ),
            ("contact time [ms]", number(report.contact_time_s, 1e3)),
            ("  Hertz [ms]", number(hertz["contact_time_s"], 1e3)),
            ("peak floor force [N]", f"{peak:.4g}"),
            ("  Hertz [N]", f"{hertz['peak_force_N']:.4g}"),
            (
                "  Hertz regime: t_H/T_2, a/R",
                f"{hertz['quasi_static_ratio']:.3g}, {hertz['contact_angle_rad']:.3g}",
            ),
            ("  floor points in a (expected)", f"{hertz['contact_points_expected']:.3g}"),
        ]
    else:
        wall = model["wall"]
        rows += [
            (
                "wall: E [MPa], h/R, nu, rho",
                f"{wall['youngs_modulus'] / 1e6:.4g}, {wall['thickness_ratio_used']:.4g}, "
                f"{wall['poisson']:g}, {wall['density_kg_m3']:.4g}",
            ),
            ("gas", str(model.get("gas"))),
            ("prestress", str(model["prestress"])),
            ("contact time [ms]", number(report.contact_time_s, 1e3)),
        ]
    return rows


#: Flags of the membrane's lift-off that a dropped solid does not take, and why.
NOT_DROPPED = {
    "mass_ratio": "with --ball solid in liftoff (the massless body on the dropped ball; a body "
    "of finite mass: twoball bounce --ball solid --mass-ratio)",
    "contact_radius": "with --ball solid in liftoff (the massless body rests on the pole)",
    "restitution": "with --ball solid in liftoff (no body impacts)",
    "energy": "with --ball solid in liftoff",
    "sigma": "with --ball solid in liftoff (the drop starts undeformed: nothing to filter)",
    "recontact": "with --ball solid in liftoff (the whole window)",
    "scheme": "with --ball solid in liftoff (Moreau-Jean steps)",
    "route": "with --ball solid in liftoff (every eigenpair of the space)",
    "geometry": "with --ball solid in liftoff",
    "initial": "with --ball solid in liftoff",
    "mesh_file": "with --ball solid in liftoff",
    "pole": "with --ball solid in liftoff",
    "wall_cells": "with --ball solid (the thick wall's: --ball thick in twoball bounce)",
}


def solid_liftoff(args: argparse.Namespace, kind: str) -> twoball.LiftoffReport:
    """``twoball liftoff --ball solid``: the ball dropped, the massless body on its top."""
    from twoball.cli.mesh_options import damping_options

    if kind != "solid":
        valid = "membrane or solid for liftoff (a shell or a thick wall: twoball bounce)"
        raise ParameterError("ball", valid, kind)
    for name, why in NOT_DROPPED.items():
        value = getattr(args, name, None)
        if value is not None and not (name == "recontact" and value == "window"):
            raise ParameterError(name, f"left out {why}", value)
    case = solid_case(args)
    solver = twoball.MoreauJean(solid_ball(args), dt=args.dt, t_end=args.t_end)
    return twoball.liftoff(case, solver=solver, damping=damping_options(args))


def run_eigen(args: argparse.Namespace) -> int:
    """``twoball eigen --ball solid``: Lamb's roots (legendre) or the (r, z) P2 values (fem)."""
    from rich.table import Table

    from twoball._common.provenance import attach, block
    from twoball.cli.console import console, print_json

    for name in ("mesh", "mesh_file", "pole", "geometry", "membrane", "thickness_ratio"):
        if getattr(args, name, None) is not None:
            raise ParameterError(name, "left out with --ball solid", getattr(args, name))
    for name in ("prestress_ratio", "gas", "preset", "youngs_modulus", "thickness"):
        if getattr(args, name, None) is not None:
            valid = "left out with --ball solid (the spectrum in omega R / c_s needs nu only)"
            raise ParameterError(name, valid, getattr(args, name))
    backend = args.backend or "legendre"
    if backend not in ("legendre", "fem"):
        raise ParameterError("backend", "one of legendre, fem", backend)
    poisson = 0.25 if args.poisson is None else float(args.poisson)
    twoball.SolidMaterial(1.0, 1.0, poisson)  # validates nu in (-1, 0.5)
    count = 5 if args.count is None else args.count
    top = 10 if args.max_degree is None else args.max_degree
    if not 1 <= count <= 40:
        raise ParameterError("count", "radial orders in [1, 40]", count)
    if not 0 <= top <= 60:
        raise ParameterError("max_degree", "an integer in [0, 60]", top)
    level = 4 if args.level is None else args.level
    if backend == "legendre" and args.level is not None:
        raise ParameterError("level", "left out with backend legendre (no mesh)", args.level)
    if not 1 <= level <= 6:
        raise ParameterError("level", "an integer in [1, 6]", level)
    rows = twoball.fem.solid_eigen(poisson, count, backend, level=level, max_degree=top)
    if args.json:
        arguments = {"backend": backend, "poisson": poisson, "count": count, "max_degree": top}
        if backend == "fem":
            arguments["level"] = level
        print_json(attach(rows, block(None, "twoball.fem.solid_eigen", arguments)))
        return 0
    table = Table(title=f"Lamb's spheroidal modes, nu = {poisson:g} ({backend})")
    for name in ("n", "k", "omega R / c_s", "Lamb's root", "rel. error"):
        table.add_column(name, justify="right")
    for r in rows:
        table.add_row(
            str(r["degree"]),
            str(r["radial_order"]),
            "-" if r["value"] is None else f"{r['value']:.10g}",
            f"{r['exact']:.10g}",
            "-" if r["relative_error"] is None else f"{r['relative_error']:.2e}",
        )
    console().print(table)
    return 0
