"""Time series files (verify/output/series.py): XDMF/PVD/VTU hold every field, read back equal.

Every format reads back in meshio, pyvista and VTK's own readers with the same
arrays; side entries the user did not name (``NAME.h5``, ``NAME_frames-*``) are
replaced only if twoball wrote them, anything else is refused before any work.
"""

from __future__ import annotations

import json
import os
import subprocess
import sys
import xml.etree.ElementTree as ET
from pathlib import Path

import h5py
import meshio
import numpy as np
import pytest
import pyvista as pv
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkIOXdmf2 import vtkXdmfReader
from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridReader

import twoball
from tests import ROOT
from tests.helpers import text_of
from tests.verify.output.nodal import closed_form, fem_values
from twoball._common.errors import ParameterError
from twoball._common.staging import staged_collection
from twoball.verify.output import series as export
from twoball.verify.output.series import (
    H5_MARK,
    TimeSeries,
    check_side_entries,
    is_twoball_h5,
    read_series,
    text_value,
    write_series,
)

FIELDS = ("u_m", "u_t_m_s", "u_tt_m_s2", "displacement_m", "u_fem_m", "u_legendre_m", "u_diff_m")


def check_content(sphere, got: TimeSeries, expected: TimeSeries, frames=None):
    frames = range(len(expected)) if frames is None else frames
    case = sphere.case
    assert set(FIELDS) <= set(got.point_data)
    assert got.points == pytest.approx(sphere.mesh.points * case.radius, abs=1e-12)
    assert got.cells.shape == sphere.mesh.cells.shape
    np.testing.assert_array_equal(got.cells, sphere.mesh.cells)
    assert got.times == pytest.approx(expected.times[list(frames)], rel=1e-14, abs=0)
    for j, k in enumerate(frames):
        t = expected.times[k]
        u_leg = closed_form(sphere, t)[0]
        u_fem = fem_values(sphere, t)[0]
        scale = max(np.abs(u_fem).max(), 1e-6)
        assert got.point_data["u_legendre_m"][j] == pytest.approx(u_leg, abs=1e-12 * scale)
        assert got.point_data["u_fem_m"][j] == pytest.approx(u_fem, rel=1e-9, abs=1e-10 * scale)
        assert got.point_data["u_m"][j] == pytest.approx(u_fem, rel=1e-9, abs=1e-10 * scale)
        assert got.point_data["u_diff_m"][j] == pytest.approx(u_fem - u_leg, abs=1e-9 * scale)
        for name, derivative in (("u_t_m_s", 1), ("u_tt_m_s2", 2)):
            want = fem_values(sphere, t, derivative)[0]
            assert got.point_data[name][j] == pytest.approx(
                want, rel=1e-9, abs=1e-10 * np.abs(want).max()
            )
        vector = got.point_data["displacement_m"][j]
        normal = got.points / np.linalg.norm(got.points, axis=1, keepdims=True)
        assert vector == pytest.approx(u_fem[:, None] * normal, rel=1e-9, abs=1e-10 * scale)
    fem = sphere.backends["fem"]
    pole = fem.series.pole(got.times / case.scalings.time)
    assert got.point_data["u_fem_m"][:, sphere.mesh.pole] == pytest.approx(
        pole.u * case.radius, rel=1e-9, abs=1e-12
    )
    report = fem.report
    assert got.field_data["t_liftoff_s"] == pytest.approx(report.t_liftoff_s, rel=1e-14)
    assert got.field_data["v_liftoff_m_s"] == pytest.approx(report.v_liftoff_m_s, rel=1e-14)


def test_xdmf_reads_back_with_its_h5_beside_it(sphere, sphere_series, tmp_path, monkeypatch):
    elsewhere = tmp_path / "cwd"
    elsewhere.mkdir()
    monkeypatch.chdir(elsewhere)  # meshio would put the .h5 here (issue #1442)
    out = tmp_path / "data" / "series.xdmf"
    out.parent.mkdir()
    files = write_series(out, sphere_series)
    assert files == [out, out.with_suffix(".h5")]
    assert sorted(p.name for p in out.parent.iterdir()) == ["series.h5", "series.xdmf"]
    assert list(elsewhere.iterdir()) == []
    got = read_series(out)
    check_content(sphere, got, sphere_series)
    assert got.field_data == sphere_series.field_data and got.text == sphere_series.text


def test_xdmf_reads_with_pyvista(sphere, sphere_series, tmp_path):
    out = tmp_path / "series.xdmf"
    write_series(out, sphere_series)
    reader = pv.get_reader(str(out))
    assert reader.time_values == pytest.approx(list(sphere_series.times), rel=1e-12)
    k = 3
    reader.set_active_time_value(sphere_series.times[k])
    grid = reader.read()
    assert isinstance(grid, pv.UnstructuredGrid)  # one block: no separate mesh grid
    assert set(FIELDS) <= set(grid.point_data.keys())
    assert np.asarray(grid.points) == pytest.approx(sphere_series.points)
    for name in FIELDS:
        assert np.asarray(grid.point_data[name]) == pytest.approx(sphere_series.point_data[name][k])
    # VTK's XDMF reader shows the case (with units in the names) and the texts as field data
    for name in ("radius_m", "wave_speed_1_s", "v0_m_s", "phi_a_rad", "t_liftoff_s"):
        assert grid.field_data[name][0] == sphere_series.field_data[name]
    assert text_of(grid.field_data["case"]) == sphere_series.text["case"]
    assert (
        "R = 0.12 m" in sphere_series.text["case"] and "u_t_m_s [m/s]" in sphere_series.text["case"]
    )
    first = pv.read(str(out))  # pv.read: the first frame
    assert np.asarray(first.point_data["u_m"]) == pytest.approx(sphere_series.point_data["u_m"][0])


def test_pvd_opens_in_pyvista_with_the_same_content(sphere, sphere_series, tmp_path):
    out = tmp_path / "series.pvd"
    files = write_series(out, sphere_series)
    assert len(files) == 1 + len(sphere_series)
    assert files[0].parent == tmp_path and all(f.parent.parent == tmp_path for f in files[1:])
    reader = pv.get_reader(str(out))
    assert reader.time_values == pytest.approx(list(sphere_series.times), rel=1e-12)
    for k in (0, 2, len(sphere_series) - 1):
        reader.set_active_time_value(sphere_series.times[k])
        grid = reader.read()[0]
        assert np.asarray(grid.points) == pytest.approx(sphere_series.points)
        for name in FIELDS:
            assert np.asarray(grid.point_data[name]) == pytest.approx(
                sphere_series.point_data[name][k]
            )
        assert grid.field_data["t_liftoff_s"][0] == sphere_series.field_data["t_liftoff_s"]
        assert grid.field_data["TimeValue"][0] == pytest.approx(sphere_series.times[k])
        assert text_of(grid.field_data["case"]) == sphere_series.text["case"]  # UTF-8 bytes
    block = pv.read(str(out))
    assert block[0].n_points == len(sphere_series.points)
    check_content(sphere, read_series(out), sphere_series)


def test_single_vtu(sphere, sphere_series, tmp_path):
    out = tmp_path / "one.vtu"
    write_series(out, sphere_series.select([2]))
    grid = pv.read(str(out))
    expected_cells = (
        5 if sphere_series.cell_type == "triangle" else 22
    )  # VTK triangle / quad. triangle
    assert set(grid.celltypes) == {expected_cells}
    assert grid.field_data["TimeValue"][0] == pytest.approx(sphere_series.times[2])
    check_content(sphere, read_series(out), sphere_series, frames=[2])
    with pytest.raises(ParameterError, match="times"):
        write_series(out, sphere_series)


def test_no_partial_files_on_failure(sphere_series, tmp_path, monkeypatch):
    out = tmp_path / "series.pvd"
    write_series(out, sphere_series)
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
        write_series(out, sphere_series.select([0, 1, 2, 3]))
    assert error.value.errno == 28 and error.value.filename == str(out)
    assert calls == [0, 1, 2]
    after = {p: p.read_bytes() for p in tmp_path.rglob("*") if p.is_file()}
    assert after == before  # the old collection untouched, no scratch folder left


def test_rewriting_a_pvd_replaces_its_frames_folder_as_a_whole(sphere_series, tmp_path):
    out = tmp_path / "series.pvd"
    first = write_series(out, sphere_series)
    (tmp_path / "notes.txt").write_text("keep")
    files = write_series(out, sphere_series.select([0, 1]))
    folder = files[1].parent
    assert folder.name.startswith("series_frames-") and folder != first[1].parent
    names = sorted(p.name for p in tmp_path.iterdir())
    assert names == ["notes.txt", "series.pvd", folder.name]  # the earlier frames are gone
    assert sorted(p.name for p in folder.iterdir()) == [
        ".twoball-output",
        "series_0000.vtu",
        "series_0001.vtu",
    ]
    assert read_series(out).times.tolist() == sphere_series.times[:2].tolist()


@pytest.mark.parametrize("fmt", ["pvd", "xdmf", "vtu"])
def test_same_series_gives_byte_identical_files(sphere_series, tmp_path, fmt):
    chosen = sphere_series.select([0]) if fmt == "vtu" else sphere_series
    (tmp_path / "a").mkdir()
    (tmp_path / "b").mkdir()
    first = write_series(tmp_path / "a" / f"s.{fmt}", chosen)
    again = write_series(tmp_path / "b" / f"s.{fmt}", chosen)
    assert len(first) == len(again) > 0
    for one, two in zip(first, again, strict=True):
        assert one.read_bytes() == two.read_bytes(), one.name


@pytest.mark.parametrize("fmt", ["xdmf", "pvd", "vtu"])
def test_missing_or_read_only_folder(sphere_series, tmp_path, read_only_folder, fmt):
    for folder in (tmp_path / "missing", read_only_folder):
        out = os.path.join(folder, f"series.{fmt}")
        with pytest.raises(ParameterError, match="out") as error:
            write_series(out, sphere_series.select([0]))
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


READERS = ("meshio", "pyvista", "vtk")


FORMATS = ("xdmf", "pvd", "vtu")


def synthetic(frames: int) -> TimeSeries:
    """A P2 sphere-like mesh with random node data; texts with non-ASCII characters."""
    rng = np.random.default_rng(7)
    points = rng.normal(size=(30, 3))
    cells = rng.integers(0, 30, size=(8, 6))
    times = np.sort(rng.uniform(0.0, 0.04, size=frames))
    return TimeSeries(
        points,
        cells,
        times,
        {"u_m": rng.normal(size=(frames, 30)), "displacement_m": rng.normal(size=(frames, 30, 3))},
        {"t_liftoff_s": 0.01234567890123, "radius_m": 0.12},
        {"case": "µ = 0.1, φ_a = 2.6 rad", "provenance": json.dumps({"twoball": "x", "k": [1, 2]})},
        {"s_m": rng.normal(size=frames), "contact": (rng.uniform(size=frames) > 0.5) * 1.0},
    )


@pytest.fixture(scope="module", params=FORMATS)
def written(request, tmp_path_factory):
    fmt = request.param
    series = synthetic(1 if fmt == "vtu" else 4)
    out = tmp_path_factory.mktemp(fmt) / f"s.{fmt}"
    write_series(out, series)
    return fmt, out, series


# --------------------------------------------------------------------------- readers
def _vtk_fields(data) -> dict[str, np.ndarray]:
    fields = data.GetFieldData()
    return {
        fields.GetAbstractArray(i).GetName(): vtk_to_numpy(fields.GetArray(i))
        for i in range(fields.GetNumberOfArrays())
        if fields.GetArray(i) is not None
    }


def _vtk_points(data) -> dict[str, np.ndarray]:
    points = data.GetPointData()
    return {
        points.GetArrayName(i): vtk_to_numpy(points.GetArray(i))
        for i in range(points.GetNumberOfArrays())
    }


def _pvd_frames(out: Path) -> list[tuple[float, Path]]:
    root = ET.parse(out).getroot()
    return [(float(d.get("timestep")), out.parent / d.get("file")) for d in root.iter("DataSet")]


def read_with(reader: str, fmt: str, out: Path) -> list[dict]:
    """Per frame: ``time``, ``points``, ``point_data`` and ``field_data`` (as the reader gives)."""
    frames = []
    if reader == "meshio" and fmt == "xdmf":
        with meshio.xdmf.TimeSeriesReader(str(out)) as series:
            points, _ = series.read_points_cells()
            for k in range(series.num_steps):
                t, point_data, _ = series.read_data(k)
                frames.append({"time": t, "points": points, "point_data": point_data})
        return frames  # meshio's time series reader gives node data only
    if reader == "meshio":
        files = [(None, out)] if fmt == "vtu" else _pvd_frames(out)
        for _, name in files:
            mesh = meshio.read(str(name))  # used to exit the interpreter (string arrays)
            fields = dict(mesh.field_data)
            frames.append(
                {
                    "time": float(np.ravel(fields["TimeValue"])[0]),
                    "points": mesh.points,
                    "point_data": mesh.point_data,
                    "field_data": fields,
                }
            )
        return frames
    if reader == "pyvista":
        if fmt == "vtu":
            grids, times = [pv.read(str(out))], [None]
        else:
            source = pv.get_reader(str(out))
            times, grids = source.time_values, []
            for t in times:
                source.set_active_time_value(t)
                grid = source.read()
                grids.append(grid[0] if isinstance(grid, pv.MultiBlock) else grid)
        for t, grid in zip(times, grids, strict=True):
            fields = {name: np.asarray(grid.field_data[name]) for name in grid.field_data}
            t = float(fields["TimeValue"][0]) if t is None else t
            frames.append(
                {
                    "time": t,
                    "points": np.asarray(grid.points),
                    "point_data": {n: np.asarray(grid.point_data[n]) for n in grid.point_data},
                    "field_data": fields,
                }
            )
        return frames
    if fmt == "xdmf":
        source = vtkXdmfReader()
        source.SetFileName(str(out))
        source.UpdateInformation()
        info = source.GetOutputInformation(0)
        from vtkmodules.vtkCommonExecutionModel import vtkStreamingDemandDrivenPipeline as sddp

        times = list(info.Get(sddp.TIME_STEPS()))
        for t in times:
            source.UpdateTimeStep(t)
            data = source.GetOutputDataObject(0)
            frames.append(
                {
                    "time": t,
                    "points": vtk_to_numpy(data.GetPoints().GetData()),
                    "point_data": _vtk_points(data),
                    "field_data": _vtk_fields(data),
                }
            )
        return frames
    files = [(None, out)] if fmt == "vtu" else _pvd_frames(out)
    for t, name in files:
        source = vtkXMLUnstructuredGridReader()
        source.SetFileName(str(name))
        source.Update()
        data = source.GetOutput()
        fields = _vtk_fields(data)
        frames.append(
            {
                "time": float(fields["TimeValue"][0]) if t is None else t,
                "points": vtk_to_numpy(data.GetPoints().GetData()),
                "point_data": _vtk_points(data),
                "field_data": fields,
            }
        )
    return frames


# --------------------------------------------------------------------------- a real export
@pytest.fixture(scope="module")
def exports(tmp_path_factory):
    folder = tmp_path_factory.mktemp("exports")
    mesh = twoball.MeshOptions("sphere", level=1)
    body = twoball.Body(mass_ratio=0.1)
    results = {}
    for fmt in FORMATS:
        frames = None if fmt == "vtu" else 3
        out = folder / f"x.{fmt}"
        solver = twoball.Superposition(mesh)
        results[fmt] = twoball.export(out, solver=solver, body=body, frames=frames)
    return results


# --------------------------------------------------------------------------- the matrix
@pytest.mark.parametrize("reader", READERS)
def test_every_reader_gives_the_written_arrays(written, reader):
    fmt, out, series = written
    frames = read_with(reader, fmt, out)
    assert len(frames) == len(series)
    for k, frame in enumerate(frames):
        assert frame["time"] == pytest.approx(series.times[k], rel=1e-15)
        assert np.array_equal(frame["points"], series.points)
        assert set(frame["point_data"]) == set(series.point_data)
        for name, values in series.point_data.items():
            got = np.asarray(frame["point_data"][name])
            assert got.dtype == np.float64
            assert got.tobytes() == np.ascontiguousarray(values[k]).tobytes(), name  # bit for bit
        if "field_data" not in frame:
            continue  # meshio's XDMF time series: node data only (the rest: read_series)
        fields = frame["field_data"]
        for name, value in series.field_data.items():
            assert float(np.ravel(fields[name])[0]) == value, name
        for name, values in series.frame_data.items():
            assert float(np.ravel(fields[name])[0]) == values[k], name
        for name, text in series.text.items():
            assert text_value(fields[name]) == text, name


def test_read_series_gives_the_written_series(written):
    fmt, out, series = written
    back = read_series(out)
    assert back.times.tolist() == series.times.tolist()
    assert np.array_equal(back.points, series.points) and np.array_equal(back.cells, series.cells)
    for name, values in series.point_data.items():
        assert back.point_data[name].tobytes() == values.tobytes()
    assert back.field_data == series.field_data
    assert back.text == series.text
    for name, values in series.frame_data.items():
        assert back.frame_data[name].tolist() == values.tolist()


def test_meshio_read_of_a_vtu_does_not_exit(tmp_path):
    """``meshio.read`` printed an error and called ``sys.exit(1)`` on the string arrays."""
    out = tmp_path / "one.vtu"
    write_series(out, synthetic(1))
    try:
        mesh = meshio.read(out)
    except SystemExit:  # pragma: no cover - the defect
        pytest.fail("meshio.read exited the interpreter")
    assert text_value(mesh.field_data["case"]) == "µ = 0.1, φ_a = 2.6 rad"


def test_text_value_reads_vtk_char_arrays():
    codes = np.frombuffer("φ".encode(), dtype=np.uint8)
    assert text_value(codes.astype(np.int8)) == "φ" == text_value(codes) == text_value("φ")


@pytest.mark.parametrize("reader", ("meshio", "pyvista", "vtk"))
@pytest.mark.parametrize("fmt", FORMATS)
def test_provenance_events_and_liftoff_travel_with_every_export(exports, fmt, reader):
    result = exports[fmt]
    out = result.files[0]
    report = result.report
    if reader == "meshio" and fmt == "xdmf":  # the metadata: XML and HDF5 beside meshio
        import h5py

        with h5py.File(out.with_suffix(".h5"), "r") as h5:
            fields = {name: h5[f"text/{name}"][()] for name in h5["text"]}
            numbers = {k: v for k, v in h5.attrs.items() if not isinstance(v, str)}
            fields |= {name: np.array([value]) for name, value in numbers.items()}
        frames = [{"field_data": fields}]
    else:
        frames = read_with(reader, fmt, out)
    for frame in frames:
        fields = frame["field_data"]
        provenance = json.loads(text_value(fields["provenance"]))
        assert provenance == json.loads(json.dumps(result.provenance))
        events = json.loads(text_value(fields["contact_events"]))
        assert [e["kind"] for e in events] == [e["kind"] for e in report.events_si()]
        assert [e["t_s"] for e in events] == [e["t_s"] for e in report.events_si()]
        assert float(np.ravel(fields["t_liftoff_s"])[0]) == report.t_liftoff_s
        assert float(np.ravel(fields["v_liftoff_m_s"])[0]) == report.v_liftoff_m_s
        assert float(np.ravel(fields["mass_ratio"])[0]) == 0.1
        assert "R = 0.12 m" in text_value(fields["case"])


MESH = twoball.MeshOptions("sphere", level=1)


def small_series() -> TimeSeries:
    points = np.eye(3)
    return TimeSeries(points, np.array([[0, 1, 2]]), [0.0, 1.0], {"u_m": np.ones((2, 3))})


def users_h5(path: Path) -> bytes:
    with h5py.File(path, "w") as h5:
        h5["measurements"] = np.arange(5.0)
        h5.attrs["owner"] = "me"
    return path.read_bytes()


@pytest.mark.parametrize("kind", ["hdf5", "text", "folder"])
def test_export_refuses_a_users_h5_before_any_work(tmp_path, kind):
    side = tmp_path / "x.h5"
    if kind == "hdf5":
        before = users_h5(side)
    elif kind == "text":
        side.write_text("my notes")
        before = side.read_bytes()
    else:
        side.mkdir()
        before = None
    said: list[str] = []
    with pytest.raises(twoball.ParameterError) as error:
        solver = twoball.Superposition(MESH)
        twoball.export(tmp_path / "x.xdmf", solver=solver, frames=2, progress=said.append)
    assert error.value.name == "out" and "x.h5" in str(error.value)
    assert said == []  # refused before any solve
    assert sorted(p.name for p in tmp_path.iterdir()) == ["x.h5"]
    if before is not None:
        assert side.read_bytes() == before


def test_cli_refuses_a_users_h5_in_one_line(tmp_path):
    before = users_h5(tmp_path / "x.h5")
    done = subprocess.run(
        [sys.executable, "-m", "twoball", "export", "--level", "1", "--out", tmp_path / "x.xdmf"],
        capture_output=True,
        text=True,
        cwd="/",
        env={"PYTHONPATH": str(ROOT), "OPENBLAS_NUM_THREADS": "1", "PATH": "/usr/bin:/bin"},
        timeout=120,
    )
    assert done.returncode == 2
    lines = done.stderr.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("twoball: error: --out must be"), lines
    assert "x.h5" in lines[0]
    assert (tmp_path / "x.h5").read_bytes() == before


def test_twoballs_own_h5_is_replaced(tmp_path):
    out = tmp_path / "x.xdmf"
    write_series(out, small_series())
    assert is_twoball_h5(out.with_suffix(".h5"))
    series = small_series()
    series = TimeSeries(series.points, series.cells, [0.0, 2.0], series.point_data)
    write_series(out, series)
    assert read_series(out).times.tolist() == [0.0, 2.0]


def test_an_h5_of_twoball_0_2_is_recognised_by_its_provenance(tmp_path):
    side = tmp_path / "x.h5"
    provenance = {"twoball": "0.2.0", "versions": {"twoball": "0.2.0"}, "command": "twoball export"}
    with h5py.File(side, "w") as h5:
        h5.attrs["provenance"] = json.dumps(provenance)
    assert is_twoball_h5(side)
    check_side_entries(tmp_path / "x.xdmf")  # no error
    with h5py.File(side, "w") as h5:
        h5.attrs["provenance"] = json.dumps({"versions": {}})  # someone else's provenance
    assert not is_twoball_h5(side)
    users_h5(side)
    assert not is_twoball_h5(side)
    with h5py.File(side, "r") as h5:
        assert H5_MARK not in h5.attrs


def test_a_users_h5_put_there_during_the_run_is_not_replaced(tmp_path):
    out = tmp_path / "x.xdmf"
    side = tmp_path / "x.h5"
    with pytest.raises(twoball.ParameterError):
        with staged_collection(out, ours=is_twoball_h5) as scratch:
            (scratch / "x.xdmf").write_text("<Xdmf/>")
            (scratch / "x.h5").write_bytes(b"new")
            before = users_h5(side)  # appears after the early check, before the commit
    assert side.read_bytes() == before and not out.exists()


def test_pvd_refuses_a_frames_folder_it_did_not_write(tmp_path):
    out = tmp_path / "x.pvd"
    write_series(out, small_series())  # twoball's own folder: accepted on the next run
    write_series(out, small_series())
    foreign = tmp_path / "x_frames-0123456789ab"
    foreign.mkdir()
    (foreign / "x_0000.vtu").write_text("mine")
    said: list[str] = []
    with pytest.raises(twoball.ParameterError) as error:
        twoball.export(out, solver=twoball.Superposition(MESH), frames=2, progress=said.append)
    assert "x_frames-0123456789ab" in str(error.value) and said == []
    assert (foreign / "x_0000.vtu").read_text() == "mine"
    (tmp_path / "x_frames-0123456789ab" / "x_0000.vtu").unlink()
    foreign.rmdir()
    (tmp_path / "x_frames-fedcba987654").write_text("a file, not a folder")
    with pytest.raises(twoball.ParameterError):
        write_series(out, small_series())


# --------------------------------------------------------------------------- the whole bounce
@pytest.fixture(scope="module")
def whole_exports(tmp_path_factory):
    """One whole bounce (basketball and tennis ball, touching, N = 64) in every format."""
    folder = tmp_path_factory.mktemp("whole")
    solver = twoball.MoreauJean(twoball.LegendreBall(64))
    report = twoball.bounce(solver=solver, pair="basketball-tennis")
    mesh = twoball.MeshOptions("sphere", level=1)
    files = {}
    for fmt in FORMATS:
        frames = 1 if fmt == "vtu" else 3
        files[fmt] = report.export(folder / f"w.{fmt}", frames=frames, mesh=mesh)[0]
    return report, files


@pytest.mark.parametrize("reader", READERS)
@pytest.mark.parametrize("fmt", FORMATS)
def test_the_whole_bounces_events_travel_with_every_export(whole_exports, fmt, reader):
    """Both contacts' events (contact, kind, time, both velocities) read back in meshio,
    pyvista and VTK as the report gives them: the JSON text ``contact_events`` (UTF-8
    bytes) and the counts as numbers; the body's start in contact at t = 0 among them."""
    report, files = whole_exports
    out = files[fmt]
    if reader == "meshio" and fmt == "xdmf":  # the metadata: XML and HDF5 beside meshio
        with h5py.File(out.with_suffix(".h5"), "r") as h5:
            fields = {name: h5[f"text/{name}"][()] for name in h5["text"]}
            numbers = {k: v for k, v in h5.attrs.items() if not isinstance(v, str)}
            fields |= {name: np.array([value]) for name, value in numbers.items()}
        frames = [{"field_data": fields}]
    else:
        frames = read_with(reader, fmt, out)
    expected = json.loads(json.dumps(report.events))
    body = [e for e in expected if e["contact"] == "body"]
    assert body[0]["kind"] == "touch" and body[0]["t_s"] == 0.0  # started touching
    assert body[1]["kind"] == "separation" and body[1]["t_s"] == 0.0  # the top dropped away
    for frame in frames:
        fields = frame["field_data"]
        events = json.loads(text_value(fields["contact_events"]))
        assert events == expected
        assert {e["contact"] for e in events} == {"floor", "body"}
        assert float(np.ravel(fields["events"])[0]) == len(expected)
        touches = sum(1 for e in expected if e["contact"] == "body" and e["kind"] == "touch")
        assert float(np.ravel(fields["body_contacts"])[0]) == touches
        assert float(np.ravel(fields["v1_ratio"])[0]) == report.v1_ratio
