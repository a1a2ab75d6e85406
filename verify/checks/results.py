"""Results of ``twoball verify``: PASS/FAIL checks, rows of the run table, the whole result.

The rows are SI (keys end in their unit); relative differences compare a
run's lift-off with the Legendre series with the case's N and with its
converged limit.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from twoball.modal.converged import ConvergedReference
from twoball.modal.parameters import Case
from twoball.verify.checks.config import VerifyConfig
from twoball.verify.output.figures.eigen import EigenErrors
from twoball.verify.output.figures.pole import Trace
from twoball.verify.studies.reference import LegendreRun
from twoball.verify.studies.result import si


@dataclass(frozen=True)
class Check:
    """One PASS/FAIL check: a measured value against a tolerance.

    ``value <= tolerance`` passes (for order checks: ``value`` inside ``band``).
    """

    name: str
    description: str
    value: float | None
    tolerance: float | None
    passed: bool
    band: tuple[float, float] | None = None

    def as_dict(self) -> dict[str, Any]:
        """JSON-ready dictionary."""
        return {
            "name": self.name,
            "description": self.description,
            "value": self.value,
            "tolerance": self.tolerance,
            "band": None if self.band is None else list(self.band),
            "passed": self.passed,
        }

    @property
    def verdict(self) -> str:
        """``PASS`` or ``FAIL``."""
        return "PASS" if self.passed else "FAIL"


def bounded(name: str, description: str, value: float | None, tolerance: float) -> Check:
    """A check that passes when ``value`` is finite and at most ``tolerance``."""
    ok = value is not None and math.isfinite(value) and value <= tolerance
    return Check(name, description, value, tolerance, bool(ok))


@dataclass
class RunRow:
    """One row of the run table (SI)."""

    backend: str
    mesh: str
    dofs: int
    t_l_s: float | None
    v_l_m_s: float | None
    ratio: float | None
    t_diff: float | None  # relative to the Legendre series with the case's N
    v_diff: float | None
    t_diff_converged: float | None  # relative to the converged Legendre limit
    v_diff_converged: float | None
    seconds: float
    details: dict[str, Any] = field(default_factory=dict)

    def as_dict(self) -> dict[str, Any]:
        """JSON-ready dictionary (keys end in their unit)."""
        return {
            "backend": self.backend,
            "mesh": self.mesh,
            "dofs": self.dofs,
            "t_liftoff_s": self.t_l_s,
            "v_liftoff_m_s": self.v_l_m_s,
            "ratio": self.ratio,
            "t_rel_diff": self.t_diff,
            "v_rel_diff": self.v_diff,
            "t_rel_diff_converged": self.t_diff_converged,
            "v_rel_diff_converged": self.v_diff_converged,
            "seconds": self.seconds,
            **self.details,
        }


RUN_COLUMNS = (
    "backend",
    "mesh",
    "dofs",
    "t_liftoff_s",
    "v_liftoff_m_s",
    "ratio",
    "t_rel_diff",
    "v_rel_diff",
    "t_rel_diff_converged",
    "v_rel_diff_converged",
    "seconds",
)


@dataclass
class VerifyResult:
    """Everything ``verify`` found, ready for the table, the files and the plots."""

    case: Case
    config: VerifyConfig
    settings: dict[str, Any]
    rows: list[RunRow]
    checks: list[Check]
    traces: list[Trace]
    eigen: list[EigenErrors]
    energy_curves: list[tuple[str, np.ndarray, np.ndarray]]
    energy_bound: tuple[np.ndarray, np.ndarray] | None
    reference: ConvergedReference
    seconds: float = 0.0
    notes: list[str] = field(default_factory=list)
    provenance: dict[str, Any] | None = None  # set by twoball.verify (twoball._common.provenance)
    #: inputs far from any ball (:func:`twoball.modal.guards.case_warnings`)
    warnings: list[str] = field(default_factory=list)

    @property
    def passed(self) -> bool:
        """True when every check passed."""
        return all(c.passed for c in self.checks)

    def as_dict(self) -> dict[str, Any]:
        """JSON-ready dictionary of the whole verification."""
        return {
            "passed": self.passed,
            "configuration": self.config.name,
            "seconds": self.seconds,
            "settings": self.settings,
            "runs": [r.as_dict() for r in self.rows],
            "checks": [c.as_dict() for c in self.checks],
            "eigenvalue_errors": [
                {"label": e.label, "l": e.degrees.tolist(), "relative_error": e.errors.tolist()}
                for e in self.eigen
            ],
            "notes": self.notes,
            "warnings": self.warnings,
            "provenance": self.provenance,
        }


def relative_difference(value: float | None, reference: float | None) -> float | None:
    """``(value - reference) / reference``, or None if either is missing or the reference is 0."""
    if value is None or reference is None or reference == 0:
        return None
    return (value - reference) / reference


def run_row(
    case: Case,
    backend: str,
    mesh: str,
    dofs: int,
    t: float | None,
    v: float | None,
    seconds: float,
    reference: LegendreRun,
    limit: ConvergedReference,
    details: dict[str, Any] | None = None,
) -> RunRow:
    """One row of the run table: lift-off ``t``, ``v`` (dimensionless) in SI, with its
    differences to the Legendre series with the case's N and to the converged limit."""
    scale = case.scalings
    v_si = si(v, scale.velocity)
    return RunRow(
        backend,
        mesh,
        dofs,
        si(t, scale.time),
        v_si,
        None if v_si is None else v_si / case.v0,
        relative_difference(t, reference.t),
        relative_difference(v, reference.velocity),
        relative_difference(t, limit.t),
        relative_difference(v, limit.velocity),
        seconds,
        dict(details or {}),
    )


def liftoff_gap(
    t: float | None, v: float | None, ref_t: float | None, ref_v: float | None
) -> float | None:
    """``max(|dt|/t, |dv|/v)``, or None if either did not lift off."""
    dt, dv = relative_difference(t, ref_t), relative_difference(v, ref_v)
    if dt is None or dv is None:
        return None
    return max(abs(dt), abs(dv))


def format_rows(rows: Sequence[RunRow]) -> list[list[Any]]:
    """The run table as lists in the order of ``RUN_COLUMNS``."""
    return [[r.as_dict()[c] for c in RUN_COLUMNS] for r in rows]
