"""The checks of ``twoball verify``: every backend against the closed form, with tolerances.

One call, :func:`run_verify`, computes

* the Legendre series with the case's N (the reference of every finite-element
  run, which uses the same filter) and its converged limit N -> infinity;
* finite-element runs (axisymmetric and sphere, P1 and P2) by modal superposition;
* one direct generalized-alpha run against modal superposition on the same mesh;
* eigenvalue, energy (eq. (3.5)) and energy-decay checks;

and returns the rows of the run table, the list of checks (each PASS or FAIL
against its tolerance) and what the plots need.  Dimensionless inside, SI out.
"""

from __future__ import annotations

import math
import time
from collections.abc import Sequence
from dataclasses import dataclass, field
from typing import Any

import numpy as np
from scipy.sparse.linalg import splu
from twoball.modal.filters import FilterKind
from twoball.modal.initial import deformation_work
from twoball.modal.liftoff import Horizon, find_liftoff
from twoball.modal.parameters import Case
from twoball.modal.report import t_end_dimensionless
from twoball.verify.output.figures.eigen import EigenErrors
from twoball.verify.output.figures.pole import Trace
from twoball.verify.studies.orders import OrderBand, observed_order
from twoball.verify.studies.studies import (
    EIGEN_DEGREES,
    REFERENCE_TOLERANCE,
    ConvergedReference,
    FEMRun,
    FEMSpec,
    LegendreRun,
    Progress,
    TrajectoryNorm,
    case_settings,
    cluster_errors,
    converged_legendre,
    fem_run,
    hermite_resample,
    legendre_run,
    projection_energy,
)


# --------------------------------------------------------------------------- configuration
@dataclass(frozen=True)
class FEMTarget:
    """A finite-element run of ``verify`` and its tolerances (relative).

    Attributes
    ----------
    spec : FEMSpec
    liftoff : float
        Bound on ``max(|dt_l|/t_l, |dv_l|/v_l)`` against the Legendre series
        with the same N and filter.
    eigen : float
        Bound on the largest relative eigenvalue error for l = 1..6.
    energy : float
        Bound on ``|1/2 u0^T K u0 - (-W)| / (-W)`` (eq. (3.5)).
    """

    spec: FEMSpec
    liftoff: float
    eigen: float
    energy: float


@dataclass(frozen=True)
class AlphaTarget:
    """The direct time-stepping check: generalized-alpha against modal superposition.

    Attributes
    ----------
    spec : FEMSpec
        Mesh of both runs.
    dt : float
        Time step (dimensionless, unit 1/c).
    liftoff : float
        Bound on ``max(|dt_l|/t_l, |dv_l|/v_l)`` between the two time schemes (the
        stepped samples as the backend interpolates them: per-field cubic splines).
    trajectory : float
        Bound on ``||u_alpha - u_modal||_L2 / ||u_modal||`` of the pole over [0, t_end].
    energy : float
        Bound on ``max_t |E_alpha(t) - E_modal(t)| / E_modal(0)`` (total energy).
    modal_energy : float
        Bound on ``max_{k,t} |E_k,alpha(t) - E_k,modal(t)| / E_modal(0)`` (every mode).
    bound : float
        Allowed excess of a stepped mode's energy over the band
        ``E_k(0) exp(-2 D omega_k t) [1/(1+D), 1/(1-D)]`` (relative), for modes with
        at least 1e-6 of the initial energy while they keep 1e-6 of their own.  The
        stepping error of a mode grows like omega^3 dt^2 t, so this bound is loose.
    """

    spec: FEMSpec
    dt: float
    liftoff: float
    trajectory: float
    energy: float
    modal_energy: float
    bound: float


@dataclass(frozen=True)
class VerifyConfig:
    """Which runs ``verify`` makes, with their tolerances."""

    name: str
    fem: tuple[FEMTarget, ...]
    alpha: tuple[AlphaTarget, ...]
    energy_pair: tuple[FEMSpec, FEMSpec] | None = None
    energy_band: OrderBand | None = None
    reference_tolerance: float = REFERENCE_TOLERANCE
    krylov: tuple[FEMTarget, ...] = ()
    """Meshes solved by the fast rational Krylov route (issue 7): lift-off only."""


# Tolerances: lift-off as set in issue 3 (axisym P2 400 el. 1e-6; sphere P2 level 3 1e-3,
# level 4 1e-4; sphere P1 level 4 2 %); eigenvalue and energy bounds about twice the errors
# the convergence studies measure on these meshes (eigenvalues: orders 2 and 4 for P1 and
# P2).  The energy of the projected F converges slowly on the icosphere (order ~1: the kink
# of F at phi_a cuts through the triangles; P2 oscillates more than P1 there), fast on the
# axisymmetric line, which has a node at the kink (order P + 1).
DEFAULT_FEM: tuple[FEMTarget, ...] = (
    FEMTarget(FEMSpec("axisym", 2, 400), liftoff=1e-6, eigen=2e-8, energy=3e-7),
    FEMTarget(FEMSpec("sphere", 1, 4), liftoff=2e-2, eigen=3e-2, energy=2e-2),
    FEMTarget(FEMSpec("sphere", 2, 3), liftoff=1e-3, eigen=1.5e-3, energy=6e-2),
)
THOROUGH_EXTRA: tuple[FEMTarget, ...] = (
    FEMTarget(FEMSpec("axisym", 2, 800), liftoff=1e-7, eigen=2e-9, energy=4e-8),
    FEMTarget(FEMSpec("sphere", 1, 5), liftoff=5e-3, eigen=8e-3, energy=1.5e-2),
    FEMTarget(FEMSpec("sphere", 2, 4), liftoff=1e-4, eigen=1e-4, energy=3e-2),
)
# The fast route on the finest meshes: lift-off against Legendre N = 30 (the issue-3 ladder
# 1e-3, 1e-4 continued to 1e-5 at level 5) and, where the full route ran too, route agreement.
THOROUGH_KRYLOV: tuple[FEMTarget, ...] = (
    FEMTarget(FEMSpec("sphere", 2, 4), liftoff=1e-4, eigen=0.0, energy=0.0),
    FEMTarget(FEMSpec("sphere", 2, 5), liftoff=1e-5, eigen=0.0, energy=0.0),
)
ROUTE_AGREEMENT = 1e-6  # Krylov against the full eigen route, relative in t_l and v_l
DEFAULT_ALPHA = AlphaTarget(
    FEMSpec("axisym", 2, 100), dt=0.0025, liftoff=1e-4, trajectory=2e-4, energy=1e-4,
    modal_energy=5e-5, bound=4e-2,
)  # fmt: skip
THOROUGH_ALPHA = AlphaTarget(
    FEMSpec("sphere", 1, 3), dt=0.0025, liftoff=1e-4, trajectory=2e-4, energy=1e-4,
    modal_energy=5e-5, bound=4e-2,
)  # fmt: skip
ENERGY_BAND = OrderBand(3.0, 0.4, 0.4)  # P2 L2 projection, kink at a node: order P + 1


def config(name: str = "default") -> VerifyConfig:
    """The named configuration: ``default`` (< 60 s), ``thorough`` or ``fast`` (tests only)."""
    pair = (FEMSpec("axisym", 2, 100), FEMSpec("axisym", 2, 400))
    if name == "default":
        return VerifyConfig("default", DEFAULT_FEM, (DEFAULT_ALPHA,), pair, ENERGY_BAND)
    if name == "thorough":
        return VerifyConfig(
            "thorough",
            DEFAULT_FEM + THOROUGH_EXTRA,
            (DEFAULT_ALPHA, THOROUGH_ALPHA),
            pair,
            ENERGY_BAND,
            krylov=THOROUGH_KRYLOV,
        )
    if name == "fast":  # coarse meshes with loose bounds: exercises every code path in seconds
        fem = (
            FEMTarget(FEMSpec("axisym", 2, 100), liftoff=1e-5, eigen=4e-6, energy=2e-5),
            FEMTarget(FEMSpec("sphere", 1, 3), liftoff=0.1, eigen=0.15, energy=0.2),
        )
        alpha = AlphaTarget(
            FEMSpec("axisym", 1, 50), dt=0.005, liftoff=1e-3, trajectory=1e-3, energy=1e-3,
            modal_energy=2e-4, bound=0.15,
        )  # fmt: skip
        pair = (FEMSpec("axisym", 2, 100), FEMSpec("axisym", 2, 200))
        return VerifyConfig("fast", fem, (alpha,), pair, ENERGY_BAND)
    raise ValueError(f"unknown verify configuration {name!r}")


# --------------------------------------------------------------------------- results
@dataclass(frozen=True)
class Check:
    """One PASS/FAIL check: a measured value against a tolerance.

    ``value <= tolerance`` passes (for order checks: ``value`` inside ``band``).
    """

    name: str
    description: str
    value: float | None
    tolerance: float | None
    passed: bool
    band: tuple[float, float] | None = None

    def as_dict(self) -> dict[str, Any]:
        """JSON-ready dictionary."""
        return {
            "name": self.name,
            "description": self.description,
            "value": self.value,
            "tolerance": self.tolerance,
            "band": None if self.band is None else list(self.band),
            "passed": self.passed,
        }

    @property
    def verdict(self) -> str:
        """``PASS`` or ``FAIL``."""
        return "PASS" if self.passed else "FAIL"


def bounded(name: str, description: str, value: float | None, tolerance: float) -> Check:
    """A check that passes when ``value`` is finite and at most ``tolerance``."""
    ok = value is not None and math.isfinite(value) and value <= tolerance
    return Check(name, description, value, tolerance, bool(ok))


@dataclass
class RunRow:
    """One row of the run table (SI)."""

    backend: str
    mesh: str
    dofs: int
    t_l_s: float | None
    v_l_m_s: float | None
    ratio: float | None
    t_diff: float | None  # relative to the Legendre series with the case's N
    v_diff: float | None
    t_diff_converged: float | None  # relative to the converged Legendre limit
    v_diff_converged: float | None
    seconds: float
    details: dict[str, Any] = field(default_factory=dict)

    def as_dict(self) -> dict[str, Any]:
        """JSON-ready dictionary (keys end in their unit)."""
        return {
            "backend": self.backend,
            "mesh": self.mesh,
            "dofs": self.dofs,
            "t_liftoff_s": self.t_l_s,
            "v_liftoff_m_s": self.v_l_m_s,
            "ratio": self.ratio,
            "t_rel_diff": self.t_diff,
            "v_rel_diff": self.v_diff,
            "t_rel_diff_converged": self.t_diff_converged,
            "v_rel_diff_converged": self.v_diff_converged,
            "seconds": self.seconds,
            **self.details,
        }


RUN_COLUMNS = (
    "backend",
    "mesh",
    "dofs",
    "t_liftoff_s",
    "v_liftoff_m_s",
    "ratio",
    "t_rel_diff",
    "v_rel_diff",
    "t_rel_diff_converged",
    "v_rel_diff_converged",
    "seconds",
)


@dataclass
class VerifyResult:
    """Everything ``verify`` found, ready for the table, the files and the plots."""

    case: Case
    config: VerifyConfig
    settings: dict[str, Any]
    rows: list[RunRow]
    checks: list[Check]
    traces: list[Trace]
    eigen: list[EigenErrors]
    energy_curves: list[tuple[str, np.ndarray, np.ndarray]]
    energy_bound: tuple[np.ndarray, np.ndarray] | None
    reference: ConvergedReference
    seconds: float = 0.0
    notes: list[str] = field(default_factory=list)

    @property
    def passed(self) -> bool:
        """True when every check passed."""
        return all(c.passed for c in self.checks)

    def as_dict(self) -> dict[str, Any]:
        """JSON-ready dictionary of the whole verification."""
        return {
            "passed": self.passed,
            "configuration": self.config.name,
            "seconds": self.seconds,
            "settings": self.settings,
            "runs": [r.as_dict() for r in self.rows],
            "checks": [c.as_dict() for c in self.checks],
            "eigenvalue_errors": [
                {"label": e.label, "l": e.degrees.tolist(), "relative_error": e.errors.tolist()}
                for e in self.eigen
            ],
            "notes": self.notes,
        }


# --------------------------------------------------------------------------- the checks
def _relative(value: float | None, reference: float | None) -> float | None:
    if value is None or reference is None or reference == 0:
        return None
    return (value - reference) / reference


def _row(
    case: Case,
    backend: str,
    mesh: str,
    dofs: int,
    t: float | None,
    v: float | None,
    seconds: float,
    reference: LegendreRun,
    limit: ConvergedReference,
    details: dict[str, Any] | None = None,
) -> RunRow:
    scale = case.scalings
    v_si = None if v is None else v * scale.velocity
    return RunRow(
        backend,
        mesh,
        dofs,
        None if t is None else t * scale.time,
        v_si,
        None if v_si is None else v_si / case.v0,
        _relative(t, reference.t),
        _relative(v, reference.velocity),
        _relative(t, limit.t),
        _relative(v, limit.velocity),
        seconds,
        dict(details or {}),
    )


def _liftoff_gap(t: float | None, v: float | None, ref_t: float | None, ref_v: float | None):
    """``max(|dt|/t, |dv|/v)``, or None if either did not lift off."""
    dt, dv = _relative(t, ref_t), _relative(v, ref_v)
    if dt is None or dv is None:
        return None
    return max(abs(dt), abs(dv))


def eigen_checks(run: FEMRun, target: FEMTarget) -> tuple[list[Check], EigenErrors]:
    """Largest relative error for l = 1..6, the constant mode and the multiplicities."""
    from twoball.fem_membrane.eigen import sphere_degree

    values = np.sort(run.model.pairs.values)
    label = run.spec.label
    degrees = np.array(EIGEN_DEGREES)
    errors = cluster_errors(values, run.spec.mesh, EIGEN_DEGREES)
    checks = [
        bounded(
            f"eigenvalues {label}",
            f"{label}: largest relative error of lambda_h against l(l+1), l = 1..6",
            float(errors.max()),
            target.eigen,
        )
    ]
    expected = np.ones(7, dtype=int) if run.spec.mesh == "axisym" else 2 * np.arange(7) + 1
    counts = np.bincount(sphere_degree(values), minlength=7)[:7]
    if run.spec.mesh == "axisym":
        counts = np.minimum(counts, 1)  # one eigenvalue per degree on the line by construction
    structure_ok = bool(np.array_equal(counts, expected)) and abs(values[0]) <= 1e-10
    checks.append(
        Check(
            f"spectrum {label}",
            f"{label}: lambda_0 = 0 (within 1e-10, got {abs(values[0]):.1e}) and "
            f"multiplicities {expected.tolist()} for l = 0..6 (got {counts.tolist()})",
            float(abs(values[0])),
            1e-10,
            structure_ok,
        )
    )
    return checks, EigenErrors(label, degrees, errors)


def energy_check(case: Case, run: FEMRun, target: FEMTarget) -> tuple[Check, float]:
    """1/2 u0^T K u0 of the projected F against -W of eq. (3.5) (unit T R^2)."""
    exact = -deformation_work(case.phi_a)
    energy = projection_energy(run.model)
    error = abs(energy - exact) / exact
    check = bounded(
        f"energy W {run.spec.label}",
        f"{run.spec.label}: relative error of 1/2 u0^T K u0 = {energy:.8f} T R^2 against "
        f"-W = {exact:.8f} T R^2 (eq. (3.5))",
        error,
        target.energy,
    )
    return check, error


@dataclass
class AlphaEnergy:
    """Modal energies of a generalized-alpha run, sampled on a subset of the steps."""

    times: np.ndarray
    energies: np.ndarray  # (samples, modes)
    pole: np.ndarray  # pole displacement at every step (to compare with the integrator)


def alpha_energies(run: FEMRun, dt: float, t_end: float, rho_inf: float = 1.0) -> AlphaEnergy:
    """Step ``M u'' + C u' + K u = 0`` and record the energy of every mode.

    The loop is the generalized-alpha update of :class:`twoball.fem_membrane.alpha.GeneralizedAlpha`
    (same effective matrix and solve), with the state projected on the M-orthonormal
    eigenvectors: ``q = Phi^T M u``, ``q' = Phi^T M v``, ``E_k = (q'_k^2 + omega_k^2 q_k^2)/2``.
    The pole displacement at every step is kept so the caller can confirm that this
    loop reproduces the integrator's own run exactly.
    """
    from twoball.fem_membrane.alpha import GeneralizedAlpha
    from twoball.fem_membrane.damping import ModalDamping
    from twoball.fem_membrane.modal import filtered_displacement

    model = run.model
    space, pairs, series = model.space, model.pairs, model.series
    M, K = space.mass, space.stiffness
    stepper = GeneralizedAlpha(M, K, dt, ModalDamping.from_modes(M, pairs, series.damping), rho_inf)
    p = stepper.parameters
    steps = max(1, math.ceil(t_end / dt - 1e-9))
    stride = max(1, steps // 800)
    project = np.asarray((M @ pairs.vectors).T)  # Phi^T M
    omega2 = pairs.omega**2
    d = filtered_displacement(series, pairs)
    v = np.zeros_like(d)
    a = stepper.initial_acceleration(d, v)
    times, energies, pole = [], [], np.empty(steps + 1)
    pole[0] = d[space.pole]

    def record(n: int) -> None:
        q, qd = project @ d, project @ v
        times.append(n * dt)
        energies.append(0.5 * (qd * qd + omega2 * q * q))

    record(0)
    for n in range(steps):
        d_pred = d + dt * v + dt * dt * (0.5 - p.beta) * a
        v_pred = v + dt * (1.0 - p.gamma) * a
        rhs = -(p.alpha_m * (M @ a))
        rhs -= K @ ((1.0 - p.alpha_f) * d_pred + p.alpha_f * d)
        rhs -= stepper.damping @ ((1.0 - p.alpha_f) * v_pred + p.alpha_f * v)
        a = stepper.solve(rhs)
        d = d_pred + p.beta * dt * dt * a
        v = v_pred + p.gamma * dt * a
        pole[n + 1] = d[space.pole]
        if (n + 1) % stride == 0:
            record(n + 1)
    return AlphaEnergy(np.array(times), np.array(energies), pole)


def _closed_mode_energies(run: FEMRun, times: np.ndarray) -> np.ndarray:
    """Energy of every mode of the modal series, ``(q_k'^2 + omega_k^2 q_k^2) / 2``."""
    q = run.series.modal_coordinates(times, 0)
    qt = run.series.modal_coordinates(times, 1)
    return 0.5 * (qt**2 + (run.series.omega * q) ** 2) * run.series.mode_norms


def _band_excess(
    energies: np.ndarray, envelope: np.ndarray, visible: np.ndarray, low: float, high: float
) -> float:
    """Largest relative excursion of ``energies / envelope`` outside [low, high]."""
    if not visible.any():
        return 0.0
    factor = energies[visible] / envelope[visible]
    return float(max(np.max(factor / high) - 1.0, np.max(low / factor) - 1.0, 0.0))


def decay_band(damping: float) -> tuple[float, float]:
    """Range of ``E_k(t) exp(2 D omega_k t) / E_k(0)`` for a damped mode released at rest.

    With ``q = exp(-D w t) (cos w_d t + D/sqrt(1 - D^2) sin w_d t)`` the energy
    ``(q'^2 + w^2 q^2)/2`` times ``exp(2 D w t)`` is a quadratic form in
    (cos w_d t, sin w_d t) with eigenvalues ``1/(1 + D)`` and ``1/(1 - D)``.
    """
    return 1.0 / (1.0 + damping), 1.0 / (1.0 - damping)


def alpha_checks(
    case: Case,
    target: AlphaTarget,
    modal: FEMRun,
    recontact: Horizon,
    t_end: float,
    reference: LegendreRun,
    limit: ConvergedReference,
) -> tuple[list[Check], list[RunRow], list[Trace], dict[str, Any]]:
    """Generalized-alpha against modal superposition on one mesh, and the energy decay."""
    from twoball.fem_membrane.solve import alpha_motion

    label = f"{target.spec.label}, dt = {target.dt:g}"
    start = time.perf_counter()
    motion, info = alpha_motion(modal.model, dt=target.dt, t_end=t_end)
    result = find_liftoff(motion, case.gamma, t_end=t_end, horizon=recontact)
    seconds = time.perf_counter() - start
    hermite = find_liftoff(hermite_resample(motion), case.gamma, t_end=t_end, horizon=recontact)
    norm = TrajectoryNorm(modal.series, t_end)
    l2 = norm.relative_error(motion)
    gap = _liftoff_gap(result.t, result.velocity, modal.t, modal.velocity)
    hermite_gap = _liftoff_gap(hermite.t, hermite.velocity, modal.t, modal.velocity)
    checks = [
        bounded(
            f"alpha lift-off {label}",
            f"generalized-alpha ({label}, {info['steps']} steps) against modal superposition "
            "on the same mesh: largest relative difference in t_l and v_l",
            gap,
            target.liftoff,
        ),
        bounded(
            f"alpha trajectory {label}",
            f"{label}: relative L2(0, t_end) difference of the pole displacement",
            l2,
            target.trajectory,
        ),
    ]
    rows = [
        _row(
            case, "fem alpha", label, modal.dofs, result.t, result.velocity, seconds, reference,
            limit, {"steps": info["steps"], "dt": target.dt,
                    "liftoff_gap_to_modal": gap, "liftoff_gap_to_modal_hermite": hermite_gap},
        )
    ]  # fmt: skip
    traces = [Trace(f"FE alpha {label}", motion, result.t, result.velocity)]
    energy = alpha_energies(modal, target.dt, t_end)
    same = float(np.max(np.abs(energy.pole - motion.pole(motion.times).u)))
    scale = float(np.max(np.abs(energy.pole)))
    checks.append(
        bounded(
            f"energy monitor {label}",
            f"{label}: the energy monitor's loop reproduces the integrator's pole history "
            "(largest difference relative to the largest displacement)",
            same / scale,
            1e-12,
        )
    )
    closed = modal.series.energy(energy.times)
    total = energy.energies.sum(axis=1)
    checks.append(
        bounded(
            f"energy decay {label}",
            f"{label}: largest difference of the total energy E_alpha(t) and E_modal(t), relative "
            "to E_modal(0); E_modal the closed form "
            "of the same modes (ModalSeries.energy)",
            float(np.max(np.abs(total - closed)) / closed[0]),
            target.energy,
        )
    )
    closed_modes = _closed_mode_energies(modal, energy.times)
    checks.append(
        bounded(
            f"mode energies {label}",
            f"{label}: largest difference of any single mode's energy, stepped against closed "
            "form, relative to E_modal(0)",
            float(np.max(np.abs(energy.energies - closed_modes)) / closed[0]),
            target.modal_energy,
        )
    )
    low, high = decay_band(case.damping)
    omega = modal.model.pairs.omega
    e0 = energy.energies[0]
    envelope = np.exp(-2.0 * case.damping * np.outer(energy.times, omega)) * e0
    significant = (e0 > 1e-6 * e0.sum()) & (omega > 0)
    visible = (envelope > 1e-6 * e0[None, :]) & significant[None, :]
    closed_excess = _band_excess(closed_modes, envelope, visible, low, high)
    checks.append(
        bounded(
            f"modal energy band, closed form {label}",
            f"{label}: every mode of ModalSeries within E_k(0) exp(-2 D omega_k t) "
            f"[1/(1+D), 1/(1-D)] = [{low:.4f}, {high:.4f}] (largest relative excess)",
            closed_excess,
            1e-9,
        )
    )
    checks.append(
        bounded(
            f"modal energy band, stepped {label}",
            f"{label}: every stepped mode with >= 1e-6 of E(0) within the same band while it "
            "keeps >= 1e-6 of its energy (largest relative excess; grows like omega^3 dt^2 t)",
            _band_excess(energy.energies, envelope, visible, low, high),
            target.bound,
        )
    )
    curves = {
        "times": energy.times,
        "alpha": total,
        "closed": closed,
        "bound": (energy.times, (envelope[:, significant].sum(axis=1)) * high),
        "label": label,
    }
    return checks, rows, traces, curves


def run_verify(
    case: Case,
    sigma: FilterKind = "lanczos",
    recontact: Horizon = "window",
    t_end_s: float | None = None,
    configuration: VerifyConfig | None = None,
    progress: Progress | None = None,
) -> VerifyResult:
    """Run every backend and every check of ``twoball verify``.

    Parameters
    ----------
    case : Case
        The impact (SI).
    sigma, recontact, t_end_s
        Filter, re-contact horizon and window, as for ``twoball liftoff``.
    configuration : VerifyConfig, optional
        Default: :func:`config` ``("default")``.
    progress : callable(str), optional
        Called with a description before each step.

    Returns
    -------
    VerifyResult
    """
    clock = time.perf_counter()
    configuration = configuration or config("default")
    say = progress or (lambda _: None)
    t_end = t_end_dimensionless(case, t_end_s)
    scale = case.scalings
    say(f"Legendre series N = {case.modes}")
    reference = legendre_run(case, case.modes, sigma, recontact, t_end)
    say("converged Legendre reference (N doubled)")
    limit = converged_legendre(
        case, sigma, recontact, t_end, configuration.reference_tolerance, case.modes
    )
    rows = [
        _row(case, "legendre", f"N = {case.modes}", case.modes + 1, reference.t,
             reference.velocity, reference.seconds, reference, limit),
        _row(case, "legendre N->inf", f"N = {limit.modes}, unfiltered", limit.modes + 1, limit.t,
             limit.velocity, limit.seconds, reference, limit),
    ]  # fmt: skip
    checks: list[Check] = []
    history = limit.history
    change = None
    if len(history) >= 2:
        change = max(
            abs(history[-1][2] - history[-2][2]) / abs(history[-1][2]),
            abs(history[-1][1] - history[-2][1]) / abs(history[-1][1]),
        )
    checks.append(
        Check(
            "Legendre reference converged",
            f"N doubled to {limit.modes}: last relative change of t_l and v_l, and free flight "
            "after lift-off clear of the pole",
            change,
            configuration.reference_tolerance,
            bool(limit.converged and limit.clear and change is not None),
        )
    )
    traces = [Trace(f"Legendre N = {case.modes}", reference.series, reference.t,
                    reference.velocity)]  # fmt: skip
    if limit.series is not None:
        traces.append(Trace(f"Legendre N -> inf ({limit.modes}, unfiltered)", limit.series,
                            limit.t, limit.velocity))  # fmt: skip
    eigen: list[EigenErrors] = []
    fem_runs: dict[FEMSpec, FEMRun] = {}
    for target in configuration.fem:
        say(f"finite elements {target.spec.label}")
        run = fem_run(case, target.spec, sigma, recontact, t_end)
        fem_runs[target.spec] = run
        rows.append(
            _row(case, "fem modal", target.spec.label, run.dofs, run.t, run.velocity,
                 run.seconds, reference, limit,
                 {"modes_computed": len(run.model.pairs), "h": target.spec.step})
        )  # fmt: skip
        traces.append(Trace(f"FE modal {target.spec.label}", run.series, run.t, run.velocity))
        checks.append(
            bounded(
                f"lift-off {target.spec.label}",
                f"{target.spec.label} ({run.dofs} DOFs) against Legendre N = {case.modes}: "
                "largest relative difference in t_l and v_l",
                _liftoff_gap(run.t, run.velocity, reference.t, reference.velocity),
                target.liftoff,
            )
        )
        more, table = eigen_checks(run, target)
        checks += more
        eigen.append(table)
        checks.append(energy_check(case, run, target)[0])
    for target in configuration.krylov:
        say(f"finite elements {target.spec.label}, Krylov route")
        fast = fem_run(case, target.spec, sigma, recontact, t_end, route="krylov")
        label = f"{target.spec.label} krylov"
        rows.append(
            _row(case, "fem krylov", target.spec.label, fast.dofs, fast.t, fast.velocity,
                 fast.seconds, reference, limit,
                 {"modes_computed": len(fast.model.series.omega), "h": target.spec.step})
        )  # fmt: skip
        traces.append(Trace(f"FE Krylov {target.spec.label}", fast.series, fast.t, fast.velocity))
        checks.append(
            bounded(
                f"lift-off {label}",
                f"{target.spec.label} ({fast.dofs} DOFs, rational Krylov route) against "
                f"Legendre N = {case.modes}: largest relative difference in t_l and v_l",
                _liftoff_gap(fast.t, fast.velocity, reference.t, reference.velocity),
                target.liftoff,
            )
        )
        full = fem_runs.get(target.spec)
        if full is not None:
            checks.append(
                bounded(
                    f"routes agree {target.spec.label}",
                    f"{target.spec.label}: Krylov route against the full eigen route "
                    f"({full.seconds:.1f} s vs {fast.seconds:.1f} s): relative difference "
                    "in t_l and v_l",
                    _liftoff_gap(fast.t, fast.velocity, full.t, full.velocity),
                    ROUTE_AGREEMENT,
                )
            )
    energy_curves: list[tuple[str, np.ndarray, np.ndarray]] = []
    bound = None
    for target in configuration.alpha:
        say(f"generalized-alpha {target.spec.label}, dt = {target.dt:g}")
        modal = fem_runs.get(target.spec)
        if modal is None:
            modal = fem_run(case, target.spec, sigma, recontact, t_end)
            fem_runs[target.spec] = modal
            rows.append(
                _row(case, "fem modal", target.spec.label, modal.dofs, modal.t, modal.velocity,
                     modal.seconds, reference, limit,
                     {"modes_computed": len(modal.model.pairs), "h": target.spec.step})
            )  # fmt: skip
        more, alpha_rows, alpha_traces, curves = alpha_checks(
            case, target, modal, recontact, t_end, reference, limit
        )
        rows += alpha_rows
        checks += more
        traces += alpha_traces
        energy_curves.append((f"alpha {curves['label']}", curves["times"], curves["alpha"]))
        energy_curves.append((f"modal {curves['label']}", curves["times"], curves["closed"]))
        bound = bound or curves["bound"]
    if configuration.energy_pair is not None and configuration.energy_band is not None:
        checks.append(
            _energy_order_check(case, configuration, fem_runs, sigma, recontact, t_end, say)
        )
    notes = [
        f"Reference of the finite elements: the Legendre series with N = {case.modes} and "
        f"sigma = {sigma}, the limit of finite elements that use the same filter; the "
        f"converged series (N = {limit.modes}) is the N -> infinity limit.",
        "Lift-off of generalized-alpha: the step samples interpolated field by field with "
        "cubic splines, as the backend returns them.  One quintic Hermite spline through the "
        "same samples would make u_tt first-order accurate between the steps "
        "(results.json: liftoff_gap_to_modal_hermite).",
    ]
    settings = case_settings(case, sigma, recontact, t_end)
    settings["configuration"] = configuration.name
    settings["reference"] = {
        "modes": limit.modes,
        "converged": limit.converged,
        "t_liftoff_s": None if limit.t is None else limit.t * scale.time,
        "v_liftoff_m_s": None if limit.velocity is None else limit.velocity * scale.velocity,
    }
    return VerifyResult(
        case, configuration, settings, rows, checks, traces, eigen, energy_curves, bound,
        limit, time.perf_counter() - clock, notes,
    )  # fmt: skip


def _energy_order_check(
    case: Case,
    configuration: VerifyConfig,
    runs: dict[FEMSpec, FEMRun],
    sigma: FilterKind,
    recontact: Horizon,
    t_end: float,
    say: Progress,
) -> Check:
    """Observed order of the W error between two meshes of the energy pair."""
    errors, steps = [], []
    exact = -deformation_work(case.phi_a)
    for spec in configuration.energy_pair or ():
        run = runs.get(spec)
        if run is None:
            say(f"finite elements {spec.label} (energy)")
            from twoball.fem_membrane.build import build_space
            from twoball.fem_membrane.initial import initial_load

            space = build_space(
                spec.mesh, level=spec.size, elements=spec.size, order=spec.order, phi_a=case.phi_a
            )
            u0 = splu(space.mass.tocsc()).solve(initial_load(space, case.phi_a))
            energy = 0.5 * float(u0 @ (space.stiffness @ u0))
        else:
            energy = projection_energy(run.model)
        errors.append(abs(energy - exact) / exact)
        steps.append(spec.step)
    order = observed_order(errors[0], errors[1], steps[0], steps[1])
    band = configuration.energy_band
    assert band is not None
    labels = " -> ".join(s.label for s in configuration.energy_pair or ())
    return Check(
        "energy W converges",
        f"observed order of the relative error of 1/2 u0^T K u0 against -W for {labels} "
        f"({errors[0]:.2e} -> {errors[1]:.2e}); expected {band.describe()}",
        order,
        None,
        band.contains(order),
        (band.low, band.high),
    )


def format_rows(rows: Sequence[RunRow]) -> list[list[Any]]:
    """The run table as lists in the order of ``RUN_COLUMNS``."""
    return [[r.as_dict()[c] for c in RUN_COLUMNS] for r in rows]
