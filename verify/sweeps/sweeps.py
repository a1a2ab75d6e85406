"""Sweeps of the closed-form lift-off over one or two parameters (Fig. 11(b), Fig. 12).

A sweep is a list of cases (the grid, row-major: the first parameter varies
slowest), solved by :class:`SweepSolver` through a :class:`twoball.verify.sweeps.parallel.Runner`
so the same code runs serially, on local processes or on a Dask cluster, with
identical numbers.  A point whose solve raises is kept as a :class:`SweepPoint`
with ``error`` set, next to its parameters.

One rule for phi_a in one sweep.  A preset's measured phi_a holds only at its
own R, c and ``|v0|`` (:class:`~twoball.modal.parameters.Case`); a sweep of v0,
c or R passing through that point would take the measured angle there and eq.
(3.7) beside it -- a dip of the curve made by the rule, not the physics
(basketball: 2.6 rad measured against 2.62 rad from eq. (3.7) at 4.1 m/s).  So
every point of such a sweep takes eq. (3.7); a sweep of anything else keeps the
base case's phi_a at every point.  :func:`phi_a_rule` says which, in the JSON
and on the figure.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Iterable, Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np

from twoball._common.budget import check, check_all
from twoball._common.choices import SWEEP_PARAMETERS
from twoball._common.errors import ParameterError
from twoball.modal.cost import case_liftoff_work
from twoball.modal.parameters import FROM_V0, Case
from twoball.modal.report import LiftoffReport, legendre_liftoff
from twoball.verify.sweeps.parallel import Runner

#: Axis labels (SI) of the swept parameters.
PARAMETER_LABELS: dict[str, str] = {
    "damping": "damping ratio D",
    "v0": "impact speed |v0| [m/s]",
    "wave-speed": "wave speed c [1/s]",
    "radius": "radius R [m]",
    "modes": "modes N",
    "mass-ratio": "mass ratio mu = m1/m2",
    "bending": "flexural rigidity B [N m]",
}


def parse_range(text: str, name: str = "values") -> np.ndarray:
    """The values of ``text`` in the one list syntax (:mod:`twoball._common.ranges`).

    ``START:STOP:COUNT`` gives ``COUNT`` evenly spaced values from START to STOP
    inclusive; ``v1,v2,...`` the values as written.
    """
    from twoball._common.ranges import parse_values
    from twoball.verify.sweeps.cost import check_count

    if isinstance(text, str) and text.count(":") == 2:  # the budget before building the list
        try:
            count = int(float(text.split(":")[2]))
        except ValueError:
            count = 0
        if count > 1:
            check_count(f"{name} {text}", count)
    return np.asarray(parse_values(text, name), dtype=float)


def _field_value(field: str, value: float) -> float | int:
    if field == "modes":
        if float(value) != round(float(value)):
            raise ParameterError("values", "whole numbers for param modes", value)
        return int(round(float(value)))
    return float(value)


def _check_parameter(parameter: str) -> str:
    if parameter not in SWEEP_PARAMETERS:
        raise ParameterError("param", "one of " + ", ".join(SWEEP_PARAMETERS), parameter)
    return SWEEP_PARAMETERS[parameter]


def _check_law(base: Case, field: str) -> None:
    """Refuse sweeping D when the case's Rayleigh law has its own coefficients (D unused)."""
    if field == "damping" and base.rayleigh is not None and not base.rayleigh.fitted:
        valid = "a swept parameter that the case uses (its Rayleigh law has its own alpha, beta)"
        raise ParameterError("param", valid, "damping")


#: Case fields whose change re-applies the phi_a rule (eq. (3.7) away from a preset's point).
PHI_A_FIELDS = ("v0", "wave_speed", "radius")


def _one_rule(fields: Iterable[str]) -> dict[str, str]:
    """``phi_a="eq. (3.7)"`` when a field of the phi_a rule is swept (module docstring)."""
    return {"phi_a": FROM_V0} if set(fields) & set(PHI_A_FIELDS) else {}


def sweep_cases(base: Case, parameter: str, values: Iterable[float]) -> list[Case]:
    """The cases of a sweep: ``base`` with one parameter varied (one phi_a rule, module doc)."""
    field = _check_parameter(parameter)
    _check_law(base, field)
    rule = _one_rule([field])
    return [base.derive(**{field: _field_value(field, value)}, **rule) for value in values]


def phi_a_rule(cases: Sequence[Any]) -> str:
    """How phi_a was chosen at the points: ``eq. (3.7) at every point`` or the one value."""
    sources = {c.phi_a_source for c in cases}
    if sources == {FROM_V0}:
        return "eq. (3.7) at every point (from |v0|, R, c)"
    angles = {c.phi_a for c in cases}
    if len(angles) == 1 and len(sources) == 1:
        return f"{angles.pop():.6g} rad at every point ({sources.pop()})"
    return "mixed: " + ", ".join(sorted(str(s) for s in sources))


def phi_a_note(cases: Sequence[Any]) -> str | None:
    """The one note of a sweep whose rule replaced a preset's measured phi_a (else None).

    Said once for the sweep, its preset's own point included, in place of each
    point's own note (:attr:`~twoball.modal.parameters.Case.phi_a_note`).
    """
    notes = [c.phi_a_note for c in cases]
    if not any(notes):
        return None
    first = next(c for c, n in zip(cases, notes, strict=True) if n)
    from twoball.modal.presets import MEASURED

    measured = MEASURED[first.preset_name].phi_a
    own = [c for c in cases if c.at_measured_point]
    where = (
        f", the {first.preset_name} preset's own R, c, |v0| included: one rule for the sweep"
        if own
        else ""
    )
    return (
        f"phi_a from {phi_a_rule(cases)}{where}; the {first.preset_name} preset's measured "
        f"{measured:g} rad holds only at its own R, c, |v0|"
        + (" and is used at none of the points" if own else "")
    )


@dataclass(frozen=True)
class SweepGrid:
    """The swept parameters (CLI names) and their values; one or two axes."""

    parameters: tuple[str, ...]
    values: tuple[np.ndarray, ...]

    @property
    def shape(self) -> tuple[int, ...]:
        """Number of values per axis."""
        return tuple(len(v) for v in self.values)

    def indices(self) -> list[tuple[int, ...]]:
        """Grid indices in row-major order (the first parameter varies slowest)."""
        return [tuple(int(i) for i in k) for k in np.ndindex(*self.shape)]

    def cases(self, base: Case) -> list[Case]:
        """One case per grid point, in :meth:`indices` order.

        A sweep of v0, c or R takes phi_a from eq. (3.7) at every point, the
        preset's own point included; any other keeps the base case's phi_a
        (one rule per sweep, module docstring).
        """
        fields = [_check_parameter(p) for p in self.parameters]
        for field in fields:
            _check_law(base, field)
        rule = _one_rule(fields)
        out = []
        for index in self.indices():
            changes = {
                f: _field_value(f, self.values[axis][i])
                for axis, (f, i) in enumerate(zip(fields, index, strict=True))
            } | rule
            mass_ratio = changes.pop("mass_ratio", None)
            case = base.derive(**changes) if changes else base
            if mass_ratio is not None:
                from twoball.modal.contact.report import ContactCase

                case = ContactCase(case, mass_ratio)
            out.append(case)
        return out


def make_grid(parameters: Sequence[str], values: Sequence[str]) -> SweepGrid:
    """Check ``param``/``values`` as the command line gives them and build the grid.

    One ``param`` gives a 1-D sweep, two give a grid; ``values`` must be given
    once per ``param``, in the same order, and the two parameters must differ.
    """
    parameters = list(parameters or [])
    values = list(values or [])
    if not 1 <= len(parameters) <= 2:
        raise ParameterError("param", "given once (1-D sweep) or twice (grid)", len(parameters))
    if len(values) != len(parameters):
        raise ParameterError(
            "values",
            f"given once per param ({len(parameters)} times here), in the same order",
            values,
        )
    if len(set(parameters)) != len(parameters):
        raise ParameterError("param", "two different parameters for a grid", parameters)
    for p in parameters:
        _check_parameter(p)
    arrays = tuple(parse_range(v) for v in values)
    return SweepGrid(tuple(parameters), arrays)


@dataclass(frozen=True)
class SweepSolver:
    """Picklable solve of one case: the closed-form lift-off with fixed model options."""

    sigma: str = "lanczos"
    recontact: str = "window"
    t_end_s: float | None = None
    #: the converged-series reference of the truncation guard (10 ms-1 s a point: off)
    reference: bool = False

    #: the upper body of finite mass (:class:`~twoball.modal.contact.body.Body`) on
    #: every point; a ``mass-ratio`` point replaces its mass ratio
    body: Any = None
    #: the contact core's step (units 1/c; None: its default) for a body of finite mass
    dt: float | None = None
    #: told what each point does (:class:`~twoball._common.monitor.Monitor`)
    monitor: Any = None

    def __call__(self, case: Case) -> LiftoffReport:
        if hasattr(case, "mass_ratio") or self.body is not None:
            from dataclasses import replace

            from twoball.modal.contact.cost import legendre_contact_work
            from twoball.modal.contact.report import legendre_contact

            body, plain = self.body, case
            if hasattr(case, "mass_ratio"):
                plain = case.case
                body = replace(body, mass_ratio=case.mass_ratio)
            check_all(legendre_contact_work(plain, body, self.t_end_s, reference=self.reference))
            return legendre_contact(
                plain,
                body,
                sigma=self.sigma,
                t_end_s=self.t_end_s,
                reference=self.reference,
                dt=self.dt,
                monitor=self.monitor,
            )
        check(*case_liftoff_work(case, self.t_end_s))
        return legendre_liftoff(
            case,
            self.sigma,
            self.recontact,
            self.t_end_s,
            reference=self.reference,
            monitor=self.monitor,
        )


@dataclass(frozen=True)
class SweepPoint:
    """One grid point: its index, case, and either a report or an error message."""

    index: tuple[int, ...]
    case: Case
    report: LiftoffReport | None
    error: str | None = None
    #: how phi_a was chosen over the whole sweep (:func:`phi_a_rule`), set by twoball.sweep
    phi_a_rule: str | None = None

    def __repr__(self) -> str:
        """The answer first, in SI (t_l [s], v_l [m/s], v_l/|v0|), then the point's case."""
        return (
            f"SweepPoint(index={self.index}, t_liftoff_s={self.t_liftoff_s!r}, "
            f"v_liftoff_m_s={self.v_liftoff_m_s!r}, ratio={self.ratio!r}, "
            f"error={self.error!r}, case={self.case!r})"
        )

    @property
    def ratio(self) -> float:
        """``v_l / |v0|``; NaN without lift-off or on error."""
        r = None if self.report is None else self.report.ratio
        return math.nan if r is None else r

    @property
    def t_liftoff_s(self) -> float:
        """Lift-off time [s]; NaN without lift-off or on error."""
        t = None if self.report is None else self.report.t_liftoff_s
        return math.nan if t is None else t

    @property
    def v_liftoff_m_s(self) -> float:
        """Lift-off velocity [m/s]; NaN without lift-off or on error."""
        v = None if self.report is None else self.report.v_liftoff_m_s
        return math.nan if v is None else v

    def as_dict(self) -> dict[str, Any]:
        """JSON-ready: the report's keys (or the case's, on error), ``index``, ``error`` and
        the sweep's ``phi_a_rule``."""
        if self.report is not None:
            data = self.report.as_dict()
        else:
            c = self.case
            data = {
                "lifted": None,
                "t_liftoff_s": None,
                "v_liftoff_m_s": None,
                "ratio": None,
                "phi_a_rad": c.phi_a,
                "phi_a_source": c.phi_a_source,
                "radius_m": c.radius,
                "wave_speed_1_s": c.wave_speed,
                "v0_m_s": c.v0,
                "damping": c.damping,
                "modes": c.modes,
            }
        data["index"] = list(self.index)
        data["error"] = self.error
        if self.phi_a_rule is not None:
            data["phi_a_rule"] = self.phi_a_rule
        return data


def run_sweep(
    cases: list[Case],
    solve: Callable[[Case], LiftoffReport],
    progress: Callable[[int], None] | None = None,
    runner: Runner | None = None,
    indices: list[tuple[int, ...]] | None = None,
) -> list[SweepPoint]:
    """Solve every case; points come back in input order whatever ran them.

    Parameters
    ----------
    cases : list of Case
        The points.
    solve : callable
        Case -> LiftoffReport; picklable (e.g. :class:`SweepSolver`) for parallel runs.
    progress : callable, optional
        Called with the number of points done.
    runner : Runner, optional
        Where to run (default: serially in this process).
    indices : list of tuple, optional
        Grid index of each case (default ``(k,)``).
    """
    if indices is None:
        indices = [(k,) for k in range(len(cases))]
    if runner is None:
        with Runner(workers=1) as serial:
            outcomes = serial.map(solve, cases, progress)
    else:
        outcomes = runner.map(solve, cases, progress)
    return [
        SweepPoint(index, case, o.value if o.ok else None, o.error)
        for index, case, o in zip(indices, cases, outcomes, strict=True)
    ]
