"""The models a fit adjusts: the closed-form lift-off and the whole bounce, row by row (SI).

A model takes the base case, the measured rows and the names of the fitted
parameters, checks every row before any work (its inputs build a case, its
columns are ones the model can use) and then predicts the measured columns of
every row for given parameter values:

:class:`ClosedModel`
    The closed-form lift-off of the paper's massless body, eqs. (3.12)-(3.16)
    with criteria (i)-(ii) of §3(a): ``v1_m_s`` is the lift-off velocity v_l,
    ``t_liftoff_s`` the lift-off time t_l; a row's ``v0_m_s`` and
    ``phi_a_rad`` are its inputs.
:class:`BounceModel`
    The drop on the floor, or the whole two-ball bounce with a body
    (:mod:`twoball.modal.floor.bounce`, Moreau-Jean steps, docs/whole_bounce.rst
    eqs. (B1)-(B2)): ``v1_m_s`` is the body's speed at its last separation,
    ``v2_m_s`` the ball's at its last release, ``t_liftoff_s`` the body's
    lift-off after the first floor touch; a row's ``v0_m_s`` and ``gap_m`` are
    its inputs.

Where the model has no value (no lift-off, the ball still on the floor at the
window's end) a prediction is NaN; :meth:`fallback` gives what the residual
takes instead (a speed of 0, a time at the window's end).

Examples
--------
>>> from twoball.modal.parameters import Case
>>> from twoball.verify.fit.data import Measurements
>>> data = Measurements.from_columns({"v0_m_s": [4.1], "phi_a_rad": [2.6], "v1_m_s": [3.7]})
>>> model = ClosedModel(Case.preset("basketball"), data, ("damping",))
>>> model.start()
{'damping': 0.13}
>>> round(float(model.predict({"damping": 0.13})[0, 0]), 4)
3.8322
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, replace
from typing import Any

import numpy as np

from twoball._common.choices import FIT_MODEL_COLUMNS, FIT_PARAMETERS
from twoball._common.errors import ParameterError
from twoball._common.monitor import Monitor
from twoball.modal.parameters import Case
from twoball.modal.scalings import WAVE_SPEED_RANGE
from twoball.verify.fit.data import Measurements

__all__ = [
    "PARAMETERS",
    "BounceModel",
    "ClosedModel",
    "Parameter",
    "parameter_names",
    "start_values",
]

#: The largest damping ratio a fit tries (the case takes D in [0, 1)).
DAMPING_MAX = 0.999


@dataclass(frozen=True)
class Parameter:
    """A fittable parameter: its names, the range its model accepts, its unit and symbol.

    Examples
    --------
    >>> PARAMETERS["wave-speed"].field, PARAMETERS["wave-speed"].unit
    ('wave_speed', '1/s')
    """

    name: str
    field: str
    low: float
    high: float
    unit: str
    symbol: str
    models: tuple[str, ...]

    @property
    def label(self) -> str:
        """``D``, ``c [1/s]``: the symbol with its unit."""
        return self.symbol + (f" [{self.unit}]" if self.unit else "")


#: The fittable parameters by command-line name (:data:`~twoball._common.choices.FIT_PARAMETERS`).
PARAMETERS: dict[str, Parameter] = {
    "damping": Parameter("damping", "damping", 0.0, DAMPING_MAX, "", "D", ("closed", "bounce")),
    "wave-speed": Parameter(
        "wave-speed", "wave_speed", *WAVE_SPEED_RANGE, "1/s", "c", ("closed", "bounce")
    ),
    "restitution": Parameter("restitution", "restitution", 0.0, 1.0, "", "e12", ("bounce",)),
    "floor-restitution": Parameter(
        "floor-restitution", "floor_restitution", 0.0, 1.0, "", "e", ("bounce",)
    ),
}
assert set(PARAMETERS) == set(FIT_PARAMETERS)


def start_values(
    names: Sequence[str], case: Case, body: Any = None, drop: Any = None
) -> dict[str, float]:
    """The start of each fitted parameter: the case's D and c, the body's e12, the drop's e."""
    out = {}
    for name in names:
        if name == "restitution":
            out[name] = 0.0 if body is None else float(body.restitution)
        elif name == "floor-restitution":
            out[name] = 0.0 if drop is None else float(drop.floor_restitution)
        else:
            out[name] = float(getattr(case, PARAMETERS[name].field))
    return out


def parameter_names(params: object, model: str) -> tuple[str, ...]:
    """``params`` (a name or a list; ``wave_speed`` or ``wave-speed``) as command-line names.

    Raises
    ------
    ParameterError
        Naming ``params``: empty, unknown, repeated, or not fitted by ``model``.
    """
    items = [params] if isinstance(params, str) else params
    valid = "one or more of " + ", ".join(PARAMETERS)
    if not isinstance(items, Sequence) or isinstance(items, bytes) or not items:
        raise ParameterError("params", valid, params)
    names = []
    for item in items:
        if not isinstance(item, str) or item.replace("_", "-") not in PARAMETERS:
            raise ParameterError("params", valid, item)
        name = item.replace("_", "-")
        if name in names:
            raise ParameterError("params", "each parameter once", item)
        if model not in PARAMETERS[name].models:
            where = " or ".join(PARAMETERS[name].models)
            raise ParameterError(
                "params", f"a parameter of the {model} model ({name}: model {where})", item
            )
        names.append(name)
    return tuple(names)


class _Rows:
    """What both models share: the data's columns checked, the outputs, a cache per row."""

    name = "closed"

    def __init__(self, data: Measurements, parameters: tuple[str, ...]) -> None:
        inputs, outputs = FIT_MODEL_COLUMNS[self.name]
        data.refuse_columns((*inputs, *outputs), self.description, self.hints)
        self.data = data
        self.parameters = parameters
        self.outputs = tuple(c for c in outputs if data.has(c))
        if not self.outputs:
            valid = f"a file with at least one measured column ({', '.join(outputs)})"
            raise data.error(valid, "inputs only")
        measured = np.zeros(data.rows, dtype=bool)
        for column in self.outputs:
            measured |= data.measured(column)
        if not measured.all():
            row = int(np.flatnonzero(~measured)[0])
            valid = "a row with at least one measured value (" + ", ".join(self.outputs) + ")"
            raise data.error(valid, "blank cells only", row=row)
        self._cache: dict[tuple[int, tuple[float, ...]], tuple[float, ...]] = {}
        self.runs = 0

    description = "the model"
    hints: dict[str, str] = {}  # noqa: RUF012 -- read only

    def key(self, values: Mapping[str, float]) -> tuple[float, ...]:
        return tuple(float(values[name]) for name in self.parameters)

    def predict(self, values: Mapping[str, float], rows: Sequence[int] | None = None) -> np.ndarray:
        """The outputs (columns :attr:`outputs`) of ``rows`` (default all) at ``values`` (SI).

        NaN where the model has no value (:meth:`fallback`).
        """
        rows = range(self.data.rows) if rows is None else rows
        key = self.key(values)
        out = np.empty((len(rows), len(self.outputs)))
        for k, row in enumerate(rows):
            if (row, key) not in self._cache:
                self.runs += 1
                self._cache[(row, key)] = self.row_outputs(int(row), values)
            out[k] = self._cache[(row, key)]
        return out

    def row_outputs(self, row: int, values: Mapping[str, float]) -> tuple[float, ...]:
        raise NotImplementedError

    def _check_ranges(self, values: Mapping[str, float]) -> None:
        for name in self.parameters:
            p = PARAMETERS[name]
            if not (p.low <= values[name] <= p.high):
                raise ParameterError(name, f"in [{p.low:g}, {p.high:g}]", values[name])


def _row_error(data: Measurements, row: int, column: str, error: ParameterError) -> Exception:
    """A row's input refused by the model, named by its row and column."""
    return data.error(error.valid, error.got, row=row, column=column)


class ClosedModel(_Rows):
    """The closed-form lift-off, eqs. (3.12)-(3.16), of each row (module docstring).

    Parameters
    ----------
    case : Case
        The base case: every value a row does not give and every parameter's start.
    data : Measurements
        The rows: inputs ``v0_m_s``, ``phi_a_rad``; measured ``v1_m_s``, ``t_liftoff_s``.
    parameters : tuple of str
        The fitted parameters (``damping``, ``wave-speed``).
    sigma, recontact : str
        The filter of eq. (3.16) and the re-contact horizon of criterion (ii).
    t_end : float, optional
        The window [s] (default 4 pi / c).
    monitor : Monitor, optional
        Handed to every evaluation (it may stop the work by raising).
    """

    name = "closed"
    description = "the closed-form lift-off"
    hints = {  # noqa: RUF012 -- read only
        "gap_m": "gap_m is an input of the whole bounce (model bounce)",
        "v2_m_s": "v2_m_s is measured in the whole bounce (model bounce)",
    }

    def __init__(
        self,
        case: Case,
        data: Measurements,
        parameters: tuple[str, ...],
        *,
        sigma: str = "lanczos",
        recontact: str = "window",
        t_end: float | None = None,
        monitor: Monitor | None = None,
    ) -> None:
        super().__init__(data, parameters)
        self.case, self.sigma, self.recontact, self.t_end = case, sigma, recontact, t_end
        self.monitor = monitor
        if "damping" in parameters and case.rayleigh is not None and not case.rayleigh.fitted:
            valid = "fitted with the modal ratio or Rayleigh() fitted to D (a Rayleigh law of "
            raise ParameterError("params", valid + "its own alpha, beta has no D)", "damping")
        v0, phi = data.column("v0_m_s"), data.column("phi_a_rad")
        self.rows_cases: list[Case] = []
        self.given_phi = np.isfinite(phi)
        for row in range(data.rows):
            changes: dict[str, Any] = {}
            if np.isfinite(v0[row]):
                changes["v0"] = float(v0[row])
            if np.isfinite(phi[row]):
                changes["phi_a"] = float(phi[row])
            try:
                self.rows_cases.append(case.derive(**changes) if changes else case)
            except ParameterError as error:
                column = "phi_a_rad" if error.name.startswith("phi_a") else "v0_m_s"
                raise _row_error(data, row, column, error) from None
        self.rule_note = None
        if "wave-speed" in parameters and not self.given_phi.all():
            self.rule_note = (
                "phi_a from eq. (3.7) at every trial c in the rows without phi_a_rad (one rule "
                "for the whole fit; the preset's measured angle holds only at its own c)"
            )

    def start(self) -> dict[str, float]:
        """The case's value of each fitted parameter."""
        return start_values(self.parameters, self.case)

    def row_case(self, row: int, values: Mapping[str, float]) -> Case:
        """Row ``row``'s case at the parameter values (phi_a by one rule for the fit)."""
        base = self.rows_cases[row]
        changes = {PARAMETERS[n].field: float(values[n]) for n in self.parameters}
        if "wave_speed" in changes:  # phi_a: the row's own, else eq. (3.7) at every c
            changes["phi_a"] = base.phi_a if self.given_phi[row] else "eq. (3.7)"
        return base.derive(**changes)

    def report(self, row: int, values: Mapping[str, float], *, reference: bool = False) -> Any:
        """The lift-off report of row ``row`` at ``values`` (with the truncation guard's
        reference on request)."""
        from twoball.modal.report import legendre_liftoff

        self._check_ranges(values)
        return legendre_liftoff(
            self.row_case(row, values),
            self.sigma,
            self.recontact,
            self.t_end,
            reference=reference,
            monitor=self.monitor,
        )

    def row_outputs(self, row: int, values: Mapping[str, float]) -> tuple[float, ...]:
        report = self.report(row, values)
        found = {"v1_m_s": report.v_liftoff_m_s, "t_liftoff_s": report.t_liftoff_s}
        return tuple(math.nan if found[c] is None else float(found[c]) for c in self.outputs)

    def fallback(self, row: int, column: str, values: Mapping[str, float]) -> float:
        """What a residual takes where the model has no lift-off: v1 = 0, t_l = the window's end."""
        if column == "v1_m_s":
            return 0.0
        from twoball.modal.report import t_end_dimensionless

        case = self.row_case(row, values)
        return t_end_dimensionless(case, self.t_end) / case.wave_speed

    def inputs(self) -> dict[str, np.ndarray]:
        """The inputs every row ran with: ``v0_m_s``, ``phi_a_rad`` (at the base case's c)."""
        return {
            "v0_m_s": np.array([c.v0 for c in self.rows_cases]),
            "phi_a_rad": np.array([c.phi_a for c in self.rows_cases]),
        }

    def curve(self, values: Mapping[str, float], count: int = 41) -> dict[str, np.ndarray] | None:
        """The model along ``|v0|`` over the rows' range (None when the rows do not vary v0 or
        give their own phi_a): ``v0_m_s`` and every output."""
        v0 = np.array([c.v0 for c in self.rows_cases])
        if self.given_phi.any() or np.ptp(v0) <= 1e-9 * v0.max():
            return None
        grid = np.linspace(v0.min(), v0.max(), count)
        out: dict[str, list[float]] = {c: [] for c in self.outputs}
        for speed in grid:
            changes = {PARAMETERS[n].field: float(values[n]) for n in self.parameters}
            case = self.case.derive(v0=float(speed), **changes)
            if "wave_speed" in changes:
                case = case.derive(phi_a="eq. (3.7)")
            from twoball.modal.report import legendre_liftoff

            report = legendre_liftoff(
                case, self.sigma, self.recontact, self.t_end, reference=False, monitor=self.monitor
            )
            found = {"v1_m_s": report.v_liftoff_m_s, "t_liftoff_s": report.t_liftoff_s}
            for column in self.outputs:
                out[column].append(math.nan if found[column] is None else found[column])
        return {"v0_m_s": grid, **{c: np.array(v) for c, v in out.items()}}

    def solver_dict(self) -> dict[str, Any]:
        """The model's own options, for the JSON."""
        return {
            "model": "closed",
            "sigma": self.sigma,
            "recontact": self.recontact,
            "t_end_s": self.t_end,
        }


class BounceModel(_Rows):
    """The drop, or the whole bounce with a body, of each row (module docstring).

    Parameters
    ----------
    case : Case
        The lower ball and the base values (``|v0|``, D, c); for a pair, a case of
        its lower ball's preset.
    data : Measurements
        The rows: inputs ``v0_m_s``, ``gap_m``; measured ``v1_m_s``, ``v2_m_s``,
        ``t_liftoff_s``.
    parameters : tuple of str
        The fitted parameters (``damping``, ``wave-speed``, ``restitution``,
        ``floor-restitution``).
    drop : Drop
        The drop's options (the gap of the rows without ``gap_m``).
    body : Body, optional
        The upper body (its ``restitution`` is e12's start); None with ``pair``
        resolved to it by the caller, or for the ball alone.
    ball : Ball
        The lower ball and its discretisation (a coarse :class:`LegendreBall` keeps
        a fit quick).
    dt, t_end : float, optional
        Time step and window [s].
    pair : str, optional
        The Table 1 pair the body came from (named in the JSON).
    monitor : Monitor, optional
        Handed to every run.
    """

    name = "bounce"
    description = "the whole bounce"
    hints = {  # noqa: RUF012 -- read only
        "phi_a_rad": "phi_a_rad is an input of the closed form (model closed); the drop "
        "computes its own contact angle",
    }

    def __init__(
        self,
        case: Case,
        data: Measurements,
        parameters: tuple[str, ...],
        *,
        drop: Any,
        body: Any,
        ball: Any,
        dt: float | None = None,
        t_end: float | None = None,
        pair: str | None = None,
        monitor: Monitor | None = None,
    ) -> None:
        super().__init__(data, parameters)
        from twoball.modal.floor.bounce import bounce_problem

        self.case, self.drop, self.body, self.ball = case, drop, body, ball
        self.dt, self.t_end, self.pair, self.monitor = dt, t_end, pair, monitor
        if body is None:
            for column in ("v1_m_s", "t_liftoff_s"):
                if data.has(column):
                    valid = "a column of the drop of the ball alone (v0_m_s, v2_m_s); the body's"
                    raise data.error(valid + " need a body (mass_ratio or pair)", column=column)
            if data.has("gap_m"):
                raise data.error(
                    "a column of the drop with a body (mass_ratio or pair)", column="gap_m"
                )
            if "restitution" in parameters:
                raise ParameterError(
                    "params", "restitution with a body (mass_ratio or pair)", "restitution"
                )
        if "damping" in parameters and case.rayleigh is not None and not case.rayleigh.fitted:
            valid = "fitted with the modal ratio or Rayleigh() fitted to D (a Rayleigh law of "
            raise ParameterError("params", valid + "its own alpha, beta has no D)", "damping")
        v0, gap = data.column("v0_m_s"), data.column("gap_m")
        self.rows_cases = []
        self.rows_drops = []
        for row in range(data.rows):
            column = "v0_m_s"
            try:
                row_case = case.derive(v0=float(v0[row])) if np.isfinite(v0[row]) else case
                column = "gap_m"
                row_drop = replace(drop, gap=float(gap[row])) if np.isfinite(gap[row]) else drop
                column = "v0_m_s"
                bounce_problem(row_case, row_drop, ball=ball, body=body, dt=dt, t_end=t_end)
            except ParameterError as error:
                if error.name == "gap":
                    column = "gap_m"
                raise _row_error(data, row, column, error) from None
            self.rows_cases.append(row_case)
            self.rows_drops.append(row_drop)
        self.rule_note = None

    def start(self) -> dict[str, float]:
        """The case's, the body's and the drop's value of each fitted parameter."""
        return start_values(self.parameters, self.case, self.body, self.drop)

    def problem(self, row: int, values: Mapping[str, float]) -> Any:
        """Row ``row``'s resolved drop at the parameter values."""
        from twoball.modal.floor.bounce import bounce_problem

        case, drop, body = self.rows_cases[row], self.rows_drops[row], self.body
        changes = {
            PARAMETERS[n].field: float(values[n])
            for n in self.parameters
            if n in ("damping", "wave-speed")
        }
        if changes:
            case = case.derive(**changes)
        if "restitution" in self.parameters:
            body = replace(body, restitution=float(values["restitution"]))
        if "floor-restitution" in self.parameters:
            drop = replace(drop, floor_restitution=float(values["floor-restitution"]))
        return bounce_problem(case, drop, ball=self.ball, body=body, dt=self.dt, t_end=self.t_end)

    def report(self, row: int, values: Mapping[str, float]) -> Any:
        """The SI report of row ``row`` at ``values`` (without the lumped baselines)."""
        from twoball.modal.floor.bounce import simulate

        self._check_ranges(values)
        return simulate(self.problem(row, values), self.monitor, baselines=False)

    def row_outputs(self, row: int, values: Mapping[str, float]) -> tuple[float, ...]:
        return self.outputs_of(self.report(row, values))

    def outputs_of(self, report: Any) -> tuple[float, ...]:
        """The measured columns of one run's report (NaN where undefined)."""
        if report.has_body:  # the ball's centre at its last release, as the JSON's v2_m_s
            body_v2 = report.result.body.v2
            v2 = None if body_v2 is None else body_v2 * report.case.scalings.velocity
        else:
            v2 = report.v2_m_s
        found = {"v1_m_s": report.v1_m_s, "v2_m_s": v2, "t_liftoff_s": report.t_liftoff_s}
        return tuple(math.nan if found[c] is None else float(found[c]) for c in self.outputs)

    def fallback(self, row: int, column: str, values: Mapping[str, float]) -> float:
        """What a residual takes where the run has no value: a speed of 0, the window's end."""
        if column != "t_liftoff_s":
            return 0.0
        problem = self.problem(row, values)
        return problem.t_end / problem.case.wave_speed

    def inputs(self) -> dict[str, np.ndarray]:
        """The inputs every row ran with: ``v0_m_s`` and, with a body, ``gap_m``."""
        out = {"v0_m_s": np.array([c.v0 for c in self.rows_cases])}
        if self.body is not None:
            out["gap_m"] = np.array([d.gap for d in self.rows_drops])
        return out

    def curve(self, values: Mapping[str, float], count: int = 41) -> None:
        """No curve between the rows: each point is a run (the figure joins the rows)."""
        return None

    def solver_dict(self) -> dict[str, Any]:
        """The model's own options, for the JSON."""
        out = {
            "model": "bounce",
            "ball": self.ball.as_dict(),
            "dt_s": self.dt,
            "t_end_s": self.t_end,
            "drop": self.drop.as_dict(),
        }
        if self.body is not None:
            out["body"] = self.body.as_dict()
        if self.pair is not None:
            out["pair"] = self.pair
        return out
