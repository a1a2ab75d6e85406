"""The result of a fit: values with standard errors, every row's residual, chi^2 and RMS (SI).

:class:`FitResult` is what :func:`twoball.fit` returns; :meth:`FitResult.as_dict`
is the JSON of ``twoball fit``, :meth:`FitResult.plot` the figure of the data
and the model.
"""

from __future__ import annotations

import math
import os
from dataclasses import dataclass, field, replace
from pathlib import Path
from typing import Any

import numpy as np

from twoball._common.errors import ParameterError
from twoball._common.keywords import checked

__all__ = ["FitResult", "Residuals"]


@dataclass(frozen=True)
class Residuals:
    """The measured and the model's values of every row and column (SI).

    Attributes
    ----------
    columns : tuple of str
        The measured columns the fit used (``v1_m_s``, ...).
    measured, predicted : ndarray
        Rows x columns; NaN where a cell was blank.
    weights : ndarray
        The divisor of each residual: the value's uncertainty, or the column's RMS.
    mask : ndarray of bool
        Where a value was measured.
    undefined : ndarray of bool
        Where the model had no value at the optimum (no lift-off: 0 m/s, the
        window's end taken instead).
    """

    columns: tuple[str, ...]
    measured: np.ndarray
    predicted: np.ndarray
    weights: np.ndarray
    mask: np.ndarray
    undefined: np.ndarray

    @property
    def residuals(self) -> np.ndarray:
        """``measured - model`` [SI], NaN where not measured."""
        return np.where(self.mask, self.measured - self.predicted, np.nan)

    def rms(self) -> dict[str, float]:
        """The RMS of each column's residuals [its SI unit]."""
        out = {}
        for k, column in enumerate(self.columns):
            values = self.residuals[self.mask[:, k], k]
            out[column] = float(np.sqrt(np.mean(values**2))) if values.size else math.nan
        return out


def _number(value: float | None) -> float | None:
    """JSON-ready: None for NaN and infinities."""
    return None if value is None or not math.isfinite(value) else float(value)


@checked
@dataclass(frozen=True)
class FitResult:
    """Model parameters fitted to measured rows by least squares, in SI.

    Attributes
    ----------
    model : str
        ``closed`` (the closed-form lift-off) or ``bounce`` (the whole bounce).
    parameters : tuple of str
        The fitted parameters (``damping``, ``wave-speed``, ``restitution``,
        ``floor-restitution``).
    values : dict
        The fitted value of each [SI].
    standard_errors : dict
        Its standard error from the Jacobian at the optimum (None when the data
        do not determine it: no degrees of freedom without uncertainties, or a
        singular Jacobian).
    start, bounds, at_bound : dict
        The start, the ``(low, high)`` range and ``"lower"``/``"upper"``/None:
        whether the fit ended on a bound.
    covariance : ndarray
        The parameters' covariance (the order of :attr:`parameters`).
    residuals : Residuals
        Measured and model values of every row.
    chi2 : float
        The sum of the squared weighted residuals.
    dof : int
        Measured values minus parameters.
    absolute : bool
        True when the file gave uncertainties (``sigma_`` columns): residuals
        over them, chi^2 with its statistical meaning and the covariance as it
        stands; False: each column over the RMS of its values and the
        covariance scaled by ``chi2 / dof``.
    converged : bool
        The least-squares solver met its tolerance.
    message : str
        The solver's own words.
    tolerance : float
        Its relative tolerance.
    evaluations : int
        Evaluations of the residual vector (each one run of the model per row).
    runs : int
        Runs of the model (one row at one set of values; the Jacobian's included).
    bootstrap : ndarray, optional
        The values fitted to each bootstrap resample (samples x parameters).
    case : Case
        The base case.
    data : Measurements
        The rows.
    inputs : dict
        The inputs every row ran with (``v0_m_s``, ``phi_a_rad`` or ``gap_m``).
    solver : dict
        The model's options.
    notes, warnings : tuple of str
    provenance : dict, optional

    Examples
    --------
    >>> import twoball
    >>> result = twoball.fit({"v0_m_s": [4.1], "phi_a_rad": [2.6], "v1_m_s": [3.7]}, "damping")
    >>> round(result.values["damping"], 4), result.dof
    (0.1329, 0)
    >>> result.as_dict()["parameters"]["damping"]["standard_error"] is None  # no freedom left
    True
    """

    model: str
    parameters: tuple[str, ...]
    values: dict[str, float]
    standard_errors: dict[str, float | None]
    start: dict[str, float]
    bounds: dict[str, tuple[float, float]]
    at_bound: dict[str, str | None]
    covariance: np.ndarray
    residuals: Residuals
    chi2: float
    dof: int
    absolute: bool
    converged: bool
    message: str
    tolerance: float
    evaluations: int
    runs: int
    case: Any
    data: Any
    inputs: dict[str, np.ndarray]
    solver: dict[str, Any]
    bootstrap: np.ndarray | None = None
    seed: int | None = None
    notes: tuple[str, ...] = ()
    warnings: tuple[str, ...] = ()
    provenance: dict[str, Any] | None = field(default=None, compare=False, repr=False)
    fitted_model: Any = field(default=None, compare=False, repr=False)

    @classmethod
    def build(
        cls,
        *,
        model: Any,
        names: tuple[str, ...],
        x: np.ndarray,
        start: dict[str, float],
        bounds: dict[str, tuple[float, float]],
        errors: dict[str, float | None],
        covariance: np.ndarray,
        at_bound: dict[str, str | None],
        residuals: Residuals,
        chi2: float,
        dof: int,
        absolute: bool,
        solution: Any,
        tolerance: float,
        evaluations: int,
        samples: np.ndarray | None,
        seed: int | None,
    ) -> FitResult:
        """The result of :func:`~twoball.verify.fit.solve.fit_model`, its notes and warnings."""
        from twoball.verify.fit.data import plausibility_warnings

        values = {name: float(v) for name, v in zip(names, x, strict=True)}
        warnings = list(plausibility_warnings(model.data))
        notes = []
        if model.rule_note:
            notes.append(model.rule_note)
        if solution.status <= 0:
            warnings.append(f"the fit did not converge: {solution.message}")
        for name, side in at_bound.items():
            if side is not None:
                low, high = bounds[name]
                end = low if side == "lower" else high
                warnings.append(
                    f"{name} = {values[name]:.6g} ends on the {side} bound {end:g} of "
                    f"[{low:g}, {high:g}]: the data want a value beyond it; its standard "
                    "error does not measure its uncertainty"
                )
        for name in names:
            if errors[name] is None:
                why = (
                    "no degrees of freedom (as many measured values as parameters): give "
                    "more rows, or sigma_ columns for an error from the uncertainties"
                    if dof <= 0 and not absolute
                    else "the data do not determine it (its Jacobian column vanishes or "
                    "depends on the others)"
                )
                warnings.append(f"{name}: no standard error: {why}")
        undefined = residuals.undefined
        if undefined.any():
            rows = sorted({int(k) + 1 for k in np.nonzero(undefined)[0]})
            warnings.append(
                "the model has no value at the optimum in row(s) "
                + ", ".join(map(str, rows))
                + " (no lift-off, or not apart within the window): 0 m/s or the window's "
                "end was taken"
            )
        if model.name == "closed":
            warnings += _closed_warnings(model, values)
        if not absolute:
            notes.append(
                "residuals weighted by the RMS of each measured column; standard errors from "
                "the Jacobian at the optimum scaled by the residual variance chi^2/(m - n)"
            )
        else:
            notes.append(
                "residuals weighted by the sigma_ columns; standard errors from the Jacobian "
                "at the optimum (absolute: chi^2 has its statistical meaning)"
            )
        return cls(
            model=model.name,
            parameters=names,
            values=values,
            standard_errors=errors,
            start=dict(start),
            bounds=dict(bounds),
            at_bound=at_bound,
            covariance=covariance,
            residuals=residuals,
            chi2=chi2,
            dof=dof,
            absolute=absolute,
            converged=solution.status > 0,
            message=str(solution.message),
            tolerance=tolerance,
            evaluations=evaluations,
            runs=model.runs,
            case=model.case,
            data=model.data,
            inputs=model.inputs(),
            solver=model.solver_dict(),
            bootstrap=samples,
            seed=seed,
            notes=tuple(notes),
            warnings=tuple(dict.fromkeys(warnings)),
            fitted_model=model,
        )

    # --- numbers -------------------------------------------------------------------------
    @property
    def reduced_chi2(self) -> float | None:
        """``chi2 / dof`` (None without degrees of freedom)."""
        return self.chi2 / self.dof if self.dof > 0 else None

    @property
    def units(self) -> dict[str, str | None]:
        """The SI unit of each fitted parameter (None: a pure number)."""
        from twoball.verify.fit.models import PARAMETERS

        return {name: PARAMETERS[name].unit or None for name in self.parameters}

    @property
    def rms(self) -> dict[str, float]:
        """The RMS residual of each measured column [its SI unit]."""
        return self.residuals.rms()

    @property
    def bootstrap_errors(self) -> dict[str, float | None] | None:
        """The standard deviation of the bootstrap's values (None without a bootstrap)."""
        if self.bootstrap is None:
            return None
        samples = self.bootstrap
        return {
            name: float(np.std(samples[:, k], ddof=1)) if samples.shape[0] > 1 else None
            for k, name in enumerate(self.parameters)
        }

    def rows(self) -> list[dict[str, Any]]:
        """Every row: its number and line, its inputs, measured, model and residual (SI)."""
        r = self.residuals
        out = []
        for k in range(self.data.rows):
            cells = {c: _number(self.inputs[c][k]) for c in self.inputs}
            measured = {}
            model = {}
            residual = {}
            for j, column in enumerate(r.columns):
                if not r.mask[k, j]:
                    continue
                measured[column] = _number(r.measured[k, j])
                model[column] = _number(r.predicted[k, j])
                residual[column] = _number(r.measured[k, j] - r.predicted[k, j])
            out.append(
                {
                    "row": k + 1,
                    "line": self.data.lines[k] or None,
                    "inputs": cells,
                    "measured": measured,
                    "model": model,
                    "residual": residual,
                    "no_model_value": [c for j, c in enumerate(r.columns) if r.undefined[k, j]],
                }
            )
        return out

    def as_dict(self) -> dict[str, Any]:
        """JSON-ready: parameters with errors, rows with residuals, chi^2, RMS, the case (SI)."""
        from twoball.verify.fit.models import PARAMETERS

        boot = self.bootstrap_errors
        parameters = {}
        for k, name in enumerate(self.parameters):
            low, high = self.bounds[name]
            entry = {
                "value": self.values[name],
                "standard_error": self.standard_errors[name],
                "unit": PARAMETERS[name].unit or None,
                "start": self.start[name],
                "bounds": [low, high],
                "at_bound": self.at_bound[name],
            }
            if boot is not None:
                column = self.bootstrap[:, k]
                entry["bootstrap_standard_error"] = boot[name]
                entry["bootstrap_16_84"] = (
                    [float(np.percentile(column, 16)), float(np.percentile(column, 84))]
                    if column.size
                    else None
                )
            parameters[name] = entry
        cov = [[_number(v) for v in row] for row in np.atleast_2d(self.covariance)]
        data: dict[str, Any] = {
            "model": self.model,
            "parameters": parameters,
            "covariance": cov,
            "chi2": self.chi2,
            "dof": self.dof,
            "reduced_chi2": self.reduced_chi2,
            "rms": {c: _number(v) for c, v in self.rms.items()},
            "weighting": "sigma" if self.absolute else "column rms",
            "converged": self.converged,
            "message": self.message,
            "tolerance": self.tolerance,
            "evaluations": self.evaluations,
            "runs": self.runs,
            "columns": list(self.residuals.columns),
            "rows": self.rows(),
            "data": self.data.source,
            "case": self.case.as_dict(),
            "solver": self.solver,
            "notes": list(self.notes),
            "warnings": list(self.warnings),
        }
        if self.bootstrap is not None:
            data["bootstrap"] = {"samples": int(self.bootstrap.shape[0]), "seed": self.seed}
        if self.provenance is not None:
            data["provenance"] = self.provenance
        return data

    def summary(self) -> str:
        """``D = 0.1329 +- 0.0012`` for every parameter, one line."""
        parts = []
        for name in self.parameters:
            error = self.standard_errors[name]
            value = self.values[name]
            text = f"{name} = {value:.6g}"
            text += f" +- {error:.2g}" if error is not None else " (no standard error)"
            parts.append(text)
        return ", ".join(parts)

    # --- files ---------------------------------------------------------------------------
    @checked
    def plot(self, out: str | os.PathLike[str], *, dpi: float | None = None) -> Path:
        """Figure of the data and the fitted model: each measured column against the rows'
        varying input (|v0|, the gap, or the row), with the residuals below.

        ``out``'s suffix chooses the format (``.png``, ``.pdf``, ``.svg``, ...).
        """
        from twoball.verify.output.figures import save_figure
        from twoball.verify.output.figures.fit import fit_figure

        curve = None
        if self.fitted_model is not None:
            curve = self.fitted_model.curve(self.values)
        title = _title(self)
        sigma = None
        if self.absolute:
            sigma = self.residuals.weights
        figure = fit_figure(
            self.inputs,
            self.residuals.columns,
            self.residuals.measured,
            self.residuals.predicted,
            sigma,
            curve,
            title,
        )
        return save_figure(figure, out, "plot", dpi)

    def with_provenance(self, provenance: dict[str, Any]) -> FitResult:
        """This result with its provenance block."""
        return replace(self, provenance=provenance)


def _title(result: FitResult) -> str:
    from twoball.verify.fit.models import PARAMETERS

    what = "closed-form lift-off" if result.model == "closed" else "whole bounce"
    parts = []
    for name in result.parameters:
        p = PARAMETERS[name]
        error = result.standard_errors[name]
        value = f"{result.values[name]:.4g}"
        if error is not None:
            value += f" ± {error:.2g}"
        parts.append(f"{p.symbol} = {value}" + (f" {p.unit}" if p.unit else ""))
    source = Path(str(result.data.source)).name
    return f"Fit of the {what} to {source}: " + ", ".join(parts)


def _closed_warnings(model: Any, values: dict[str, float]) -> list[str]:
    """The closed form's own accuracy warnings at the optimum (the truncation guard), once."""
    seen: list[str] = []
    for row in range(model.data.rows):
        try:
            report = model.report(row, values, reference=True)
        except ParameterError:
            continue
        for text in report.warnings:
            line = f"row {row + 1}: {text}"
            if text not in {s.split(": ", 1)[-1] for s in seen}:
                seen.append(line)
    return seen
