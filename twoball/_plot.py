"""``twoball.plot``: the figures of the lift-off, and the figure files of the other verbs.

The kinds are drawn in :mod:`twoball.verify.output.plots`; here are the verb, its
options (the solver of the kind, the body, the damping law, the figure's), the
file and its provenance.
"""

from __future__ import annotations

import os
from pathlib import Path
from typing import Any

from twoball._common.budget import timed
from twoball._common.errors import ParameterError
from twoball._common.keywords import checked
from twoball._common.progress import Step, check_progress, silent
from twoball._common.provenance import block
from twoball._common.staging import check_path_type
from twoball._fields import _case, _field_options, _not_the_mesh, mesh_block
from twoball.modal.parameters import Case
from twoball.verify.output.results import PlotResult

__all__ = ["check_figure_path", "plot", "save_report_figure"]


@checked
@timed
def plot(
    kind: str,
    out: str | os.PathLike[str],
    case: Case | None = None,
    *,
    solver: Any = None,
    body: Any = None,
    damping: Any = None,
    figure: Any = None,
    progress: Step | None = None,
) -> PlotResult:
    """Figures: ``waterfall`` (Fig. 6), ``pole`` motion, FE ``eigen`` errors, ``precursor``.

    Parameters
    ----------
    kind : {"waterfall", "pole", "eigen", "precursor"}
        The figure.  ``precursor``: the pole's displacement under the case's
        damping law beside the other law matched to it and the undamped
        membrane, with the motion before the wave front ``phi_a / c`` (closed
        form; :mod:`twoball.verify.output.figures.precursor`).
    out : path
        Output file; its suffix chooses the format: any format matplotlib
        writes (``.pdf``, ``.svg``, ``.eps``, ``.png``, ...).
    case : Case, optional
        The impact (default the basketball preset); refused by ``eigen``.
    solver : Superposition or ClosedForm, optional
        ``waterfall`` and ``pole``: as in :func:`export` (a
        :class:`~twoball.Superposition`; a mesh file too); ``precursor``: a
        :class:`~twoball.ClosedForm` (its filter, horizon and window); ``eigen``
        takes none (use the figure's levels and orders).
    body : Body, optional
        ``pole`` only: an upper body of finite mass; the panels show the cap
        average of the coupled membrane with the body's path s(t), every impact
        and separation marked.
    damping : ModalRatio or Rayleigh, optional
        The damping law, as in :func:`twoball.liftoff` (not with ``eigen``);
        ``precursor`` draws it beside the other law matched to it.
    figure : PlotOptions, optional
        The solvers drawn, resolution, waterfall instants, eigenvalue meshes
        and degree (:class:`~twoball.PlotOptions`).
    progress : callable, optional
        Called with a short text as each stage starts (:class:`~twoball.Reporter`).

    Every argument that the chosen ``kind`` does not use is refused
    (:class:`~twoball.ParameterError`), never ignored.  ``pole`` with both
    backends puts a panel of the difference finite elements minus closed form
    under each quantity; ``waterfall`` with both stacks that difference at the
    nodes beside the waterfall.

    Examples
    --------
    >>> import tempfile, pathlib, twoball
    >>> out = pathlib.Path(tempfile.mkdtemp()) / "pole.svg"
    >>> solver = twoball.Superposition(twoball.MeshOptions("sphere", level=1))
    >>> figure = twoball.PlotOptions(backends=["legendre"])
    >>> result = twoball.plot("pole", out, solver=solver, figure=figure)
    >>> result.file.name, result.rows[0][0]
    ('pole.svg', 'lift-off (legendre)')
    """
    from twoball._common.staging import check_file
    from twoball._solvers import ClosedForm
    from twoball.modal.damping import with_damping
    from twoball.verify.output.figures import PLOT_KINDS, figure_format, save_figure
    from twoball.verify.output.options import PlotOptions

    check_path_type(out)
    check_progress(progress)
    if kind not in PLOT_KINDS:
        raise ParameterError("kind", "one of " + ", ".join(PLOT_KINDS), kind)
    closed = None
    if kind == "precursor":  # the closed form: its filter, horizon and window
        closed = ClosedForm() if solver is None else solver
        if not isinstance(closed, ClosedForm):
            valid = "a twoball.ClosedForm with kind precursor (the closed form only)"
            raise ParameterError("solver", valid, solver)
        given = _field_options(None, body, damping)
    elif kind == "eigen":
        if solver is not None:
            shown = solver.as_dict() if hasattr(solver, "as_dict") else solver
            raise ParameterError("solver", "left out with kind eigen (use levels, orders)", shown)
        given = _field_options(None, body, damping)
    else:
        given = _field_options(solver, body, damping)
    figure = PlotOptions() if figure is None else figure
    if not isinstance(figure, PlotOptions):
        raise ParameterError("figure", "a twoball.PlotOptions", type(figure).__name__)
    figure_format(out, "out")
    target = check_file(out)
    _not_the_mesh(out, given)
    say = progress or silent
    if kind in ("precursor", "eigen"):
        from twoball.verify.output.plots import closed_form_figure

        drawn, rows = closed_form_figure(
            kind, case, closed, given.mesh, given.body, given.damping, figure, say
        )
        reports, warnings, field = {}, [], None
    else:
        from twoball.verify.output.plots import field_figure

        case = with_damping(_case(case), given.damping)
        drawn, rows, reports, warnings, field = field_figure(
            kind, case, given.solver, given.body, figure, say
        )
    say(f"writing {target}")
    save_figure(drawn, target, "out", figure.dpi, "dpi")
    arguments = {"kind": kind, "out": out, "figure": figure.as_dict(), **given.as_dict()}
    if kind in ("precursor", "eigen"):  # the closed form's options, or none
        arguments.pop("solver")
        if closed is not None:
            arguments["solver"] = closed.as_dict()
    provenance = block(None if kind == "eigen" else case, "twoball.plot", arguments)
    if field is not None:
        provenance |= mesh_block(field)
    return PlotResult(target, kind, rows, reports, warnings, provenance)


def check_figure_path(path: str | os.PathLike[str], name: str = "out") -> Path:
    """A figure path (any format matplotlib writes, not a folder or link) in a writable folder."""
    from twoball._common.staging import check_file
    from twoball.verify.output.figures import figure_format

    check_path_type(path, name)
    figure_format(path, name)
    return check_file(path, name)


def save_report_figure(report: Any, path: str | os.PathLike[str], name: str = "out") -> Path:
    """Draw a finite-mass lift-off (the body's path over the cap, every event) into ``path``."""
    from twoball.verify.output.figures import save_figure
    from twoball.verify.output.figures.contact import contact_figure

    if getattr(report, "history", None) is None:
        raise ParameterError(name, "given with a body of mass ratio > 0", os.fspath(path))
    return save_figure(contact_figure(report), path, name)
