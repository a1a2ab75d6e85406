"""``twoball bounce``: the lower ball dropped on a rigid floor, alone or with a body on top.

A thin layer over :func:`twoball.bounce`: the options become its case, its
:class:`~twoball.Drop`, its :class:`~twoball.Body` (``--mass-ratio``,
``--contact-radius``, ``--restitution``; or ``--pair``), its mesh and its time
step; ``--plot``, ``--export`` and ``--render`` write the report's files.
"""

from __future__ import annotations

import argparse
from copy import copy
from typing import Any

import twoball
from twoball._common.errors import ParameterError
from twoball.cli.body_options import (
    add_body_options,
    elastic_body,
    elastic_rows,
    floor_alone_rows,
)
from twoball.cli.case_options import add_case_options, case_from_options
from twoball.cli.console import (
    console,
    key_value_table,
    number,
    print_json,
    print_notes,
    print_warnings,
)
from twoball.cli.contact_options import add_contact_options, body_options
from twoball.cli.mesh_options import damping_options
from twoball.cli.values import integer
from twoball.cli.values import number as numeric

__all__ = [
    "add_drop_options",
    "add_kind_options",
    "add_mesh_options",
    "bounce_rows",
    "bounce_from_options",
    "drop_ball",
    "drop_case",
    "drop_options",
    "drop_solver",
    "register",
    "run",
]


def add_drop_options(parser: argparse.ArgumentParser) -> None:
    """The drop's own options: height, membrane, floor restitution, resolution, time step."""
    group = parser.add_argument_group("the drop on the floor")
    group.add_argument(
        "--drop-height",
        type=numeric,
        metavar="H",
        help="height [m] of the lowest point above the floor at release, at least the radius "
        "R: |v0| = sqrt(2 g H), eq. (2.1) (instead of --v0; a slower impact: --v0)",
    )
    group.add_argument(
        "--centre-height",
        type=numeric,
        metavar="X2",
        help="height [m] of the ball's centre above the floor at release, the paper's x2, at "
        "least 2R: the lowest point falls x2 - R (instead of --drop-height or --v0)",
    )
    group.add_argument(
        "--floor-restitution",
        type=numeric,
        metavar="E",
        help="Newton's e at every floor point in [0, 1] (default 0; 1 keeps the energy)",
    )
    group.add_argument(
        "--damping-model", help="modal (the ratio D on every mode, default) or rayleigh (causal)"
    )
    group.add_argument(
        "--dt",
        type=numeric,
        metavar="SECONDS",
        help="time step [s] of the Moreau-Jean steps (default 0.005 / c)",
    )
    group.add_argument(
        "--gap",
        type=numeric,
        metavar="DX",
        help="the whole bounce: gap Delta x [m] in [0, 10] between the body and the ball's "
        "top when the ball first touches the floor (default 0: touching)",
    )
    group.add_argument(
        "--pair",
        metavar="NAME",
        help="a pair of Table 1: the lower ball, mu, e12 and the contact radius "
        "(tennis-coin, tennis-nut, tennis-table-tennis, basketball-tennis, "
        "basketball-tissue, basketball-table-tennis)",
    )


def add_mesh_options(parser: argparse.ArgumentParser) -> None:
    """The drop's finite-element mesh: ``--mesh``, ``--elements``, ``--order``."""
    mesh = parser.add_argument_group("finite-element mesh (--backend fem)")
    mesh.add_argument("--mesh", help="axisym (the line x = cos phi; default)")
    mesh.add_argument(
        "--elements",
        type=integer,
        help="axisymmetric line elements (default 192 / order: 96 at P2, node spacing pi / 192)",
    )
    mesh.add_argument("--order", type=integer, help="element order 1, 2, 3 or 4 (default 2)")


def add_kind_options(parser: argparse.ArgumentParser, *, view: bool = False) -> None:
    """The lower ball's and the upper body's kinds with their options.

    ``--backend``, ``--ball`` (membrane, shell, solid, thick) with the mesh, the
    shell's wall and the solid's options, and ``--body`` (rigid, lumped, ball)
    with the body's own: the options of ``twoball bounce`` that ``twoball sweep
    --bounce`` shares (:func:`drop_ball`, :func:`twoball.cli.body_options.elastic_body`
    read them).  ``view`` adds ``--view`` (the field files' cut).
    """
    from twoball.cli.shell import add_ball_option, add_wall_options
    from twoball.cli.solid import add_solid_options

    parser.add_argument(
        "--backend", default="legendre", help="legendre (Legendre modes, default) or fem"
    )
    add_ball_option(parser)
    add_mesh_options(parser)
    add_wall_options(parser)
    add_solid_options(parser, view=view)
    add_body_options(parser)
    for flag in ("--elements", "--order"):  # the drop's reading, with --ball shell's
        _action(parser, flag).help = DROP_HELP[flag]


#: Help of shared case options where the drop reads them differently.
DROP_HELP = {
    "--membrane": "membrane operator: pressurised ((n-1)(n+2), default: degree 1 a free "
    "translation) or paper (n(n+1) for n != 1)",
    "--restitution": "Newton's e12 in [0, 1] at the body's impacts on the ball (default 0)",
    "--contact-radius": "radius a [m] of the cap where the body touches (default R/10)",
    "--youngs-modulus": "wall Young's modulus E [Pa]: the membrane's bending, or with --ball "
    "shell the shell's wall (with --thickness and --poisson)",
    "--thickness": "wall thickness h [m] (with --youngs-modulus)",
    "--poisson": "Poisson's ratio of the wall (default 0.5, rubber)",
    "--modes": "Legendre degree N of the drop (default 192; --ball shell: 128, 2N + 1 modes of "
    "both branches); floor points at its Gauss-Radau nodes on the lower hemisphere",
    "--elements": "axisymmetric line elements (default 192 / order: 96 at P2); --ball shell: "
    "the meridian's elements (default 64)",
    "--order": "element order 1, 2, 3 or 4 (default 2); --ball shell: the Lagrange order 1, 2 "
    "or 3 of the meridional displacement",
}


#: Shared case options the drop only refuses (or takes at their default, which changes
#: nothing): parsed, so that the refusal says why, but left out of ``--help``.  The
#: contact angle is the drop's output (phi_a_max_rad), its modes are not filtered, it
#: has no lift-off criteria, and both bodies fall at |v0| in the whole bounce.
REFUSED = ("--phi-a", "--sigma", "--recontact", "--energy")


def _action(parser: argparse.ArgumentParser, flag: str) -> argparse.Action:
    return next(a for a in parser._actions if flag in a.option_strings)


def drop_case(args: argparse.Namespace) -> twoball.Case:
    """The case of the options; ``--gas``, ``--membrane`` and ``--modes`` go to the drop.

    The drop supplies the gas (adiabatic by default) and the pressure (the
    preset's), which the case alone would need before it took the pressurised
    membrane; ``--modes`` is the drop's Legendre degree, not the case's filter.
    """
    if args.phi_a is not None:
        raise ParameterError(
            "phi_a", "left out for the drop (the contact angle is its output)", args.phi_a
        )
    pair = getattr(args, "pair", None)
    from twoball.cli.shell import check_ball_kind

    kind = check_ball_kind(args)
    if kind == "thick" and args.preset is None and pair is None:
        args.preset = "tennis"  # the preset with a thick wall
    if args.preset is None:  # the pair's lower ball, else the basketball
        if pair is not None:
            from twoball import _lookup

            args.preset = _lookup.pair(pair).lower
        else:
            args.preset = "basketball"
    elif pair is not None:
        raise ParameterError(
            "preset", "left out with --pair (the pair sets the lower ball)", args.preset
        )
    if args.drop_height is not None and args.v0 is not None:
        raise ParameterError("drop_height", "given alone, not with --v0", args.drop_height)
    centre = getattr(args, "centre_height", None)
    if centre is not None:
        for name in ("drop_height", "v0"):
            if getattr(args, name) is not None:
                flag = "--" + name.replace("_", "-")
                raise ParameterError("centre_height", f"given alone, not with {flag}", centre)
    for name, default in (("sigma", "lanczos"), ("recontact", "window")):
        if getattr(args, name, None) not in (None, default):
            valid = "left out for the drop (no lift-off criteria)"
            raise ParameterError(name, valid, getattr(args, name))
    from twoball.cli.shell import refuse_wall_flags, shell_case_args

    if kind == "solid":
        from twoball.cli.solid import solid_case

        return solid_case(args)
    if kind == "shell":
        args = shell_case_args(args)  # the SI wall flags define the wall, not a bending
    elif kind == "thick":
        from twoball.cli.solid import thick_case_args

        args = thick_case_args(args)  # the SI wall flags define the thick wall
    else:
        refuse_wall_flags(args)
    case_args = copy(args)
    case_args.gas = None
    case_args.modes = None
    case_args.membrane = None
    return case_from_options(case_args)


def drop_options(args: argparse.Namespace) -> twoball.Drop:
    """``--drop-height`` or ``--centre-height``, ``--gas``, ``--floor-restitution``,
    ``--membrane``, ``--gap``."""
    fields: dict[str, Any] = {
        "drop_height": args.drop_height,
        "centre_height": getattr(args, "centre_height", None),
        "gas": args.gas,
        "gap": getattr(args, "gap", None),
    }
    if args.floor_restitution is not None:
        fields["floor_restitution"] = args.floor_restitution
    if args.membrane is not None:
        fields["membrane"] = args.membrane
    return twoball.Drop(**{k: v for k, v in fields.items() if v is not None})


def drop_ball(args: argparse.Namespace) -> Any:
    """The lower ball of ``--ball`` and ``--backend``: ``--modes`` on Legendre modes, the mesh
    options on finite elements (the axisymmetric line, 192 / order elements by default);
    ``--ball shell``: :func:`twoball.cli.shell.shell_ball`."""
    from twoball.cli.shell import check_ball_kind, shell_ball

    kind = check_ball_kind(args)
    if kind in ("solid", "thick"):
        from twoball.cli.solid import solid_ball, thick_ball

        return solid_ball(args) if kind == "solid" else thick_ball(args)
    from twoball.cli.solid import refuse_solid_flags

    refuse_solid_flags(args)
    if kind == "shell":
        return shell_ball(args)
    fields = {n: getattr(args, n) for n in ("elements", "order") if getattr(args, n) is not None}
    if args.backend == "legendre":
        if args.mesh is not None or fields:
            name, value = (
                ("mesh", args.mesh) if args.mesh is not None else next(iter(fields.items()))
            )
            valid = "left out with backend legendre (no mesh: --modes sets its resolution)"
            raise ParameterError(name, valid, value)
        return twoball.LegendreBall(args.modes)
    if args.backend != "fem":
        raise ParameterError("backend", "one of legendre, fem", args.backend)
    if args.modes is not None:
        raise ParameterError("modes", "left out with backend fem (the mesh sets it)", args.modes)
    order = fields.get("order", 2)
    if "elements" not in fields and args.mesh in (None, "axisym") and order in (1, 2, 3, 4):
        fields["elements"] = twoball.drop_elements(order)  # the drop's line, not the lift-off's
    return twoball.FEBall(twoball.MeshOptions(args.mesh or "axisym", **fields))


def drop_solver(args: argparse.Namespace) -> twoball.MoreauJean:
    """The Moreau-Jean steps of ``--dt`` and ``--t-end`` on the ball of the options."""
    return twoball.MoreauJean(drop_ball(args), dt=args.dt, t_end=args.t_end)


def whole_body(args: argparse.Namespace) -> twoball.Body | None:
    """The upper body of ``--mass-ratio`` and its companions; refused with ``--pair``."""
    if getattr(args, "pair", None) is not None:
        for name in ("mass_ratio", "contact_radius", "restitution", "energy"):
            if getattr(args, name, None) is not None:
                valid = "left out with --pair (the pair fixes mu, e12 and the contact radius)"
                raise ParameterError(name, valid, getattr(args, name))
        return None
    return body_options(args)


def bounce_from_options(args: argparse.Namespace) -> twoball.BounceReport:
    """Call :func:`twoball.bounce` with the options."""
    elastic = elastic_body(args)  # --body lumped|ball (None: the rigid body's options)
    body = whole_body(args) if elastic is None else elastic
    case = drop_case(args)
    return twoball.bounce(
        case,
        drop_options(args),
        solver=drop_solver(args),
        body=body,
        pair=args.pair,
        damping=damping_options(args),
    )


def _damping_text(law: dict[str, Any]) -> str:
    """The damping law of the JSON block as one line (SI)."""
    if law["law"] != "rayleigh":
        return f"modal, D = {law['ratio']:g}"
    fitted = " (fitted to D)" if law["fitted"] else ""
    return f"rayleigh, alpha {law['alpha_1_s']:.4g} 1/s, beta {law['beta_s']:.4g} s{fitted}"


def _wall_rows(model: dict[str, Any]) -> list[tuple[str, str]]:
    """The shell's wall (no rows for a membrane)."""
    wall = model.get("wall")
    if not wall:
        return []
    youngs = wall["youngs_modulus_Pa"]
    return [
        (
            "wall: E [MPa], h [mm], nu",
            f"{'-' if youngs is None else f'{youngs / 1e6:.4g}'}, "
            f"{wall['thickness_m'] * 1e3:.4g}, {wall['poisson']:g}",
        ),
        (
            "  C/N0, h/R",
            f"{wall['wall_stiffness_ratio']:.4g}, {wall['thickness_ratio']:.4g}",
        ),
        (
            "  pi R/c_e, pi/c [ms]",
            f"{model['in_plane_arrival_s'] * 1e3:.4g}, "
            f"{model['pressure_wave_arrival_s'] * 1e3:.4g}",
        ),
    ]


def bounce_rows(report: twoball.BounceReport) -> list[tuple[str, str]]:
    """The human-readable rows of a drop (SI)."""
    case, model = report.case, report.model
    pa = report.comparisons()["pressure_area"]
    rows = [
        ("R [m]", f"{case.radius:g}"),
        ("c [1/s]", f"{case.wave_speed:g}"),
        ("|v0| [m/s]", f"{case.v0:g}"),
    ]
    if model.get("ball") in ("solid", "thick"):  # no membrane: its own rows
        from twoball.cli.solid import solid_rows

        rows += solid_rows(report)
    else:
        rows += [
            ("P [Pa], m2 [kg]", f"{report.pressure:g}, {report.mass_kg:.4g}"),
            ("membrane, gas", f"{model['membrane'] or model.get('ball')}, {model['gas']}"),
            ("omega_0^2 (units c^2)", f"{model['omega0_squared']:.4g}"),
            *_wall_rows(model),
            ("contact time [ms]", number(report.contact_time_s, 1e3)),
            ("  pressure x area pi/c [ms]", number(pa["contact_time_s"], 1e3)),
        ]
    rows += [
        ("damping", _damping_text(model["damping"])),
        ("resolution", f"{model['resolution']} ({model['floor_points']} floor points)"),
        ("dt [s]", f"{model['dt_s']:.4g}"),
        ("left the floor", "yes" if report.left_floor else "no"),
        ("v2 [m/s]", number(report.v2_m_s)),
        ("e2 = v2/|v0|", number(report.e2)),
        ("phi_a,max [rad]", number(report.phi_a_max_rad)),
        ("  pressure x area [rad]", number(pa["phi_a_max_rad"])),
        ("flattening max [mm]", number(report.flattening_max_m, 1e3)),
        ("  pressure x area |v0|/c [mm]", number(pa["flattening_max_m"], 1e3)),
        ("t max compression [ms]", number(report.t_max_compression_s, 1e3)),
        ("floor impulse [N s]", number(report.floor_impulse_N_s)),
    ]
    if model.get("ball") in ("solid", "thick"):  # the membrane's pressure x area: not theirs
        rows = [row for row in rows if "pressure x area" not in row[0]]
    energy = report.energy_J
    rows += [
        ("energy lost at impacts [J]", f"{energy['lost_impacts']:.4g}"),
        ("energy damped [J]", f"{energy['dissipated_damping']:.4g}"),
        ("vibration after leaving [J]", f"{energy['vibration_after_leaving']:.4g}"),
    ]
    if report.has_body:
        rows += whole_rows(report)
        events = report.events
        shown = events if len(events) <= 12 else events[:4] + events[-6:]
        for event in shown:
            rows.append(
                (
                    f"{event['contact']} {event['kind']} [ms]",
                    f"{event['t_s'] * 1e3:.4f} (ball {event['velocity_m_s']:+.4f}, "
                    f"body {event['body_velocity_m_s']:+.4f} m/s)",
                )
            )
        if len(shown) < len(events):
            rows.append(("events", f"{len(events)} in all (--json lists every one)"))
        return rows
    for event in report.events:
        rows.append(
            (
                f"{event['kind']} [ms]",
                f"{event['t_s'] * 1e3:.4f} (v = {event['velocity_m_s']:+.4f} m/s)",
            )
        )
    return rows


def whole_rows(report: twoball.BounceReport) -> list[tuple[str, str]]:
    """The rows of the whole bounce: the body, v1, v2, timing, e12, the baselines (SI)."""
    data = report.as_dict()
    body = data["body"]
    if "kind" in body:  # an elastic body: its kind, restitution, contact and disc
        rows = elastic_rows(data)
    else:
        rows = [
            ("body: mu, mass [g]", f"{body['mass_ratio']:g}, {body['mass_kg'] * 1e3:.4g}"),
            ("  contact radius a [mm]", f"{body['contact_radius_m'] * 1e3:.4g}"),
            ("  Newton e12, gap [mm]", f"{body['restitution']:g}, {body['gap_m'] * 1e3:g}"),
        ]
    rows += [
        ("v1 [m/s], v1/|v0|", f"{number(data['v1_m_s'])}, {number(data['v1_ratio'])}"),
        ("v2 [m/s], v2/|v0|", f"{number(data['v2_m_s'])}, {number(data['v2_ratio'])}"),
        ("lift-off [ms] after the floor touch", number(data["t_liftoff_s"], 1e3)),
        (
            "  after the largest compression [ms]",
            number(data["t_liftoff_from_max_compression_s"], 1e3),
        ),
        ("ball leaves the floor [ms]", number(data["t_floor_release_s"], 1e3)),
        ("sequence, body left first", f"{data['sequence']}, {data['body_left_first']}"),
        ("body contacts", str(data["body_contacts"])),
        ("e12 effective (eq. (2.4))", number(data["e12_effective"])),
    ]
    caveats = data.get("caveats") or []
    icm = data["icm_solver"]
    if icm is not None:
        rows.append(
            ("ICM (2.5), this e2 and e12_eff", f"{icm['v1_ratio']:.4f} / {icm['v2_ratio']:.4f}")
        )
    elif "overlap" in caveats:  # said, not left blank
        undefined = "not defined: the floor and body contacts overlap"
        rows[-1] = (rows[-1][0], undefined)
        rows.append(("ICM (2.5), this e2 and e12_eff", undefined))
    from twoball._bounce import CAVEATS

    rows += [("warning", CAVEATS[tag]) for tag in caveats if tag != "overlap"]
    for name, out in (data["baselines"] or {}).get("models", {}).items():
        text = out.get("error") or f"{out['v1_ratio']:.4f} / {out['v2_ratio']:.4f}"
        rows.append((f"{name} v1/|v0| / v2/|v0|", text))
    table1 = data["comparisons"].get("table1")
    if table1 is not None:  # a pair: Table 1's measurement beside the model's
        rows += [
            (
                f"Table 1 row {table1['row']} measured v1/|v0| / v2/|v0|",
                f"{table1['measured_v1_ratio']:g} / {table1['measured_v2_ratio']:g} (touching)",
            ),
            (
                "  Table 1's ICM (printed)",
                f"{table1['icm_printed_v1_ratio']:g} / {table1['icm_printed_v2_ratio']:g}",
            ),
            (
                "  this run (model)",
                f"{number(table1['model_v1_ratio'])} / {number(table1['model_v2_ratio'])}",
            ),
        ]
    return rows


def _field_targets(args: argparse.Namespace) -> tuple[Any, Any, int]:
    """``--export`` and ``--render`` checked before any work, and the frame count."""
    from twoball._bounce import check_field_targets

    return check_field_targets(args.export, args.render, args.frames)


def _floor_alone(args: argparse.Namespace) -> int:
    """``--floor-alone``: the elastic body alone on a rigid floor (:func:`twoball.floor_alone`)."""
    for name in ("plot", "export", "render", "gap"):
        if getattr(args, name, None) is not None:
            raise ParameterError(name, "left out with --floor-alone", getattr(args, name))
    body = elastic_body(args)
    if body is None:
        raise ParameterError("--floor-alone", "given with --body lumped or ball", True)
    case = drop_case(args)
    try:
        if isinstance(body, str):
            result = twoball.floor_alone(pair=args.pair, kind=body, case=case, dt=args.dt)
        else:
            result = twoball.floor_alone(body, case=case, dt=args.dt)
    except ParameterError as error:
        if error.name != "kind":
            raise
        raise ParameterError("--body", error.valid, error.got) from None
    if args.json:
        print_json(result.as_dict())
    else:
        title = "The body alone on a rigid floor"
        console().print(key_value_table(title, floor_alone_rows(result)))
    return 0


def run(args: argparse.Namespace) -> int:
    """Run ``twoball bounce``."""
    if getattr(args, "floor_alone", False):
        return _floor_alone(args)
    from twoball._common.progress import QUICK, Reporter
    from twoball._plot import check_figure_path

    plot = None if args.plot is None else check_figure_path(args.plot, "plot")
    export, render, frames = _field_targets(args)
    view = getattr(args, "view", None) or "surface"
    if view != "surface" and export is None and render is None:
        raise ParameterError("view", "given with --export or --render", view)
    from twoball.cli.measured import check_paths, measured_rows, print_overlay

    outputs = {"plot": args.plot, "export": args.export, "render": args.render}  # one path each
    check_paths(args, outputs)
    rows = measured_rows(args)  # --measured: read before the work
    # the solvers say what they do (eigenpairs, the steps of the drop) through the
    # activity of the progress line; quick runs print nothing
    with Reporter("bounce", delay=QUICK) as progress:
        progress(args.backend)
        report = bounce_from_options(args)
        for name, target, write in (
            ("figure", plot, lambda out: report.plot(out, measured=rows)),
            ("export", export, lambda out: report.export(out, frames=frames, view=view)),
            ("render", render, lambda out: report.render(out, frames=frames, view=view)),
        ):
            if target is not None:
                progress(f"{name} {target.name}")
                write(target)
    print_notes(list(report.notes))
    if plot is not None:
        print_overlay(report, rows)
    print_warnings(report.warnings)
    if args.json:
        print_json(report.as_dict())
    else:
        title = f"{'Whole bounce' if report.has_body else 'Drop on the floor'} ({report.backend})"
        console().print(key_value_table(title, bounce_rows(report)))
    return 0


def register(parser: argparse.ArgumentParser) -> None:
    """The options of ``twoball bounce``."""
    add_case_options(parser, window="10 pi / c + 2 gap / |v0|")
    add_drop_options(parser)
    add_kind_options(parser, view=True)
    add_contact_options(
        parser, "the whole bounce: mass ratio m1/m2 in (0, 100] of a body on the ball's top"
    )
    for flag, text in DROP_HELP.items():  # the shared case options, as the drop reads them
        _action(parser, flag).help = text
    for flag in REFUSED:
        _action(parser, flag).help = argparse.SUPPRESS
    preset = _action(parser, "--preset")
    preset.default = None  # the pair's lower ball, else the basketball
    preset.help = "named case: basketball (default), tennis, volleyball; --pair sets it"
    parser.add_argument(
        "--plot",
        metavar="FILE",
        help="also write the figure (.png, .pdf, .svg, ...): floor force, contact angle, the "
        "centre's height and the energy books against time (with a body: heights, both "
        "forces, both velocities, the energy books and every event)",
    )
    from twoball.cli.measured import add_measured_option

    add_measured_option(
        parser, "over the velocities and the contact angle (rows at this drop's |v0| and gap)"
    )
    parser.add_argument(
        "--export",
        metavar="FILE",
        help="also write the motion on a sphere mesh: .xdmf (+ .h5), .pvd (+ .vtu) or one "
        ".vtu frame; with a body its height, gap and force per frame",
    )
    parser.add_argument(
        "--render",
        metavar="FILE",
        help="also draw the ball (and the body): .png (the largest compression), .gif or .mp4",
    )
    parser.add_argument(
        "--frames", type=integer, metavar="N", help="instants of --export/--render (default 40)"
    )
    parser.add_argument("--json", action="store_true", help="print one JSON object")
    parser.set_defaults(run=run)
