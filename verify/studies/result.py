"""What every convergence study returns: :class:`StudyResult`, its settings and run rows.

Shared by the studies of :mod:`~twoball.verify.studies.modes`,
:mod:`~twoball.verify.studies.refinement` and :mod:`~twoball.verify.studies.time_step`;
the values are dimensionless (length R, time 1/c) and the run rows SI.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

from twoball._common.choices import STUDIES
from twoball._common.progress import (
    Step as Progress,  # the one progress mechanism (twoball._common.progress)
)
from twoball._common.progress import silent as quiet
from twoball.modal.parameters import Case
from twoball.verify.studies.quantities import QuantityResult

__all__ = ["STUDIES", "Progress", "StudyResult", "case_settings", "quiet", "si", "time_step_text"]


def si(value: float | None, scale: float) -> float | None:
    """``value * scale`` (a dimensionless value in SI), None kept."""
    return None if value is None else value * scale


def time_step_text(dt: float, time_unit_s: float) -> str:
    """A time step as the user types it: ``dt = 7.8125e-06 s (c dt = 0.0025)``.

    ``dt`` is dimensionless (unit 1/c, ``time_unit_s`` seconds): the seconds
    come first, as ``dt`` takes them, the dimensionless ``c dt`` beside them.
    """
    return f"dt = {dt * time_unit_s:.6g} s (c dt = {dt:g})"


@dataclass
class StudyResult:
    """A finished convergence study: its quantities, notes and timings.

    Attributes
    ----------
    study : str
        ``h``, ``order``, ``modes`` or ``dt``.
    title : str
        One line describing the discretisations.
    step_name : str
        What the step size h is (``h = sqrt(4 pi / triangles)``, ``1/N``, ...).
    quantities : list of QuantityResult
    notes : list of str
        Statements for the reader (e.g. the truncation error of N = 30).
    runs : list of dict
        One row per discretisation: label, DOFs, t_l, v_l, seconds (SI).
    settings : dict
        The case and options used.
    provenance : dict, optional
        Versions, command line or call, UTC time, case (:mod:`twoball._common.provenance`).
    """

    study: str
    title: str
    step_name: str
    quantities: list[QuantityResult] = field(default_factory=list)
    notes: list[str] = field(default_factory=list)
    runs: list[dict[str, Any]] = field(default_factory=list)
    settings: dict[str, Any] = field(default_factory=dict)
    seconds: float = 0.0
    provenance: dict[str, Any] | None = None
    #: inputs far from any ball (:func:`twoball.modal.guards.case_warnings`)
    warnings: list[str] = field(default_factory=list)

    @property
    def passed(self) -> bool:
        """True when every quantity with a band observed an order inside it."""
        return all(q.passed is not False for q in self.quantities)

    def as_dict(self) -> dict[str, Any]:
        """JSON-ready dictionary of the whole study."""
        return {
            "study": self.study,
            "title": self.title,
            "step": self.step_name,
            "passed": self.passed,
            "seconds": self.seconds,
            "settings": self.settings,
            "notes": self.notes,
            "warnings": self.warnings,
            "runs": self.runs,
            "quantities": [q.as_dict() for q in self.quantities],
            "provenance": self.provenance,
        }


def case_settings(case: Case, sigma: str, recontact: str, t_end: float) -> dict[str, Any]:
    """The case (:meth:`twoball.Case.as_dict`) and the model options, JSON-ready (SI)."""
    return {
        **case.as_dict(),
        "gamma": case.gamma,
        "sigma": sigma,
        "recontact": recontact,
        "t_end_s": t_end * case.scalings.time,
    }
