"""Checks of the finite-element spectra and energies: eigenvalues, multiplicities, -W of eq. (3.5).

Each check compares a finite-element result with an independent value: the
eigenvalues l (l + 1) of the sphere, and the deformation work W of eq. (3.5).
"""

from __future__ import annotations

import numpy as np

from twoball.modal.filters import FilterKind
from twoball.modal.initial import deformation_work
from twoball.modal.liftoff import Horizon
from twoball.modal.parameters import Case
from twoball.verify.checks.config import FEMTarget, VerifyConfig
from twoball.verify.checks.results import Check, bounded
from twoball.verify.output.figures.eigen import EigenErrors
from twoball.verify.studies.fem_runs import (
    EIGEN_DEGREES,
    FEMRun,
    FEMSpec,
    cluster_errors,
    projected_strain_energy,
    projection_energy,
)
from twoball.verify.studies.orders import observed_order
from twoball.verify.studies.result import Progress


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


def energy_order_check(
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
            energy = projected_strain_energy(space, initial_load(space, case.phi_a))
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
