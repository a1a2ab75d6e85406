"""``twoball converge``: refinement studies with observed orders, Richardson and GCI."""

from __future__ import annotations

import argparse
import re
import sys
from pathlib import Path

from rich.progress import Progress, SpinnerColumn, TextColumn, TimeElapsedColumn
from rich.table import Table
from twoball.modal.errors import ParameterError
from twoball.verify.cli.case_options import add_case_options, case_from_options
from twoball.verify.cli.console import console
from twoball.verify.output.report_files import (
    check_output_dir,
    json_text,
    study_files,
    study_summary_rows,
    write_report_dir,
)
from twoball.verify.studies.fem_runs import DEFAULT_LEVELS, LEVEL_LIMITS
from twoball.verify.studies.modes import parse_modes, run_modes_study
from twoball.verify.studies.refinement import run_h_study, run_order_study
from twoball.verify.studies.result import STUDIES, StudyResult
from twoball.verify.studies.time_step import DT_LEVEL_LIMITS, run_dt_study

MESHES = ("sphere", "axisym")


def parse_levels(text: str, mesh: str, study: str = "h") -> tuple[int, ...]:
    """``A:B`` -> levels A, A+1, ..., B (integers, A < B, inside the allowed range).

    Mesh levels are bounded per mesh (``LEVEL_LIMITS``); time-step levels
    (``--study dt``: dt = 0.01 / 2^level) by ``DT_LEVEL_LIMITS``.
    """
    low_limit, high_limit = DT_LEVEL_LIMITS if study == "dt" else LEVEL_LIMITS[mesh]
    what = "--study dt" if study == "dt" else f"--mesh {mesh}"
    valid = f"A:B with integers {low_limit} <= A < B <= {high_limit} for {what}"
    match = re.fullmatch(r"\s*(\d+)\s*:\s*(\d+)\s*", text)
    if match is None:
        raise ParameterError("--levels", valid, text)
    low, high = int(match.group(1)), int(match.group(2))
    if not (low_limit <= low < high <= high_limit):
        raise ParameterError("--levels", valid, text)
    return tuple(range(low, high + 1))


def run_study(args: argparse.Namespace, progress) -> StudyResult:
    """Dispatch to the study named by ``--study``."""
    case = case_from_options(args)
    common = {
        "sigma": args.sigma,
        "recontact": args.recontact,
        "t_end_s": args.t_end,
        "progress": progress,
    }
    if args.study == "modes":
        modes = parse_modes(args.modes_list) if args.modes_list else None
        extra = {} if modes is None else {"modes": modes}
        return run_modes_study(case, **common, **extra)
    text = args.levels or DEFAULT_LEVELS[(args.study, args.mesh, args.order)]
    levels = parse_levels(text, args.mesh, args.study)
    if args.study == "h":
        return run_h_study(case, mesh=args.mesh, order=args.order, levels=levels, **common)
    if args.study == "order":
        return run_order_study(case, mesh=args.mesh, levels=levels, **common)
    return run_dt_study(case, mesh=args.mesh, order=args.order, levels=levels, **common)


def print_study(study: StudyResult, out: Path) -> None:
    """The summary table, the notes and where the files went."""
    header, rows = study_summary_rows(study)
    table = Table(title=f"converge --study {study.study}: {study.title}")
    for name in header:
        table.add_column(name, justify="right" if name != "quantity" else "left")
    for row in rows:
        table.add_row(*row)
    out_console = console(wide=True)
    out_console.print(table)
    for note in study.notes:
        out_console.print("* " + note)
    verdict = "PASS" if study.passed else "FAIL"
    out_console.print(f"{verdict} ({study.seconds:.1f} s); report in {out}/")


def resolve_defaults(args: argparse.Namespace) -> None:
    """Fill in ``--mesh`` and ``--order`` not given: sphere P1, or axisym P2 for ``dt``.

    The time-step study measures the time discretisation against modal
    superposition on the same mesh; the small axisymmetric P2 mesh makes that
    cheap and its lift-off close to the closed form.
    """
    if args.mesh is None:
        args.mesh = "axisym" if args.study == "dt" else "sphere"
    if args.order is None:
        args.order = 2 if args.study == "dt" else 1


def run(args: argparse.Namespace) -> int:
    """Run ``twoball converge``."""
    resolve_defaults(args)
    if args.study != "modes" and args.levels is not None:
        parse_levels(args.levels, args.mesh, args.study)  # fail before any work
    if args.modes_list is not None:
        parse_modes(args.modes_list)
    out = check_output_dir(args.out or f"twoball-converge-{args.study}")
    if args.json:
        study = run_study(args, lambda _: None)
    else:
        columns = (SpinnerColumn(), TextColumn("{task.description}"), TimeElapsedColumn())
        with Progress(*columns, transient=True, console=console()) as bar:
            task = bar.add_task(f"converge --study {args.study}", total=None)
            study = run_study(args, lambda text: bar.update(task, description=text))
    data = study.as_dict()
    write_report_dir(out, study_files(study), "twoball converge")
    if args.json:
        data["out"] = str(out)
        sys.stdout.write(json_text(data))
    else:
        print_study(study, out)
    return 0 if study.passed else 1


def register(parser: argparse.ArgumentParser) -> None:
    """The options of ``twoball converge``."""
    parser.description = (
        "Refine one discretisation parameter and report errors, observed and "
        "least-squares orders, the Richardson extrapolate and the GCI (Celik et al. 2008) "
        "of eigenvalues, the pole trajectory, t_l, v_l and the energy at t_end.  Exit "
        "status 1 if an observed order falls outside its expected band."
    )
    parser.add_argument(
        "--study",
        required=True,
        choices=STUDIES,
        help="h: mesh refinement; order: P1 against P2; modes: Legendre N; dt: time step",
    )
    parser.add_argument(
        "--mesh",
        choices=MESHES,
        help="finite-element mesh (default: sphere; axisym for --study dt)",
    )
    parser.add_argument(
        "--order",
        type=int,
        choices=(1, 2),
        help="element order P (default: 1; 2 for --study dt)",
    )
    parser.add_argument(
        "--levels",
        metavar="A:B",
        help="refinement levels A..B (sphere: icosphere level; axisym: 25 * 2^level "
        "elements; dt: dt = dt0 / 2^level)",
    )
    parser.add_argument(
        "--modes-list",
        metavar="N1,N2,..|NMIN:NMAX",
        help="mode counts of --study modes (default 30:480, doubling)",
    )
    add_case_options(parser)
    parser.add_argument(
        "--out", metavar="DIR", help="report directory (default ./twoball-converge-STUDY)"
    )
    parser.add_argument("--json", action="store_true", help="print the results as one JSON object")
    parser.set_defaults(run=run)
