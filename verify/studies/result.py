"""What every convergence study returns: :class:`StudyResult`, its settings and run rows.

Shared by the studies of :mod:`~twoball.verify.studies.modes`,
:mod:`~twoball.verify.studies.refinement` and :mod:`~twoball.verify.studies.time_step`;
the values are dimensionless (length R, time 1/c) and the run rows SI.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any

from twoball.modal.parameters import Case

from .quantities import QuantityResult

STUDIES: tuple[str, ...] = ("h", "order", "modes", "dt")
Progress = Callable[[str], None]


def quiet(_: str) -> None:
    """A :data:`Progress` that says nothing."""
    return None


def si(value: float | None, scale: float) -> float | None:
    """``value * scale`` (a dimensionless value in SI), None kept."""
    return None if value is None else value * scale


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
    """

    study: str
    title: str
    step_name: str
    quantities: list[QuantityResult] = field(default_factory=list)
    notes: list[str] = field(default_factory=list)
    runs: list[dict[str, Any]] = field(default_factory=list)
    settings: dict[str, Any] = field(default_factory=dict)
    seconds: float = 0.0

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
            "runs": self.runs,
            "quantities": [q.as_dict() for q in self.quantities],
        }


def case_settings(case: Case, sigma: str, recontact: str, t_end: float) -> dict[str, Any]:
    """The case and model options as a JSON-ready dictionary (SI)."""
    return {
        "radius_m": case.radius,
        "wave_speed_1_s": case.wave_speed,
        "v0_m_s": case.v0,
        "phi_a_rad": case.phi_a,
        "phi_a_source": case.phi_a_source,
        "damping": case.damping,
        "modes": case.modes,
        "g_m_s2": case.g,
        "gamma": case.gamma,
        "sigma": sigma,
        "recontact": recontact,
        "t_end_s": t_end * case.scalings.time,
    }
