"""Side entries the user did not name (``NAME.h5``, ``NAME_frames-*``) are replaced only if
twoball wrote them; anything else is refused before any work, and left as it was."""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import h5py
import numpy as np
import pytest
from twoball.verify.output.series import (
    H5_MARK,
    TimeSeries,
    check_side_entries,
    is_twoball_h5,
    read_series,
    write_series,
)

import twoball
from twoball._common.staging import staged_collection

ROOT = Path(__file__).resolve().parents[3]
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
        twoball.export(tmp_path / "x.xdmf", mesh=MESH, frames=2, progress=said.append)
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
        twoball.export(out, mesh=MESH, frames=2, progress=said.append)
    assert "x_frames-0123456789ab" in str(error.value) and said == []
    assert (foreign / "x_0000.vtu").read_text() == "mine"
    (tmp_path / "x_frames-0123456789ab" / "x_0000.vtu").unlink()
    foreign.rmdir()
    (tmp_path / "x_frames-fedcba987654").write_text("a file, not a folder")
    with pytest.raises(twoball.ParameterError):
        write_series(out, small_series())
