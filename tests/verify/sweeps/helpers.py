"""A sweep's cases and a picklable solver that fails above a limit (process pools)."""

from __future__ import annotations

import numpy as np

from twoball._common.errors import NumericalError
from twoball.modal.parameters import Case, preset
from twoball.verify.sweeps.sweeps import SweepSolver, sweep_cases


def cases(count=40):
    return sweep_cases(preset("basketball"), "v0", np.linspace(1.0, 12.0, count))


class FailAbove:
    """Picklable solver that raises a NumericalError for v0 above a limit."""

    def __init__(self, limit):
        self.limit = limit
        self.solve = SweepSolver()

    def __call__(self, case: Case):
        if case.v0 > self.limit:
            raise NumericalError(f"refusing v0 = {case.v0:g}")
        return self.solve(case)
