"""Least squares of model parameters to measured rows, with standard errors and a bootstrap.

The residual of a measured value ``y`` with model value ``f(p)`` is
``r = (f(p) - y) / w``: ``w`` the value's uncertainty when the file has
``sigma_`` columns (every measured column then needs one), else the RMS of the
column's measured values, so that speeds [m/s] and times [s] weigh alike.
:func:`scipy.optimize.least_squares` (trust-region reflective, the parameters
inside the range their model accepts) minimises ``chi^2 = sum r^2``.  The
covariance is the Gauss-Newton one at the optimum,
``C = (J^T J)^-1`` from the Jacobian ``J = dr/dp`` (pseudo-inverse by SVD), as
it stands with uncertainties (``absolute``), else scaled by the residual
variance ``chi^2 / (m - n)`` (m measured values, n parameters); the standard
errors are ``sqrt(diag C)``.  A bootstrap (rows drawn with replacement, the
fit repeated from the optimum) gives a second estimate that does not lean on
the linearisation.

Examples
--------
>>> import numpy as np
>>> from twoball.modal.parameters import Case
>>> from twoball.verify.fit.data import Measurements
>>> from twoball.verify.fit.models import ClosedModel
>>> data = Measurements.from_columns({"v0_m_s": [4.1], "phi_a_rad": [2.6], "v1_m_s": [3.7]})
>>> result = fit_model(ClosedModel(Case.preset("basketball"), data, ("damping",)))
>>> round(result.values["damping"], 4), result.standard_errors["damping"]
(0.1329, None)
"""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping
from typing import Any

import numpy as np

from twoball._common.errors import NumericalError, ParameterError
from twoball.verify.fit.models import PARAMETERS
from twoball.verify.fit.result import FitResult, Residuals

__all__ = [
    "DEFAULT_TOLERANCE",
    "MAX_BOOTSTRAP",
    "check_bootstrap",
    "check_bounds",
    "check_start",
    "check_tolerance",
    "fit_model",
]

#: Relative change of the parameters at which a fit stops (``xtol``), per model.
DEFAULT_TOLERANCE: dict[str, float] = {"closed": 1e-10, "bounce": 1e-6}
#: Relative finite-difference step of the Jacobian, per model (a run of the whole
#: bounce is piecewise smooth in its parameters: a wider step averages its kinks).
DIFF_STEP: dict[str, float] = {"closed": 1e-6, "bounce": 1e-3}
#: Most evaluations of the residual vector per fitted parameter (the Jacobian's not counted).
MAX_EVALUATIONS = 50
#: Most bootstrap samples.
MAX_BOOTSTRAP = 10_000


def check_bounds(
    names: tuple[str, ...], bounds: Mapping[str, Any] | None
) -> dict[str, tuple[float, float]]:
    """Each parameter's bounds: the given ``(low, high)`` inside its model range, else the range.

    Raises
    ------
    ParameterError
        Naming ``bounds``: a parameter not fitted, not two numbers, outside the
        range, or ``low >= high``.
    """
    out = {name: (PARAMETERS[name].low, PARAMETERS[name].high) for name in names}
    if bounds is None:
        return out
    if not isinstance(bounds, Mapping):
        raise ParameterError("bounds", "a mapping of fitted parameters to (low, high)", bounds)
    for key, pair in bounds.items():
        name = str(key).replace("_", "-")
        if name not in out:
            raise ParameterError(
                "bounds", "bounds of fitted parameters (" + ", ".join(names) + ")", key
            )
        p = PARAMETERS[name]
        valid = f"two numbers low < high inside the range of {name}, [{p.low:g}, {p.high:g}]" + (
            f" [{p.unit}]" if p.unit else ""
        )
        try:
            low, high = (float(v) for v in pair)
        except (TypeError, ValueError):
            raise ParameterError("bounds", valid, pair) from None
        if not (math.isfinite(low) and math.isfinite(high) and p.low <= low < high <= p.high):
            raise ParameterError("bounds", valid, (low, high))
        out[name] = (low, high)
    return out


def check_start(
    names: tuple[str, ...],
    model_start: Mapping[str, float],
    start: Mapping[str, Any] | None,
    bounds: Mapping[str, tuple[float, float]],
) -> dict[str, float]:
    """The start of each parameter: the given one, else the model's (case's) value, in bounds.

    Raises
    ------
    ParameterError
        Naming ``start``: a parameter not fitted, not a finite number, outside
        its bounds.
    """
    out = dict(model_start)
    if start is not None:
        if not isinstance(start, Mapping):
            raise ParameterError("start", "a mapping of fitted parameters to values", start)
        for key, value in start.items():
            name = str(key).replace("_", "-")
            if name not in out:
                raise ParameterError(
                    "start", "values of fitted parameters (" + ", ".join(names) + ")", key
                )
            if isinstance(value, bool) or not isinstance(value, int | float):
                raise ParameterError("start", f"a number for {name}", value)
            out[name] = float(value)
    for name in names:
        low, high = bounds[name]
        if not (math.isfinite(out[name]) and low <= out[name] <= high):
            raise ParameterError(
                "start", f"inside the bounds of {name}, [{low:g}, {high:g}]", out[name]
            )
    return out


def check_tolerance(tolerance: object, model: str) -> float:
    """The fit's relative tolerance in [1e-15, 1e-2] (None: the model's default)."""
    if tolerance is None:
        return DEFAULT_TOLERANCE[model]
    if (
        isinstance(tolerance, bool)
        or not isinstance(tolerance, int | float)
        or not (1e-15 <= tolerance <= 1e-2)
    ):
        raise ParameterError("tolerance", "a number in [1e-15, 1e-2]", tolerance)
    return float(tolerance)


def check_bootstrap(bootstrap: object) -> int:
    """The number of bootstrap samples, an integer in [0, :data:`MAX_BOOTSTRAP`]."""
    if (
        isinstance(bootstrap, bool)
        or not isinstance(bootstrap, int)
        or not (0 <= bootstrap <= MAX_BOOTSTRAP)
    ):
        raise ParameterError("bootstrap", f"an integer in [0, {MAX_BOOTSTRAP}]", bootstrap)
    return bootstrap


class _Problem:
    """The residual vector of a model's rows, its weights and the model values behind it."""

    def __init__(self, model: Any, names: tuple[str, ...], progress: Callable[[str], None] | None):
        data = model.data
        self.model, self.names, self.progress = model, names, progress
        self.columns = model.outputs
        self.measured = np.column_stack([data.column(c) for c in self.columns])
        self.mask = np.isfinite(self.measured)
        sigmas = [data.sigma(c) for c in self.columns]
        given = [s is not None for s in sigmas]
        if any(given) and not all(given):
            missing = self.columns[given.index(False)]
            valid = "given for every measured column the fit uses, or for none"
            raise data.error(valid, column="sigma_" + missing)
        self.absolute = all(given)
        if self.absolute:
            self.weights = np.column_stack(sigmas)
        else:
            scale = []
            for k in range(len(self.columns)):
                values = self.measured[self.mask[:, k], k]
                rms = float(np.sqrt(np.mean(values**2))) if values.size else 1.0
                scale.append(rms if rms > 0.0 else 1.0)
            self.weights = np.tile(np.array(scale), (data.rows, 1))
        self.evaluations = 0

    def values(self, x: np.ndarray) -> dict[str, float]:
        return {name: float(v) for name, v in zip(self.names, x, strict=True)}

    def model_values(self, x: np.ndarray, rows: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """The model at ``x`` for ``rows``, undefined values replaced (and where they were)."""
        values = self.values(x)
        predicted = self.model.predict(values, [int(r) for r in rows])
        undefined = ~np.isfinite(predicted)
        for k, j in zip(*np.nonzero(undefined), strict=True):
            predicted[k, j] = self.model.fallback(int(rows[k]), self.columns[j], values)
        return predicted, undefined

    def residuals(self, x: np.ndarray, rows: np.ndarray) -> np.ndarray:
        self.evaluations += 1
        if self.progress is not None:
            shown = ", ".join(f"{n} = {v:.6g}" for n, v in self.values(x).items())
            self.progress(f"fit evaluation {self.evaluations}: {shown}")
        predicted, _ = self.model_values(x, rows)
        r = (predicted - self.measured[rows]) / self.weights[rows]
        return r[self.mask[rows]]


def _least_squares(
    problem: _Problem,
    x0: np.ndarray,
    low: np.ndarray,
    high: np.ndarray,
    rows: np.ndarray,
    tolerance: float,
    step: float,
) -> Any:
    from scipy.optimize import least_squares

    scale = np.where(np.abs(x0) > 0.0, np.abs(x0), np.maximum(high - low, 1.0) * 1e-2)
    return least_squares(
        problem.residuals,
        x0,
        bounds=(low, high),
        x_scale=scale,
        diff_step=step,
        xtol=tolerance,
        ftol=tolerance,
        gtol=tolerance,
        max_nfev=MAX_EVALUATIONS * len(x0),
        kwargs={"rows": rows},
    )


def _covariance(jacobian: np.ndarray) -> np.ndarray:
    """``(J^T J)^-1`` by SVD, singular directions dropped (inf on their diagonal)."""
    _, s, vt = np.linalg.svd(jacobian, full_matrices=False)
    n = jacobian.shape[1]
    if not s.size or s[0] == 0.0:
        return np.full((n, n), np.inf)
    keep = s > np.finfo(float).eps * max(jacobian.shape) * s[0]
    vt_kept = vt[keep]
    cov = (vt_kept.T / s[keep] ** 2) @ vt_kept
    if keep.sum() < n:  # a direction the data do not determine
        lost = vt[~keep]
        cov = cov + np.inf * (lost.T @ lost != 0.0)
    return cov


def fit_model(
    model: Any,
    *,
    start: Mapping[str, Any] | None = None,
    bounds: Mapping[str, Any] | None = None,
    tolerance: float | None = None,
    bootstrap: int = 0,
    seed: int | None = 0,
    progress: Callable[[str], None] | None = None,
) -> FitResult:
    """Fit ``model``'s parameters to its rows by least squares (module docstring).

    Parameters
    ----------
    model : ClosedModel or BounceModel
        The model with its rows and fitted parameters
        (:mod:`twoball.verify.fit.models`).
    start : mapping, optional
        Start values (SI) of some fitted parameters (default: the case's).
    bounds : mapping, optional
        ``{name: (low, high)}`` inside the range each model accepts (default: that range).
    tolerance : float, optional
        Relative change of the parameters (and of chi^2) at which the fit stops
        (default :data:`DEFAULT_TOLERANCE` of the model).
    bootstrap : int
        Bootstrap samples (0: none; at most :data:`MAX_BOOTSTRAP`); needs more
        rows than fitted parameters.
    seed : int, optional
        Seed of the bootstrap's draws.
    progress : callable, optional
        Told of every evaluation (a short text).

    Returns
    -------
    FitResult
        The values, standard errors, residuals, chi^2 and RMS, notes and warnings.
    """
    names = tuple(model.parameters)
    limits = check_bounds(names, bounds)
    x_start = check_start(names, model.start(), start, limits)
    tolerance = check_tolerance(tolerance, model.name)
    check_bootstrap(bootstrap)
    problem = _Problem(model, names, progress)
    count = int(problem.mask.sum())
    if count < len(names):
        valid = f"at least as many measured values as fitted parameters ({len(names)})"
        raise model.data.error(valid, count)
    if bootstrap and model.data.rows <= len(names):
        raise ParameterError(
            "bootstrap",
            f"0 with {model.data.rows} row(s) for {len(names)} "
            "parameter(s) (a resample needs more rows than parameters)",
            bootstrap,
        )
    low = np.array([limits[n][0] for n in names])
    high = np.array([limits[n][1] for n in names])
    x0 = np.array([x_start[n] for n in names])
    rows = np.arange(model.data.rows)
    step = DIFF_STEP[model.name]
    solution = _least_squares(problem, x0, low, high, rows, tolerance, step)
    if not np.all(np.isfinite(solution.x)):
        raise NumericalError(f"the fit left finite numbers: {solution.message}")
    x = solution.x
    predicted, undefined = problem.model_values(x, rows)
    r = ((predicted - problem.measured) / problem.weights)[problem.mask]
    chi2 = float(r @ r)
    dof = count - len(names)
    covariance = _covariance(np.atleast_2d(solution.jac))
    if not problem.absolute:
        with np.errstate(invalid="ignore"):  # an undetermined direction stays undetermined
            covariance = covariance * (chi2 / dof) if dof > 0 else np.full_like(covariance, np.nan)
    errors = {
        name: (
            float(math.sqrt(covariance[k, k]))
            if math.isfinite(covariance[k, k]) and covariance[k, k] >= 0.0
            else None
        )
        for k, name in enumerate(names)
    }
    at_bound = {}
    for k, name in enumerate(names):
        side = None
        span = high[k] - low[k]
        if solution.active_mask[k] < 0 or x[k] - low[k] <= 1e-9 * span:
            side = "lower"
        elif solution.active_mask[k] > 0 or high[k] - x[k] <= 1e-9 * span:
            side = "upper"
        at_bound[name] = side
    samples = None
    if bootstrap:
        samples = _bootstrap(problem, x, low, high, bootstrap, seed, tolerance, step)
    residuals = Residuals(
        columns=problem.columns,
        measured=problem.measured,
        predicted=predicted,
        weights=problem.weights,
        mask=problem.mask,
        undefined=undefined & problem.mask,
    )
    return FitResult.build(
        model=model,
        names=names,
        x=x,
        start=x_start,
        bounds=limits,
        errors=errors,
        covariance=covariance,
        at_bound=at_bound,
        residuals=residuals,
        chi2=chi2,
        dof=dof,
        absolute=problem.absolute,
        solution=solution,
        tolerance=float(tolerance),
        evaluations=problem.evaluations,
        samples=samples,
        seed=seed,
    )


def _bootstrap(
    problem: _Problem,
    x: np.ndarray,
    low: np.ndarray,
    high: np.ndarray,
    count: int,
    seed: int | None,
    tolerance: float,
    step: float,
) -> np.ndarray:
    """The fit repeated on ``count`` resamples of the rows (drawn with replacement)."""
    rng = np.random.default_rng(seed)
    rows = problem.model.data.rows
    out = []
    for _ in range(count):
        draw = np.sort(rng.integers(0, rows, rows))
        if int(problem.mask[draw].sum()) < len(x):
            continue
        solution = _least_squares(problem, x, low, high, draw, tolerance, step)
        if solution.status > 0 and np.all(np.isfinite(solution.x)):
            out.append(solution.x)
    return np.array(out).reshape(-1, len(x))
