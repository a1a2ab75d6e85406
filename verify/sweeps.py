"""One-parameter sweeps of the closed-form lift-off (Fig. 11(b), Fig. 12)."""

from __future__ import annotations

from collections.abc import Callable, Iterable

import numpy as np

from modal.errors import ParameterError
from modal.parameters import Case
from modal.report import LiftoffReport

# CLI name -> Case field; v0, c and R re-derive phi_a from eq. (3.7) (Case.derive).
SWEEP_PARAMETERS: dict[str, str] = {
    "damping": "damping",
    "v0": "v0",
    "wave-speed": "wave_speed",
    "radius": "radius",
    "modes": "modes",
}


def parse_range(text: str, name: str = "--values") -> np.ndarray:
    """``START:STOP:COUNT`` -> ``COUNT`` evenly spaced values from START to STOP inclusive."""
    parts = text.split(":")
    valid = "START:STOP:COUNT (numbers, COUNT an integer >= 1)"
    if len(parts) != 3:
        raise ParameterError(name, valid, text)
    try:
        start, stop = float(parts[0]), float(parts[1])
        count = int(parts[2])
    except ValueError:
        raise ParameterError(name, valid, text) from None
    if count < 1 or not (np.isfinite(start) and np.isfinite(stop)):
        raise ParameterError(name, valid, text)
    if count == 1 and start != stop:
        raise ParameterError(name, valid + " (COUNT 1 needs START = STOP)", text)
    return np.linspace(start, stop, count)


def sweep_cases(base: Case, parameter: str, values: Iterable[float]) -> list[Case]:
    """The cases of a sweep: ``base`` with one parameter varied (phi_a per eq. (3.7))."""
    if parameter not in SWEEP_PARAMETERS:
        raise ParameterError("--param", "one of " + ", ".join(SWEEP_PARAMETERS), parameter)
    field = SWEEP_PARAMETERS[parameter]
    cases = []
    for value in values:
        if field == "modes":
            if float(value) != round(float(value)):
                raise ParameterError("--values", "whole numbers for --param modes", value)
            value = int(round(float(value)))
        cases.append(base.derive(**{field: value}))
    return cases


def run_sweep(
    cases: list[Case],
    solve: Callable[[Case], LiftoffReport],
    progress: Callable[[int], None] | None = None,
) -> list[LiftoffReport]:
    """Solve every case in order; ``progress(k)`` is called after each."""
    reports = []
    for k, case in enumerate(cases):
        reports.append(solve(case))
        if progress is not None:
            progress(k + 1)
    return reports
