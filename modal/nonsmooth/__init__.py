"""Nonsmooth time integration of linear elastodynamics with unilateral constraints.

One contact core for every backend (Legendre modes, finite elements, the bar
benchmark): :class:`ContactProblem` bundles ``M q'' + C q' + K q = f + G^T
lambda`` with ``G q + g0 >= 0``, and :class:`MoreauJean` integrates it.
Dimensionless throughout (the units of the matrices given).
"""

from .lcp import LCPSolution, solve_lcp
from .moreau_jean import ContactEvent, MoreauJean, StepperState, StepRecord, Trajectory
from .problem import ContactProblem

__all__ = [
    "ContactEvent",
    "ContactProblem",
    "LCPSolution",
    "MoreauJean",
    "StepRecord",
    "StepperState",
    "Trajectory",
    "solve_lcp",
]
