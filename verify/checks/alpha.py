"""Checks of direct time stepping: generalized-alpha against modal superposition on one mesh.

Lift-off, the pole trajectory, the total energy and every mode's energy of the
stepped run are compared with the closed-form modal series of the same mesh,
and the modal energies with the decay band of a damped oscillator.
"""

from __future__ import annotations

import math
import time
from dataclasses import dataclass
from typing import Any

import numpy as np

from twoball._common.watch import Watch
from twoball.modal.converged import ConvergedReference
from twoball.modal.liftoff import Horizon, find_liftoff
from twoball.modal.parameters import Case
from twoball.verify.checks.config import AlphaTarget
from twoball.verify.checks.results import Check, RunRow, bounded, liftoff_gap, run_row
from twoball.verify.output.figures.pole import Trace
from twoball.verify.studies.fem_runs import FEMRun
from twoball.verify.studies.reference import LegendreRun
from twoball.verify.studies.result import time_step_text
from twoball.verify.studies.trajectory import TrajectoryNorm, hermite_resample


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

    label = f"{target.spec.label}, {time_step_text(target.dt, case.scalings.time)}"
    start = time.perf_counter()
    motion, info = alpha_motion(modal.model, dt=target.dt, t_end=t_end, monitor=Watch())
    result = find_liftoff(motion, case.gamma, t_end=t_end, horizon=recontact)
    seconds = time.perf_counter() - start
    hermite = find_liftoff(hermite_resample(motion), case.gamma, t_end=t_end, horizon=recontact)
    norm = TrajectoryNorm(modal.series, t_end)
    l2 = norm.relative_error(motion)
    gap = liftoff_gap(result.t, result.velocity, modal.t, modal.velocity)
    hermite_gap = liftoff_gap(hermite.t, hermite.velocity, modal.t, modal.velocity)
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
        run_row(
            case,
            "fem alpha",
            label,
            modal.dofs,
            result.t,
            result.velocity,
            seconds,
            reference,
            limit,
            {
                "steps": info["steps"],
                "dt_s": target.dt * case.scalings.time,
                "liftoff_gap_to_modal": gap,
                "liftoff_gap_to_modal_hermite": hermite_gap,
            },
        )
    ]
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
