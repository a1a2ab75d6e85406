"""``twoball verify``: every backend against the closed form, PASS/FAIL, and a report directory.

A thin layer over :func:`twoball.verify`, which runs the checks and writes the report.
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path
from typing import Any

from twoball._common.strict_json import json_text
from twoball.cli.case_options import add_case_options, case_from_options
from twoball.cli.console import Table, console, print_notes, print_warnings
from twoball.cli.solver_options import closed_form

DEFAULT_OUT = "twoball-report"


def _pct(value: float | None) -> str:
    return "-" if value is None else f"{value:+.2e}"


def print_result(result: Any, out: Path) -> None:
    """The run table, the checks and the verdict."""
    out_console = console(wide=True)
    runs = Table(title=f"twoball verify ({result.config.name}): runs")
    for name in ("backend", "mesh", "DOFs", "t_l [ms]", "v_l [m/s]", "v_l/|v0|"):
        runs.add_column(name, justify="left" if name in ("backend", "mesh") else "right")
    for name in ("dt_l/t_l", "dv_l/v_l", "dv_l/v_l (N->inf)", "seconds"):
        runs.add_column(name, justify="right")
    for row in result.rows:
        runs.add_row(
            row.backend,
            row.mesh,
            str(row.dofs),
            "-" if row.t_l_s is None else f"{row.t_l_s * 1e3:.6f}",
            "-" if row.v_l_m_s is None else f"{row.v_l_m_s:.6f}",
            "-" if row.ratio is None else f"{row.ratio:.5f}",
            _pct(row.t_diff),
            _pct(row.v_diff),
            _pct(row.v_diff_converged),
            f"{row.seconds:.2f}",
        )
    out_console.print(runs)
    settings = result.settings
    out_console.print(f"phi_a = {settings['phi_a_rad']:.6f} rad ({settings['phi_a_source']})")
    checks = Table(title="checks")
    for name in ("check", "value", "tolerance", "result"):
        checks.add_column(name, justify="left" if name == "check" else "right")
    for check in result.checks:
        tolerance = (
            f"[{check.band[0]:g}, {check.band[1]:g}]"
            if check.band is not None
            else ("-" if check.tolerance is None else f"{check.tolerance:.1e}")
        )
        value = "-" if check.value is None else f"{check.value:.3e}"
        checks.add_row(check.name, value, tolerance, check.verdict)
    out_console.print(checks)
    failed = [c.name for c in result.checks if not c.passed]
    verdict = "PASS" if not failed else f"FAIL ({len(failed)}: {', '.join(failed)})"
    out_console.print(
        f"{verdict}: {len(result.checks)} checks in {result.seconds:.1f} s; report in {out}/"
    )


def run(args: argparse.Namespace) -> int:
    """Run ``twoball verify``: :func:`twoball.check` with the options, report in ``--out``."""
    from twoball._studies import check

    case = case_from_options(args)
    print_notes(case.notes)
    options = {
        "thorough": args.thorough,
        "fast": args.fast,
        "solver": closed_form(args),
        "out": args.out,
    }
    from twoball._common.progress import Reporter
    from twoball._studies import verify_steps

    steps = verify_steps(args.thorough, args.fast)
    with Reporter("verify", total=steps) as progress:
        result = check(case, progress=progress, **options)
    print_warnings(result.warnings)
    out = Path(args.out).expanduser()
    if args.json:
        data = result.as_dict()
        data["out"] = str(out)
        sys.stdout.write(json_text(data))
    else:
        print_result(result, out)
    return 0 if result.passed else 1


def register(parser: argparse.ArgumentParser) -> None:
    """The options of ``twoball verify``."""
    parser.description = (
        "Runs the Legendre series (N and converged), the axisymmetric and sphere "
        "finite elements (P1, P2), eigenvalue, energy and time-stepping checks; prints a "
        "table and PASS/FAIL per check; writes report.md, results.json, results.csv, "
        "summary.csv, checks.csv, eigenvalues.csv and PNG plots (pole.png, eigenvalues.png, "
        "energy.png) into --out.  Exit status 0 only if every check passes."
    )
    add_case_options(parser)
    parser.add_argument(
        "--out",
        metavar="DIR",
        default=DEFAULT_OUT,
        help="report directory, replaced once the new report is complete "
        f"(default ./{DEFAULT_OUT})",
    )
    parser.add_argument(
        "--thorough", action="store_true", help="finer meshes as well (minutes, not seconds)"
    )
    parser.add_argument("--fast", action="store_true", help=argparse.SUPPRESS)  # tests only
    parser.add_argument("--json", action="store_true", help="print the results as one JSON object")
    parser.set_defaults(run=run)
