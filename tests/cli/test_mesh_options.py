"""export, render and plot on the user's sphere mesh (``--mesh-file``, ``--pole``, ``--geometry``).

References: the finite-element lift-off of :func:`twoball.liftoff` on the same
file (the pole's displacement at lift-off and t_l), the Legendre closed form
evaluated at the nodes' polar angles (computed here, not by the exporter), the
file's own radius and centre, and the command line against the Python API on
the same file (bit-identical arrays).  The meshes are written here: a P2
icosphere of level 2 (642 nodes) on a ball of 0.12 m around an offset centre
as ``.vtu``, and the P1 icosphere of level 2 in millimetres as gmsh ``.msh``.
"""

from __future__ import annotations

import json
from pathlib import Path

import imageio.v3 as iio
import numpy as np
import pytest
from test_mesh_input import CENTER, OFF_NODE_POLES, RADIUS, on_ball, write
from twoball.fem_membrane.mesh import icosphere
from twoball.modal.filters import SpectralFilter
from twoball.modal.legendre import displacement, legendre_series
from twoball.verify.output.fields import check_frame_budget, field_mesh
from twoball.verify.output.series import read_series

import twoball
from twoball._common.budget import BudgetError, frames_estimate, limits
from twoball._common.errors import ParameterError
from twoball.cli.main import main

CASE = twoball.Case.preset("basketball")
MM = 1000.0  # the .msh file is in millimetres


@pytest.fixture(scope="module")
def files(tmp_path_factory) -> dict[str, Path]:
    """``vtu``: P2 ball of 0.12 m off the origin; ``msh``: P1 ball in mm; ``hole``: broken."""
    folder = tmp_path_factory.mktemp("meshes")
    quadratic, flat = icosphere(2, 2), icosphere(2)
    paths = {name: folder / f"ball.{name}" for name in ("vtu", "msh")}
    write(paths["vtu"], on_ball(quadratic), quadratic.cells)
    write(paths["msh"], on_ball(flat) * MM, flat.cells, file_format="gmsh22")
    paths["hole"] = folder / "hole.vtu"
    write(paths["hole"], on_ball(flat), flat.cells[2:])  # two triangles removed
    return paths


@pytest.fixture(scope="module")
def reference(files):
    """The finite-element lift-off on each file (twoball.liftoff, full eigen route)."""
    return {name: twoball.liftoff(CASE, backend="fem", mesh=files[name]) for name in ("vtu", "msh")}


def pole_at_liftoff(series, report) -> float:
    """u_m [m] at the pole node (the point on +z) in the frame at t_l of ``report``."""
    frame = int(np.argmin(np.abs(series.times - report.t_liftoff_s)))
    assert series.times[frame] == pytest.approx(report.t_liftoff_s, rel=1e-12)
    pole = int(np.argmax(series.points[:, 2]))
    assert np.allclose(series.points[pole], [0.0, 0.0, CASE.radius], atol=1e-12)
    return float(series.point_data["u_m"][frame, pole])


def closed_form(points_m: np.ndarray, times_s: np.ndarray) -> np.ndarray:
    """u [m] of eq. (3.16) at the nodes' polar angles from +z, independently of the exporter."""
    scale = CASE.scalings
    series = legendre_series(CASE.phi_a, CASE.damping, SpectralFilter("lanczos", CASE.modes))
    phi = np.arccos(points_m[:, 2] / np.linalg.norm(points_m, axis=1))
    return displacement(series, times_s / scale.time, phi) * scale.length


@pytest.mark.parametrize(("name", "suffix"), [("vtu", "vtu"), ("msh", "xdmf")])
def test_export_matches_the_liftoff_on_the_same_file(files, reference, tmp_path, name, suffix):
    out = tmp_path / f"fields.{suffix}"
    frames = None if suffix == "vtu" else 3  # a .vtu holds the lift-off frame alone
    result = twoball.export(out, CASE, mesh=files[name], frames=frames)
    series = read_series(out)
    fem = reference[name]
    scale = fem.case.scalings
    # SI, in the case's frame: R times the unit sphere whatever the file's radius and unit
    radii = np.linalg.norm(series.points, axis=1)
    assert np.allclose(radii, CASE.radius, rtol=1e-12)
    assert series.cells.shape[1] == (6 if name == "vtu" else 3)
    u_pole = pole_at_liftoff(series, fem)
    assert u_pole == pytest.approx(fem.result.displacement * scale.length, rel=1e-9, abs=1e-15)
    assert series.field_data["t_liftoff_s"] == pytest.approx(fem.t_liftoff_s, rel=1e-12)
    assert result.report.v_liftoff_m_s == pytest.approx(fem.v_liftoff_m_s, rel=1e-12)
    legendre = closed_form(series.points, series.times)
    assert np.allclose(series.point_data["u_legendre_m"], legendre, rtol=1e-10, atol=1e-14)
    # the file's own radius, centre and pole (its unit) in the metadata and the provenance
    unit = MM if name == "msh" else 1.0
    assert series.field_data["mesh_file_radius"] == pytest.approx(RADIUS * unit, rel=1e-12)
    centre = [series.field_data[f"mesh_file_center_{a}"] for a in "xyz"]
    assert np.allclose(centre, CENTER * unit, rtol=1e-12, atol=1e-12 * unit)
    assert [series.field_data[f"mesh_file_pole_{a}"] for a in "xyz"] == [0.0, 0.0, 1.0]
    text = json.loads(series.text["mesh_file"])
    assert text["path"] == str(files[name].resolve()) and text["source_order"] == (
        2 if name == "vtu" else 1
    )
    assert result.provenance["mesh_file"]["radius"] == pytest.approx(RADIUS * unit, rel=1e-12)
    assert json.loads(series.text["provenance"])["mesh_file"]["path"] == text["path"]


def test_cli_and_api_give_identical_arrays(files, tmp_path, capsys):
    cli, api = tmp_path / "cli.xdmf", tmp_path / "api.xdmf"
    pole = ",".join(str(c) for c in OFF_NODE_POLES[0])
    code = main(["export", "--mesh-file", str(files["msh"]), "--pole", pole]
                + ["--frames", "3", "--out", str(cli)])  # fmt: skip
    assert code == 0 and "Exported fields" in capsys.readouterr().out
    mesh = twoball.MeshOptions(file=files["msh"], pole=OFF_NODE_POLES[0])
    twoball.export(api, CASE, mesh=mesh, frames=3)
    a, b = read_series(cli), read_series(api)
    assert np.array_equal(a.points, b.points) and np.array_equal(a.cells, b.cells)
    assert np.array_equal(a.times, b.times)
    assert a.point_data.keys() == b.point_data.keys()
    for key in a.point_data:
        assert np.array_equal(a.point_data[key], b.point_data[key]), key
    assert a.field_data == b.field_data
    assert a.text["mesh_file"] == b.text["mesh_file"]


def test_exact_geometry_and_pole_inside_an_element(files, tmp_path):
    """--geometry exact with the pole off every node: t_l and v_l as twoball.liftoff's."""
    pole = OFF_NODE_POLES[1]
    mesh = twoball.MeshOptions(file=files["vtu"], pole=pole, geometry="exact")
    fem = twoball.liftoff(CASE, backend="fem", mesh=mesh)
    out = tmp_path / "exact.pvd"
    result = twoball.export(out, CASE, mesh=mesh, frames=2)
    assert not fem.extra["mesh_file"]["pole_at_node"]
    assert result.report.t_liftoff_s == pytest.approx(fem.t_liftoff_s, rel=1e-12)
    assert result.report.v_liftoff_m_s == pytest.approx(fem.v_liftoff_m_s, rel=1e-12)
    assert result.provenance["mesh_file"]["geometry"] == "exact"
    series = read_series(out)
    assert np.allclose(np.linalg.norm(series.points, axis=1), CASE.radius, rtol=1e-12)


def test_render_writes_a_png_of_the_file_mesh(files, tmp_path, capsys):
    out = tmp_path / "ball.png"
    code = main(["render", "--mesh-file", str(files["vtu"]), "--size", "160x120"]
                + ["--out", str(out)])  # fmt: skip
    assert code == 0 and "Rendered" in capsys.readouterr().out
    image = iio.imread(out)
    assert image.shape[:2] == (120, 160)
    assert np.mean(np.any(image[..., :3] < 245, axis=-1)) > 0.05  # the ball, not a blank


def test_plot_pole_on_the_file_mesh(files, reference, tmp_path):
    out = tmp_path / "pole.png"
    result = twoball.plot("pole", out, CASE, mesh=files["msh"])
    assert out.stat().st_size > 0
    fem = reference["msh"]
    assert result.reports["fem"].t_liftoff_s == pytest.approx(fem.t_liftoff_s, rel=1e-12)
    assert result.provenance["mesh_file"]["radius"] == pytest.approx(RADIUS * MM, rel=1e-12)


def test_warnings_of_a_file_are_those_of_its_liftoff(files, reference, tmp_path):
    """No resolution estimate for a file (as in liftoff); a generated level 1 does warn."""
    result = twoball.export(tmp_path / "x.vtu", CASE, mesh=files["msh"])
    assert result.warnings == list(reference["msh"].warnings)
    coarse = twoball.export(tmp_path / "y.vtu", CASE, mesh=twoball.MeshOptions(level=1, order=1))
    assert any("under-resolves" in w for w in coarse.warnings)


def test_frame_budget_counts_the_file_nodes(files):
    """2000 frames fit on the 642 nodes of the file in a budget that level 3 P2 (2562) exceeds."""
    small = frames_estimate(2000, 642, (CASE.modes + 1) ** 2).memory
    large = frames_estimate(2000, 2562, (CASE.modes + 1) ** 2).memory
    with limits(max_memory=(small + large) / 2):
        check_frame_budget(CASE, 2000, "frames", field_mesh(files["vtu"]))
        with pytest.raises(BudgetError, match="frames"):
            check_frame_budget(CASE, 2000, "frames", field_mesh(None))


COMMANDS = {
    "export": ["export", "--out", "{out}/x.vtu"],
    "render": ["render", "--size", "64x48", "--out", "{out}/x.png"],
    "plot": ["plot", "pole", "--out", "{out}/p.png"],
}


def refused(argv: list[str], out: Path, capsys) -> str:
    """The one error line of ``argv`` (exit 2, no traceback, nothing written)."""
    out.mkdir()
    with pytest.raises(SystemExit) as stop:
        main([a.replace("{out}", str(out)) for a in argv])
    err = capsys.readouterr().err
    assert stop.value.code == 2
    lines = err.strip().splitlines()
    assert len(lines) == 1 and "Traceback" not in err
    assert list(out.iterdir()) == []
    return lines[0]


@pytest.mark.parametrize("command", COMMANDS)
def test_broken_mesh_is_refused(files, tmp_path, capsys, command):
    line = refused([*COMMANDS[command], "--mesh-file", str(files["hole"])], tmp_path / "o", capsys)
    assert "--mesh-file" in line and "closed surface" in line and "boundary edges" in line


@pytest.mark.parametrize("command", COMMANDS)
def test_pole_without_mesh_file_is_refused(tmp_path, capsys, command):
    line = refused([*COMMANDS[command], "--pole", "0,0,1"], tmp_path / "o", capsys)
    assert line.startswith("twoball: error: --pole ") and "mesh is a file" in line


@pytest.mark.parametrize("command", ["export", "render"])
def test_order_3_on_a_file_is_refused(files, tmp_path, capsys, command):
    argv = [*COMMANDS[command], "--mesh-file", str(files["vtu"]), "--order", "3"]
    assert "--order must be 1 or 2 for field files and pictures" in refused(
        argv, tmp_path / "o", capsys
    )


def test_refusals_that_do_not_apply(files, tmp_path, capsys):
    eigen = ["plot", "eigen", "--mesh-file", str(files["vtu"]), "--out", "{out}/p.png"]
    assert "--mesh-file must be left out with kind eigen" in refused(eigen, tmp_path / "a", capsys)
    ring = [*COMMANDS["export"], "--mesh", "ring", "--geometry", "exact"]
    assert "--geometry must be isoparametric with mesh ring" in refused(
        ring, tmp_path / "b", capsys
    )
    level = [*COMMANDS["render"], "--mesh-file", str(files["vtu"]), "--level", "2"]
    assert "--level must be left out with a mesh file" in refused(level, tmp_path / "c", capsys)
    with pytest.raises(ParameterError, match="^pole"):
        twoball.plot(
            "waterfall", tmp_path / "w.png", CASE, mesh=twoball.MeshOptions(pole=(0, 0, 1))
        )


@pytest.mark.parametrize("command", COMMANDS)
def test_a_body_of_finite_mass_needs_a_generated_mesh(files, tmp_path, capsys, command):
    """A body of finite mass is solved on generated meshes: a file or exact geometry is refused."""
    argv = [*COMMANDS[command], "--mass-ratio", "0.01", "--mesh-file", str(files["vtu"])]
    line = refused(argv, tmp_path / "a", capsys)
    assert line.startswith("twoball: error: --mesh-file must be a generated mesh"), line
    argv = [*COMMANDS[command], "--mass-ratio", "0.01", "--geometry", "exact"]
    line = refused(argv, tmp_path / "b", capsys)
    assert "--geometry must be isoparametric with mass_ratio" in line, line
