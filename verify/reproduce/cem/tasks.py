"""Picklable tasks of the continuum-model reproduction and how they are run.

The lift-off criteria compared in Fig. 11(a) and the §5 thresholds
(:data:`CRITERIA`), the bisection of a no-lift-off boundary
(:class:`ThresholdTask`), and :func:`run_tasks`, which maps a list of tasks
through the context's runner: serially, on local processes or on Dask, with
the same numbers.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

from twoball.modal.parameters import Case
from twoball.verify.reproduce.common import (
    Context,
    Threshold,
    acceleration_minima,
    find_threshold,
    liftoff,
)
from twoball.verify.sweeps.parallel import Outcome

CRITERIA: dict[str, str] = {
    "overall": "criterion (i) alone: min u_tt(t, 0) over the whole window (t = 0 included) < -g",
    "moving_up": "criterion (i) while the pole moves up: min u_tt where u_t > 0 < -g",
    "main_wave": "criterion (i) on the main wave: min u_tt for t >= 5 ms < -g",
    "paper": "criteria (i) + (ii), re-contact checked for dt < t_l (`paper` horizon)",
    "window": "criteria (i) + (ii), re-contact checked to the window's end (`window`, default)",
}


@dataclass(frozen=True)
class CriterionTest:
    """Picklable yes/no: does ``case`` lift off under ``criterion`` (see CRITERIA)?"""

    criterion: str
    sigma: str = "lanczos"

    def __call__(self, case: Case) -> bool:
        if self.criterion in ("paper", "window"):
            return liftoff(case, self.criterion, self.sigma).result.lifted
        minima = acceleration_minima(case, self.sigma)
        value = getattr(minima, self.criterion)
        return value is not None and value < -case.g


@dataclass(frozen=True)
class ThresholdTask:
    """Picklable bisection of the no-lift-off boundary of one parameter (Case field)."""

    base: Case
    field: str
    criterion: str
    lo: float
    hi: float
    log: bool
    lifts_above: bool
    scan_points: int = 21
    rtol: float = 1e-5
    sigma: str = "lanczos"

    def __call__(self) -> Threshold:
        test = CriterionTest(self.criterion, self.sigma)
        return find_threshold(
            lambda x: test(self.base.derive(**{self.field: x})),
            self.lo,
            self.hi,
            lifts_above=self.lifts_above,
            log=self.log,
            scan_points=self.scan_points,
            rtol=self.rtol,
        )


def call(task: Any) -> Any:
    """Run a picklable zero-argument task (for Runner.map)."""
    return task()


def minima_task(case: Case):
    """Acceleration minima of one case (for Runner.map)."""
    return acceleration_minima(case)


def outcome_value(outcome: Outcome) -> Any:
    """The task's value, or None if it failed."""
    return outcome.value if outcome.ok else None


def run_tasks(ctx: Context, label: str, func, items, heavy: bool = False) -> list[Outcome]:
    """Map through the context's runner; ``heavy`` tasks (bisections) go one per message."""
    update = ctx.progress(label, len(items))
    if heavy:
        return ctx.runner.map(func, items, update, min_parallel=2, chunk=1)
    return ctx.runner.map(func, items, update)


def threshold_text(t: Threshold | None, digits: int) -> str:
    """A threshold in words: its value, or why there is none, and its caveats."""
    if t is None:
        return "error"
    if t.value is None:
        return "no change in range"
    text = f"{t.value:.{digits}g}"
    if len(t.transitions) > 1:
        text += f" ({len(t.transitions)} changes on the scan)"
    if t.errors:
        text += f" ({len(t.errors)} failed evaluations)"
    return text
