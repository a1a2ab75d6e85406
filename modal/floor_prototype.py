"""Prototype: the lower ball dropped on a rigid floor, Legendre modes + the contact core.

Dimensionless: length R, time 1/c, mass m2 = 4 pi rho R^2.  Coordinates
``q = (Z, a_0, a_2, ..., a_N)``: Z the height of the sphere's centre (the rigid
translation, carried once, so n = 1 is left out of u) and a_n the Legendre
amplitudes of the radial displacement ``u(phi) = sum a_n P_n(cos phi)``.

* Mass: ``m_Z = 1``, ``m_n = 1/(2n + 1)`` (``int P_n^2 dOmega = 4 pi/(2n + 1)``).
* Stiffness ``m_n omega_n^2``: the paper's operator ``omega_n^2 = n (n + 1)``
  (eq. (3.11)) or the pressurised one ``(n - 1)(n + 2)`` (second variation of
  ``T dA - P dV``); the enclosed gas adds ``gas`` to ``omega_0^2`` (on the
  pressurised operator ``omega_0^2 = 6 kappa P_abs / P - 2``).
* Damping: modal ratio D (``c_n = 2 D omega_n m_n``, eq. (3.14)) or Rayleigh
  ``alpha M + beta K`` on the membrane modes (never on Z, which gravity and the
  floor alone move).
* Gravity ``-gamma`` on Z only: its load on u is ``-gamma cos(phi)``, pure n = 1.
* Floor: the height of the material point at ``phi_i`` is
  ``z_i = Z + (1 + u(phi_i)) cos(phi_i) >= 0``, linear in q, at fixed points of
  the lower hemisphere; Newton's law with restitution e at each.

Start: undeformed, the south pole touching (Z = 1), falling at ``v0``.  The run
ends when the ball has been off the floor for ``flight`` time units and moves up.
"""

from __future__ import annotations

import math
import time
from dataclasses import dataclass, field

import numpy as np
from numpy.polynomial.legendre import legvander
from twoball.modal.nonsmooth import ContactProblem, MoreauJean, Trajectory

from twoball._common.errors import ParameterError

OPERATORS = ("paper", "pressurised")

BASKETBALL_V0 = 4.1 / (0.12 * 320.0)  # |v0| / (R c): 4.1 m/s, R = 0.12 m, c = 320 1/s
BASKETBALL_GAMMA = 9.81 / (0.12 * 320.0**2)  # g / (R c^2)
BASKETBALL_GAS = 6.0 * 1.4 * (77.2e3 + 101325.0) / 77.2e3  # 6 kappa P_abs / P, adiabatic


@dataclass(frozen=True)
class FloorModel:
    """The ball on the floor, modal backend (dimensionless).

    Parameters
    ----------
    modes : int
        Highest Legendre degree N >= 2.
    operator : {"paper", "pressurised"}
        ``n (n + 1)`` or ``(n - 1)(n + 2)``.
    gas : float
        Added to ``omega_0^2`` (0: none).  The pressurised operator needs
        ``omega_0^2 = gas - 2 > 0``.
    damping : float
        Modal damping ratio D in [0, 1).
    rayleigh : tuple of float or None
        ``(alpha, beta)``: ``C = alpha M + beta K`` on the membrane modes instead
        of the modal ratio (then ``damping`` must be 0).
    points : int
        Floor points, equally spaced in phi on [pi/2, pi], the pole included;
        default ``modes // 2`` (spacing pi/N, the modes' own resolution: more
        points make neighbouring rows of G nearly dependent).
    v0 : float
        Impact speed ``|v0| / (R c)`` > 0.
    gamma : float
        ``g / (R c^2)`` >= 0.
    restitution : float
        Newton's e at the floor points, in [0, 1].
    """

    modes: int = 40
    operator: str = "pressurised"
    gas: float = BASKETBALL_GAS
    damping: float = 0.0
    rayleigh: tuple[float, float] | None = None
    points: int | None = None
    v0: float = BASKETBALL_V0
    gamma: float = BASKETBALL_GAMMA
    restitution: float = 0.0

    def __post_init__(self) -> None:
        if not isinstance(self.modes, int) or self.modes < 2:
            raise ParameterError("modes", "an integer >= 2", self.modes)
        if self.operator not in OPERATORS:
            raise ParameterError("operator", "one of " + ", ".join(OPERATORS), self.operator)
        if not 0.0 <= self.damping < 1.0:
            raise ParameterError("damping", "a number in [0, 1)", self.damping)
        if self.rayleigh is not None and self.damping != 0.0:
            raise ParameterError("damping", "0 when rayleigh is given", self.damping)
        if not (math.isfinite(self.v0) and self.v0 > 0):
            raise ParameterError("v0", "a finite number > 0", self.v0)
        if not (math.isfinite(self.gamma) and self.gamma >= 0):
            raise ParameterError("gamma", "a finite number >= 0", self.gamma)
        if self.points is not None and (not isinstance(self.points, int) or self.points < 2):
            raise ParameterError("points", "an integer >= 2", self.points)
        if self.operator == "pressurised" and self.omega_squared[1] <= 0.0:
            raise ParameterError(
                "gas", "large enough that omega_0^2 > 0 on the pressurised operator", self.gas
            )

    @property
    def degrees(self) -> np.ndarray:
        """Legendre degrees of the membrane coordinates: 0, 2, 3, ..., N."""
        return np.concatenate([[0], np.arange(2, self.modes + 1)])

    @property
    def omega_squared(self) -> np.ndarray:
        """``omega^2`` of Z (0) and of each membrane coordinate."""
        n = self.degrees.astype(float)
        w2 = n * (n + 1.0) if self.operator == "paper" else (n - 1.0) * (n + 2.0)
        w2[0] += self.gas
        return np.concatenate([[0.0], w2])

    @property
    def masses(self) -> np.ndarray:
        """Masses of Z (1) and of each mode, ``1 / (2n + 1)``, in units of m2."""
        return np.concatenate([[1.0], 1.0 / (2.0 * self.degrees + 1.0)])

    @property
    def phi(self) -> np.ndarray:
        """Polar angles of the floor points [rad], ascending to pi."""
        count = max(self.modes // 2, 2) if self.points is None else self.points
        return np.linspace(0.5 * math.pi, math.pi, count + 1)[1:]


@dataclass(frozen=True)
class FloorSetup:
    """The :class:`ContactProblem` of a :class:`FloorModel` and its start."""

    problem: ContactProblem
    q0: np.ndarray
    v0: np.ndarray
    phi: np.ndarray
    shapes: np.ndarray  # P_n(cos phi_i) for the membrane degrees, (points, modes)


def floor_setup(model: FloorModel) -> FloorSetup:
    """Matrices, floor constraints and the falling start of ``model``."""
    m = model.masses
    w2 = model.omega_squared
    K = m * w2
    if model.rayleigh is None:
        C = 2.0 * model.damping * np.sqrt(w2) * m
    else:
        alpha, beta = model.rayleigh
        C = alpha * m + beta * K
        C[0] = 0.0
    phi = model.phi
    x = np.cos(phi)
    shapes = legvander(x, model.modes)[:, model.degrees]
    G = np.column_stack([np.ones_like(x), x[:, None] * shapes])
    f = np.zeros(m.size)
    f[0] = -model.gamma
    problem = ContactProblem.create(m, C, K, f, G, x, model.restitution)
    q0 = np.zeros(m.size)
    q0[0] = 1.0
    v0 = np.zeros(m.size)
    v0[0] = -model.v0
    return FloorSetup(problem, q0, v0, phi, shapes)


@dataclass(frozen=True)
class DropResult:
    """Measured quantities of one drop (dimensionless unless named otherwise).

    Attributes
    ----------
    contact_time : float
        From the first touch (t = 0) to lift-off (the floor force extrapolated
        to zero over the last two steps that carried it).
    e2 : float
        ``v2 / |v0|`` with v2 the centre's velocity at lift-off.
    phi_a_max : float
        Contact angle at the largest contact [rad]: the smallest edge angle
        (:func:`contact_edge`) over the steps in contact (the contact is
        ``phi_a <= phi <= pi``, the paper's phi_a).
    flattening_max : float
        Largest ``1 - Z`` (cubic Hermite refinement of the step samples).
    impulse : float
        Total floor impulse.
    impulse_balance : float
        ``|impulse - (v2 + v0 + gamma t_c)| / impulse`` (momentum of m2 = 1).
    energy_lost_impacts : float
        Energy lost at impacts, over the initial kinetic energy.
    energy_damped : float
        Work of the damping over the initial kinetic energy (<= 0).
    energy_error : float
        ``max |E - E_0 - works|`` over the initial kinetic energy.
    final_vibration : float
        Membrane energy (kinetic + elastic) at the end over the initial kinetic energy.
    steps : int
    wall_s : float
        Wall time of the run [s].
    """

    contact_time: float
    e2: float
    phi_a_max: float
    flattening_max: float
    impulse: float
    impulse_balance: float
    energy_lost_impacts: float
    energy_damped: float
    energy_error: float
    final_vibration: float
    steps: int
    wall_s: float
    trajectory: Trajectory | None = field(default=None, repr=False, compare=False)


def lift_off_time(
    t: np.ndarray, step_impulse: np.ndarray, impact_impulse: np.ndarray
) -> tuple[float, int]:
    """Lift-off time from the total floor force of the steps, and the last step with contact.

    The force of step k is its impulse over its length, placed at the step's
    midpoint; the last two positive values are extrapolated linearly to zero
    (second order when the force leaves zero with a finite slope), limited to
    the last step's end.  When the last contact is an impact (restitution > 0,
    no persistent contact after it) lift-off is that impact's time.
    """
    total = step_impulse.sum(axis=1)
    carried = np.flatnonzero(total > 0.0)
    struck = np.flatnonzero(impact_impulse.sum(axis=1) > 0.0)
    if carried.size == 0 and struck.size == 0:
        return 0.0, -1
    if carried.size == 0 or (struck.size and struck[-1] > carried[-1]):
        k = int(struck[-1])
        return float(t[k]), k
    k = int(carried[-1])
    if k == 0 or total[k - 1] <= 0.0:
        return float(t[k + 1]), k
    h = np.diff(t)
    mid = 0.5 * (t[:-1] + t[1:])
    f1, f0 = total[k] / h[k], total[k - 1] / h[k - 1]
    if f0 <= f1:
        return float(t[k + 1]), k
    estimate = mid[k] + f1 * (mid[k] - mid[k - 1]) / (f0 - f1)
    return float(min(max(estimate, t[k]), t[k + 1] + 0.5 * h[k])), k


def contact_edge(phi: np.ndarray, gap: np.ndarray, in_contact: np.ndarray) -> float:
    """Polar angle [rad] of the contact edge between the floor points (pi if none in contact).

    ``phi`` ascends to pi (the south pole last).  The outermost point in contact
    is i; outside it the gap grows as ``c (phi_e - phi)^2`` (the membrane meets
    the floor tangentially), so ``sqrt(gap)`` of the two next points outside is
    extrapolated linearly to zero, and the edge is kept between point i - 1
    and point i.  With fewer than two points outside it is ``phi[i]``.
    """
    inside = np.flatnonzero(in_contact)
    if inside.size == 0:
        return math.pi
    i = int(inside.min())
    if i < 2 or gap[i - 1] <= 0.0 or gap[i - 2] <= gap[i - 1]:
        return float(phi[i])
    s1, s2 = math.sqrt(gap[i - 1]), math.sqrt(gap[i - 2])
    slope = (s2 - s1) / (phi[i - 1] - phi[i - 2])
    return float(min(max(phi[i - 1] + s1 / slope, phi[i - 1]), phi[i]))


def hermite_peak(t: np.ndarray, x: np.ndarray, xdot: np.ndarray) -> float:
    """Largest value of a sampled motion, refined by the cubic Hermite interpolant.

    The largest sample is refined on each neighbouring interval where the rate
    changes sign (the cubic through values and rates, fourth order).
    """
    k = int(np.argmax(x))
    best = float(x[k])
    for a in (k - 1, k):
        if a < 0 or a + 1 >= t.size or xdot[a] * xdot[a + 1] > 0:
            continue
        h = t[a + 1] - t[a]
        s = np.linspace(0.0, 1.0, 201)
        h00, h10 = (1 + 2 * s) * (1 - s) ** 2, s * (1 - s) ** 2
        h01, h11 = s * s * (3 - 2 * s), s * s * (s - 1)
        values = h00 * x[a] + h10 * h * xdot[a] + h01 * x[a + 1] + h11 * h * xdot[a + 1]
        best = max(best, float(values.max()))
    return best


def measure_drop(
    tr: Trajectory,
    phi: np.ndarray,
    gaps: np.ndarray,
    *,
    gamma: float,
    v0: float,
    membrane_mass: float = 1.0,
    wall_s: float = 0.0,
    keep: bool = False,
) -> DropResult:
    """The quantities of :class:`DropResult` from a run whose coordinate 0 is Z (mass 1).

    Parameters
    ----------
    tr : Trajectory
        With states kept.
    phi : ndarray
        Polar angles of the constraints (ascending to pi).
    gaps : ndarray, shape (K + 1, m)
        Gaps of the constraints at every step end.
    gamma, v0 : float
        Gravity and impact speed (dimensionless).
    membrane_mass : float
        m2 in the problem's mass unit (1 modal; 1 for the FE prototype too).
    """
    step_impulse = tr.impulse - tr.impact_impulse
    t_c, last = lift_off_time(tr.t, step_impulse, tr.impact_impulse)
    t_end = tr.t[-1]
    v2 = tr.v_final[0] + gamma * (t_end - t_c)
    impulse = float(tr.impulse.sum())
    expected = membrane_mass * (v2 + v0 + gamma * t_c)
    edges = [contact_edge(phi, gaps[k + 1], tr.impulse[k] > 0.0) for k in range(max(last + 1, 0))]
    kinetic0 = 0.5 * membrane_mass * v0**2
    rigid = 0.5 * membrane_mass * tr.v_final[0] ** 2
    return DropResult(
        contact_time=t_c,
        e2=v2 / v0,
        phi_a_max=min(edges, default=math.pi),
        flattening_max=hermite_peak(tr.t, 1.0 - tr.q[:, 0], -tr.v[:, 0]),
        impulse=impulse,
        impulse_balance=abs(impulse - expected) / impulse,
        energy_lost_impacts=-tr.impact_work[-1] / kinetic0,
        energy_damped=tr.damping_work[-1] / kinetic0,
        energy_error=float(np.max(np.abs(tr.balance))) / kinetic0,
        final_vibration=(tr.kinetic[-1] - rigid + tr.elastic[-1]) / kinetic0,
        steps=tr.steps,
        wall_s=wall_s,
        trajectory=tr if keep else None,
    )


def run_drop(
    problem: ContactProblem,
    q0: np.ndarray,
    v0: np.ndarray,
    dt: float,
    *,
    flight: float = 1.0,
    t_max: float = 20.0,
    **options: object,
) -> tuple[Trajectory, float]:
    """Integrate a drop until the ball has been off the floor for ``flight`` and moves up.

    Returns the trajectory and the wall time [s]; ``options`` go to
    :class:`~twoball.modal.nonsmooth.MoreauJean`.
    """
    stepper = MoreauJean(problem, dt, **options)
    last_contact = [0.0]

    def stop(state, record) -> bool:
        if np.any(record.step_impulse > 0) or np.any(record.impact_impulse > 0):
            last_contact[0] = state.t
            return False
        return state.t - last_contact[0] >= flight and state.v[0] > 0.0

    start = time.perf_counter()
    tr = stepper.run(q0, v0, t_max, stop=stop, keep_states=True)
    return tr, time.perf_counter() - start


def drop(
    model: FloorModel,
    dt: float,
    *,
    flight: float = 1.0,
    t_max: float = 20.0,
    keep: bool = False,
    localise: bool = True,
    theta: float = 0.5,
) -> DropResult:
    """Drop the ball of ``model`` on the floor with time step ``dt`` and measure the bounce.

    Parameters
    ----------
    model : FloorModel
    dt : float
        Time step (units 1/c).
    flight : float
        Time off the floor, moving up, after which the run ends.
    t_max : float
        Guard on the run's length.
    keep : bool
        Keep the trajectory in the result.
    localise, theta
        Passed to :class:`~twoball.modal.nonsmooth.MoreauJean`.
    """
    setup = floor_setup(model)
    tr, wall = run_drop(
        setup.problem,
        setup.q0,
        setup.v0,
        dt,
        flight=flight,
        t_max=t_max,
        localise=localise,
        theta=theta,
    )
    gaps = tr.q @ setup.problem.constraints.T + setup.problem.offset
    return measure_drop(tr, setup.phi, gaps, gamma=model.gamma, v0=model.v0, wall_s=wall, keep=keep)


@dataclass(frozen=True)
class RestResult:
    """A ball settled on the floor under gravity (dimensionless).

    Attributes
    ----------
    floor_force : float
        Total floor force of the last step (impulse over step length).
    weight : float
        gamma (m2 = 1).
    contact_area : tuple of float
        ``(inner, outer)``: the polar caps ``2 pi (1 - cos psi)`` through the
        outermost point in contact and through the next point out (units R^2);
        the contact set of the discrete solution lies between them.
    pressure_area : float
        ``m2 g / P`` in units R^2: ``2 pi gamma`` (P = 2T/R).
    residual_speed : float
        Largest |velocity| at the end.
    contact_points : int
        Points carrying a force.
    wall_s : float
    """

    floor_force: float
    weight: float
    contact_area: tuple[float, float]
    pressure_area: float
    residual_speed: float
    contact_points: int
    wall_s: float


def settle(model: FloorModel, dt: float = 0.2, t_end: float = 800.0) -> RestResult:
    """Put the ball at rest on the floor (Z = 1, touching) and let it settle under gravity.

    ``model.damping`` (or its Rayleigh damping) must be > 0 for the motion to die
    out; with D = 0.9 the residual speed falls by e every ~13 time units.
    """
    setup = floor_setup(model)
    v0 = np.zeros_like(setup.v0)
    speed = model.gamma / math.sqrt(model.omega_squared[2])  # sag speed scale
    stepper = MoreauJean(setup.problem, dt, zeno_velocity=1e-4 * speed)
    start = time.perf_counter()
    tr = stepper.run(setup.q0, v0, t_end, keep_states=False)
    wall = time.perf_counter() - start
    h = tr.t[-1] - tr.t[-2]
    last = tr.impulse[-1]
    inside = np.flatnonzero(last > 0.0)
    i = int(inside.min()) if inside.size else setup.phi.size
    psi_in = math.pi - setup.phi[i] if inside.size else 0.0
    psi_out = math.pi - setup.phi[i - 1]
    return RestResult(
        floor_force=float(last.sum() / h),
        weight=model.gamma,
        contact_area=(
            2.0 * math.pi * (1.0 - math.cos(psi_in)),
            2.0 * math.pi * (1.0 - math.cos(psi_out)),
        ),
        pressure_area=2.0 * math.pi * model.gamma,
        residual_speed=float(np.max(np.abs(tr.v_final))),
        contact_points=int(inside.size),
        wall_s=wall,
    )


__all__ = [
    "FloorModel",
    "FloorSetup",
    "DropResult",
    "RestResult",
    "contact_edge",
    "drop",
    "floor_setup",
    "hermite_peak",
    "lift_off_time",
    "measure_drop",
    "run_drop",
    "settle",
]
