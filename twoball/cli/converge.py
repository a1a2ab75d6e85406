"""``twoball converge``: refinement studies with observed orders, Richardson and GCI.

A thin layer over :func:`twoball.converge`, which runs the study and writes the report.
"""

from __future__ import annotations

import argparse
import sys
from collections.abc import Sequence
from pathlib import Path
from typing import Any

import twoball
from twoball._common import choices as _choices
from twoball._common.errors import ParameterError
from twoball._common.strict_json import json_text
from twoball.cli.case_options import add_case_options, case_from_options
from twoball.cli.console import Table, console, print_notes, print_warnings
from twoball.cli.solver_options import closed_form

MESHES = ("sphere", "axisym")
#: The lower balls a study refines: the membrane (every study), the solid ball (h only).
CONVERGE_BALLS = ("membrane", "solid")


def print_study(study: Any, out: Path, said: Sequence[str] = ()) -> None:
    """The summary table, the notes (but those ``said`` already) and where the files went."""
    from twoball._studies import summary_rows

    header, rows = summary_rows(study)
    table = Table(title=f"converge {study.study}: {study.title}")
    for name in header:
        table.add_column(name, justify="right" if name != "quantity" else "left")
    for row in rows:
        table.add_row(*row)
    out_console = console(wide=True)
    out_console.print(table)
    settings = study.settings
    out_console.print(f"phi_a = {settings['phi_a_rad']:.6f} rad ({settings['phi_a_source']})")
    for note in study.notes:
        if note not in said:
            out_console.print("* " + note)
    verdict = "PASS" if study.passed else "FAIL"
    out_console.print(f"{verdict} ({study.seconds:.1f} s); report in {out}/")


def run(args: argparse.Namespace) -> int:
    """Run ``twoball converge``: :func:`twoball.converge` with the options, report in ``--out``."""
    import twoball

    args.study = chosen_study(args.study, args.study_option)
    if args.ball == "solid":
        return run_solid(args)
    out = args.out if args.out is not None else f"twoball-converge-{args.study}"
    options = {
        "study": args.study,
        "mesh": _mesh(args),
        "levels": args.levels,
        "modes_list": args.modes_list,
        "solver": closed_form(args),
        "out": out,
    }
    if args.study == "modes" and args.modes is not None:
        raise ParameterError("modes", "left out with study modes (use --modes-list)", args.modes)
    case = case_from_options(args)
    print_notes(case.notes)
    from twoball._common.progress import Reporter

    with Reporter(f"converge {args.study}") as progress:
        study = twoball.converge(case, progress=progress, **options)
    print_warnings(study.warnings)
    target = Path(out).expanduser()
    if args.json:
        data = study.as_dict()
        data["out"] = str(target)
        sys.stdout.write(json_text(data))
    else:
        print_study(study, target, case.notes)
    return 0 if study.passed else 1


def run_solid(args: argparse.Namespace) -> int:
    """``twoball converge h --ball solid``: the half disc's eigenvalues against Lamb's roots.

    :func:`twoball._studies.converge_solid`; the report (``report.md``,
    ``results.json``, ``results.csv``) in ``--out``.
    """
    from twoball._common.progress import Reporter
    from twoball._studies import converge_solid, solid_rows

    if args.study != "h":
        valid = "h with --ball solid (the half disc refined; its eigenvalues against Lamb's)"
        raise ParameterError("study", valid, args.study)
    for name in ("mesh", "geometry", "modes_list"):
        value = getattr(args, name)
        if value is not None:
            raise ParameterError(name, "left out with --ball solid (the half disc)", value)
    out = args.out if args.out is not None else "twoball-converge-h-solid"
    with Reporter("converge h --ball solid") as progress:
        study = converge_solid(order=args.order, levels=args.levels, out=out, progress=progress)
    target = Path(out).expanduser()
    if args.json:
        data = study.as_dict()
        data["out"] = str(target)
        sys.stdout.write(json_text(data))
    else:
        out_console = console(wide=True)
        out_console.print(solid_rows(study))
        for note in study.notes:
            out_console.print("* " + note)
        verdict = "PASS" if study.passed else "FAIL"
        out_console.print(f"{verdict} ({study.seconds:.1f} s); report in {target}/")
    return 0 if study.passed else 1


def chosen_study(positional: str | None, option: str | None) -> str:
    """The study named as ``STUDY`` or as ``--study STUDY`` (the same if both)."""
    if positional is not None and option is not None and positional != option:
        raise ParameterError("study", "given once, as STUDY or --study", f"{positional}, {option}")
    study = positional if positional is not None else option
    if study is None:
        valid = "given (none was): one of " + ", ".join(_choices.STUDIES)
        raise ParameterError("study", valid, None)
    return study


def register(parser: argparse.ArgumentParser) -> None:
    """The options of ``twoball converge``."""
    parser.description = (
        "Refine one discretisation parameter and report errors, observed and "
        "least-squares orders, the Richardson extrapolate and the GCI (Celik et al. 2008) "
        "of eigenvalues, the pole trajectory, t_l, v_l and the energy at t_end.  Exit "
        "status 1 if an observed order falls outside its expected band."
    )
    parser.add_argument(
        "study",
        metavar="STUDY",
        nargs="?",
        choices=_choices.STUDIES,
        help="h: mesh refinement; order: P1 to P4 at equal DOFs; modes: Legendre N; dt: time step",
    )
    parser.add_argument(
        "--study",
        dest="study_option",
        metavar="STUDY",
        choices=_choices.STUDIES,
        help="the same as the positional STUDY (twoball converge --study order)",
    )
    parser.add_argument(
        "--mesh",
        choices=MESHES,
        help="finite-element mesh (default: sphere; axisym for study dt)",
    )
    parser.add_argument(
        "--order",
        type=int,
        choices=(1, 2, 3, 4),
        help="element order P (default 2, as in every subcommand)",
    )
    parser.add_argument(
        "--geometry",
        help="study h or order on the sphere: isoparametric (default) or exact (the sphere "
        "itself, radial projection of the flat triangles)",
    )
    parser.add_argument(
        "--levels",
        metavar="LIST",
        help="consecutive refinement levels, e.g. 2:5 or 2,3,4,5 (sphere: icosphere "
        "level; axisym: 25 * 2^level elements; dt: c dt = 0.01 / 2^level, i.e. "
        "31.25 us / 2^level for c = 320 1/s)",
    )
    parser.add_argument(
        "--modes-list",
        metavar="LIST",
        help="mode counts of study modes, 3 to 16 increasing (default 30,60,120,240,480)",
    )
    parser.add_argument(
        "--ball",
        choices=CONVERGE_BALLS,
        default="membrane",
        help="the lower ball: membrane (default) or solid (study h only: the (r, z) half "
        "disc's P1 or P2 eigenvalues against Lamb's roots at the superball's nu; --levels "
        "are half-disc levels, default 2:5 for P1, 1:4 for P2)",
    )
    add_case_options(parser)
    parser.add_argument(
        "--out", metavar="DIR", help="report directory (default ./twoball-converge-STUDY)"
    )
    parser.add_argument("--json", action="store_true", help="print the results as one JSON object")
    parser.set_defaults(run=run)


def _mesh(args: argparse.Namespace) -> str | twoball.MeshOptions | None:
    """``--mesh``, ``--order``, ``--geometry`` as the study's mesh (None: the study's default)."""
    fields = {n: getattr(args, n) for n in ("order", "geometry") if getattr(args, n) is not None}
    if not fields:
        return args.mesh
    if args.study == "modes":  # the Legendre series has no mesh
        name = next(iter(fields))
        raise ParameterError(name, "left out with study modes (no mesh)", fields[name])
    if args.study == "order" and "order" in fields:
        valid = "left out with study order (it compares P1 to P4)"
        raise ParameterError("order", valid, fields["order"])
    kind = args.mesh or ("axisym" if args.study == "dt" else "sphere")
    return twoball.MeshOptions(kind, **fields)
