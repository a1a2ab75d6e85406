"""An elastic body dropped alone on a rigid floor: its inputs give back its restitution.

The check of a body's inputs (the issue's "consistency of inputs"): the same
body that rides the whole bounce, dropped alone on a rigid floor at the speed
of interest, must return the restitution it was given and the contact time its
law implies.

A lumped body (:func:`lumped_alone`)
    One coordinate, the height x of its lowest point, and its compliant row
    ``g = x`` with its law (C1) on the same integrator as the whole bounce
    (:class:`~twoball.modal.nonsmooth.compliant.CompliantMoreauJean`), in units
    of its own undamped peak compression and contact time.  The contact ends
    where the force ``f(delta) + c(delta) delta'`` vanishes, located between
    the step ends by linear interpolation; the rebound is the velocity there
    (free flight back from the next step end).
A ball body (:func:`ball_alone`)
    The body's ball dropped as the lower ball of ``twoball bounce``
    (:func:`~twoball.modal.floor.bounce.simulate`), at its own default step.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from twoball._common.errors import NumericalError, ParameterError
from twoball._common.keywords import checked
from twoball.modal.nonsmooth import ContactProblem
from twoball.modal.nonsmooth.compliant import CompliantMoreauJean, CompliantRow
from twoball.modal.upper.options import BallBody, LumpedBody

__all__ = ["AloneResult", "ball_alone", "lumped_alone"]


@checked
@dataclass(frozen=True)
class AloneResult:
    """A body dropped alone on a rigid floor (SI).

    Attributes
    ----------
    kind : {"lumped", "ball"}
    mass : float
        Its mass [kg].
    speed : float
        Impact speed [m/s].
    restitution : float
        Rebound over impact speed, measured.
    contact_time : float
        First touch to separation [s], measured.
    stated_restitution : float
        The restitution it was given (a ball body: its preset's target, or None).
    stated_contact_time : float or None
        Its law's contact time [s] (computed: the damped law's closed form or
        reduced integral); None for a ball body.
    undamped_contact_time : float or None
        The law's undamped closed form [s] (pi sqrt(m/k); Hertz's 2.87 law).
    peak_force : float
        Largest force [N] (step means).
    peak_compression : float or None
        Largest compression [m] (lumped).
    energy : dict
        ``initial`` (kinetic), ``final_kinetic``, ``stored`` (left at the end),
        ``dissipated`` (the body's own), ``balance`` (the books' largest error),
        all [J].
    steps : int
    provenance : dict, optional
        Versions, command line or call, UTC time and the lower ball's case.

    Examples
    --------
    >>> import twoball
    >>> alone = twoball.floor_alone(pair="tennis-table-tennis")
    >>> alone.kind, round(alone.restitution, 3), alone.stated_restitution > 0.9
    ('lumped', 0.905, True)
    """

    kind: str
    mass: float
    speed: float
    restitution: float
    contact_time: float
    stated_restitution: float | None
    stated_contact_time: float | None
    undamped_contact_time: float | None
    peak_force: float
    peak_compression: float | None
    energy: dict[str, float] = field(default_factory=dict)
    steps: int = 0
    provenance: dict[str, Any] | None = field(default=None, compare=False, repr=False)

    def __post_init__(self) -> None:
        if self.kind not in ("lumped", "ball"):
            raise ParameterError("kind", "lumped or ball", self.kind)

    def as_dict(self) -> dict[str, Any]:
        """JSON-ready (SI; keys end in their unit)."""
        return {
            "kind": self.kind,
            "mass_kg": self.mass,
            "v0_m_s": self.speed,
            "restitution": self.restitution,
            "stated_restitution": self.stated_restitution,
            "contact_time_s": self.contact_time,
            "stated_contact_time_s": self.stated_contact_time,
            "undamped_contact_time_s": self.undamped_contact_time,
            "peak_force_N": self.peak_force,
            "peak_compression_m": self.peak_compression,
            "energy_J": dict(self.energy),
            "steps": self.steps,
        } | ({} if self.provenance is None else {"provenance": self.provenance})


def lumped_alone(
    body: LumpedBody, mass: float, speed: float, g: float = 9.81, steps: int | None = None
) -> AloneResult:
    """Drop a lumped body of ``mass`` [kg] at ``speed`` [m/s] on a rigid floor (module doc).

    Parameters
    ----------
    body : LumpedBody
    mass : float
        m1 [kg] (a pair's ``mu m2``).
    speed : float
        Impact speed [m/s].
    g : float
        Gravity [m/s^2] (acts through the contact too).
    steps : int, optional
        Steps per contact time (default the body's :attr:`~LumpedBody.steps`).
    """
    if not isinstance(body, LumpedBody):
        raise ParameterError("body", "a twoball.LumpedBody", type(body).__name__)
    law = body.law
    m = float(mass)
    v = float(speed)
    if not (m > 0.0 and v > 0.0 and g >= 0.0):
        raise ParameterError("speed", "a mass, speed > 0 and g >= 0", (mass, speed, g))
    length = law.peak_compression(m, v)
    time = law.contact_time(m, v)
    core = law.power_law(m).scaled(length, time, m)
    gamma = g * time * time / length
    n = body.steps if steps is None else int(steps)
    problem = ContactProblem.create(
        np.array([1.0]), None, np.array([0.0]), np.array([-gamma]), np.ones((1, 1)), np.zeros(1)
    )
    h = 1.0 / n
    stepper = CompliantMoreauJean(problem, h, [CompliantRow(0, core, h)])
    u = v * time / length
    state = {"seen": False}

    def stop(s: Any, record: Any) -> bool:
        if record.step_impulse[0] > 0.0:
            state["seen"] = True
            return False
        return bool(state["seen"] and s.v[0] > 0.0 and s.q[0] > 0.0)

    tr = stepper.run(np.zeros(1), np.array([-u]), 4.0, stop=stop, keep_states=True)
    books = stepper.final_books()
    delta = -tr.q[:, 0]
    rate = -tr.v[:, 0]
    if not np.any(tr.impulse[:, 0] > 0.0):
        raise NumericalError("the body never pressed on the floor")
    t_end, k = _separation(core, tr.t, delta, rate)
    k = max(k, int(np.flatnonzero(tr.impulse[:, 0] > 0.0)[-1]) + 1)  # after the scheme's force
    t_start = float(tr.t[0])
    rebound = float(tr.v[k, 0] + gamma * (tr.t[k] - t_end))
    force_unit = m * length / time**2
    energy_unit = m * length * length / time**2
    energy = tr.energy + books["stored"] + books["dissipated"]
    works = tr.damping_work + tr.contact_work - books["work"] + tr.impact_work
    return AloneResult(
        kind="lumped",
        mass=m,
        speed=v,
        restitution=rebound / u,
        contact_time=(t_end - t_start) * time,
        stated_restitution=law.restitution,
        stated_contact_time=time,
        undamped_contact_time=law.undamped_contact_time(m, v),
        peak_force=float(books["force"][:, 0].max()) * force_unit,
        peak_compression=float(delta.max()) * length,
        energy={
            "initial": 0.5 * u * u * energy_unit,
            "final_kinetic": float(tr.kinetic[-1]) * energy_unit,
            "stored": float(books["stored"][-1]) * energy_unit,
            "dissipated": float(books["dissipated"][-1]) * energy_unit,
            "balance": float(np.max(np.abs(energy - energy[0] - works))) * energy_unit,
        },
        steps=tr.steps,
    )


def _separation(law: Any, t: np.ndarray, delta: np.ndarray, rate: np.ndarray) -> tuple[float, int]:
    """When the force ``f(delta) + c(delta) delta'`` ends, and the step end after it.

    In the step after the last step end with a compression and a force, the
    compression is the cubic through the values and rates at both ends; the
    contact ends at the first zero of the force on it, or of the compression
    (Brent's method on the cubic).
    """
    from scipy.optimize import brentq

    def force(d: float, r: float) -> float:
        return law.force(d) + law.dashpot(d) * r if d > 0.0 else -1.0

    pressing = [j for j in range(t.size) if delta[j] > 0.0 and force(delta[j], rate[j]) > 0.0]
    if not pressing or pressing[-1] + 1 >= t.size:
        raise NumericalError("the body's contact did not end within the window")
    j = pressing[-1]
    h = float(t[j + 1] - t[j])
    d0, d1, r0, r1 = float(delta[j]), float(delta[j + 1]), h * rate[j], h * rate[j + 1]

    def cubic(s: float) -> tuple[float, float]:
        a = 2 * d0 - 2 * d1 + r0 + r1
        b = -3 * d0 + 3 * d1 - 2 * r0 - r1
        value = ((a * s + b) * s + r0) * s + d0
        slope = (3 * a * s + 2 * b) * s + r0
        return value, slope / h

    end = 1.0
    if d1 <= 0.0:  # the compression ends in the step
        end = brentq(lambda s: cubic(s)[0], 0.0, 1.0, xtol=1e-15)

    def pushing(s: float) -> float:
        value, slope = cubic(s)
        return law.force(value) + law.dashpot(value) * slope if value > 0.0 else 0.0

    inside = end * (1.0 - 1e-12)
    if pushing(inside) < 0.0:  # the dashpot ends it first, still compressed
        end = brentq(pushing, 0.0, inside, xtol=1e-15)
    return float(t[j] + end * h), j + 1


def ball_alone(
    body: BallBody, speed: float, dt: float | None = None, target: float | None = None
) -> tuple[AloneResult, Any]:
    """Drop a ball body's ball alone on a rigid floor at ``speed`` [m/s] (SI).

    Returns the result and the full :class:`~twoball.modal.floor.report.BounceReport`.
    ``dt`` [s] (default the drop's 0.005 / c1); ``target``: the restitution it
    was set to give (a preset's), reported as stated.
    """
    from twoball.modal.floor.bounce import bounce_problem, simulate

    if not isinstance(body, BallBody):
        raise ParameterError("body", "a twoball.BallBody", type(body).__name__)
    case = body.case.derive(v0=float(speed))
    problem = bounce_problem(case, ball=body.ball, damping=body.damping, dt=dt)
    report = simulate(problem)
    if report.e2 is None or report.contact_time_s is None:
        raise NumericalError("the ball body did not leave the floor within the window")
    tr = report.result.trajectory
    h = np.diff(tr.t)
    force = tr.impulse[:, report.result.system.floor].sum(axis=1) - tr.impact_impulse[
        :, report.result.system.floor
    ].sum(axis=1)
    unit = report.mass_kg * report.case.radius * report.case.wave_speed**2
    books = report.energy_J
    result = AloneResult(
        kind="ball",
        mass=report.mass_kg,
        speed=case.v0,
        restitution=float(report.e2),
        contact_time=float(report.contact_time_s),
        stated_restitution=target,
        stated_contact_time=None,
        undamped_contact_time=None,
        peak_force=float(np.max(force / h)) * unit,
        peak_compression=report.flattening_max_m,
        energy={
            "initial": books["initial_kinetic"],
            "final_kinetic": books["final_rigid_kinetic"] + books["final_membrane_kinetic"],
            "stored": books["final_membrane_elastic"] + books["final_gas"],
            "dissipated": books["dissipated_damping"] + books["lost_impacts"],
            "balance": books["balance_error"],
        },
        steps=report.result.steps,
    )
    if not math.isfinite(result.restitution):
        raise NumericalError("the ball body's restitution is not finite")
    return result, report
