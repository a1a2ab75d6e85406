"""``twoball.converge`` and ``twoball.verify``: refinement studies and the verification report.

Both return their result object (``as_dict()`` for JSON) and, given ``out=``,
write a report directory (report.md, results.json, CSV tables, PNG plots).
"""

from __future__ import annotations

import os
from collections.abc import Callable
from typing import Any

from twoball.modal.errors import ParameterError
from twoball.modal.parameters import Case

__all__ = ["converge", "parse_levels", "verify"]

Progress = Callable[[str], None]


def _quiet(_: str) -> None:
    return None


def parse_levels(text: str, mesh: str, study: str = "h") -> tuple[int, ...]:
    """Consecutive levels, e.g. ``"2:5"`` or ``"2,3,4,5"`` (the one list syntax).

    Mesh levels are bounded per mesh; time-step levels (``study="dt"``: dt =
    0.01 / 2^level) have their own bounds.  At least two levels, each one more
    than the last (a refinement ratio of 2 between neighbours).
    """
    from twoball.ranges import parse_values
    from twoball.verify.studies.fem_runs import LEVEL_LIMITS
    from twoball.verify.studies.time_step import DT_LEVEL_LIMITS

    low_limit, high_limit = DT_LEVEL_LIMITS if study == "dt" else LEVEL_LIMITS[mesh]
    what = "study dt" if study == "dt" else f"mesh {mesh}"
    valid = f"consecutive integers in [{low_limit}, {high_limit}] for {what}, e.g. 2:4"
    levels = parse_values(text, "levels", integer=True, valid=valid)
    consecutive = all(b == a + 1 for a, b in zip(levels[:-1], levels[1:], strict=True))
    if len(levels) < 2 or not consecutive or levels[0] < low_limit or levels[-1] > high_limit:
        raise ParameterError("levels", valid, text)
    return tuple(int(v) for v in levels)


def converge(
    case: Case | None = None,
    *,
    study: str,
    mesh: str | None = None,
    order: int | None = None,
    levels: str | None = None,
    modes_list: str | None = None,
    sigma: str = "lanczos",
    recontact: str = "window",
    t_end: float | None = None,
    out: str | os.PathLike[str] | None = None,
    progress: Progress = _quiet,
) -> Any:
    """A refinement study: observed orders, Richardson extrapolation and GCI.

    Parameters
    ----------
    case : Case, optional
        The impact (default the basketball preset).
    study : {"h", "order", "modes", "dt"}
        Mesh refinement, P1 against P2, Legendre truncation N, or time step.
    mesh : {"sphere", "axisym"}, optional
        Default sphere (axisym for ``dt``); not used by ``modes``.
    order : {1, 2}, optional
        Default 1 (2 for ``dt``).
    levels : str, optional
        ``"A:B"``; default per study and mesh.
    modes_list : str, optional
        ``modes`` study: ``"30,60,120"`` or ``"30:480"`` (doubling).
    sigma, recontact, t_end
        Filter, re-contact horizon and window [s], as in :func:`twoball.liftoff`.
    out : path, optional
        Report directory to write (an earlier report there is replaced).
    progress : callable
        Called with a short text per step.

    Returns
    -------
    StudyResult
        ``passed`` is False if an observed order leaves its expected band.
    """
    from twoball.verify.studies.fem_runs import DEFAULT_LEVELS
    from twoball.verify.studies.modes import parse_modes, run_modes_study
    from twoball.verify.studies.refinement import run_h_study, run_order_study
    from twoball.verify.studies.result import STUDIES
    from twoball.verify.studies.time_step import run_dt_study

    case = Case.preset("basketball") if case is None else case
    if case.stiff:  # the studies measure against the membrane's l (l + 1) and eq. (3.16)
        raise ParameterError(
            "bending",
            "0 with gas none for the convergence studies (the stiffened ball: "
            "tests/test_fem_shell.py, docs 'Stiffer balls')",
            case.bending if case.bending else case.gas,
        )
    if study not in STUDIES:
        raise ParameterError("study", "one of " + ", ".join(STUDIES), study)
    if study == "modes":  # the Legendre series: no mesh
        for name, value in (("mesh", mesh), ("order", order)):
            if value is not None:
                raise ParameterError(name, "left out with study modes (no mesh)", value)
    if mesh is None:
        mesh = "axisym" if study == "dt" else "sphere"
    if mesh not in ("sphere", "axisym"):
        raise ParameterError("mesh", "one of sphere, axisym", mesh)
    if order is None:
        order = 2 if study == "dt" else 1
    if order not in (1, 2) or isinstance(order, bool):
        raise ParameterError("order", "1 or 2", order)
    if study == "modes":
        if levels is not None:
            raise ParameterError("levels", "left out with study modes (use modes_list)", levels)
        mode_list = parse_modes(modes_list) if modes_list is not None else None
    else:
        if modes_list is not None:
            raise ParameterError("modes_list", "given only with study modes", modes_list)
        level_list = parse_levels(levels or DEFAULT_LEVELS[(study, mesh, order)], mesh, study)
    target = None
    if out is not None:
        from twoball.verify.output.report_files import check_output_dir

        target = check_output_dir(out)
    common = {"sigma": sigma, "recontact": recontact, "t_end_s": t_end, "progress": progress}
    if study == "modes":
        extra = {} if mode_list is None else {"modes": mode_list}
        result = run_modes_study(case, **common, **extra)
    elif study == "h":
        result = run_h_study(case, mesh=mesh, order=order, levels=level_list, **common)
    elif study == "order":
        result = run_order_study(case, mesh=mesh, levels=level_list, **common)
    else:
        result = run_dt_study(case, mesh=mesh, order=order, levels=level_list, **common)
    if target is not None:
        from twoball.verify.output.report_files import study_files, write_report_dir

        write_report_dir(target, study_files(result), "twoball converge")
    return result


def verify(
    case: Case | None = None,
    *,
    thorough: bool = False,
    fast: bool = False,
    sigma: str = "lanczos",
    recontact: str = "window",
    t_end: float | None = None,
    out: str | os.PathLike[str] | None = None,
    progress: Progress | None = None,
) -> Any:
    """Every backend against the closed form, with PASS/FAIL per check.

    Parameters
    ----------
    case : Case, optional
        The impact (default the basketball preset).
    thorough : bool
        Finer meshes as well (minutes, not seconds).
    fast : bool
        The small configuration of the test suite.
    sigma, recontact, t_end
        As in :func:`twoball.liftoff`.
    out : path, optional
        Report directory to write (report.md, results.json, CSV, PNG).
    progress : callable, optional
        Called with a short text per step.

    Returns
    -------
    VerifyResult
        ``passed`` only if every check passes.
    """
    from twoball.verify.checks.config import config
    from twoball.verify.checks.run import run_verify

    case = Case.preset("basketball") if case is None else case
    if thorough and fast:
        raise ParameterError("fast", "left out with thorough", fast)
    target = None
    if out is not None:
        from twoball.verify.output.report_files import check_output_dir

        target = check_output_dir(out)
    configuration = config("fast" if fast else ("thorough" if thorough else "default"))
    result = run_verify(case, sigma, recontact, t_end, configuration, progress)
    if target is not None:
        from twoball.verify.output.report_files import verify_files, write_report_dir

        write_report_dir(target, verify_files(result), "twoball verify")
    return result
