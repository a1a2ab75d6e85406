"""Cost model of a drop on the floor: memory and time before it runs.

A drop usually ends soon after its contact (the ball is seen to leave, see
:mod:`twoball.modal.floor.drop`): its steps are those of the *expected span*
(twice the pressure x area contact time ``pi / c``, three times with a body on
top, plus the gap's fall) rather than of the whole window, plus the shortened
steps of its localised touches.  A run that goes on (a ball that does not leave,
a long window) meets the deadline of the time limit in its step loop (its
monitor, exit 3), so the estimate may be the likely cost rather than the worst.
The estimate only estimates; ``twoball.bounce`` refuses at the edge.

Steps
    ``span / dt + points (1 + 8 v0^2)`` (``v0 = |v0| / (R c)``): floor points
    touch and leave about once each at the basketball's 4.1 m/s (v0 = 0.11), and
    rattle in proportion to ``v0^2`` at higher speeds (measured N = 192: 51, 106,
    1448, 5843 and 13935 point events at 4.1, 14, 44, 77 and 140 m/s; 1127 to
    6757 steps).  Beyond :data:`RATTLE_SPEED` (140 m/s for the basketball) the
    ball leaves sooner and rattles less (measured N = 192: 1627, 764 and 758
    steps at 300, 1000 and 4100 m/s, a unit slip's speeds), so the term stays
    at its value there.
Seconds per step
    :data:`SECONDS_PER_STEP` plus :data:`SECONDS_PER_ENTRY` per entry of the
    constraint matrix G (points x unknowns): each step and each localisation
    multiplies by G several times.  The step loop runs with one BLAS thread
    (:func:`~twoball.modal.floor.drop.run_drop`).
Dense eigenpairs (finite elements)
    ``4e-9 n^3`` s for n unknowns (measured 8 s at n = 1200 on the loaded
    machine) and ``~5 n^2`` doubles.
Memory
    The states and impulses of every step of the whole window (``16 n + 16 m``
    bytes per step), the constraint matrices and the dense eigenproblem.

Calibration, wall time of the whole ``twoball.bounce`` on the 2-core build
machine with other jobs running (load 2-2.3) against this estimate (0.5 to 1.9 times):

================================  ======  ========  =========
case                              steps   measured  estimate
================================  ======  ========  =========
Legendre N = 192, 4.1 m/s          1129     1.1 s     1.0 s
Legendre N = 192, 140 m/s          6757    14.5 s     8.4 s
axisym P2, 96 elements             1199     1.2 s     1.0 s
axisym P3, 64 elements             1220     1.2 s     1.0 s
axisym P4, 48 elements             1311     1.3 s     1.0 s
axisym P4, 200 elements            2045     5.9 s     6.9 s
axisym P2, 400 elements            1564     6.4 s     6.9 s
axisym P3, 400 elements            1678     9.5 s    17.7 s
axisym P3, 400 elements, mu 0.1    2023    19.3 s    35.6 s
axisym P3, 64 elements, tennis-coin 1748    3.2 s     1.5 s
================================  ======  ========  =========

(with a body that is not a Table 1 pair the ball alone is dropped once more
for the lumped baselines' e2: two drops).  Meant to be right within a factor
of 2-3, which is all a refusal needs; ``benchmarks/bench_bounce.py`` times the
defaults.
"""

from __future__ import annotations

import math

from twoball._common.estimate import BASE_MEMORY, Estimate

__all__ = ["drop_estimate", "drop_steps", "expected_span", "likely_drop"]

SECONDS_PER_STEP = 6e-4  # a step with its LCP and stop test, localisations included
SECONDS_PER_ENTRY = 7e-9  # per entry of the constraint matrix G, per step
SECONDS_PER_CUBE = 4e-9  # dense eigenpairs of n unknowns: this times n^3
#: Point events per floor point per (dimensionless |v0|)^2 beyond the first touch.
RATTLE = 8.0
#: Dimensionless |v0| beyond which the rattle no longer grows (measured, see above).
RATTLE_SPEED = 4.0


def expected_span(body: bool = False, gap: float = 0.0, v0: float = 1.0) -> float:
    """Expected length of a drop [1/c]: 2 pi (3 pi with a body), plus the gap's fall twice."""
    return (3.0 if body else 2.0) * math.pi + 2.0 * gap / v0


def drop_steps(points: int, span: float, step: float, v0: float) -> float:
    """Steps of a drop over ``span`` at ``step`` with ``points`` floor points, ``|v0|`` = v0."""
    rattle = min(abs(v0), RATTLE_SPEED)
    return span / step + points * (1.0 + RATTLE * rattle * rattle)


def drop_estimate(
    dofs: int,
    points: int,
    steps: float,
    dense: bool = False,
    *,
    stored: float | None = None,
    runs: int = 1,
) -> Estimate:
    """A drop with ``dofs`` coordinates, ``points`` floor points and about ``steps`` steps.

    ``stored``: the steps whose states may be kept (memory; default ``steps``);
    ``runs``: drops of the same ball one after the other (the eigenpairs once).
    """
    stored = steps if stored is None else stored
    per_step = 8.0 * (2.0 * dofs + 2.0 * points)
    matrices = 8.0 * points * dofs * 3.0 + (40.0 * dofs * dofs if dense else 0.0)
    memory = BASE_MEMORY + matrices + per_step * stored
    seconds = runs * steps * (SECONDS_PER_STEP + SECONDS_PER_ENTRY * points * dofs)
    seconds += (SECONDS_PER_CUBE * dofs**3) if dense else 0.0
    return Estimate(memory, seconds)


def likely_drop(
    dofs: int,
    points: int,
    window: float,
    step: float,
    dense: bool = False,
    *,
    span: float | None = None,
    v0: float = 0.0,
    runs: int = 1,
) -> Estimate:
    """A drop's likely cost (window, span and step in units of 1/c).

    ``span`` is the expected length of the run (:func:`expected_span`; default the
    whole window), ``v0`` the dimensionless impact speed, ``runs`` the number of
    drops; the states of the whole window count for the memory.
    """
    likely = window if span is None else min(window, span)
    steps = drop_steps(points, likely, step, v0)
    stored = drop_steps(points, window, step, v0)
    return drop_estimate(dofs, points, steps, dense, stored=stored, runs=runs)
