"""``twoball.fit``: model parameters fitted to measured rows by least squares, in SI.

The command line (``twoball fit``) calls exactly this function, so the same
inputs give bit-identical numbers in Python and in a shell.  The numerics live
below the face (:mod:`twoball.verify.fit`: the measured file read and refused
by row and column, the models row by row, the least squares with standard
errors); here are the verb, its refusals before work (every option, then the
file, then each row's budget) and the monitor handed to every run.
docs/fit.rst explains the columns and the statistics.
"""

from __future__ import annotations

import os
from collections.abc import Callable, Mapping, Sequence
from typing import Any

from twoball._common.budget import timed
from twoball._common.errors import ParameterError
from twoball._common.keywords import checked

__all__ = ["DEFAULT_FIT_MODES", "fit", "overlay_notes", "read_measured"]

#: Legendre degree of the whole bounce's ball in a fit (each row runs many times;
#: ``twoball.bounce`` takes 192): a coarse ball keeps a fit to minutes.
DEFAULT_FIT_MODES = 32


def read_measured(data: Any, name: str = "data") -> Any:
    """Measured rows from a CSV path, a mapping of columns or read rows, refused by row/column.

    ``name`` is the argument (``data``, ``measured``) the refusals name.
    """
    from twoball.verify.fit.data import as_measurements

    return as_measurements(data, name)


def overlay_notes(result: Any, measured: Any) -> list[str]:
    """What the figure of ``result`` (a sweep, a drop) leaves out of the ``measured`` rows.

    The notes the command line prints beside ``--measured``; the figure itself is
    drawn by ``result.plot(path, measured=...)``.
    """
    from twoball.verify.output.figures.measured import overlay_for

    return list(overlay_for(result, read_measured(measured, "measured")).notes)


@checked
@timed
def fit(
    data: str | os.PathLike[str] | Mapping[str, Sequence[float]],
    params: str | Sequence[str],
    *,
    model: str = "closed",
    case: Any = None,
    pair: str | None = None,
    solver: Any = None,
    body: Any = None,
    drop: Any = None,
    damping: Any = None,
    start: Mapping[str, float] | None = None,
    bounds: Mapping[str, tuple[float, float]] | None = None,
    tolerance: float | None = None,
    bootstrap: int = 0,
    seed: int | None = 0,
    progress: Callable[[str], None] | None = None,
) -> Any:
    """Fit model parameters to measured rows by least squares (``scipy.optimize``), in SI.

    Each row of ``data`` is one measurement: its inputs (``v0_m_s``;
    ``phi_a_rad`` for the closed form, ``gap_m`` for the whole bounce; blank or
    absent: the case's) and at least one measured value (``v1_m_s``,
    ``t_liftoff_s``; ``v2_m_s`` for the bounce).  The model predicts each
    measured value at trial parameters; :func:`scipy.optimize.least_squares`
    minimises the sum of the squared residuals (over the ``sigma_`` columns'
    uncertainties when given, else over each column's RMS) inside the range
    each parameter's model accepts; the standard errors come from the
    Jacobian at the optimum, scaled by the residual variance ``chi^2/(m - n)``
    unless the file gives uncertainties (docs/fit.rst).

    Parameters
    ----------
    data : path-like or mapping
        A CSV file with a header line (columns: ``v0_m_s``, ``phi_a_rad``,
        ``gap_m``, ``v1_m_s``, ``v2_m_s``, ``t_liftoff_s`` and ``sigma_`` + any
        of them; ``#`` comments), or ``{"v0_m_s": [...], "v1_m_s": [...]}``.  A
        column the model cannot use is refused by name.
    params : str or sequence of str
        The fitted parameters: ``damping`` (D, eq. (3.14)), ``wave-speed`` (c
        [1/s], eq. (3.8)), and for the whole bounce ``restitution`` (e12 of the
        body's impacts) and ``floor-restitution``.  Their start is the case's
        (the body's, the drop's) value unless ``start`` says.
    model : {"closed", "bounce"}
        ``closed``: the closed-form lift-off of the paper's massless body, eqs.
        (3.12)-(3.16) (``v1_m_s`` is v_l, ``t_liftoff_s`` is t_l).  ``bounce``:
        the drop of the ball, or the whole two-ball bounce with ``body`` or
        ``pair`` (:func:`twoball.bounce`; v1 the body's speed at its last
        separation, v2 the ball's at its last release, t_liftoff the body's
        lift-off after the first floor touch).
    case : Case, optional
        The ball and every value a row does not give (default the basketball,
        or the pair's lower ball).
    pair : str, optional
        ``model="bounce"``: a Table 1 pair (its lower ball, mu, e12 and cap).
    solver : ClosedForm or MoreauJean, optional
        The closed form's filter, horizon and window; the bounce's ball, step
        and window (default ``MoreauJean(LegendreBall(32))``: each row runs many times).
    body : Body, optional
        ``model="bounce"``: the upper body (refused with ``pair``).
    drop : Drop, optional
        ``model="bounce"``: the drop's options (the gap of rows without ``gap_m``).
    damping : ModalRatio or Rayleigh, optional
        The damping law, as in :func:`twoball.liftoff`.
    start : mapping, optional
        ``{"damping": 0.2}``: start values of fitted parameters (SI).
    bounds : mapping, optional
        ``{"damping": (0.05, 0.5)}``: bounds inside each model's range
        (damping [0, 0.999], wave-speed [1e-6, 1e9] 1/s, restitutions [0, 1]).
    tolerance : float, optional
        Relative change at which the fit stops (default 1e-10 closed, 1e-6 bounce).
    bootstrap : int
        Bootstrap resamples of the rows (0: none): a second standard error.
    seed : int, optional
        The bootstrap's seed.
    progress : callable, optional
        Told of every evaluation (a :class:`~twoball.Reporter`).

    Returns
    -------
    FitResult
        ``values``, ``standard_errors``, ``at_bound``, ``rows()`` (inputs,
        measured, model, residual of every row), ``chi2``, ``dof``, ``rms``,
        ``warnings``; ``as_dict()`` for JSON, ``plot(path)`` for the figure.

    Raises
    ------
    ParameterError
        Before any work: an option out of range, a file refused (one line naming
        the file, the row and the column), a column the model cannot use.

    Examples
    --------
    >>> import twoball
    >>> # the paper's one-point fit (§4(b)): v1 = 3.7 m/s at |v0| = 4.1 m/s, phi_a = 2.6
    >>> one = twoball.fit({"v0_m_s": [4.1], "phi_a_rad": [2.6], "v1_m_s": [3.7]}, "damping")
    >>> round(one.values["damping"], 4)
    0.1329
    >>> rows = {"v0_m_s": [3.0, 4.1, 5.0], "v1_m_s": [2.0, 3.5, 4.4]}
    >>> result = twoball.fit(rows, ["damping"])
    >>> round(result.values["damping"], 3), result.standard_errors["damping"] > 0
    (0.142, True)
    """
    from twoball._common.progress import check_progress
    from twoball.modal.damping import with_damping
    from twoball.modal.parameters import Case
    from twoball.verify.fit.models import parameter_names, start_values
    from twoball.verify.fit.solve import (
        check_bootstrap,
        check_bounds,
        check_start,
        check_tolerance,
        fit_model,
    )

    check_progress(progress)
    given = {"body": body, "drop": drop, "damping": damping}
    if model not in ("closed", "bounce"):
        raise ParameterError("model", "closed or bounce", model)
    names = parameter_names(params, model)
    if case is not None and not isinstance(case, Case):
        raise ParameterError("case", "a twoball.Case", type(case).__name__)
    limits = check_bounds(names, bounds)
    check_tolerance(tolerance, model)
    check_bootstrap(bootstrap)
    if seed is not None and (isinstance(seed, bool) or not isinstance(seed, int) or seed < 0):
        raise ParameterError("seed", "an integer >= 0 or None (the bootstrap's)", seed)
    if model == "closed":
        for name, value in (("pair", pair), ("body", body), ("drop", drop)):
            if value is not None:
                valid = "left out with model closed (the closed form's body is massless; "
                raise ParameterError(name, valid + "model bounce)", value)
        case = with_damping(Case.preset("basketball") if case is None else case, damping)
        solver = _closed_solver(solver)
        from twoball._costs import check_legendre_liftoff

        check_legendre_liftoff(case, solver.t_end)  # the window and the budget, before the file
        check_start(names, start_values(names, case), start, limits)
        measured = read_measured(data)
        fitted = _closed_model(case, measured, names, solver)
    else:
        case, body, drop, solver = _bounce_options(case, pair, solver, body, drop, damping)
        if "restitution" in names and body is None:
            valid = "restitution with a body (body or pair): e12 acts at its impacts"
            raise ParameterError("params", valid, "restitution")
        check_start(names, start_values(names, case, body, drop), start, limits)
        measured = read_measured(data)
        fitted = _bounce_model(case, measured, names, solver, body, drop, pair)
    result = fit_model(
        fitted,
        start=start,
        bounds=bounds,
        tolerance=tolerance,
        bootstrap=bootstrap,
        seed=seed,
        progress=progress,
    )
    from twoball._common.provenance import block

    arguments: dict[str, Any] = {
        "data": measured.source,
        "params": list(names),
        "model": model,
        "solver": solver.as_dict(),
    }
    for key, value in (("pair", pair), ("start", start), ("bounds", bounds)):
        if value is not None:
            arguments[key] = dict(value) if isinstance(value, Mapping) else value
    for key, value in given.items():
        if value is not None:
            arguments[key] = value.as_dict()
    if bootstrap:
        arguments |= {"bootstrap": bootstrap, "seed": seed}
    return result.with_provenance(block(case, "twoball.fit", arguments))


def _closed_solver(solver: Any) -> Any:
    from twoball._solvers import ClosedForm

    if solver is None:
        return ClosedForm()
    if not isinstance(solver, ClosedForm):
        raise ParameterError("solver", "a twoball.ClosedForm with model closed", solver)
    return solver


def _closed_model(case: Any, measured: Any, names: tuple[str, ...], solver: Any) -> Any:
    """The closed form on every row, each row's budget checked before any work."""
    from twoball._common.watch import Watch
    from twoball._costs import check_legendre_liftoff
    from twoball.verify.fit.models import ClosedModel

    fitted = ClosedModel(
        case,
        measured,
        names,
        sigma=solver.sigma,
        recontact=solver.recontact,
        t_end=solver.t_end,
        monitor=Watch(),
    )
    for row_case in fitted.rows_cases:
        check_legendre_liftoff(row_case, solver.t_end)
    return fitted


def _bounce_options(
    case: Any, pair: str | None, solver: Any, body: Any, drop: Any, damping: Any
) -> tuple[Any, Any, Any, Any]:
    """The case (a pair's lower ball), the body (a pair's), the drop and the solver, checked."""
    from twoball._solvers import MoreauJean
    from twoball.modal.balls.membrane import LegendreBall
    from twoball.modal.contact.body import Body
    from twoball.modal.damping import with_damping
    from twoball.modal.floor.inputs import resolve_pair
    from twoball.modal.floor.options import Drop
    from twoball.modal.parameters import Case

    if solver is None:
        solver = MoreauJean(LegendreBall(DEFAULT_FIT_MODES))
    elif not isinstance(solver, MoreauJean):
        raise ParameterError("solver", "a twoball.MoreauJean with model bounce", solver)
    if solver.sigma is not None:
        valid = "left out for the drop (it starts undeformed: nothing to filter)"
        raise ParameterError("sigma", valid, solver.sigma)
    if body is not None and not isinstance(body, Body):
        raise ParameterError("body", "a twoball.Body", type(body).__name__)
    if drop is None:
        drop = Drop()
    elif not isinstance(drop, Drop):
        raise ParameterError("drop", "a twoball.Drop", type(drop).__name__)
    case, body, _ = resolve_pair(case, body, pair)
    case = with_damping(Case.preset("basketball") if case is None else case, damping)
    if solver.ball is None:
        solver = MoreauJean(LegendreBall(DEFAULT_FIT_MODES), dt=solver.dt, t_end=solver.t_end)
    from twoball._costs import check_bounce_cost
    from twoball.modal.floor.bounce import bounce_problem

    # the base drop resolved and its budget checked: its options refused before the file
    check_bounce_cost(
        bounce_problem(case, drop, ball=solver.ball, body=body, dt=solver.dt, t_end=solver.t_end)
    )
    return case, body, drop, solver


def _bounce_model(
    case: Any,
    measured: Any,
    names: tuple[str, ...],
    solver: Any,
    body: Any,
    drop: Any,
    pair: str | None,
) -> Any:
    """The drop or the whole bounce on every row, each run's budget checked before any work."""
    from twoball._common.watch import Watch
    from twoball._costs import check_bounce_cost
    from twoball.verify.fit.models import BounceModel

    fitted = BounceModel(
        case,
        measured,
        names,
        drop=drop,
        body=body,
        ball=solver.ball,
        dt=solver.dt,
        t_end=solver.t_end,
        pair=pair,
        monitor=Watch(),
    )
    for row in range(measured.rows):
        check_bounce_cost(fitted.problem(row, fitted.start()))
    return fitted
