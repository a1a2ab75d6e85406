"""``twoball reproduce``: recompute the paper's figures and numbers, side by side with ours.

The parts (see :data:`PARTS`) each write their PNG figures and return a section of
the report; :func:`reproduce` runs the selected parts in a private working folder
and, as each part finishes, puts everything finished so far in place of the
output folder (:func:`twoball._common.staging.staged_folder`) with a report that
names the parts still missing.  A run stopped at its time limit or by a signal
keeps its finished parts, each whole; no part is ever half written.  The output
folder is recognised by twoball's marker file and its list of files, never by a
file name: a folder holding anything else is refused.  ``reproduction.json`` is
byte-identical for the same inputs; the date and run times go to ``provenance.json``.
"""

from __future__ import annotations

import json
import os
import platform
import time
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from datetime import UTC, datetime
from pathlib import Path
from typing import Any

from twoball._common.choices import REPRODUCTION_DIR, REPRODUCTION_PARTS, REPRODUCTION_REPORT
from twoball._common.errors import ParameterError
from twoball._common.progress import TaskHook
from twoball.verify.reproduce import cem as reproduce_cem
from twoball.verify.reproduce import contact as reproduce_contact
from twoball.verify.reproduce import icm as reproduce_icm
from twoball.verify.reproduce import kinds as reproduce_kinds
from twoball.verify.reproduce import whole as reproduce_whole
from twoball.verify.reproduce.common import Context, Section, comparison_table
from twoball.verify.sweeps.parallel import Runner

#: Part name -> function(Context) -> Section, in report order (the names: REPRODUCTION_PARTS).
PARTS: dict[str, Callable[[Context], Section]] = dict(
    zip(
        REPRODUCTION_PARTS,
        (
            reproduce_icm.part_table2,
            reproduce_cem.part_fig6,
            reproduce_cem.part_fig10,
            reproduce_cem.part_fig11,
            reproduce_cem.part_fig12,
            reproduce_cem.part_thresholds,
            reproduce_icm.part_table1,
            reproduce_icm.part_icm,
            reproduce_contact.part_contact,
            reproduce_whole.part_whole_table1,
            reproduce_whole.part_whole_gap,
            reproduce_whole.part_whole_timing,
            reproduce_kinds.part_kinds_table1,
            reproduce_kinds.part_kinds_gap,
        ),
        strict=True,
    )
)
DEFAULT_OUT = REPRODUCTION_DIR
REPORT = REPRODUCTION_REPORT
DATA = "reproduction.json"
PROVENANCE = "provenance.json"


def parse_only(text: str | Sequence[str] | None) -> list[str]:
    """``only="a,b"`` or ``["a", "b"]`` -> part names in report order; None -> all parts."""
    if text is None:
        return list(PARTS)
    valid = "a comma-separated subset of " + ",".join(PARTS)
    if not isinstance(text, str):
        parts = list(text) if isinstance(text, list | tuple) else None
        if parts is None or not all(isinstance(part, str) for part in parts):
            raise ParameterError("only", valid + " (a str or a list of str)", text)
        text = ",".join(parts)
    names = [t.strip() for t in text.split(",") if t.strip()]
    unknown = [n for n in names if n not in PARTS]
    if not names or unknown:
        raise ParameterError("only", "a comma-separated subset of " + ",".join(PARTS), text)
    return [p for p in PARTS if p in names]


def check_output(out: str | os.PathLike) -> Path:
    """The output folder, checked before any work (:func:`twoball._common.staging.check_folder`).

    It may be missing, empty, or an earlier twoball output holding only the
    files its marker lists; anything else raises ParameterError naming ``out``.
    """
    from twoball._common.staging import check_folder

    return check_folder(out, "out")


def reproduce(
    out: str | os.PathLike,
    only: Sequence[str] | None = None,
    runner: Runner | None = None,
    progress: TaskHook | None = None,
    command: str = "twoball reproduce",
    monitor: Any = None,
) -> tuple[Path, list[Section]]:
    """Run the selected parts and write figures, ``reproduction.md`` and ``.json`` to ``out``.

    Returns the output directory and the sections.  The parts run in a private
    working folder; as each finishes, ``out`` is replaced by everything finished
    so far (:func:`publish`), its report listing the parts still missing.  A run
    stopped at the time limit (:class:`~twoball._common.budget.DeadlineError`) or
    by SIGINT/SIGTERM therefore leaves every finished part in ``out`` with a
    report that says which parts are missing and why, and then raises as before
    (exit status 3, 130, 143); stopped before its first part finished, it leaves
    ``out`` as it was.  ``progress(label, total)`` starts a counted task and
    returns its ``update(done)``: :meth:`twoball._common.progress.Reporter.task`.
    ``monitor`` (:class:`~twoball._common.monitor.Monitor`) is handed to the runs
    of the parts (the whole bounce's drops).
    """
    from twoball._common.budget import DeadlineError
    from twoball._common.signals import pause
    from twoball._common.staging import scratch_folder

    target = check_output(out)
    names = list(PARTS) if only is None else list(only)
    own_runner = runner is None
    try:
        if own_runner:
            runner = Runner(workers=1).__enter__()
        assert runner is not None
        with scratch_folder(target, "out") as work:
            ctx = Context(work, runner, monitor=monitor)
            if progress is not None:
                ctx.progress = progress
            sections: list[Section] = []
            started = time.perf_counter()
            run = Run(target, work, names, runner.describe(), command, out, started)
            try:
                for name in names:
                    update = ctx.progress(f"part {name}", 1)
                    t0 = time.perf_counter()
                    section = PARTS[name](ctx)
                    section.seconds = time.perf_counter() - t0
                    sections.append(section)
                    update(1)
                    run.publish(sections)
                    pause("part")  # test hook: a part is committed, more may follow
            except DeadlineError as stop:
                if not sections:
                    raise
                why = " ".join(str(stop).split()).replace(" (raise the time limit, max_time)", "")
                run.publish(sections, why)
                raise DeadlineError(f"{stop}; {run.kept(sections)}") from None
            except KeyboardInterrupt as stop:
                if sections:
                    name = getattr(stop, "signum", None)
                    how = "SIGTERM" if name == 15 else "SIGINT" if name == 2 else "an interrupt"
                    run.publish(sections, f"interrupted by {how}")
                raise
    finally:
        if own_runner and runner is not None:
            runner.close()
    return target, sections


@dataclass(frozen=True)
class Run:
    """One reproduction in progress: where it works, what it was asked, when it started."""

    target: Path
    work: Path
    names: list[str]
    where: str
    command: str
    out: str | os.PathLike
    started: float

    def missing(self, sections: Sequence[Section]) -> list[str]:
        """The asked parts not (yet) in ``sections``, in report order."""
        done = {s.key for s in sections}
        return [n for n in self.names if n not in done]

    def kept(self, sections: Sequence[Section]) -> str:
        """``kept the finished parts a, b in DIR (reproduction.md lists the missing ones)``."""
        done = ", ".join(s.key for s in sections)
        return f"kept the finished parts {done} in {self.target} ({REPORT} lists the missing ones)"

    def publish(self, sections: Sequence[Section], stopped: str | None = None) -> None:
        """Replace the output folder by the finished parts and their report.

        ``stopped``: why the run ended early (None: it goes on, or is complete).
        """
        import shutil

        from twoball._common.provenance import block
        from twoball._common.staging import staged_folder
        from twoball.verify.output.report_files import result_files

        missing = self.missing(sections)
        total = time.perf_counter() - self.started
        with staged_folder(self.target, "out", "twoball reproduce") as staging:
            shutil.copytree(self.work, staging, dirs_exist_ok=True)
            text = render_markdown(list(sections), self.where, total, self.command)
            if missing:
                text = incomplete_note(text, missing, stopped)
            (staging / REPORT).write_text(text, encoding="utf-8")
            plain = json.dumps(report_data(list(sections), self.where, total), default=_json)
            data = json.loads(plain)
            if missing:
                data["missing"] = missing
                data["stopped"] = stopped
            arguments = {"out": self.out, "only": self.names, "runner": self.where}
            data["provenance"] = block(None, "twoball.verify.reproduce.driver.reproduce", arguments)
            files = result_files(data, ("seconds", "generated", "runner"))
            (staging / DATA).write_text(files["results.json"], encoding="utf-8")
            (staging / PROVENANCE).write_text(files[PROVENANCE], encoding="utf-8")


def incomplete_note(text: str, missing: Sequence[str], stopped: str | None) -> str:
    """``text`` (the report) with a paragraph after its title naming the missing parts."""
    why = (
        f"The run was {stopped}."
        if stopped is not None and stopped.startswith("interrupted")
        else f"The run {stopped}."
        if stopped is not None
        else "It was written while the run went on; if the run has ended since, it was "
        "stopped (killed) before these parts finished."
    )
    note = (
        f"**Incomplete: {len(missing)} part(s) missing: {', '.join(missing)}.**  {why}  "
        f"Every part listed below is complete.  `twoball reproduce --only "
        f"{','.join(missing)}` recomputes the missing ones (into another folder)."
    )
    title, _, rest = text.partition("\n\n")
    return f"{title}\n\n{note}\n\n{rest}"


def _json(value: Any) -> Any:
    if hasattr(value, "item"):
        return value.item()
    if hasattr(value, "tolist"):
        return value.tolist()
    return str(value)


def report_data(sections: list[Section], where: str, seconds: float) -> dict[str, Any]:
    """Everything in the report, machine-readable."""
    return {
        "generated": datetime.now(UTC).isoformat(timespec="seconds"),
        "runner": where,
        "seconds": seconds,
        "sections": {
            s.key: {
                "title": s.title,
                "seconds": s.seconds,
                "comparisons": [c.as_dict() for c in s.comparisons],
                "figures": [f for f, _ in s.figures],
                "data": s.data,
            }
            for s in sections
        },
    }


def render_markdown(sections: list[Section], where: str, seconds: float, command: str) -> str:
    """The report: header, then per part its prose, comparison table, extra tables, figures."""
    import matplotlib
    import numpy
    import scipy

    now = datetime.now(UTC).strftime("%Y-%m-%d %H:%M UTC")
    lines = [
        "# Reproduction of the two-ball bounce paper",
        "",
        f"Generated {now} by `{command}` ({where}; {seconds:.1f} s in total).  Python "
        f"{platform.python_version()}, numpy {numpy.__version__}, scipy {scipy.__version__}, "
        f"matplotlib {matplotlib.__version__}.",
        "",
        "Every number the paper states in the reproduced parts is listed with ours beside it "
        "and the difference (ours - paper).  Nothing is fitted to the paper.  "
        + models_line([s.key for s in sections])
        + "  Where the two differ, the notes and the text of each section say by how much "
        "and what we found about why.",
        "",
        "Parts: "
        + ", ".join(
            f"[{s.title.split(':')[0]}](#{_anchor(s.title)}) ({s.seconds:.1f} s)" for s in sections
        ),
        "",
    ]
    for s in sections:
        lines += [f"## {s.title}", ""]
        for p in s.paragraphs:
            lines += [p, ""]
        if s.comparisons:
            lines += [comparison_table(s.comparisons), ""]
        for t in s.tables:
            lines += [t, ""]
        for name, caption in s.figures:
            lines += [f"![{name}]({name})", "", f"*{name}*: {caption}", ""]
    return "\n".join(lines)


#: What each group of parts computes with (the report's preamble names those that ran).
MODELS_USED = (
    (
        ("table2", "fig6", "fig10", "fig11", "fig12", "thresholds"),
        "The CEM parts use the closed-form Legendre series with the Lanczos filter, N = 30 "
        "and the default `window` re-contact horizon unless a row says otherwise.",
    ),
    (("table1", "icm"), "The ICM parts evaluate eqs. (2.1)-(2.6) in closed form."),
    (
        ("contact",),
        "The finite-mass part uses the closed-form event-driven contact solver "
        "(Legendre, N = 30, Lanczos filter).",
    ),
    (
        ("whole_table1", "whole_gap", "whole_timing"),
        "The whole-bounce parts drop the pair's lower ball on the floor with the body on "
        "top (Legendre modes N = 192 of the pressurised membrane with its gas, floor points "
        "at the Gauss-Radau nodes, the Moreau-Jean scheme at dt = 0.005/c; the pair's preset "
        "and Table 1's mu, e12), beside the lumped baselines.",
    ),
    (
        ("kinds_table1", "kinds_gap"),
        "The parts of the balls and bodies run the same whole bounce with the lower ball a "
        "radial membrane or a thin shell (the preset's wall), both on Legendre modes "
        "N = 64, and the body rigid, lumped or a second ball (the pair's presets).",
    ),
)


def models_line(keys: Sequence[str]) -> str:
    """The sentences of :data:`MODELS_USED` for the parts that ran (``keys``)."""
    return "  ".join(text for parts, text in MODELS_USED if any(k in parts for k in keys))


def _anchor(title: str) -> str:
    keep = [ch.lower() if ch.isalnum() else "-" if ch == " " else "" for ch in title]
    return "".join(keep)


__all__ = ["DEFAULT_OUT", "PARTS", "check_output", "parse_only", "reproduce"]
