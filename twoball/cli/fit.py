"""``twoball fit``: model parameters fitted to a measured CSV file, with standard errors.

A thin layer over :func:`twoball.fit`: ``--data`` is the file, ``--param`` the
fitted parameters, ``--model`` the closed-form lift-off or the whole bounce;
the case options give the base case and the parameters' start, ``--pair`` or
``--mass-ratio`` the body of the whole bounce.
"""

from __future__ import annotations

import argparse
import textwrap
from copy import copy
from typing import Any

import twoball
from twoball._common import choices as _choices
from twoball._common.errors import ParameterError
from twoball.cli.case_options import add_case_options, case_from_options
from twoball.cli.console import (
    Table,
    console,
    print_json,
    print_notes,
    print_warnings,
)
from twoball.cli.contact_options import add_contact_options, body_options
from twoball.cli.values import integer
from twoball.cli.values import number as numeric

__all__ = ["register", "run"]

#: Units of the measured columns, for the table's headers.
_UNITS = {"v1_m_s": "m/s", "v2_m_s": "m/s", "t_liftoff_s": "ms", "v0_m_s": "m/s", "gap_m": "mm"}
_SCALES = {"t_liftoff_s": 1e3, "gap_m": 1e3}
_SHORT = {
    "v1_m_s": "v1",
    "v2_m_s": "v2",
    "t_liftoff_s": "t_l",
    "v0_m_s": "|v0|",
    "gap_m": "gap",
    "phi_a_rad": "phi_a",
}


def _pairs(items: list[str] | None, flag: str, parameters: list[str]) -> dict[str, Any]:
    """``["damping=0.2"]`` (``--start``) or ``["damping=0.05:0.5"]`` (``--bounds``) as a mapping."""
    out: dict[str, Any] = {}
    for text in items or []:
        name, sep, value = str(text).partition("=")
        name = name.strip()
        shape = "NAME=LOW:HIGH" if flag == "bounds" else "NAME=VALUE"
        valid = f"{shape} with NAME one of the --param given ({', '.join(parameters)})"
        if not sep or name not in parameters:
            raise ParameterError(flag, valid, text)
        if name in out:
            raise ParameterError(flag, f"given once per parameter ({name} twice)", text)
        if flag == "bounds":
            low, colon, high = value.partition(":")
            if not colon:
                raise ParameterError(flag, valid, text)
            out[name] = (_float(low, flag, valid, text), _float(high, flag, valid, text))
        else:
            out[name] = _float(value, flag, valid, text)
    return out


def _float(text: str, flag: str, valid: str, whole: str) -> float:
    value = numeric(text.strip())
    if isinstance(value, str) or "_" in text:
        raise ParameterError(flag, valid + " and numbers", whole)
    return value


def _closed_options(args: argparse.Namespace) -> dict[str, Any]:
    """The case and the closed form of the options; the bounce's own options refused."""
    for name in ("pair", "gap", "floor_restitution", "dt", *_CONTACT):
        if getattr(args, name, None) is not None:
            valid = "left out with --model closed (the closed form's body is massless: "
            raise ParameterError(name, valid + "--model bounce)", getattr(args, name))
    if args.preset is None:
        args.preset = "basketball"
    case = case_from_options(args)
    fields = {n: getattr(args, n) for n in ("sigma", "recontact", "t_end")}
    solver = twoball.ClosedForm(**{k: v for k, v in fields.items() if v is not None})
    return {"case": case, "solver": solver}


_CONTACT = ("mass_ratio", "contact_radius", "restitution", "energy")


def _bounce_options(args: argparse.Namespace) -> dict[str, Any]:
    """The case, drop, body, pair and Moreau-Jean solver of the options (``--model bounce``)."""
    if args.phi_a is not None:
        valid = "left out with --model bounce (the contact angle is the drop's output)"
        raise ParameterError("phi_a", valid, args.phi_a)
    for name in ("sigma", "recontact"):
        if getattr(args, name) is not None:
            raise ParameterError(
                name, "left out with --model bounce (no lift-off criteria)", getattr(args, name)
            )
    if args.pair is not None:
        if args.preset is not None:
            valid = "left out with --pair (the pair sets the lower ball)"
            raise ParameterError("preset", valid, args.preset)
        for name in _CONTACT:
            if getattr(args, name) is not None:
                valid = "left out with --pair (the pair fixes mu, e12 and the contact radius)"
                raise ParameterError(name, valid, getattr(args, name))
        from twoball import _lookup

        args.preset = _lookup.pair(args.pair).lower
    elif args.preset is None:
        args.preset = "basketball"
    body = None if args.pair is not None else body_options(args)
    case_args = copy(args)
    case_args.gas = None
    case_args.modes = None
    case_args.membrane = None
    case = case_from_options(case_args)
    fields: dict[str, Any] = {"gas": args.gas, "gap": args.gap, "membrane": args.membrane}
    fields["floor_restitution"] = args.floor_restitution
    drop = twoball.Drop(**{k: v for k, v in fields.items() if v is not None})
    from twoball._fit import DEFAULT_FIT_MODES

    modes = DEFAULT_FIT_MODES if args.modes is None else args.modes
    solver = twoball.MoreauJean(twoball.LegendreBall(modes), dt=args.dt, t_end=args.t_end)
    return {"case": case, "solver": solver, "body": body, "drop": drop, "pair": args.pair}


def run(args: argparse.Namespace) -> int:
    """Run ``twoball fit``: :func:`twoball.fit` with the options; print or write the result."""
    from twoball._common.progress import QUICK, Reporter
    from twoball._plot import check_figure_path

    plot = None if args.plot is None else check_figure_path(args.plot, "plot")
    if args.model not in _choices.FIT_MODELS:
        raise ParameterError("model", "one of " + ", ".join(_choices.FIT_MODELS), args.model)
    options = _closed_options(args) if args.model == "closed" else _bounce_options(args)
    start = _pairs(args.start, "start", args.param)
    bounds = _pairs(args.bounds, "bounds", args.param)
    bootstrap = 0 if args.bootstrap is None else args.bootstrap
    if isinstance(bootstrap, bool) or not isinstance(bootstrap, int) or bootstrap < 0:
        raise ParameterError("bootstrap", "an integer in [0, 10000]", args.bootstrap)
    with Reporter("fit", delay=QUICK) as progress:
        result = twoball.fit(
            args.data,
            args.param,
            model=args.model,
            start=start or None,
            bounds=bounds or None,
            bootstrap=bootstrap,
            progress=progress,
            **options,
        )
        if plot is not None:
            progress(f"figure {plot.name}")
            result.plot(plot)
    print_notes(list(result.notes))
    print_warnings(result.warnings)
    if args.json:
        print_json(result.as_dict())
        return 0
    print_result(result)
    if plot is not None:
        console().print(f"plot written to {plot}")
    return 0


def print_result(result: Any) -> None:
    """The fitted values with their errors, every row's residual, chi^2 and the RMS."""
    out = console()
    what = "closed-form lift-off" if result.model == "closed" else "whole bounce"
    table = Table(title=f"Fit of the {what} to {result.data.source}")
    columns = ["parameter", "value", "std. error", "start", "bounds", "at bound"]
    boot = result.bootstrap_errors
    if boot is not None:
        columns.insert(3, "bootstrap error")
    for name in columns:
        table.add_column(name, justify="left" if name in ("parameter", "at bound") else "right")
    for name in result.parameters:
        error = result.standard_errors[name]
        low, high = result.bounds[name]
        unit = result.units[name]
        cells = [
            name + (f" [{unit}]" if unit else ""),
            f"{result.values[name]:.6g}",
            "-" if error is None else f"{error:.3g}",
            f"{result.start[name]:.6g}",
            f"[{low:g}, {high:g}]",
            result.at_bound[name] or "no",
        ]
        if boot is not None:
            cells.insert(3, "-" if boot[name] is None else f"{boot[name]:.3g}")
        table.add_row(*cells)
    out.print(table)
    rows = Table(title="Rows: measured, model and residual (measured - model)")
    inputs = list(result.inputs)
    rows.add_column("row", justify="right")
    for column in inputs:
        rows.add_column(_header(column), justify="right")
    for column in result.residuals.columns:
        for what_ in ("", " model", " resid."):
            rows.add_column(_header(column, what_), justify="right")
    for entry in result.rows():
        cells = [str(entry["row"])]
        for column in inputs:
            cells.append(_cell(column, entry["inputs"].get(column)))
        for column in result.residuals.columns:
            for key in ("measured", "model", "residual"):
                cells.append(_cell(column, entry[key].get(column)))
        rows.add_row(*cells)
    out.print(rows)
    rms = ", ".join(
        f"{_SHORT[c]} {_cell(c, v)} {_UNITS.get(c, '')}".rstrip() for c, v in result.rms.items()
    )
    reduced = result.reduced_chi2
    out.print(
        f"chi^2 = {result.chi2:.4g} ({'sigma' if result.absolute else 'column-RMS'} weights), "
        f"dof = {result.dof}"
        + ("" if reduced is None else f", chi^2/dof = {reduced:.4g}")
        + f"; RMS residual: {rms}"
    )
    out.print(
        f"{'converged' if result.converged else 'NOT converged'} after {result.evaluations} "
        f"evaluations ({result.runs} model runs): {result.message}"
    )


def _header(column: str, what: str = "") -> str:
    unit = _UNITS.get(column, "rad" if column == "phi_a_rad" else "")
    return f"{_SHORT[column]}{what} [{unit}]"


def _cell(column: str, value: float | None) -> str:
    if value is None:
        return "-"
    return f"{value * _SCALES.get(column, 1.0):.5g}"


def _columns_help() -> str:
    """The CSV columns for ``--help`` (and the generated CLI reference), one item each."""
    lines = textwrap.wrap(
        "The CSV file: a header line naming its columns, then one row per measurement; "
        "lines starting with # are comments; a blank cell is not measured (an input then "
        "takes the case's value).  Columns (SI, the unit in the name):",
        88,
    )
    lines.append("")
    items = dict(_choices.MEASURED_COLUMNS)
    items[_choices.SIGMA_PREFIX + "COLUMN"] = (
        "the standard uncertainty of COLUMN (same unit, > 0; e.g. sigma_v1_m_s); with these, "
        "residuals are weighted by 1/sigma and the standard errors need no residual variance"
    )
    for name, text in items.items():
        lines += textwrap.wrap(f"- {name}: {text}", 88, subsequent_indent="  ")
    closed, bounce = (_choices.FIT_MODEL_COLUMNS[m] for m in ("closed", "bounce"))
    lines += [
        "",
        *textwrap.wrap(
            f"--model closed uses {', '.join(closed[0] + closed[1])}; --model bounce uses "
            f"{', '.join(bounce[0] + bounce[1])} (v1_m_s and t_liftoff_s with a body: "
            "--pair or --mass-ratio).  A column the model cannot use is refused by name; "
            "at least one measured column is needed.  Example:",
            88,
        ),
        "",
        "  v0_m_s,phi_a_rad,v1_m_s",
        "  4.1,2.6,3.7",
    ]
    return "\n".join(lines)


class _Help(argparse.RawDescriptionHelpFormatter):
    """The description and the columns as written (lists stay lists), at the terminal's width."""

    def __init__(self, prog: str, **kwargs: Any) -> None:
        from twoball.cli.main import _columns

        kwargs.setdefault("width", _columns() - 2)
        super().__init__(prog, **kwargs)


def register(parser: argparse.ArgumentParser) -> None:
    """The options of ``twoball fit``."""
    parser.formatter_class = _Help
    parser.description = "\n".join(
        textwrap.wrap(
            "Fit model parameters to measured rows by least squares (scipy.optimize."
            "least_squares): the closed-form lift-off (--model closed, default) or the whole "
            "bounce (--model bounce).  Prints the fitted values with standard errors (from "
            "the Jacobian at the optimum), every row's residual, chi^2 and the RMS; --plot "
            "draws the data and the model.  The case options give the base case and each "
            "parameter's start.",
            88,
        )
    )
    parser.epilog = _columns_help()
    parser.add_argument(
        "--data", required=True, metavar="FILE", help="the measured CSV file (columns below)"
    )
    parser.add_argument(
        "--param",
        required=True,
        action="append",
        choices=tuple(_choices.FIT_PARAMETERS),
        help="a fitted parameter; give several times for several: "
        + "; ".join(f"{k}: {v}" for k, v in _choices.FIT_PARAMETERS.items()),
    )
    parser.add_argument(
        "--model",
        default="closed",
        help="closed (the closed-form lift-off, default) or bounce (the drop or the whole "
        "bounce, Moreau-Jean on a Legendre ball, default N = 32)",
    )
    parser.add_argument(
        "--pair",
        metavar="NAME",
        help="--model bounce: a pair of Table 1 (the lower ball, mu, e12 and the contact radius)",
    )
    parser.add_argument(
        "--gap",
        type=numeric,
        metavar="DX",
        help="--model bounce: gap Delta x [m] of the rows without gap_m (default 0)",
    )
    parser.add_argument(
        "--floor-restitution",
        type=numeric,
        metavar="E",
        help="--model bounce: Newton's e at the floor points in [0, 1] (default 0; the start "
        "of --param floor-restitution)",
    )
    parser.add_argument(
        "--dt", type=numeric, metavar="SECONDS", help="--model bounce: time step [s] (0.005 / c)"
    )
    parser.add_argument(
        "--start",
        action="append",
        metavar="NAME=VALUE",
        help="start of a fitted parameter (SI; default: the case's value), e.g. damping=0.2",
    )
    parser.add_argument(
        "--bounds",
        action="append",
        metavar="NAME=LOW:HIGH",
        help="bounds of a fitted parameter inside its model's range (damping [0, 0.999], "
        "wave-speed [1e-6, 1e9] 1/s, restitutions [0, 1]), e.g. damping=0.05:0.5",
    )
    parser.add_argument(
        "--bootstrap",
        type=integer,
        metavar="N",
        help="also N bootstrap resamples of the rows (a second standard error; default 0)",
    )
    parser.add_argument(
        "--plot",
        metavar="FILE",
        help="also write the figure (.png, .pdf, .svg, ...): data and model against the rows' "
        "|v0| (or gap), residuals below",
    )
    add_case_options(parser)
    add_contact_options(
        parser, "--model bounce: mass ratio m1/m2 in (0, 100] of a body on the ball's top"
    )
    preset = next(a for a in parser._actions if "--preset" in a.option_strings)
    preset.default = None  # the pair's lower ball, else the basketball
    modes = next(a for a in parser._actions if "--modes" in a.option_strings)
    modes.help = "Legendre modes N (closed: default 30; bounce: the ball's degree, default 32)"
    restitution = next(a for a in parser._actions if "--restitution" in a.option_strings)
    restitution.help = "--model bounce: Newton's e12 at the body's impacts (the start of "
    restitution.help += "--param restitution; default 0)"
    energy = next(a for a in parser._actions if "--energy" in a.option_strings)
    energy.help = "refused: both bodies fall at |v0| in the whole bounce"
    parser.add_argument(
        "--json",
        action="store_true",
        help="print one JSON object: parameters (value, standard_error, bounds, at_bound), "
        "rows (inputs, measured, model, residual), chi2, dof, rms, warnings",
    )
    parser.set_defaults(run=run)
