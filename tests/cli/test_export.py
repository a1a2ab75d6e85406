"""twoball export: files from the command line, equal to the API's; bad input in one line."""

from __future__ import annotations

import json
import os
import xml.etree.ElementTree as ET

import meshio
import numpy as np
import pytest
import pyvista as pv

import twoball
from tests.helpers import text_of
from tests.meshes import OFF_NODE_POLES
from twoball.cli.main import main
from twoball.verify.output.series import read_series

FIELDS = ("u_m", "u_t_m_s", "u_tt_m_s2", "displacement_m", "u_fem_m", "u_legendre_m", "u_diff_m")


def run_cli(capsys, *argv):
    code = main(list(argv))
    return code, capsys.readouterr()


BASKETBALL = twoball.Case.preset("basketball")


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
    shown = pv.read(str(one)).field_data  # VTK's reader: the texts as UTF-8 bytes
    assert json.loads(text_of(shown["provenance"])) == json.loads(got.text["provenance"])
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


def test_cli_export_unwritable_out(tmp_path, read_only_folder, capsys):
    for folder in (tmp_path / "missing", read_only_folder):
        out = os.path.join(folder, "series.xdmf")
        with pytest.raises(SystemExit) as stop:
            main(["export", "--level", "1", "--out", out])
        err = capsys.readouterr().err
        assert stop.value.code == 2 and len(err.strip().splitlines()) == 1 and "--out" in err
        assert not os.path.exists(out)


def test_cli_and_api_give_identical_arrays(ball_files, tmp_path, capsys):
    cli, api = tmp_path / "cli.xdmf", tmp_path / "api.xdmf"
    pole = ",".join(str(c) for c in OFF_NODE_POLES[0])
    code = main(["export", "--mesh-file", str(ball_files["msh"]), "--pole", pole]
                + ["--frames", "3", "--out", str(cli)])  # fmt: skip
    assert code == 0 and "Exported fields" in capsys.readouterr().out
    mesh = twoball.MeshOptions(file=ball_files["msh"], pole=OFF_NODE_POLES[0])
    twoball.export(api, BASKETBALL, solver=twoball.Superposition(mesh), frames=3)
    a, b = read_series(cli), read_series(api)
    assert np.array_equal(a.points, b.points) and np.array_equal(a.cells, b.cells)
    assert np.array_equal(a.times, b.times)
    assert a.point_data.keys() == b.point_data.keys()
    for key in a.point_data:
        assert np.array_equal(a.point_data[key], b.point_data[key]), key
    assert a.field_data == b.field_data
    assert a.text["mesh_file"] == b.text["mesh_file"]
