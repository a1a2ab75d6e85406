"""Time series files (verify/output/series.py): XDMF/PVD/VTU hold every field, read back equal."""

from __future__ import annotations

import os

import numpy as np
import pytest
import pyvista as pv
from twoball.verify.output import series as export
from twoball.verify.output.series import TimeSeries, read_series, write_series

from tests.helpers import text_of
from tests.verify.output.nodal import closed_form, fem_values
from twoball._common.errors import ParameterError

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
        assert grid.field_data["case"][0] == sphere_series.text["case"]  # a VTK string array
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
