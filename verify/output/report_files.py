"""Report directories written all at once: Markdown, JSON, CSV and PNG files.

A report directory (``twoball verify --out DIR``, ``twoball converge --out DIR``)
is written through :func:`twoball._common.staging.staged_folder`: into a scratch folder
beside ``DIR``, then exchanged with ``DIR`` in one step.  A failed or
interrupted run leaves the previous report untouched and no scratch; a folder
that holds anything twoball did not write is refused, never emptied.
"""

from __future__ import annotations

import csv
import io
import math
import os
from collections.abc import Callable, Iterable, Mapping, Sequence
from pathlib import Path
from typing import Any

import numpy as np

from twoball._common.strict_json import json_text
from twoball.verify.checks.results import VerifyResult
from twoball.verify.studies.quantities import QuantityResult
from twoball.verify.studies.result import StudyResult

Writer = Callable[[Path], None]
PROVENANCE = "provenance.json"  # run times and dates: the one file that differs between runs


# --------------------------------------------------------------------------- directories
def check_output_dir(path: str | os.PathLike[str], flag: str = "out") -> Path:
    """Validate a report directory before any work is done.

    ``path`` may be missing, empty or an earlier twoball output (only the files
    its marker lists); anything else raises ParameterError naming ``flag``.
    """
    from twoball._common.staging import check_folder

    return check_folder(path, flag)


def write_report_dir(
    out: str | os.PathLike[str],
    writers: Mapping[str, str | Writer],
    writer: str = "twoball report",
) -> Path:
    """Write every file of a report, then put the directory in place of ``out``.

    Parameters
    ----------
    out : path
        The report directory (replaced if it exists and twoball wrote it).
    writers : mapping of file name -> str or callable(path)
        A text (written as UTF-8) or a callable that writes the file at the
        path it is given.
    writer : str
        Who wrote the folder, recorded in its marker file.

    Returns
    -------
    Path
        ``out``.
    """
    from twoball._common.staging import staged_folder

    with staged_folder(out, writer=writer) as scratch:
        for name, write in writers.items():
            if isinstance(write, str):
                (scratch / name).write_text(write, encoding="utf-8")
            else:
                write(scratch / name)
    return Path(out)


def split_provenance(data: Any, keys: Sequence[str] = ("seconds", "generated")) -> tuple[Any, Any]:
    """``data`` without run times and dates, and those entries on their own (same nesting).

    Results must be byte-identical for the same inputs; how long a run took and
    when goes into :data:`PROVENANCE` instead.
    """
    if isinstance(data, dict):
        kept, moved = {}, {}
        for key, value in data.items():
            if key in keys:
                moved[key] = value
                continue
            kept[key], sub = split_provenance(value, keys)
            if sub not in (None, {}, []):
                moved[key] = sub
        return kept, moved
    if isinstance(data, list):
        pairs = [split_provenance(v, keys) for v in data]
        moved = [m for _, m in pairs]
        return [k for k, _ in pairs], (moved if any(m not in (None, {}) for m in moved) else None)
    return data, None


def result_files(
    data: Mapping[str, Any], keys: Sequence[str] = ("seconds", "generated")
) -> dict[str, str]:
    """``results.json`` (byte-identical for the same inputs) and ``provenance.json``.

    ``data["provenance"]`` (:func:`twoball._common.provenance.block`, made here if
    missing) is split: ``results.json`` keeps what is the same for the same
    inputs (versions, platform, case); ``provenance.json`` holds the whole
    block (with the UTC time, the command line and the call) and what else
    differs from run to run: run times (every ``seconds`` entry, at its place in
    the results).
    """
    from twoball._common.provenance import block, stable

    data = dict(data)
    full = data.pop("provenance", None) or block()
    results, timings = split_provenance(data, keys)
    results["provenance"] = stable(full)
    provenance = {**full, "seconds": timings or {}}
    return {"results.json": json_text(results), PROVENANCE: json_text(provenance)}


# --------------------------------------------------------------------------- file writers
def text_writer(text: str) -> Writer:
    """A writer of a fixed text (UTF-8)."""

    def write(path: Path) -> None:
        path.write_text(text, encoding="utf-8")

    return write


def csv_text(header: Sequence[str], rows: Iterable[Sequence[Any]]) -> str:
    """CSV with a header row; floats with 17 significant digits, None as empty."""
    buffer = io.StringIO()
    writer = csv.writer(buffer, lineterminator="\n")
    writer.writerow(header)
    for row in rows:
        writer.writerow([_csv_cell(v) for v in row])
    return buffer.getvalue()


def _csv_cell(value: Any) -> str:
    if value is None:
        return ""
    if isinstance(value, (float, np.floating)):
        return "" if not math.isfinite(value) else repr(float(value))
    return str(value)


# --------------------------------------------------------------------------- Markdown
def md_table(header: Sequence[str], rows: Iterable[Sequence[Any]]) -> str:
    """A GitHub-flavoured Markdown table (cells converted with ``str``)."""
    lines = ["| " + " | ".join(header) + " |", "|" + "|".join("---" for _ in header) + "|"]
    for row in rows:
        cells = [str(c).replace("|", "\\|") for c in row]
        lines.append("| " + " | ".join(cells) + " |")
    return "\n".join(lines) + "\n"


def fmt(value: float | None, digits: int = 4, style: str = "e") -> str:
    """``value`` as text: ``-`` for None/NaN, else ``{:.{digits}{style}}``."""
    if value is None or (isinstance(value, float) and not math.isfinite(value)):
        return "-"
    return f"{value:.{digits}{style}}"


def quantity_markdown(q: QuantityResult, time_unit_s: float | None = None) -> str:
    """One quantity of a study: per-grid table and the summary line.

    ``time_unit_s`` (1/c [s], the time-step study): the step is shown as the
    time step in seconds, as ``dt`` takes it, with ``c dt`` beside it.
    """
    a = q.analysis
    show_value = not q.spec.error_norm
    header = ["grid", "h", "DOFs"] if time_unit_s is None else ["grid", "dt [s]", "c dt", "steps"]
    if show_value:
        header.append(q.spec.label)
    header += ["error (rel.)" if not q.spec.error_norm else "error", "ratio", "order"]
    rows = []
    for k, label in enumerate(q.labels):
        row = [label, fmt(a.steps[k], 3), str(q.dofs[k])]
        if time_unit_s is not None:
            row = [label, fmt(a.steps[k] * time_unit_s, 4), fmt(a.steps[k], 3), str(q.dofs[k])]
        if show_value:
            row.append(fmt(a.values[k] * q.spec.scale, 10, "g"))
        row += [
            fmt(q.relative_errors[k], 3),
            fmt(a.ratios[k - 1], 3, "f") if k else "",
            fmt(a.orders[k - 1], 2, "f") if k else "",
        ]
        rows.append(row)
    title = q.spec.label if not q.spec.error_norm else q.spec.label
    text = f"### {title}\n\n" + md_table(header, rows) + "\n"
    ref = "0" if q.spec.error_norm else fmt(a.reference * q.spec.scale, 10, "g")
    summary = [
        f"reference: {a.reference_kind} ({ref})",
        f"least-squares order {fmt(a.fit.order, 2, 'f')}",
        f"checked order (finest three) {fmt(q.checked_order, 2, 'f')}",
    ]
    if q.remark:
        summary.append(q.remark)
    if q.spec.band is not None:
        verdict = "PASS" if q.passed else "FAIL"
        summary.append(f"expected {q.spec.band.describe()}: **{verdict}**")
    if not q.spec.error_norm and math.isfinite(a.extrapolated):
        summary.append(f"Richardson {fmt(a.extrapolated * q.spec.scale, 10, 'g')}")
    if a.gci is not None:
        g = a.gci
        flag = " (flagged)" if g.flagged else ""
        summary.append(
            f"GCI three finest: p = {fmt(g.order, 2, 'f')}, {g.convergence}{flag}, "
            f"GCI_fine = {fmt(g.gci_fine * 100 if math.isfinite(g.gci_fine) else None, 3)} %"
        )
    return text + "; ".join(summary) + ".\n"


def study_markdown(study: StudyResult) -> str:
    """The whole study as Markdown: title, notes, summary table, one section per quantity."""
    verdict = "PASS" if study.passed else "FAIL"
    parts = [
        f"# Convergence study `{study.study}`: {verdict}\n",
        f"{study.title.rstrip('.')}.  Step: {study.step_name}.  Wall time {study.seconds:.1f} s.\n",
    ]
    if study.notes:
        parts.append("\n".join(f"* {n}" for n in study.notes) + "\n")
    parts.append("## Summary\n")
    parts.append(md_table(*study_summary_rows(study)))
    parts.append("\n## Quantities\n")
    unit = _time_unit(study)
    parts.extend(quantity_markdown(q, unit) + "\n" for q in study.quantities)
    return "\n".join(parts)


def _time_unit(study: StudyResult) -> float | None:
    """1/c [s] for the time-step study (its steps are c dt), else None."""
    speed = study.settings.get("wave_speed_1_s")
    return 1.0 / speed if study.study == "dt" and speed else None


def study_summary_rows(study: StudyResult) -> tuple[list[str], list[list[str]]]:
    """Header and rows of the one-line-per-quantity summary."""
    header = ["quantity", "finest rel. error", "LS order", "checked order", "expected", "GCI type"]
    header.append("result")
    rows = []
    for q in study.quantities:
        finite = q.relative_errors[np.isfinite(q.relative_errors)]
        rows.append(
            [
                q.spec.label,
                fmt(finite[-1] if finite.size else None, 3),
                fmt(q.analysis.fit.order, 2, "f"),
                fmt(q.checked_order, 2, "f"),
                "-" if q.spec.band is None else q.spec.band.describe(),
                q.remark or ("-" if q.analysis.gci is None else q.analysis.gci.convergence),
                "-" if q.passed is None else ("PASS" if q.passed else "FAIL"),
            ]
        )
    return header, rows


STUDY_CSV_HEADER = (
    "quantity",
    "label",
    "grid",
    "dofs",
    "h",
    "value",
    "reference",
    "reference_kind",
    "error",
    "relative_error",
    "ratio",
    "order",
    "expected_order",
    "passed",
    "dt_s",
)


def study_files(study: StudyResult) -> dict[str, str | Writer]:
    """Every file of the ``converge`` report: texts, and a writer for the PNG."""
    from twoball.verify.output.figures import REPORT_DPI, save_figure
    from twoball.verify.output.figures.study import study_figure

    return {
        "report.md": study_markdown(study),
        **result_files(study.as_dict()),
        "results.csv": study_csv(study),
        "convergence.png": lambda path: save_figure(study_figure(study), path, dpi=REPORT_DPI),
    }


def study_csv(study: StudyResult) -> str:
    """One row per quantity and grid (dimensionless values; see ``scale`` in the JSON).

    ``dt_s``: the time step in seconds (time-step study; empty for the others).
    """
    unit = _time_unit(study)
    rows = []
    for q in study.quantities:
        a = q.analysis
        for k, label in enumerate(q.labels):
            rows.append(
                [
                    q.spec.key,
                    q.spec.label,
                    label,
                    q.dofs[k],
                    a.steps[k],
                    a.values[k],
                    a.reference,
                    a.reference_kind,
                    a.errors[k],
                    q.relative_errors[k],
                    a.ratios[k - 1] if k else None,
                    a.orders[k - 1] if k else None,
                    None if q.spec.band is None else q.spec.band.expected,
                    "" if q.passed is None else ("PASS" if q.passed else "FAIL"),
                    None if unit is None else a.steps[k] * unit,
                ]
            )
    return csv_text(STUDY_CSV_HEADER, rows)


# --------------------------------------------------------------------------- verify report
def verify_markdown(result: VerifyResult) -> str:
    """``report.md`` of ``twoball verify``: verdict, case, runs, checks, eigenvalues, plots."""
    s = result.settings
    verdict = "PASS" if result.passed else "FAIL"
    failed = sum(not c.passed for c in result.checks)
    parts = [
        f"# twoball verify: {verdict}\n",
        f"Configuration `{result.config.name}`; {len(result.checks)} checks, {failed} failed; "
        f"wall time {result.seconds:.1f} s.\n",
        "## Case\n",
        md_table(
            [
                "R [m]",
                "c [1/s]",
                "v0 [m/s]",
                "phi_a [rad]",
                "D",
                "N",
                "sigma",
                "re-contact",
                "t_end [ms]",
            ],
            [
                [
                    f"{s['radius_m']:g}",
                    f"{s['wave_speed_1_s']:g}",
                    f"{s['v0_m_s']:g}",
                    f"{s['phi_a_rad']:.6f}",
                    f"{s['damping']:g}",
                    str(s["modes"]),
                    s["sigma"],
                    s["recontact"],
                    f"{s['t_end_s'] * 1e3:.4f}",
                ]
            ],
        ),
        "## Runs\n",
        "Relative differences: `dt_l/t_l`, `dv_l/v_l` against the Legendre series with the "
        f"case's N = {s['modes']} (the reference of every finite-element run, which uses the "
        "same filter); `(N->inf)` against the converged series.\n",
        md_table(
            [
                "backend",
                "mesh",
                "DOFs",
                "t_l [ms]",
                "v_l [m/s]",
                "v_l/\\|v0\\|",
                "dt_l/t_l",
                "dv_l/v_l",
                "dt_l/t_l (N->inf)",
                "dv_l/v_l (N->inf)",
                "seconds",
            ],
            [
                [
                    r.backend,
                    r.mesh,
                    r.dofs,
                    fmt(_scaled(r.t_l_s, 1e3), 9, "f"),
                    fmt(r.v_l_m_s, 9, "f"),
                    fmt(r.ratio, 6, "f"),
                    fmt(r.t_diff, 2),
                    fmt(r.v_diff, 2),
                    fmt(r.t_diff_converged, 2),
                    fmt(r.v_diff_converged, 2),
                    f"{r.seconds:.2f}",
                ]
                for r in result.rows
            ],
        ),
        "## Checks\n",
        md_table(
            ["check", "what is compared", "value", "tolerance", "result"],
            [
                [
                    c.name,
                    c.description,
                    fmt(c.value, 3),
                    f"[{c.band[0]:g}, {c.band[1]:g}]" if c.band else fmt(c.tolerance, 1),
                    f"**{c.verdict}**",
                ]
                for c in result.checks
            ],
        ),
        "## Eigenvalue errors\n",
        "Largest relative error `|lambda_h - l(l+1)| / l(l+1)` over the 2l + 1 discrete "
        "eigenvalues of degree l (one on the axisymmetric line).\n",
        md_table(
            ["discretisation"]
            + [f"l = {d}" for d in (result.eigen[0].degrees if result.eigen else [])],
            [[e.label] + [fmt(x, 2) for x in e.errors] for e in result.eigen],
        ),
        "## Plots\n",
        "![Pole displacement, velocity and acceleration of every backend](pole.png)\n",
        "![Eigenvalue error against the degree l](eigenvalues.png)\n",
        "![Energy decay of direct time stepping against the modal closed form](energy.png)\n",
        "## Notes\n",
        "\n".join(f"* {n}" for n in result.notes) + "\n",
    ]
    return "\n".join(parts)


def _scaled(value: float | None, factor: float) -> float | None:
    return None if value is None else value * factor


def verify_files(result: VerifyResult) -> dict[str, str | Writer]:
    """Every file of the ``verify`` report: text contents or writers (PNGs).

    ``results.csv`` holds the runs at full precision (SI); ``summary.csv``,
    ``checks.csv`` and ``eigenvalues.csv`` are rounded for reading (and for the
    documentation's tables).
    """
    from twoball.verify.checks.results import RUN_COLUMNS, format_rows
    from twoball.verify.output.figures import REPORT_DPI, save_figure
    from twoball.verify.output.figures.eigen import eigen_errors_figure
    from twoball.verify.output.figures.energy import energy_figure
    from twoball.verify.output.figures.pole import pole_motion_figure

    case = result.case
    t_end = result.settings["t_end_s"] / case.scalings.time
    checks_rows = [
        [
            c.name,
            fmt(c.value, 3),
            fmt(c.tolerance, 1),
            fmt(None if c.band is None else c.band[0], 2, "f"),
            fmt(None if c.band is None else c.band[1], 2, "f"),
            c.verdict,
            c.description,
        ]
        for c in result.checks
    ]
    summary = [
        [
            r.backend,
            r.mesh,
            r.dofs,
            fmt(_scaled(r.t_l_s, 1e3), 6, "f"),
            fmt(r.v_l_m_s, 6, "f"),
            fmt(r.ratio, 5, "f"),
            fmt(r.t_diff, 2),
            fmt(r.v_diff, 2),
            fmt(r.t_diff_converged, 2),
            fmt(r.v_diff_converged, 2),
        ]
        for r in result.rows
    ]
    degrees = result.eigen[0].degrees.tolist() if result.eigen else []
    eigen_rows = [[e.label] + [fmt(x, 2) for x in e.errors] for e in result.eigen]
    keep = [k for k, name in enumerate(RUN_COLUMNS) if name != "seconds"]
    runs = [[row[k] for k in keep] for row in format_rows(result.rows)]
    return {
        "report.md": verify_markdown(result),
        **result_files(result.as_dict()),
        "results.csv": csv_text([RUN_COLUMNS[k] for k in keep], runs),
        "summary.csv": csv_text(SUMMARY_HEADER, summary),
        "checks.csv": csv_text(
            ["check", "value", "tolerance", "band low", "band high", "result", "description"],
            checks_rows,
        ),
        "eigenvalues.csv": csv_text(["discretisation"] + [f"l = {d}" for d in degrees], eigen_rows),
        "pole.png": lambda path: save_figure(
            pole_motion_figure(case, result.traces, t_end), path, dpi=REPORT_DPI
        ),
        "eigenvalues.png": lambda path: save_figure(
            eigen_errors_figure(result.eigen), path, dpi=REPORT_DPI
        ),
        "energy.png": lambda path: save_figure(
            energy_figure(case, result.energy_curves, result.energy_bound), path, dpi=REPORT_DPI
        ),
    }


SUMMARY_HEADER = (
    "backend",
    "mesh",
    "DOFs",
    "t_l [ms]",
    "v_l [m/s]",
    "v_l/v0",
    "dt_l/t_l",
    "dv_l/v_l",
    "dt_l/t_l (N->inf)",
    "dv_l/v_l (N->inf)",
)
