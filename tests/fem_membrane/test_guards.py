"""Accuracy guards of the finite elements (fem_membrane/guards.py): mesh and time-step warnings."""

from __future__ import annotations

import math
from pathlib import Path

import gmsh
import meshio
import numpy as np
import pytest

import twoball
from tests.helpers import assert_printed, run_json
from twoball.fem_membrane.guards import (
    EIGENVALUE_ERROR,
    FREQUENCY_ERROR,
    alpha_frequency_error,
    eigenvalue_error_estimate,
    half_weight_degree,
    mesh_size,
    surface_size,
    time_step_warnings,
)
from twoball.fem_membrane.mesh import icosphere
from twoball.fem_membrane.mesh_input import load_sphere_mesh
from twoball.modal.filters import SpectralFilter


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


# --- A user's mesh is judged by the mesh-resolution guard from its size and order


def gmsh_sphere(path: Path, size: float, order: int = 1) -> Path:
    """gmsh's triangulation of the unit sphere, element size ``size``."""
    gmsh.initialize(interruptible=False)  # leaves the process's SIGINT handler alone
    try:
        gmsh.option.setNumber("General.Terminal", 0)
        gmsh.model.add("sphere")
        gmsh.model.occ.addSphere(0.0, 0.0, 0.0, 1.0)
        gmsh.model.occ.synchronize()
        gmsh.option.setNumber("Mesh.MeshSizeMin", size)
        gmsh.option.setNumber("Mesh.MeshSizeMax", size)
        gmsh.model.mesh.generate(2)
        if order > 1:
            gmsh.model.mesh.setOrder(order)
        gmsh.write(str(path))
    finally:
        gmsh.finalize()
    return path


@pytest.fixture(scope="module")
def gmsh_623(tmp_path_factory) -> Path:
    path = gmsh_sphere(tmp_path_factory.mktemp("gmsh") / "sphere.msh", 0.16)
    assert len(meshio.read(path).points) == 623
    return path


def _fem(mesh: twoball.MeshOptions):
    """The finite-element lift-off of the basketball on ``mesh`` (modal superposition)."""
    return twoball.liftoff(solver=twoball.Superposition(mesh))


def _mesh_warnings(report) -> list[str]:
    return [w for w in report.warnings if w.startswith("mesh under-resolves")]


def test_gmsh_p1_sphere_warns_like_the_generated_one(gmsh_623: Path) -> None:
    user = _fem(twoball.MeshOptions(file=str(gmsh_623)))
    generated = _fem(twoball.MeshOptions("sphere", level=3, order=1))
    (said,) = _mesh_warnings(user)
    (expected,) = _mesh_warnings(generated)
    assert "P1" in said and "1242 triangles" in said
    # the same estimate within the sizes' difference (1242 against 1280 triangles)
    assert (
        said.split("error ")[1][:3] in ("51%", "52%") and expected.split("error ")[1][:3] == "50%"
    )
    # raised to P2 the same file is resolved (estimate ~0.5 %)
    fine = _fem(twoball.MeshOptions(file=str(gmsh_623), order=2))
    assert _mesh_warnings(fine) == []


def test_estimate_matches_measured_eigenvalue_errors(gmsh_623: Path) -> None:
    mesh = load_sphere_mesh(gmsh_623).mesh
    h = surface_size(mesh.points, mesh.cells, 1)
    rows = twoball.fem.eigen(twoball.MeshOptions(file=str(gmsh_623)), count=63)
    worst: dict[int, float] = {}
    for row in rows:
        worst[row["l"]] = max(worst.get(row["l"], 0.0), abs(row["relative_error"]))
    for degree in (5, 6, 7):  # measured 5.2 %, 7.3 %, 9.7 %
        estimate = eigenvalue_error_estimate("sphere", 1, h, degree)
        assert worst[degree] / 1.5 < estimate < 1.5 * worst[degree]


@pytest.mark.parametrize("level", [2, 3, 4])
def test_icosphere_file_has_its_generated_size(level: int, tmp_path: Path) -> None:
    mesh = icosphere(level)
    path = tmp_path / "ico.vtu"
    meshio.write(path, meshio.Mesh(mesh.points * 0.12, [("triangle", mesh.cells)]))
    loaded = load_sphere_mesh(path).mesh
    for order in (1, 2):
        h = surface_size(loaded.points, loaded.cells, order)
        assert h == pytest.approx(mesh_size("sphere", level, None), rel=0.01)


def test_export_of_a_user_mesh_carries_the_warning(gmsh_623: Path, tmp_path: Path) -> None:
    solver = twoball.Superposition(twoball.MeshOptions(file=str(gmsh_623)))
    result = twoball.export(tmp_path / "ball.xdmf", solver=solver, frames=2)
    assert [w for w in result.warnings if w.startswith("mesh under-resolves")]
