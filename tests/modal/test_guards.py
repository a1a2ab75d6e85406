"""Accuracy guards: each fires on the cases of issue 11 and stays quiet on the defaults."""

from __future__ import annotations

import json
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
from twoball.modal.converged import converged_legendre
from twoball.modal.filters import SpectralFilter
from twoball.modal.guards import TRUNCATION_WARNING, truncation, window_warnings
from twoball.modal.parameters import preset
from twoball.modal.report import legendre_liftoff

from twoball.cli.main import main


def run_json(capsys: pytest.CaptureFixture[str], *argv: str) -> tuple[dict, list[str]]:
    """``twoball liftoff --json ...``: the JSON object and the stderr warning lines."""
    assert main(["liftoff", "--json", *argv]) == 0
    out, err = capsys.readouterr()
    # a finite-element solve longer than 2 s also reports progress (twoball._common.progress)
    progress = "twoball: liftoff: "
    return json.loads(out), [line for line in err.splitlines() if line and progress not in line]


def assert_printed(data: dict, lines: list[str]) -> None:
    """Every warning of the JSON is printed once on stderr, nothing else."""
    assert lines == [f"twoball: warning: {text}" for text in data["warnings"]]


# --- defaults: quiet ---------------------------------------------------------------


def test_legendre_default_is_quiet_and_reports_the_converged_series(capsys) -> None:
    data, lines = run_json(capsys)
    assert data["warnings"] == [] and lines == []
    block = data["truncation"]
    reference = converged_legendre(preset("basketball"))
    scale = preset("basketball").scalings
    assert block["converged"] and block["converged_modes"] == reference.modes
    assert block["t_liftoff_s"] == pytest.approx(reference.t * scale.time, rel=1e-12)
    assert block["v_liftoff_m_s"] == pytest.approx(reference.velocity * scale.velocity, rel=1e-12)
    # the number: N = 30 is 2.9 % below the converged series in v_l
    assert block["v_difference"] == pytest.approx(data["v_liftoff_m_s"] / 3.9454 - 1, abs=2e-4)
    assert -0.030 < block["v_difference"] < -0.028
    assert abs(block["v_difference"]) < TRUNCATION_WARNING


def test_fem_default_is_quiet(capsys) -> None:
    data, lines = run_json(capsys, "--backend", "fem")
    assert data["warnings"] == [] and lines == []
    assert abs(data["truncation"]["t_difference"]) < 1e-3


# --- N-truncation ------------------------------------------------------------------


def test_truncation_warns_above_five_percent() -> None:
    coarse = legendre_liftoff(preset("basketball").derive(modes=20))
    (text,) = coarse.warnings
    assert text.startswith("N = 20 truncation: t_l ") and text.endswith(
        "; raise the number of modes N"
    )
    assert coarse.extra["truncation"]["v_difference"] < -TRUNCATION_WARNING  # -6.3 %
    fine = legendre_liftoff(preset("basketball").derive(modes=60))
    assert fine.warnings == ()
    assert abs(fine.extra["truncation"]["v_difference"]) < 0.01


def test_truncation_difference_shrinks_with_n() -> None:
    case = preset("basketball")
    gaps = [
        abs(
            truncation(
                case.derive(modes=n), legendre_liftoff(case.derive(modes=n)).result
            ).v_difference
        )
        for n in (15, 30, 60)
    ]
    assert gaps[0] > gaps[1] > gaps[2] > 0


# --- re-contact window ---------------------------------------------------------------


def test_short_window_warns(capsys) -> None:
    data, lines = run_json(capsys, "--t-end", "0.005")
    assert data["lifted"] and data["t_liftoff_s"] == pytest.approx(4.8e-4, rel=0.01)
    assert_printed(data, lines)
    window, falling = data["warnings"][:2]
    assert window.startswith("window too short for the re-contact check")
    assert "2 pi / c = 19.6 ms" in window
    assert falling.startswith("the body is falling back at the end of the window")


def test_window_criterion_edges() -> None:
    """Quiet from one refocusing period after t_l on, while the body still rises."""
    case = preset("basketball")
    base = legendre_liftoff(case).result
    t_l = base.t
    enough = type(base)(**{**base.__dict__, "t_end": t_l + 2 * math.pi * 1.01})
    short = type(base)(**{**base.__dict__, "t_end": t_l + 2 * math.pi * 0.99})
    assert window_warnings(case, enough) == []
    assert len(window_warnings(case, short)) == 1


# --- generalized-alpha time step ------------------------------------------------------


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


# --- mesh resolution ------------------------------------------------------------------


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
