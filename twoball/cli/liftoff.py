"""``twoball liftoff``: lift-off time and velocity for one case (SI in and out).

A thin layer over :func:`twoball.liftoff`: the options become its arguments.
"""

from __future__ import annotations

import argparse

import twoball
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
from twoball.cli.mesh_options import add_mesh_options, add_time_options, damping_options
from twoball.cli.solver_options import liftoff_solver

__all__ = ["liftoff_rows", "register", "run"]


def _stiffness_rows(case) -> list[tuple[str, str]]:
    rows = []
    if case.rayleigh is not None:
        law = case.rayleigh_dict()
        fitted = " (fitted to D)" if law["fitted"] else ""
        rows.append(
            (
                "Rayleigh alpha [1/s], beta [s]" + fitted,
                f"{law['alpha_1_s']:.4g}, {law['beta_s']:.4g}",
            )
        )
    if not case.stiff:
        return rows
    stiffness = case.stiffness
    return rows + [
        ("membrane", case.membrane.kind),
        ("bending B [N m]", f"{case.bending:.4g}"),
        ("beta = B/(T R^2)", f"{stiffness.beta:.4g}"),
        ("gas", case.gas),
        ("P (excess) [Pa]", f"{case.pressure:g}"),
        ("omega_0^2 (breathing, units c^2)", f"{stiffness.breathing:.4g}"),
    ]


def _ratio_text(case) -> str:
    """D, or a dash when a Rayleigh law with its own coefficients replaces it."""
    if case.rayleigh is not None and not case.rayleigh.fitted:
        return "- (Rayleigh law)"
    return f"{case.damping:g}"


def liftoff_rows(report: twoball.LiftoffReport) -> list[tuple[str, str]]:
    """The human-readable rows of a lift-off report (SI)."""
    case = report.case
    rows = [
        ("R [m]", f"{case.radius:g}"),
        ("c [1/s]", f"{case.wave_speed:g}"),
        ("|v0| [m/s]", f"{case.v0:g}"),
        ("phi_a [rad]", f"{case.phi_a:.6f}"),
        ("phi_a from", str(case.phi_a_source)),
        ("D", _ratio_text(case)),
        ("N", f"{case.modes}"),
        *_stiffness_rows(case),
        ("gamma = g/(R c^2)", f"{case.gamma:.4e}"),
        ("lifted", "yes" if report.result.lifted else "no"),
        ("t_l [ms]", number(report.t_liftoff_s, 1e3)),
        ("floor time [ms]", number(case.floor_time, 1e3)),  # estimate pi / (2 c)
        ("v_l [m/s]", number(report.v_liftoff_m_s)),
        ("v_l / |v0|", number(report.ratio)),
        ("rejected candidates", str(len(report.result.rejected))),
    ]
    block = report.extra.get("truncation") or {}
    if block.get("t_liftoff_s") is not None:
        name = f"converged series (N = {block['converged_modes']})"
        rows.append((f"t_l [ms], {name}", number(block["t_liftoff_s"], 1e3)))
        rows.append((f"v_l [m/s], {name}", number(block["v_liftoff_m_s"])))
    rows += [("warning", text) for text in report.warnings]
    for key, value in report.extra.items():
        if isinstance(value, float):
            rows.append((key, f"{value:.4g}"))
        elif isinstance(value, (int, str)):
            rows.append((key, str(value)))
    return rows


def print_liftoff(report: twoball.LiftoffReport) -> None:
    """Print a lift-off report as a table."""
    title = f"Lift-off ({report.backend}, sigma={report.sigma}, re-contact={report.recontact})"
    console().print(key_value_table(title, liftoff_rows(report)))


def contact_rows(report) -> list[tuple[str, str]]:
    """The rows of a finite-mass (contact) report (SI): the case, every event, v1."""
    case = report.case
    rows = [
        ("R [m]", f"{case.radius:g}"),
        ("c [1/s]", f"{case.wave_speed:g}"),
        ("|v0| [m/s]", f"{case.v0:g}"),
        ("phi_a [rad]", f"{report.as_dict()['phi_a_rad']:.6f}"),
        ("D", f"{case.damping:g}"),
        ("N", f"{case.modes}"),
        ("mass ratio mu", f"{report.mass_ratio:g}"),
        ("contact radius a [m]", f"{report.contact_radius_m:g}"),
        ("restitution e", f"{report.restitution:g}"),
        ("energy at t = 0", report.energy),
    ]
    for event in report.events_si():
        rows.append(
            (
                f"{event['kind']} [ms]",
                f"{event['t_s'] * 1e3:.4f}  (v = {event['velocity_m_s']:+.4f} m/s)",
            )
        )
    rows += [
        ("lifted", "yes" if report.lifted else "no"),
        ("final separation [ms]", number(report.t_liftoff_s, 1e3)),
        ("v1 [m/s]", number(report.v_liftoff_m_s)),
        ("v1 / |v0|", number(report.ratio)),
    ]
    block = report.extra.get("truncation") or {}
    if block.get("t_liftoff_s") is not None:
        name = f"closed form, N = {block['reference_modes']}"
        rows.append((f"final separation [ms], {name}", number(block["t_liftoff_s"], 1e3)))
        rows.append((f"v1 [m/s], {name}", number(block["v_liftoff_m_s"])))
    rows += [("warning", text) for text in report.warnings]
    return rows


def solve_from_options(args: argparse.Namespace) -> twoball.LiftoffReport:
    """Call :func:`twoball.liftoff` with the case, the solver of the flags, the body and
    the damping law."""
    from twoball._common.progress import QUICK, Reporter
    from twoball.cli.shell import check_ball_kind
    from twoball.cli.solid import refuse_solid_flags, solid_liftoff

    kind = check_ball_kind(args)
    if kind != "membrane":
        return solid_liftoff(args, kind)
    refuse_solid_flags(args, level=False)  # --level is the membrane's mesh here
    body = body_options(args)
    options = {
        "solver": liftoff_solver(args, body),
        "body": body,
        "damping": damping_options(args),
    }
    case = case_from_options(args)
    # the closed form takes milliseconds, but its converged reference (the truncation
    # guard) may sum thousands of modes: quick runs print nothing (the delay)
    with Reporter("liftoff", delay=QUICK) as progress:
        return twoball.liftoff(case, progress=progress, **options)


def run(args: argparse.Namespace) -> int:
    """Run ``twoball liftoff``."""
    from twoball._plot import check_figure_path, save_report_figure

    plot = None
    if args.plot is not None:
        body = body_options(args)
        if body is None or body.mass_ratio == 0.0:
            valid = "given only with a mass ratio > 0 (the body's path is drawn)"
            raise twoball.ParameterError("plot", valid, args.plot)
        plot = check_figure_path(args.plot, "plot")
    report = solve_from_options(args)
    if plot is not None:
        save_report_figure(report, plot, "plot")
    print_notes(report.notes)
    print_warnings(report.warnings)
    if args.json:
        print_json(report.as_dict())
    elif args.mass_ratio is not None:
        console().print(key_value_table("Lift-off of a body of finite mass", contact_rows(report)))
    else:
        print_liftoff(report)
    return 0


def register(parser: argparse.ArgumentParser) -> None:
    """The options of ``twoball liftoff``."""
    parser.add_argument(
        "--backend", default="legendre", help="legendre (closed form, default) or fem"
    )
    add_case_options(parser)
    add_mesh_options(parser, geometry=True)
    add_time_options(parser)
    from twoball.cli.shell import add_ball_option
    from twoball.cli.solid import add_solid_options

    add_ball_option(parser)
    add_solid_options(parser, level=False)
    group = add_contact_options(parser)
    group.add_argument(
        "--plot",
        metavar="FILE.png",
        help="with --mass-ratio: draw the body's path and the cap with every contact",
    )
    parser.add_argument("--json", action="store_true", help="print one JSON object")
    parser.set_defaults(run=run)
