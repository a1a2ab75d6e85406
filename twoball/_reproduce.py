"""``twoball.reproduce``: the paper's figures and numbers recomputed, in one directory."""

from __future__ import annotations

import math
import os
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from twoball._common.budget import timed, verb_default
from twoball._common.keywords import checked

__all__ = ["Reproduction", "reproduce"]


@checked
@dataclass(frozen=True)
class Reproduction:
    """What :func:`reproduce` wrote: the directory and one section per part.

    Attributes
    ----------
    directory : Path
        The output directory (``reproduction.md``, ``reproduction.json``, figures).
    sections : list
        One per part, in report order: ``key``, ``title``, ``figures``,
        ``comparisons`` (paper value, ours, difference), ``seconds``.

    Examples
    --------
    >>> import tempfile, pathlib, twoball
    >>> done = twoball.reproduce(pathlib.Path(tempfile.mkdtemp()) / "paper", only="table1")
    >>> done.as_dict()["sections"][0]["key"], done.figures >= 0
    ('table1', True)
    """

    directory: Path
    sections: list[Any] = field(default_factory=list)

    @property
    def file(self) -> Path:
        """The main file, ``reproduction.md`` in :attr:`directory`."""
        from twoball.verify.reproduce.driver import REPORT

        return self.directory / REPORT

    @property
    def files(self) -> list[Path]:
        """Every file written into :attr:`directory` (report, JSON, figures), sorted."""
        return sorted(p for p in self.directory.rglob("*") if p.is_file())

    @property
    def figures(self) -> int:
        """How many figures were written."""
        return sum(len(s.figures) for s in self.sections)

    def as_dict(self) -> dict[str, Any]:
        """The directory and, per part, its figure and comparison counts and run time."""
        return {
            "directory": str(self.directory),
            "sections": [
                {
                    "key": s.key,
                    "figures": len(s.figures),
                    "comparisons": len(s.comparisons),
                    "seconds": s.seconds,
                }
                for s in self.sections
            ],
        }


@checked
@timed
def reproduce(
    out: str | os.PathLike[str] | None = None,
    *,
    only: str | Sequence[str] | None = None,
    workers: int | str | None = None,
    progress: Callable[[str, int], Callable[[int], None]] | None = None,
    command: str = "twoball reproduce",
) -> Reproduction:
    """Recompute the paper's figures, tables and thresholds beside ours, into ``out``.

    Parameters
    ----------
    out : path, optional
        Output directory (default ``./twoball-reproduction``); its parent must
        exist, and an existing one must be empty or an earlier reproduction.  It
        is replaced as each part finishes (see Notes).
    only : str or sequence of str, optional
        A subset of the parts (``"table1,fig11"`` or a list); default all.
    workers : int or str, optional
        Local worker processes for the sweeps (default: all cores; 1 = serial),
        or the address of a dask.distributed scheduler (``"tcp://host:8786"``).
    progress : callable, optional
        ``progress(label, total)`` starts a counted task and returns its
        ``update(done)`` (:meth:`twoball.Reporter.task`).
    command : str
        How the run is named in the report's header.

    Notes
    -----
    As each part finishes, ``out`` is replaced by everything finished so far.
    Stopped at a time limit given (``twoball.limits(max_time=...)``,
    ``TWOBALL_MAX_TIME``; by default there is none) it raises
    :class:`~twoball.NumericalError` and, by SIGINT/SIGTERM,
    :class:`KeyboardInterrupt`, leaving every finished part in ``out`` with a
    report (``reproduction.md``, ``reproduction.json``: ``missing``,
    ``stopped``) naming the parts that are missing.

    Returns
    -------
    Reproduction

    Examples
    --------
    >>> import tempfile, pathlib, twoball
    >>> folder = pathlib.Path(tempfile.mkdtemp()) / "paper"
    >>> done = twoball.reproduce(folder, only="table1", workers=1)
    >>> (done.directory / "reproduction.md").exists(), done.sections[0].key
    (True, 'table1')
    """
    from twoball._common.progress import check_progress
    from twoball._sweep import where
    from twoball.verify.reproduce.driver import DEFAULT_OUT, check_output, parse_only
    from twoball.verify.reproduce.driver import reproduce as run_reproduction
    from twoball.verify.sweeps.parallel import Runner, check_workers

    check_progress(progress)
    workers, scheduler = where("twoball.reproduce", workers)
    names = parse_only(only)
    if not isinstance(command, str):
        from twoball._common.errors import ParameterError

        raise ParameterError("command", "a str (the command the report names)", command)
    if not scheduler:
        workers = check_workers(workers)
    out = DEFAULT_OUT if out is None else out
    check_output(out)  # fail before any work
    from twoball._common.watch import Watch

    # no default deadline: the whole reproduction is legitimately long (2 min idle, over
    # 10 min on a shared machine); each piece's estimate is still refused above the limit
    with verb_default(math.inf), Runner(workers, scheduler) as runner:
        target, sections = run_reproduction(out, names, runner, progress, command, Watch())
    return Reproduction(target, sections)
