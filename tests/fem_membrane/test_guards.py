"""Accuracy guards of the finite elements (fem_membrane/guards.py): mesh and time-step warnings."""

from __future__ import annotations

import math

import numpy as np
import pytest
from twoball.fem_membrane.guards import (
    EIGENVALUE_ERROR,
    FREQUENCY_ERROR,
    alpha_frequency_error,
    eigenvalue_error_estimate,
    half_weight_degree,
    mesh_size,
    time_step_warnings,
)
from twoball.modal.filters import SpectralFilter

from tests.helpers import assert_printed, run_json


def _cluster_error(mesh: str, order: int, degree: int, **size: int) -> float:
    """Measured: worst relative eigenvalue error of the FE cluster of ``degree``."""
    from twoball.fem_membrane.build import build_space
    from twoball.fem_membrane.eigen import eigenpairs

    space = build_space(mesh, order=order, phi_a=2.6, **size)
    values = np.sort(eigenpairs(space.stiffness, space.mass, 1.5 * (degree + 1.5) ** 2).values)
    if mesh == "axisym":
        cluster = values[degree : degree + 1]
    else:
        cluster = values[degree**2 : (degree + 1) ** 2]
    return float(np.max(np.abs(cluster / (degree * (degree + 1)) - 1)))


def test_fem_default_is_quiet(capsys) -> None:
    data, lines = run_json(capsys, "--backend", "fem")
    assert data["warnings"] == [] and lines == []
    assert abs(data["truncation"]["t_difference"]) < 1e-3


def test_alpha_frequency_error_is_the_trapezoidal_rule_and_second_order() -> None:
    for x in (0.05, 0.2, 1.0, 3.0):  # rho_inf = 1: omega_h dt = 2 arctan(omega dt / 2)
        assert alpha_frequency_error(x) == pytest.approx(1 - 2 * math.atan(x / 2) / x, rel=1e-9)
    for rho in (1.0, 0.5, 0.0):
        small = np.array([0.02, 0.04])
        errors = np.array([alpha_frequency_error(x, rho) for x in small])
        order = math.log(errors[1] / errors[0]) / math.log(2.0)
        assert 1.9 < order < 2.1
    assert alpha_frequency_error(0.2) < FREQUENCY_ERROR < alpha_frequency_error(0.4)


def test_coarse_time_step_warns(capsys) -> None:
    argv = ("--backend", "fem", "--mesh", "axisym", "--scheme", "alpha", "--dt", "3e-3")
    data, lines = run_json(capsys, *argv)
    assert_printed(data, lines)
    step = [w for w in data["warnings"] if w.startswith("time step too coarse")]
    assert len(step) == 1 and "use a time step dt <=" in step[0]
    assert time_step_warnings(30.5, 0.2 / 31.0) == []  # the automatic step


@pytest.mark.slow
def test_default_time_step_is_quiet(capsys) -> None:
    data, lines = run_json(capsys, "--backend", "fem", "--mesh", "axisym", "--scheme", "alpha")
    assert data["warnings"] == [] and lines == []


@pytest.mark.parametrize(
    ("mesh", "order", "degree", "size"),
    [
        ("axisym", 1, 20, {"elements": 100}),
        ("axisym", 1, 30, {"elements": 400}),
        ("axisym", 2, 30, {"elements": 50}),
        ("axisym", 2, 20, {"elements": 100}),
        ("sphere", 1, 5, {"level": 2}),
        ("sphere", 1, 10, {"level": 3}),
        ("sphere", 2, 5, {"level": 2}),
        ("sphere", 3, 17, {"level": 2}),
        ("sphere", 4, 14, {"level": 2}),
        ("axisym", 3, 17, {"elements": 25}),
        ("axisym", 4, 20, {"elements": 50}),
    ],
)
def test_mesh_error_estimate_within_a_factor_two(mesh, order, degree, size) -> None:
    measured = _cluster_error(mesh, order, degree, **size)
    h = mesh_size(mesh, size.get("level"), size.get("elements"))
    estimate = eigenvalue_error_estimate(mesh, order, h, degree)
    assert 0.5 < estimate / measured < 2.0, (estimate, measured)


def test_coarse_mesh_warns_and_default_mesh_is_quiet(capsys) -> None:
    data, lines = run_json(capsys, "--backend", "fem", "--level", "2", "--order", "1")
    assert_printed(data, lines)
    assert any(w.startswith("mesh under-resolves the retained modes") for w in data["warnings"])
    lanczos = SpectralFilter("lanczos", 30)
    assert half_weight_degree(lanczos) == 17
    default = eigenvalue_error_estimate("sphere", 2, mesh_size("sphere", 3, None), 17)
    assert default < EIGENVALUE_ERROR


def test_high_order_coarse_mesh_warns_and_fine_mesh_is_quiet(capsys) -> None:
    """P3 on level 1 (estimated ~500 % at l = 17) warns; P4 on level 3 (~3e-5) is quiet."""
    data, lines = run_json(capsys, "--backend", "fem", "--level", "1", "--order", "3")
    assert_printed(data, lines)
    assert any(w.startswith("mesh under-resolves the retained modes") for w in data["warnings"])
    fine = eigenvalue_error_estimate("sphere", 4, mesh_size("sphere", 3, None), 17)
    assert fine < 1e-4
