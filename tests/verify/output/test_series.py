"""twoball export: XDMF/PVD/VTU files hold every field, in SI, equal to the solvers' values."""

from __future__ import annotations

import json
import os
import xml.etree.ElementTree as ET

import meshio
import numpy as np
import pytest
import pyvista as pv
from twoball.fem_membrane.initial import initial_load
from twoball.fem_membrane.options import MeshOptions
from twoball.fem_membrane.space import sphere_space
from twoball.modal.filters import SpectralFilter
from twoball.modal.legendre import displacement, legendre_series
from twoball.modal.parameters import preset
from twoball.verify.output import series as export
from twoball.verify.output.fields import ball_model, field_mesh, field_series, frame_times
from twoball.verify.output.series import TimeSeries, read_series, write_series

from twoball._common.errors import ParameterError
from twoball.cli.main import main

FIELDS = ("u_m", "u_t_m_s", "u_tt_m_s2", "displacement_m", "u_fem_m", "u_legendre_m", "u_diff_m")


@pytest.fixture(scope="module", params=[(2, 1), (1, 2)], ids=["P1-level2", "P2-level1"])
def model(request):
    level, order = request.param
    return ball_model(preset("basketball"), field_mesh(MeshOptions(level=level, order=order)))


@pytest.fixture(scope="module")
def series(model):
    return field_series(model, frame_times(model, frames=5))


def closed_form(model, t_s):
    """u [m] of eq. (3.16) at the node angles, evaluated without twoball.verify.output.fields."""
    case = model.case
    scale = case.scalings
    legendre = legendre_series(case.phi_a, case.damping, SpectralFilter("lanczos", case.modes))
    z = model.mesh.points[:, 2] / np.linalg.norm(model.mesh.points, axis=1)
    return displacement(legendre, np.atleast_1d(t_s) / scale.time, np.arccos(z)) * scale.length


def fem_values(model, t_s, derivative=0):
    """FE field [SI] at the nodes: filtered modal coordinates times the node shapes."""
    fem = model.backends["fem"]
    scale = model.case.scalings
    unit = (scale.length, scale.velocity, scale.acceleration)[derivative]
    q = fem.series.modal_coordinates(np.atleast_1d(t_s) / scale.time, derivative)  # (T, K)
    return q @ fem.shapes * unit


def test_fem_shapes_are_the_eigenvectors_at_the_nodes(model):
    """Match dofs to nodes by position (skfem's doflocs, not dof_nodes) and check K, M."""
    fem = model.backends["fem"]
    space = sphere_space(model.mesh)
    locations = space.basis.doflocs.T  # (dofs, 3)
    distance = np.linalg.norm(locations[:, None, :] - model.mesh.points[None, :, :], axis=2)
    node_of_dof = distance.argmin(axis=1)
    assert distance.min(axis=1).max() < 1e-12
    assert sorted(node_of_dof) == list(range(len(model.mesh.points)))
    vectors = fem.shapes[:, node_of_dof].T  # (dofs, K)
    K, M = space.stiffness, space.mass
    values = fem.series.omega**2
    residual = K @ vectors - (M @ vectors) * values
    assert np.abs(residual).max() < 1e-8 * max(1.0, values.max())
    assert vectors.T @ (M @ vectors) == pytest.approx(np.eye(values.size), abs=1e-9)
    assert vectors[space.pole] == pytest.approx(fem.series.pole_values, abs=1e-14)
    # the projected initial displacement (3.10), expanded in the modes
    load = initial_load(space, model.case.phi_a)
    assert fem.series.coefficients == pytest.approx(vectors.T @ load, abs=1e-12)


def check_content(model, got: TimeSeries, expected: TimeSeries, frames=None):
    frames = range(len(expected)) if frames is None else frames
    case = model.case
    assert set(FIELDS) <= set(got.point_data)
    assert got.points == pytest.approx(model.mesh.points * case.radius, abs=1e-12)
    assert got.cells.shape == model.mesh.cells.shape
    np.testing.assert_array_equal(got.cells, model.mesh.cells)
    assert got.times == pytest.approx(expected.times[list(frames)], rel=1e-14, abs=0)
    for j, k in enumerate(frames):
        t = expected.times[k]
        u_leg = closed_form(model, t)[0]
        u_fem = fem_values(model, t)[0]
        scale = max(np.abs(u_fem).max(), 1e-6)
        assert got.point_data["u_legendre_m"][j] == pytest.approx(u_leg, abs=1e-12 * scale)
        assert got.point_data["u_fem_m"][j] == pytest.approx(u_fem, rel=1e-9, abs=1e-10 * scale)
        assert got.point_data["u_m"][j] == pytest.approx(u_fem, rel=1e-9, abs=1e-10 * scale)
        assert got.point_data["u_diff_m"][j] == pytest.approx(u_fem - u_leg, abs=1e-9 * scale)
        for name, derivative in (("u_t_m_s", 1), ("u_tt_m_s2", 2)):
            want = fem_values(model, t, derivative)[0]
            assert got.point_data[name][j] == pytest.approx(
                want, rel=1e-9, abs=1e-10 * np.abs(want).max()
            )
        vector = got.point_data["displacement_m"][j]
        normal = got.points / np.linalg.norm(got.points, axis=1, keepdims=True)
        assert vector == pytest.approx(u_fem[:, None] * normal, rel=1e-9, abs=1e-10 * scale)
    fem = model.backends["fem"]
    pole = fem.series.pole(got.times / case.scalings.time)
    assert got.point_data["u_fem_m"][:, model.mesh.pole] == pytest.approx(
        pole.u * case.radius, rel=1e-9, abs=1e-12
    )
    report = fem.report
    assert got.field_data["t_liftoff_s"] == pytest.approx(report.t_liftoff_s, rel=1e-14)
    assert got.field_data["v_liftoff_m_s"] == pytest.approx(report.v_liftoff_m_s, rel=1e-14)


def test_frames_are_even_plus_liftoff(model, series):
    report = model.backends["fem"].report
    assert len(series) == 6 and series.times[0] == 0.0
    assert series.times[-1] == pytest.approx(model.t_end_s)
    assert np.any(series.times == report.t_liftoff_s)
    pole = model.mesh.pole
    k = int(np.flatnonzero(series.times == report.t_liftoff_s)[0])
    # the pole at the lift-off frame: u and u_t are the lift-off report's values
    scale = model.case.scalings
    assert series.point_data["u_m"][k, pole] == pytest.approx(
        report.result.displacement * scale.length, rel=1e-9
    )
    assert series.point_data["u_t_m_s"][k, pole] == pytest.approx(report.v_liftoff_m_s, rel=1e-9)


def test_xdmf_reads_back_with_its_h5_beside_it(model, series, tmp_path, monkeypatch):
    elsewhere = tmp_path / "cwd"
    elsewhere.mkdir()
    monkeypatch.chdir(elsewhere)  # meshio would put the .h5 here (issue #1442)
    out = tmp_path / "data" / "series.xdmf"
    out.parent.mkdir()
    files = write_series(out, series)
    assert files == [out, out.with_suffix(".h5")]
    assert sorted(p.name for p in out.parent.iterdir()) == ["series.h5", "series.xdmf"]
    assert list(elsewhere.iterdir()) == []
    got = read_series(out)
    check_content(model, got, series)
    assert got.field_data == series.field_data and got.text == series.text


def text_of(array) -> str:
    """A VTK character array (XDMF texts through vtkXdmfReader) as text."""
    return bytes(np.asarray(array, dtype=np.int8).view(np.uint8)).decode("utf-8")


def test_xdmf_reads_with_pyvista(model, series, tmp_path):
    out = tmp_path / "series.xdmf"
    write_series(out, series)
    reader = pv.get_reader(str(out))
    assert reader.time_values == pytest.approx(list(series.times), rel=1e-12)
    k = 3
    reader.set_active_time_value(series.times[k])
    grid = reader.read()
    assert isinstance(grid, pv.UnstructuredGrid)  # one block: no separate mesh grid
    assert set(FIELDS) <= set(grid.point_data.keys())
    assert np.asarray(grid.points) == pytest.approx(series.points)
    for name in FIELDS:
        assert np.asarray(grid.point_data[name]) == pytest.approx(series.point_data[name][k])
    # VTK's XDMF reader shows the case (with units in the names) and the texts as field data
    for name in ("radius_m", "wave_speed_1_s", "v0_m_s", "phi_a_rad", "t_liftoff_s"):
        assert grid.field_data[name][0] == series.field_data[name]
    assert text_of(grid.field_data["case"]) == series.text["case"]
    assert "R = 0.12 m" in series.text["case"] and "u_t_m_s [m/s]" in series.text["case"]
    first = pv.read(str(out))  # pv.read: the first frame
    assert np.asarray(first.point_data["u_m"]) == pytest.approx(series.point_data["u_m"][0])


def test_pvd_opens_in_pyvista_with_the_same_content(model, series, tmp_path):
    out = tmp_path / "series.pvd"
    files = write_series(out, series)
    assert len(files) == 1 + len(series)
    assert files[0].parent == tmp_path and all(f.parent.parent == tmp_path for f in files[1:])
    reader = pv.get_reader(str(out))
    assert reader.time_values == pytest.approx(list(series.times), rel=1e-12)
    for k in (0, 2, len(series) - 1):
        reader.set_active_time_value(series.times[k])
        grid = reader.read()[0]
        assert np.asarray(grid.points) == pytest.approx(series.points)
        for name in FIELDS:
            assert np.asarray(grid.point_data[name]) == pytest.approx(series.point_data[name][k])
        assert grid.field_data["t_liftoff_s"][0] == series.field_data["t_liftoff_s"]
        assert grid.field_data["TimeValue"][0] == pytest.approx(series.times[k])
        assert grid.field_data["case"][0] == series.text["case"]  # a VTK string array
    block = pv.read(str(out))
    assert block[0].n_points == len(series.points)
    check_content(model, read_series(out), series)


def test_single_vtu(model, series, tmp_path):
    out = tmp_path / "one.vtu"
    write_series(out, series.select([2]))
    grid = pv.read(str(out))
    expected_cells = 5 if series.cell_type == "triangle" else 22  # VTK triangle / quad. triangle
    assert set(grid.celltypes) == {expected_cells}
    assert grid.field_data["TimeValue"][0] == pytest.approx(series.times[2])
    check_content(model, read_series(out), series, frames=[2])
    with pytest.raises(ParameterError, match="times"):
        write_series(out, series)


def test_no_partial_files_on_failure(series, tmp_path, monkeypatch):
    out = tmp_path / "series.pvd"
    write_series(out, series)
    before = {p: p.read_bytes() for p in tmp_path.rglob("*") if p.is_file()}
    calls = []

    def broken(target, series_, k, field_data):
        calls.append(k)
        if k == 2:
            raise OSError(28, "No space left on device")
        return original(target, series_, k, field_data)

    original = export._write_vtu_file
    monkeypatch.setattr(export, "_write_vtu_file", broken)
    with pytest.raises(OSError, match="series.pvd") as error:
        write_series(out, series.select([0, 1, 2, 3]))
    assert error.value.errno == 28 and error.value.filename == str(out)
    assert calls == [0, 1, 2]
    after = {p: p.read_bytes() for p in tmp_path.rglob("*") if p.is_file()}
    assert after == before  # the old collection untouched, no scratch folder left


def test_rewriting_a_pvd_replaces_its_frames_folder_as_a_whole(series, tmp_path):
    out = tmp_path / "series.pvd"
    first = write_series(out, series)
    (tmp_path / "notes.txt").write_text("keep")
    files = write_series(out, series.select([0, 1]))
    folder = files[1].parent
    assert folder.name.startswith("series_frames-") and folder != first[1].parent
    names = sorted(p.name for p in tmp_path.iterdir())
    assert names == ["notes.txt", "series.pvd", folder.name]  # the earlier frames are gone
    assert sorted(p.name for p in folder.iterdir()) == [
        ".twoball-output",
        "series_0000.vtu",
        "series_0001.vtu",
    ]
    assert read_series(out).times.tolist() == series.times[:2].tolist()


@pytest.mark.parametrize("fmt", ["pvd", "xdmf", "vtu"])
def test_same_series_gives_byte_identical_files(series, tmp_path, fmt):
    chosen = series.select([0]) if fmt == "vtu" else series
    (tmp_path / "a").mkdir()
    (tmp_path / "b").mkdir()
    first = write_series(tmp_path / "a" / f"s.{fmt}", chosen)
    again = write_series(tmp_path / "b" / f"s.{fmt}", chosen)
    assert len(first) == len(again) > 0
    for one, two in zip(first, again, strict=True):
        assert one.read_bytes() == two.read_bytes(), one.name


def read_only_folder(tmp_path):
    """A folder nobody may write to; root ignores permission bits, but not sysfs."""
    if os.geteuid() != 0:
        folder = tmp_path / "locked"
        folder.mkdir()
        folder.chmod(0o555)
        return folder
    try:
        os.mkdir("/sys/.twoball-probe")
    except OSError:
        return "/sys"
    os.rmdir("/sys/.twoball-probe")
    pytest.skip("no read-only folder available to root")


@pytest.mark.parametrize("fmt", ["xdmf", "pvd", "vtu"])
def test_missing_or_read_only_folder(series, tmp_path, fmt):
    for folder in (tmp_path / "missing", read_only_folder(tmp_path)):
        out = os.path.join(folder, f"series.{fmt}")
        with pytest.raises(ParameterError, match="out") as error:
            write_series(out, series.select([0]))
        assert "\n" not in str(error.value)
        assert not os.path.exists(out)
    assert list(tmp_path.glob(".series*")) == []


@pytest.mark.parametrize(
    ("path", "fmt", "name"),
    [("a.xdmf", "foo", "format"), ("a.xdmf", "pvd", "out"), ("a.txt", None, "out")],
)
def test_format_and_suffix(path, fmt, name):
    with pytest.raises(ParameterError, match=f"^{name} "):
        export.series_format(path, fmt)


# --------------------------------------------------------------------------- command line
def run_cli(capsys, *argv):
    code = main(list(argv))
    return code, capsys.readouterr()


def test_cli_export_xdmf(tmp_path, capsys, monkeypatch):
    monkeypatch.chdir(tmp_path)
    out = tmp_path / "out" / "series.xdmf"
    out.parent.mkdir()
    code, _ = run_cli(capsys, "export", "--level", "1", "--order", "2", "--out", str(out))
    assert code == 0
    assert sorted(p.name for p in out.parent.iterdir()) == ["series.h5", "series.xdmf"]
    got = read_series(out)
    assert len(got) == 26  # 25 evenly spaced + the lift-off
    assert got.cell_type == "triangle6"
    assert got.field_data["t_liftoff_s"] in got.times
    assert got.field_data["radius_m"] == 0.12
    assert set(FIELDS) <= set(got.point_data)
    root = ET.parse(out).getroot()
    assert root.find("Domain/Information[@Name='t_liftoff_s']") is not None
    # the provenance: the command line, versions, the case with units; also through VTK
    provenance = json.loads(got.text["provenance"])
    assert provenance["command"] == f"twoball export --level 1 --order 2 --out {out}"
    assert provenance["call"]["function"] == "twoball.export"
    assert provenance["versions"]["meshio"] == meshio.__version__
    assert provenance["case"]["radius_m"] == 0.12 and provenance["case"]["phi_a_rad"] == 2.6
    assert json.loads(text_of(pv.read(str(out)).field_data["provenance"])) == provenance


def test_cli_export_times_and_vtu(tmp_path, capsys):
    out = tmp_path / "s.pvd"
    code, _ = run_cli(
        capsys, "export", "--level", "1", "--times", "0.002,0,0.01", "--out", str(out)
    )
    assert code == 0
    assert read_series(out).times == pytest.approx([0.0, 0.002, 0.01])
    one = tmp_path / "one.vtu"
    code, _ = run_cli(capsys, "export", "--level", "1", "--backend", "legendre", "--out", str(one))
    got = read_series(one)
    assert code == 0 and len(got) == 1
    shown = pv.read(str(one)).field_data  # VTK's reader: the texts as strings
    assert json.loads(shown["provenance"][0]) == json.loads(got.text["provenance"])
    assert json.loads(got.text["provenance"])["case"]["v0_m_s"] == 4.1
    # legendre as the main backend: u is the closed form, the lift-off frame is its own
    assert got.times[0] == pytest.approx(got.field_data["t_liftoff_legendre_s"])
    assert got.point_data["u_m"] == pytest.approx(got.point_data["u_legendre_m"])


@pytest.mark.parametrize(
    ("extra", "flag"),
    [
        (["--format", "foo"], "--format"),
        (["--frames", "0"], "--frames"),
        (["--frames", "x"], "--frames"),
        (["--times", "0,,1"], "--times"),
        (["--times", "abc"], "--times"),
        (["--times", "-0.001"], "--times"),
        (["--times", "1.5"], "--times"),
        (["--level", "-1"], "--level"),
        (["--order", "5"], "--order"),
        (["--mesh", "cube"], "--mesh"),
        (["--backend", "abaqus"], "--backend"),
        (["--initial", "guess"], "--initial"),
    ],
)
def test_cli_export_bad_input(tmp_path, capsys, extra, flag):
    out = tmp_path / "series.xdmf"
    with pytest.raises(SystemExit) as stop:
        main(["export", "--level", "1", *extra, "--out", str(out)])
    err = capsys.readouterr().err
    assert stop.value.code == 2
    assert len(err.strip().splitlines()) == 1 and flag in err and "Traceback" not in err
    assert list(tmp_path.iterdir()) == []


def test_cli_export_unwritable_out(tmp_path, capsys):
    for folder in (tmp_path / "missing", read_only_folder(tmp_path)):
        out = os.path.join(folder, "series.xdmf")
        with pytest.raises(SystemExit) as stop:
            main(["export", "--level", "1", "--out", out])
        err = capsys.readouterr().err
        assert stop.value.code == 2 and len(err.strip().splitlines()) == 1 and "--out" in err
        assert not os.path.exists(out)


def test_no_liftoff_is_recorded(tmp_path):
    model = ball_model(
        preset("basketball").derive(damping=0.9), field_mesh(MeshOptions(level=1, order=1))
    )
    series = field_series(model, frame_times(model, frames=3))
    assert len(series) == 3  # no lift-off frame to add
    assert series.field_data["lifted"] == 0.0 and "t_liftoff_s" not in series.field_data
    out = tmp_path / "calm.pvd"
    write_series(out, series)
    grid = pv.read(str(out))[0]
    assert grid.field_data["lifted"][0] == 0.0 and "t_liftoff_s" not in grid.field_data
