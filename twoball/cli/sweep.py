"""``twoball sweep``: the closed-form lift-off over one parameter or a grid of two."""

from __future__ import annotations

import argparse
from collections.abc import Collection, Iterator, Sequence
from contextlib import contextmanager
from typing import Any

from twoball import _lookup
from twoball._common import choices as _choices
from twoball._common.errors import ParameterError
from twoball._common.provenance import attach
from twoball.cli.case_options import add_case_options, case_from_options
from twoball.cli.console import (
    Table,
    console,
    number,
    print_json,
    print_notes,
    print_warnings,
)
from twoball.cli.contact_options import add_contact_options, body_options
from twoball.cli.flags import limit_flags
from twoball.cli.measured import (
    add_csv_option,
    add_measured_option,
    check_paths,
    csv_target,
    measured_rows,
    print_overlay,
)
from twoball.cli.solver_options import closed_form, series_fields
from twoball.cli.values import integer
from twoball.cli.values import number as number_value

__all__ = ["register", "run"]


def refuse_if_none_ran(labels: Sequence[str], errors: Sequence[str | None]) -> None:
    """End the command with one error line if no point of the sweep could run.

    ``labels`` name the points (``modes = 1400``), ``errors`` their error texts (None:
    the point ran).  A sweep whose every point was refused -- each over the budget,
    say -- has no result to show: its status is that of a refusal (2, e.g. a point's
    budget), or 3 if a point failed for a numerical reason.  Some points failing is
    not this: their errors are shown beside the others' results.
    """
    if not errors or any(e is None for e in errors):
        return
    from twoball.cli.main import EXIT_NUMERICAL, EXIT_USAGE, fail

    kind, _, text = str(errors[0]).partition(": ")
    refused = all(str(e).startswith(("BudgetError: ", "ParameterError: ")) for e in errors)
    text = limit_flags(" ".join((text or kind).split()))
    count = "the one point" if len(errors) == 1 else f"all {len(errors)} points"
    fail(
        f"no point of the sweep could run ({count} failed); at {labels[0]}: {text}",
        EXIT_USAGE if refused else EXIT_NUMERICAL,
    )


def print_sweep(grid: Any, points: list[Any], rule: str | None = None) -> None:
    """Print one row per grid point (an ``error`` column appears only if a point failed);
    the phi_a rule, one for the sweep (:attr:`twoball.SweepResult.phi_a_rule`), under it."""
    fields = [_choices.SWEEP_PARAMETERS[p] for p in grid.parameters]
    shape = " x ".join(str(n) for n in grid.shape)
    title = f"Sweep of {' x '.join(grid.parameters)} ({shape} values)"
    table = Table(title=title)
    if rule is not None:
        table.caption = f"phi_a: {rule}"
    columns = [
        *grid.parameters,
        "phi_a [rad]",
        "lifted",
        "t_l [ms]",
        "v_l [m/s]",
        "v_l/|v0|",
    ]
    failed = any(p.error for p in points)
    if failed:
        columns.append("error")
    for name in columns:
        table.add_column(name, justify="left" if name == "error" else "right")
    for p in points:
        r = p.report
        cells = [f"{getattr(p.case, f):g}" for f in fields]
        cells.append(f"{p.case.phi_a:.5f}")
        if r is None:
            cells += ["error", "-", "-", "-"]
        else:
            cells += [
                "yes" if r.result.lifted else "no",  # ContactReport.result too
                number(r.t_liftoff_s, 1e3),
                number(r.v_liftoff_m_s),
                number(r.ratio),
            ]
        if failed:
            cells.append(limit_flags(p.error or ""))
        table.add_row(*cells)
    console(wide=failed).print(table)


def run(args: argparse.Namespace) -> int:
    """Run ``twoball sweep``: :func:`twoball.sweep` with the options' grid and case."""
    import twoball
    from twoball._plot import check_figure_path

    if args.bounce:
        return _run_bounce(args)
    refuse_kind_options(args)
    for name in ("floor_restitution", "gap", "pair"):
        if getattr(args, name, None) is not None:
            valid = "left out without --bounce (a sweep of the drop or the whole bounce)"
            raise ParameterError(name, valid, getattr(args, name))
    for name in ("drop-height", "gap"):
        if name in args.param:
            valid = f"a parameter of the lift-off ({name} needs --bounce, a sweep of the drop)"
            raise ParameterError("param", valid, name)
    grid = _lookup.make_grid(args.param, args.values)
    for name in grid.parameters:  # the swept parameter's base value would be replaced
        field = _choices.SWEEP_PARAMETERS[name]
        fields = (field,)
        if field == "bending":  # B also comes from the wall's material: E and h (and nu)
            fields += ("youngs_modulus", "thickness", "poisson")
        for given in fields:
            if getattr(args, given, None) is not None:
                raise ParameterError(
                    given, f"left out when --param {name} is swept", getattr(args, given)
                )
    why = {  # --pressure and --mass give c by eq. (3.8) at the base radius, once
        "wave-speed": "the swept values would replace the c they give by eq. (3.8)",
        "radius": "the c they give by eq. (3.8) would stay that of the base radius",
    }
    for name, reason in why.items():
        if name in grid.parameters and args.pressure is not None:
            valid = f"left out with --mass when --param {name} is swept ({reason})"
            raise ParameterError("pressure", valid, args.pressure)
    plot = None if args.plot is None else check_figure_path(args.plot, "plot")
    rows, table = _outputs(args, len(grid.parameters))
    base = case_from_options(args)
    values = dict(zip(grid.parameters, grid.values, strict=True))
    body = _sweep_body(args, grid.parameters)
    stepped = "mass-ratio" in grid.parameters or (body is not None and body.mass_ratio > 0.0)
    if stepped:  # a body of finite mass on the points: its contacts are stepped
        if args.recontact not in (None, "window"):
            raise ParameterError("recontact", "window with --mass-ratio", args.recontact)
        solver = twoball.MoreauJean(**series_fields(args, "sigma", "t_end"))
    else:
        solver = closed_form(args)
    from twoball._common.progress import QUICK, Reporter

    total = 1
    for n in grid.shape:
        total *= n
    with (
        Reporter(f"sweep {' x '.join(grid.parameters)}", total=total, delay=QUICK) as bar,
        swept_values(grid.parameters),
    ):
        result = twoball.sweep(
            values,
            base,
            solver=solver,
            body=body,
            workers=workers(args),
            progress=bar.update,
        )
    points = result.points
    fields = [(name, _choices.SWEEP_PARAMETERS[name]) for name in grid.parameters]
    labels = [", ".join(f"{n} = {getattr(p.case, f):g}" for n, f in fields) for p in points]
    refuse_if_none_ran(labels, [p.error for p in points])
    print_notes(sweep_notes(points, result.phi_a_note))
    repeated = result.point_slips
    print_warnings([*result.warnings, *sweep_warnings(points, grid.parameters, repeated)])
    if plot is not None:
        result.plot(plot, measured=rows)
        print_overlay(result, rows)
    if table is not None:
        result.to_csv(table)
    if args.json:
        print_json(attach([p.as_dict() for p in points], result.provenance))
    else:
        print_sweep(grid, points, result.phi_a_rule)
        _written(plot, table)
    return 0


#: The options of the kinds (:func:`twoball.cli.bounce.add_kind_options`) a lift-off sweep
#: refuses when given: they describe the drop's lower ball and the whole bounce's body.
KIND_FLAGS = (
    "backend",
    "mesh",
    "elements",
    "order",
    "wall_stiffness_ratio",
    "thickness_ratio",
    "density",
    "radial_orders",
    "level",
    "pole_levels",
    "top_levels",
    "wall_cells",
    "body_law",
    "body_radius",
    "body_pressure",
    "body_modulus",
    "body_poisson",
    "body_thickness",
    "body_restitution",
    "body_steps",
    "body_preset",
    "body_modes",
    "body_damping",
)


def _action(parser: argparse.ArgumentParser, flag: str) -> argparse.Action:
    return next(a for a in parser._actions if flag in a.option_strings)


def refuse_kind_options(args: argparse.Namespace) -> None:
    """A lift-off sweep refuses ``--ball`` other than the membrane, ``--body`` other than
    rigid, ``--floor-alone`` and the kinds' own options, each by its flag."""
    valid = "given with --bounce (a sweep of the drop or the whole bounce)"
    if args.ball not in (None, "membrane"):
        raise ParameterError("ball", valid, args.ball)
    if args.body not in (None, "rigid"):
        raise ParameterError("--body", valid, args.body)
    if args.floor_alone:
        raise ParameterError("--floor-alone", "left out of a sweep (twoball bounce)", True)
    for name in KIND_FLAGS:
        value = getattr(args, name, None)
        if value is not None:
            raise ParameterError(name, valid, value)


def _outputs(args: argparse.Namespace, axes: int = 1) -> tuple[Any, Any]:
    """``--measured`` (read) and ``--csv`` (its path), checked before any work."""
    check_paths(args, {"plot": args.plot, "csv": args.csv})
    if args.measured is not None and axes != 1:
        valid = "given with a sweep of one parameter (a grid of two draws heat maps)"
        raise ParameterError("measured", valid, args.measured)
    return measured_rows(args), csv_target(args)


def _written(plot: Any, table: Any) -> None:
    """Say which files were written (the table's output)."""
    if plot is not None:
        console().print(f"plot written to {plot}")
    if table is not None:
        console().print(f"table written to {table}")


def workers(args: argparse.Namespace) -> int | str | None:
    """``--workers N`` or ``--scheduler ADDRESS`` as the API's one ``workers`` (not both)."""
    if args.scheduler is not None and args.workers is not None:
        valid = "left out with --scheduler (the cluster decides)"
        raise ParameterError("workers", valid, args.workers)
    return args.workers if args.scheduler is None else args.scheduler


def _run_bounce(args: argparse.Namespace) -> int:
    """``twoball sweep --bounce``: one drop (or whole bounce) per value of one parameter."""
    import twoball
    from twoball._bounce import OVERLAP_NOTE
    from twoball._plot import check_figure_path
    from twoball.cli.body_options import elastic_body
    from twoball.cli.bounce import drop_ball, drop_case, drop_options, whole_body

    for name in args.param:  # the base value the swept one replaces (a height sets |v0|)
        replaced = {"v0": "v0", "gap": "gap", "mass-ratio": "mass_ratio", "drop-height": "v0"}
        replaced["damping"] = "damping"
        field = replaced.get(name)
        if field is not None and getattr(args, field, None) is not None:
            raise ParameterError(
                field, f"left out when --param {name} is swept", getattr(args, field)
            )
    if len(args.values) != len(args.param):
        raise ParameterError("values", "given once per param, in the same order", args.values)
    plot = None if args.plot is None else check_figure_path(args.plot, "plot")
    rows, csv_path = _outputs(args)
    args.drop_height = None
    if args.pair is not None and args.preset == "basketball":
        args.preset = None  # the default: the pair sets the lower ball
    if args.floor_alone:
        raise ParameterError("--floor-alone", "left out of a sweep (twoball bounce)", True)
    if "mass-ratio" in args.param:
        if args.body != "rigid":  # the swept mu is a rigid body's (its cap and e12)
            valid = "rigid when --param mass-ratio is swept"
            raise ParameterError("--body", valid, args.body)
        elastic_body(args)  # the elastic body's own options refused by name
        body = _sweep_body(args, tuple(args.param))
        if args.pair is not None:
            raise ParameterError("pair", "left out when --param mass-ratio is swept", args.pair)
    else:
        elastic = elastic_body(args)  # --body lumped|ball (None: the rigid body's options)
        body = whole_body(args) if elastic is None else elastic
    args.backend = args.backend or "legendre"
    case = drop_case(args)
    drop = drop_options(args)
    solver = twoball.MoreauJean(drop_ball(args), t_end=args.t_end)
    pairs = zip(args.param, args.values, strict=True)
    values = {name.replace("-", "_"): text for name, text in pairs}
    from twoball._common.progress import QUICK, Reporter

    with Reporter("sweep of the drop", delay=QUICK) as bar, swept_values(args.param):
        result = twoball.sweep(
            values,
            case,
            solver=solver,
            drop=drop,
            body=body,
            pair=args.pair,
            workers=workers(args),
            progress=bar.update,
        )
    refuse_if_none_ran([f"{result.parameter} = {v:g}" for v in result.values], list(result.errors))
    done = [r for r in result.reports if r is not None]
    notes = [n for r in done for n in r.notes if n != OVERLAP_NOTE]  # said once, counted
    print_notes(list(dict.fromkeys(notes)) + caveat_lines(result, ("overlap",)))
    print_warnings(bounce_sweep_warnings(result))
    if plot is not None:
        result.plot(plot, measured=rows)
        print_overlay(result, rows)
    if csv_path is not None:
        result.to_csv(csv_path)
    if args.json:
        data = result.as_dict()
        print_json(attach(data["points"], result.provenance))
        return 0
    if result.parameter in ("gap", "mass-ratio") or any(r.has_body for r in done):
        _print_whole(result)
        _written(plot, csv_path)
        return 0
    table = Table(title=f"Drops on the floor against {result.parameter}")
    for column in (result.parameter, "|v0| [m/s]", "t_c [ms]", "e2", "phi_a,max", "flat. [mm]"):
        table.add_column(column, justify="right")
    for value, report, error in zip(result.values, result.reports, result.errors, strict=True):
        if report is None:
            table.add_row(f"{value:g}", "-", "-", "-", "-", error or "")
            continue
        table.add_row(
            f"{value:g}",
            f"{report.case.v0:.4g}",
            number(report.contact_time_s, 1e3),
            number(report.e2),
            number(report.phi_a_max_rad),
            number(report.flattening_max_m, 1e3, 3),
        )
    console().print(table)
    _written(plot, csv_path)
    return 0


@contextmanager
def swept_values(parameters: Sequence[str]) -> Iterator[None]:
    """A swept value refused is named as the option the user typed it in: ``--values``.

    The API names the parameter (``v0 must be a nonzero speed ...``); on the command
    line the value came from ``--values``, so the line says ``--values must be ...
    for --param v0, got 0.0``.  Budget refusals, and refusals of the parameter
    itself (no value shown), keep their own names.
    """
    from twoball._common.budget import BudgetError

    fields = {name.replace("-", "_"): name for name in parameters}
    try:
        yield
    except BudgetError:
        raise
    except ParameterError as error:
        name = fields.get(str(error.name))
        if name is None or error.got is None:  # not a value: the parameter itself refused
            raise
        valid = f"{error.valid} for --param {name}"
        raise ParameterError("values", valid, error.got) from None


def bounce_sweep_warnings(result: Any) -> list[str]:
    """One warning for a sweep of the drop: how many points carry warnings, the first.

    The first is named by its swept value (``drop-height = 500``); each point's
    warnings are in the JSON.
    """
    swept = list(getattr(result, "warnings", ()))  # the swept values' slips, found first
    said = set(swept) and {w for slips in getattr(result, "slips", ()) for w in slips}
    flagged = [
        (value, [w for w in report.warnings if w not in said])
        for value, report in zip(result.values, result.reports, strict=True)
        if report is not None
    ]
    flagged = [(value, rest) for value, rest in flagged if rest]
    caveats = caveat_lines(result, ("artefact", "e12_low"))
    if not flagged:
        return swept + caveats
    value, rest = flagged[0]
    return [
        *swept,
        f"{len(flagged)} of {len(result.values)} points carry warnings (see --json), the first "
        f"at {result.parameter} = {value:g}: {rest[0]}",
        *caveats,
    ]


def caveat_lines(result: Any, tags: Sequence[str]) -> list[str]:
    """One line per caveat of the whole bounce (``artefact``, ``e12_low``, ``overlap``) that
    some points carry: how many, at which values, and what it means."""
    from twoball._bounce import CAVEATS

    out = []
    for tag in tags:
        at = [
            f"{value:g}"
            for value, report in zip(result.values, result.reports, strict=True)
            if report is not None and tag in getattr(report, "caveats", ())
        ]
        if at:
            where = ", ".join(at if len(at) <= 6 else [*at[:3], "...", *at[-2:]])
            out.append(
                f"{len(at)} of {len(result.values)} points ({result.parameter} = {where}): "
                f"{CAVEATS[tag]}"
            )
    return out


def _print_whole(result: Any) -> None:
    """One row per point of a whole-bounce sweep: v1, v2, timing, sequence, e12_eff, ICM."""
    unit = " [mm]" if result.parameter == "gap" else ""
    scale = 1e3 if result.parameter == "gap" else 1.0
    table = Table(title=f"Whole bounce against {result.parameter}")
    columns = (
        f"{result.parameter}{unit}",
        "v1/|v0|",
        "v2/|v0|",
        "t_lift [ms]",
        "t_l [ms]",
        "body first",
        "e12 eff",
        "ICM v1/v2",
        "caveats",
    )
    from twoball._bounce import CAVEATS

    seen = [
        tag for tag in CAVEATS if any(tag in getattr(r, "caveats", ()) for r in result.reports if r)
    ]
    if seen:  # each caveat said once under the table
        table.caption = "\n".join(f"{tag}: {CAVEATS[tag]}" for tag in seen)
        table.caption_justify = "left"
    for column in columns:
        table.add_column(column, justify="left" if column == "caveats" else "right")
    for value, report, error in zip(result.values, result.reports, result.errors, strict=True):
        if report is None:
            table.add_row(f"{value * scale:g}", error or "", *["-"] * 7)
            continue
        icm = ((report.baselines or {}).get("models", {}).get("icm")) or {}
        table.add_row(
            f"{value * scale:g}",
            number(report.v1_ratio),
            number(report.v2_ratio),
            number(report.t_liftoff_s, 1e3),
            number(report.t_liftoff_from_max_compression_s, 1e3),
            str(report.body_left_first),
            number(report.e12_effective),
            f"{icm['v1_ratio']:.3f}/{icm['v2_ratio']:.3f}" if "v1_ratio" in icm else "-",
            ", ".join(getattr(report, "caveats", ())) or "-",
        )
    console().print(table)


def _sweep_body(args: argparse.Namespace, parameters: tuple[str, ...]) -> Any:
    """The upper body of the sweep: ``--mass-ratio`` (or the swept one) and its companions."""
    import twoball

    if "mass-ratio" not in parameters:
        return body_options(args)
    given = {n: getattr(args, n) for n in ("contact_radius", "restitution", "energy")}
    given = {n: v for n, v in given.items() if v is not None}
    return twoball.Body(0.0, **given) if given else None


def sweep_notes(points: list[Any], phi_a: str | None = None) -> list[str]:
    """One note for the whole sweep: the phi_a rule that replaced a preset's measured angle,
    said once (``phi_a``, :attr:`twoball.SweepResult.phi_a_note`) in place of the points'
    own; then, once each, any other remark (e.g. how a negative v0 was read)."""
    every = [n for p in points if p.report is not None for n in p.report.notes]
    others = list(dict.fromkeys(n for n in every if not n.startswith("phi_a = ")))
    return [phi_a, *others] if phi_a else others


def sweep_warnings(
    points: list[Any], parameters: tuple[str, ...] = (), said: Collection[str] = ()
) -> list[str]:
    """One warning for the whole sweep: how many points carry accuracy warnings, the first.

    The first is named by its swept values (``v0 = 3.2``), not by its grid index.
    Warnings in ``said`` (the swept values' slips, said for the sweep) are left out.
    """
    rest = {
        p.index: [w for w in p.report.warnings if w not in said]
        for p in points
        if p.report is not None
    }
    flagged = [p for p in points if rest.get(p.index)]
    if not flagged:
        return []
    first = flagged[0]
    where = (
        ", ".join(
            f"{name} = {getattr(first.case, _choices.SWEEP_PARAMETERS[name]):g}"
            for name in parameters
        )
        or f"point {first.index}"
    )
    return [
        f"{len(flagged)} of {len(points)} points carry warnings (see --json), the first "
        f"at {where}: {rest[first.index][0]}"
    ]


def register(parser: argparse.ArgumentParser) -> None:
    """The options of ``twoball sweep``."""
    parser.description = (
        "Closed-form lift-off over a range of one parameter, or over a grid of "
        "two (give --param and --values twice, in the same order; the first parameter "
        "varies slowest).  v0, wave-speed and radius re-apply the phi_a rule: the "
        "preset's measured angle at its own R, c, |v0|, eq. (3.7) elsewhere.  "
        "A point whose solve fails is reported with its parameters and an error."
    )
    parser.add_argument(
        "--param",
        required=True,
        action="append",
        choices=(*_choices.SWEEP_PARAMETERS, "drop-height", "gap"),
        help="swept parameter; give twice for a 2-D grid (--bounce: v0, drop-height, gap, "
        "mass-ratio or damping, once)",
    )
    parser.add_argument(
        "--bounce",
        action="store_true",
        help="sweep the drop of the lower ball on the floor (twoball bounce) instead of the "
        "lift-off",
    )
    parser.add_argument(
        "--floor-restitution",
        type=number_value,
        metavar="E",
        help="--bounce: Newton's e at every floor point in [0, 1] (default 0)",
    )
    parser.add_argument(
        "--gap",
        type=number_value,
        metavar="DX",
        help="--bounce: gap Delta x [m] between the body and the ball's top (default 0)",
    )
    parser.add_argument(
        "--pair",
        metavar="NAME",
        help="--bounce: a pair of Table 1 (the lower ball, mu, e12, the contact radius)",
    )
    parser.add_argument(
        "--values",
        required=True,
        action="append",
        metavar="LIST",
        help="values of the matching --param (same order): START:STOP:COUNT or v1,v2,...",
    )
    parser.add_argument(
        "--plot",
        metavar="FILE",
        help="also write a figure (.png, .pdf, .svg, ... by the suffix): v_l/|v0| and t_l "
        "against the parameter (1-D) or as two heat maps (2-D)",
    )
    add_measured_option(parser, "over the model's curves (a sweep of one parameter)")
    add_csv_option(parser)
    run_group = parser.add_argument_group("execution")
    run_group.add_argument(
        "--workers",
        type=integer,
        metavar="N",
        help="local worker processes (default: all cores; 1 = strictly serial)",
    )
    run_group.add_argument(
        "--scheduler",
        metavar="ADDRESS",
        help="run on an existing dask.distributed scheduler (needs the 'dask' extra)",
    )
    add_case_options(parser)
    add_contact_options(
        parser, "m1/m2 in [0, 100] on every point (or --param mass-ratio and its values)"
    )
    from twoball.cli.bounce import add_kind_options

    add_kind_options(parser)  # --bounce: the lower ball's and the body's kinds, as bounce's
    _action(parser, "--backend").default = None  # said only when given (refused without --bounce)
    parser.add_argument(
        "--json",
        action="store_true",
        help='print JSON: {"results": [one object per point], "provenance": {...}}',
    )
    parser.set_defaults(run=run)
