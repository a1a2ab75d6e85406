"""``twoball.converge`` and ``twoball.check``: refinement studies and the verification report.

Both return their result object (``as_dict()`` for JSON) and, given ``out=``,
write a report directory (report.md, results.json, CSV tables, PNG plots).
"""

from __future__ import annotations

import os
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

from twoball._common.budget import timed
from twoball._common.errors import ParameterError
from twoball._common.keywords import checked
from twoball._common.progress import Step, check_progress, silent
from twoball.modal.parameters import Case

if TYPE_CHECKING:
    from twoball.verify.checks.results import VerifyResult
    from twoball.verify.studies.result import StudyResult

__all__ = ["check", "converge", "parse_levels", "verify_steps"]


def parse_levels(text: str, mesh: str, study: str = "h") -> tuple[int, ...]:
    """Consecutive levels, e.g. ``"2:5"`` or ``"2,3,4,5"`` (the one list syntax).

    Mesh levels are bounded per mesh; time-step levels (``study="dt"``: dt =
    0.01 / 2^level) have their own bounds.  At least two levels, each one more
    than the last (a refinement ratio of 2 between neighbours).
    """
    from twoball._common.ranges import parse_values
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


@checked
@timed
def converge(
    case: Case | None = None,
    *,
    study: str,
    mesh: Any = None,
    levels: str | None = None,
    modes_list: str | None = None,
    solver: Any = None,
    damping: Any = None,
    out: str | os.PathLike[str] | None = None,
    progress: Step = silent,
) -> StudyResult:
    """A refinement study: observed orders, Richardson extrapolation and GCI.

    Parameters
    ----------
    case : Case, optional
        The impact (default the basketball preset).
    study : {"h", "order", "modes", "dt"}
        Mesh refinement, P1 against P2, Legendre truncation N, or time step.
    mesh : {"sphere", "axisym"} or MeshOptions, optional
        The mesh kind (default sphere; axisym for ``dt``; none for ``modes``),
        or :class:`~twoball.MeshOptions` for its kind, element order (default
        2; ``order`` runs P1 to P4 and takes none) and geometry (``exact`` on
        the sphere with ``h`` and ``order`` only); its size is refused (the
        ``levels`` set it).
    levels : str, optional
        ``"A:B"``; default per study and mesh.
    modes_list : str, optional
        ``modes`` study: ``"30,60,120"`` or ``"30:480"`` (doubling).
    solver : ClosedForm, optional
        The lift-off's options of every run (:class:`~twoball.ClosedForm`: the
        filter of eq. (3.16), the re-contact horizon, the window ``t_end`` [s],
        default 4 pi / c); the study sets its own meshes, modes and steps.
    damping : ModalRatio, optional
        The paper's ratio D on every mode (default the case's); a
        :class:`~twoball.Rayleigh` law is refused by name (``rayleigh``): the
        studies measure against eq. (3.16) with the ratio D.
    out : path, optional
        Report directory to write (an earlier report there is replaced).
    progress : callable
        Called with a short text as each step starts (:class:`~twoball.Reporter`).

    Returns
    -------
    StudyResult
        ``passed`` is False if an observed order leaves its expected band.

    Examples
    --------
    >>> import twoball
    >>> study = twoball.converge(study="modes", modes_list="30,60,120")
    >>> study.study, study.passed
    ('modes', True)
    """
    from twoball.verify.studies.fem_runs import DEFAULT_LEVELS
    from twoball.verify.studies.modes import parse_modes, run_modes_study
    from twoball.verify.studies.refinement import run_h_study, run_order_study
    from twoball.verify.studies.result import STUDIES
    from twoball.verify.studies.time_step import run_dt_study

    check_progress(progress)
    rules = _rules(damping, solver)
    sigma, recontact, t_end = rules.solver.sigma, rules.solver.recontact, rules.solver.t_end
    mesh, order, geometry = _study_mesh(mesh)
    case = Case.preset("basketball") if case is None else case
    if not isinstance(case, Case):
        raise ParameterError("case", "a twoball.Case", type(case).__name__)
    from twoball.modal.damping import with_damping

    case = with_damping(case, rules.damping)
    _paper_model(case, "the convergence studies")
    if study not in STUDIES:
        raise ParameterError("study", "one of " + ", ".join(STUDIES), study)
    if study == "modes":  # the Legendre series: no mesh
        for name, value in (("mesh", mesh), ("order", order)):
            if value is not None:
                raise ParameterError(name, "left out with study modes (no mesh)", value)
    if study == "order" and order is not None:
        raise ParameterError("order", "left out with study order (it compares P1 to P4)", order)
    if mesh is None:
        mesh = "axisym" if study == "dt" else "sphere"
    if mesh not in ("sphere", "axisym"):
        raise ParameterError("mesh", "one of sphere, axisym", mesh)
    if order is None:
        order = 2
    if order not in (1, 2, 3, 4) or isinstance(order, bool):
        raise ParameterError("order", "1, 2, 3 or 4", order)
    if geometry is not None:
        if geometry not in ("isoparametric", "exact"):
            raise ParameterError("geometry", "one of isoparametric, exact", geometry)
        if study not in ("h", "order") or mesh != "sphere":
            raise ParameterError(
                "geometry", "left out except with study h or order on the sphere", geometry
            )
    geometry = "isoparametric" if geometry is None else geometry
    if study == "modes":
        if levels is not None:
            raise ParameterError("levels", "left out with study modes (use modes_list)", levels)
        mode_list = parse_modes(modes_list) if modes_list is not None else None
        from twoball.modal.report import t_end_dimensionless
        from twoball.verify.studies.modes import DEFAULT_MODES, check_modes_study

        check_modes_study(mode_list or DEFAULT_MODES, t_end_dimensionless(case, t_end))
    else:
        if modes_list is not None:
            raise ParameterError("modes_list", "given only with study modes", modes_list)
        chosen = DEFAULT_LEVELS[(study, mesh, order)] if levels is None else levels
        level_list = parse_levels(chosen, mesh, study)
    target = None
    if out is not None:
        from twoball.verify.output.report_files import check_output_dir

        target = check_output_dir(out)
    common = {"sigma": sigma, "recontact": recontact, "t_end_s": t_end, "progress": progress}
    if study == "modes":
        extra = {} if mode_list is None else {"modes": mode_list}
        result = run_modes_study(case, **common, **extra)
    elif study == "h":
        result = run_h_study(
            case, mesh=mesh, order=order, levels=level_list, geometry=geometry, **common
        )
    elif study == "order":
        result = run_order_study(case, mesh=mesh, levels=level_list, geometry=geometry, **common)
    else:
        result = run_dt_study(case, mesh=mesh, order=order, levels=level_list, **common)
    from twoball._common.provenance import block
    from twoball.modal.guards import case_warnings

    result.warnings = case_warnings(case)
    result.notes[:0] = [n for n in case.notes if n not in result.notes]  # how the case was read
    arguments = {"study": study, "mesh": mesh, "order": order, "levels": levels}
    arguments |= {"modes_list": modes_list, **rules.as_dict(), "out": out}
    result.provenance = block(case, "twoball.converge", arguments)
    if target is not None:
        from twoball.verify.output.report_files import study_files, write_report_dir

        progress(f"writing {target}")
        write_report_dir(target, study_files(result), "twoball converge")
    return result


@checked
@timed
def check(
    case: Case | None = None,
    *,
    thorough: bool = False,
    fast: bool = False,
    damping: Any = None,
    solver: Any = None,
    out: str | os.PathLike[str] | None = None,
    progress: Step | None = None,
) -> VerifyResult:
    """Every backend against the closed form, with PASS/FAIL per check.

    Parameters
    ----------
    case : Case, optional
        The impact (default the basketball preset).
    thorough : bool
        Finer meshes as well (minutes, not seconds).
    fast : bool
        The small configuration of the test suite.
    damping : ModalRatio, optional
        The paper's ratio D on every mode, as in :func:`converge` (a Rayleigh
        law is refused by name).
    solver : ClosedForm, optional
        The lift-off's options of every check (:class:`~twoball.ClosedForm`:
        filter, re-contact horizon, window ``t_end`` [s], default 4 pi / c).
    out : path, optional
        Report directory to write (report.md, results.json, CSV, PNG).
    progress : callable, optional
        Called with a short text as each step starts (:class:`twoball.Reporter`;
        :func:`verify_steps` counts the calls).

    Returns
    -------
    VerifyResult
        ``passed`` only if every check passes.

    Examples
    --------
    >>> import twoball
    >>> result = twoball.check(fast=True)  # the small configuration; twoball.check() by default
    >>> result.passed
    True
    """
    from twoball.verify.checks.config import config
    from twoball.verify.checks.run import run_verify

    check_progress(progress)
    rules = _rules(damping, solver)
    t_end = rules.solver.t_end
    case = Case.preset("basketball") if case is None else case
    if not isinstance(case, Case):
        raise ParameterError("case", "a twoball.Case", type(case).__name__)
    from twoball.modal.damping import with_damping

    case = with_damping(case, rules.damping)
    _paper_model(case, "verify")
    for name, value in (("thorough", thorough), ("fast", fast)):
        if not isinstance(value, bool):  # "yes", 1, None: never read as a truth value
            raise ParameterError(name, "True or False", value)
    if thorough and fast:
        raise ParameterError("fast", "left out with thorough", fast)
    from twoball.verify.studies.fem_runs import EIGEN_DEGREES

    if case.modes < max(EIGEN_DEGREES):  # the eigenvalue checks need the modes up to l = 6
        valid = f"at least {max(EIGEN_DEGREES)} for verify (its eigenvalue checks cover l = 1..6)"
        raise ParameterError("modes", valid, case.modes)
    target = None
    if out is not None:
        from twoball.verify.output.report_files import check_output_dir

        target = check_output_dir(out)
    configuration = config("fast" if fast else ("thorough" if thorough else "default"))
    say = progress or silent
    result = run_verify(case, rules.solver.sigma, rules.solver.recontact, t_end, configuration, say)
    from twoball.modal.guards import case_warnings

    result.warnings = case_warnings(case)
    result.notes[:0] = [n for n in case.notes if n not in result.notes]  # how the case was read
    from twoball._common.provenance import block

    arguments = {"thorough": thorough, "fast": fast, **rules.as_dict()}
    result.provenance = block(case, "twoball.check", {**arguments, "out": out})
    if target is not None:
        from twoball.verify.output.report_files import verify_files, write_report_dir

        say(f"writing {target}")
        write_report_dir(target, verify_files(result), "twoball verify")
    return result


def verify_steps(thorough: bool = False, fast: bool = False, out: bool = True) -> int:
    """How many times :func:`verify` calls ``progress`` with these options."""
    from twoball.verify.checks.config import config

    c = config("fast" if fast else ("thorough" if thorough else "default"))
    solved = {t.spec for t in c.fem} | {t.spec for t in c.alpha}
    pair = c.energy_pair if c.energy_band is not None else None
    energy = [spec for spec in (pair or ()) if spec not in solved]
    return 2 + len(c.fem) + len(c.krylov) + len(c.alpha) + len(energy) + int(out)


def converge_solid(
    *,
    order: int | None = None,
    levels: str | None = None,
    out: str | os.PathLike[str] | None = None,
    progress: Step = silent,
) -> Any:
    """The solid ball's half disc refined: its eigenvalues against Lamb's roots, observed orders.

    :func:`~twoball.verify.studies.solid_orders.run_solid_h_study` at the superball
    preset's Poisson ratio (``twoball converge h --ball solid``).

    Parameters
    ----------
    order : {1, 2}, optional
        The element order (default 2).
    levels : str, optional
        Consecutive half-disc levels, ``"1:4"`` or ``"1,2,3,4"`` (default 2:5 for P1,
        1:4 for P2).
    out : path, optional
        Report directory (``report.md``, ``results.json``, ``results.csv``).
    progress : callable
        Called with a short text as each level starts.

    Returns
    -------
    StudyResult
        ``passed`` is False if an observed order leaves its band.
    """
    from twoball.modal.presets import SUPERBALL_MATERIAL
    from twoball.verify.studies.solid_orders import (
        parse_solid_levels,
        run_solid_h_study,
        solid_markdown,
    )

    check_progress(progress)
    element = 2 if order is None else order
    if element not in (1, 2) or isinstance(element, bool):
        raise ParameterError("order", "1 or 2 with --ball solid", element)
    chosen = parse_solid_levels(levels, element)
    target = None
    if out is not None:
        from twoball.verify.output.report_files import check_output_dir

        target = check_output_dir(out)
    study = run_solid_h_study(
        float(SUPERBALL_MATERIAL["poisson"]), element=element, levels=chosen, progress=progress
    )
    from twoball._common.provenance import block

    arguments = {"study": "h", "ball": "solid", "order": order, "levels": levels, "out": out}
    study.provenance = block(None, "twoball.converge", arguments)
    if target is not None:
        from twoball.verify.output.report_files import result_files, study_csv, write_report_dir

        progress(f"writing {target}")
        report = f"# twoball converge h --ball solid\n\n{study.title}\n\n"
        report += solid_markdown(study) + "\n\n" + "".join(f"* {n}\n" for n in study.notes)
        files = {
            "report.md": report,
            **result_files(study.as_dict()),
            "results.csv": study_csv(study),
        }
        write_report_dir(target, files, "twoball converge")
    return study


def solid_rows(study: Any) -> str:
    """The solid study's Markdown table (errors per level, observed orders, verdicts)."""
    from twoball.verify.studies.solid_orders import solid_markdown

    return solid_markdown(study)


def summary_rows(study: Any) -> tuple[list[str], list[list[str]]]:
    """Header and rows of a study's one-line-per-quantity summary (as in its ``report.md``)."""
    from twoball.verify.output.report_files import study_summary_rows

    return study_summary_rows(study)


def _paper_model(case: Case, what: str) -> None:
    """Refuse a case the studies would not measure: they check the paper's model.

    Their references are the membrane's ``l (l + 1)`` and eq. (3.16) with the
    ratio D: the pressurised operator, bending, gas and a Rayleigh law are
    checked by their own tests and documents instead (docs/pressurised.rst,
    docs/stiff_balls.rst).
    """
    if case.membrane.pressurised:
        valid = f"paper for {what} (the pressurised operator: docs/pressurised.rst)"
        raise ParameterError("membrane", valid, case.membrane.kind)
    if case.stiff:  # the studies measure against the membrane's l (l + 1) and eq. (3.16)
        raise ParameterError(
            "bending",
            f"0 with gas none for {what} (the stiffened ball: docs 'Stiffer balls')",
            case.bending if case.bending else case.gas,
        )
    if case.rayleigh is not None:
        valid = f"left out for {what} (they check the paper's ratio D, eq. (3.14))"
        raise ParameterError("rayleigh", valid, case.rayleigh.as_dict())


@dataclass(frozen=True)
class _Rules:
    """A study's damping law and its lift-off options (a :class:`~twoball.ClosedForm`)."""

    damping: Any
    solver: Any
    given: bool

    def as_dict(self) -> dict[str, Any]:
        out: dict[str, Any] = {}
        if self.given:
            out["solver"] = self.solver.as_dict()
        if self.damping is not None:
            out["damping"] = self.damping.as_dict()
        return out


def _rules(damping: Any, solver: Any) -> _Rules:
    """The damping law and the lift-off options of a study; a Rayleigh law is refused by name,
    as in the case."""
    from twoball._solvers import ClosedForm
    from twoball.modal.damping import ModalRatio, Rayleigh

    if isinstance(damping, Rayleigh):
        valid = "left out of the studies (they check the paper's ratio D, eq. (3.14))"
        raise ParameterError("rayleigh", valid, damping.as_dict())
    if damping is not None and not isinstance(damping, ModalRatio):
        raise ParameterError("damping", "a twoball.ModalRatio", damping)
    if solver is not None and not isinstance(solver, ClosedForm):
        valid = "a twoball.ClosedForm (the lift-off's options; the study sets its own steps)"
        raise ParameterError("solver", valid, solver)
    return _Rules(damping, ClosedForm() if solver is None else solver, solver is not None)


def _study_mesh(mesh: Any) -> tuple[str | None, int | None, str | None]:
    """Mesh kind, element order and geometry (None: not given) of a study.

    ``mesh`` is a kind name or a :class:`~twoball.MeshOptions` whose size is its
    default (the study's ``levels`` set the sizes).
    """
    from twoball.fem_membrane.options import DEFAULT_ELEMENTS, DEFAULT_LEVEL, FILE, MeshOptions

    order = geometry = None
    if isinstance(mesh, MeshOptions):
        if mesh.kind == FILE:
            raise ParameterError("mesh", "sphere or axisym for a study (no mesh file)", mesh.label)
        size = mesh.level if mesh.kind != "axisym" else mesh.elements
        default = DEFAULT_LEVEL if mesh.kind != "axisym" else DEFAULT_ELEMENTS
        if size != default:
            valid = "a MeshOptions without its size in a study (levels set the sizes)"
            raise ParameterError("mesh", valid, mesh.label)
        order = mesh.order if mesh.order != 2 else None
        geometry = mesh.geometry if mesh.geometry != "isoparametric" else None
        mesh = mesh.kind
    return mesh, order, geometry
