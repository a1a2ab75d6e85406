"""Cost model of a drop on the floor: memory and time before it runs.

Calibration (wall time on the 2-core build machine with other jobs running;
meant to be right within a factor of 2-3, which is all a refusal needs): the
basketball at 4.1 m/s with N = 64 / 128 Legendre modes takes ~0.6 / 1.4 s for
~560 / 890 steps, about 1 ms per step in contact (localised touches included)
and ~0.1 ms per free step.  The worst case is a window without leaving the
floor: every step in contact.  Memory: the states and impulses of every step
(``16 n + 16 m`` bytes per step), the constraint matrices and, for finite
elements, the dense eigenproblem (``~5 n^2`` doubles).
"""

from __future__ import annotations

from twoball._common.budget import BASE_MEMORY, Estimate, check, options

__all__ = ["check_drop", "drop_estimate"]

SECONDS_PER_STEP = 1e-3  # a step in contact with its LCP and localisations
SECONDS_PER_ENTRY = 2e-9  # per entry of the constraint matrix G, per step


def drop_estimate(dofs: int, points: int, steps: float, dense: bool = False) -> Estimate:
    """A drop with ``dofs`` coordinates, ``points`` floor points and up to ``steps`` steps."""
    per_step = 8.0 * (2.0 * dofs + 2.0 * points)
    matrices = 8.0 * points * dofs * 3.0 + (40.0 * dofs * dofs if dense else 0.0)
    memory = BASE_MEMORY + matrices + per_step * steps
    seconds = steps * (SECONDS_PER_STEP + SECONDS_PER_ENTRY * points * dofs)
    seconds += (1e-8 * dofs**3) if dense else 0.0
    return Estimate(memory, seconds)


def check_drop(
    dofs: int, points: int, window: float, step: float, dense: bool = False, **asked: object
) -> Estimate:
    """Refuse a drop (window and step in units of 1/c) that cannot fit the budget.

    ``asked`` names the work as the user asked for it (``modes=128``, ``dt=1e-5``).
    """
    steps = window / step + 4.0 * points  # regular steps plus localised touches
    return check(options(**asked), drop_estimate(dofs, points, steps, dense))
