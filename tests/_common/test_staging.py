"""Outputs never lose data (twoball._common.staging): user folders, links, full disks.

Every writing subcommand is pointed at folders holding a user's files; the earlier
output is replaced whole or kept whole, never mixed.
"""

from __future__ import annotations

import json
import os
import subprocess
import sys

import pytest

from tests._common.commands import (
    FAST,
    FILE_WRITERS,
    FOLDER_WRITERS,
    SUFFIX,
    messages,
    refused,
    snapshot,
    start,
    user_folder,
)
from twoball._common.staging import MARKER, SCRATCH_TAG, foreign_entry, sweep_stale
from twoball.cli.main import main
from twoball.verify.output.series import read_series


# --------------------------------------------------------------------------- full disk
@pytest.fixture
def small_disk(tmp_path):
    """A 160 kB tmpfs (needs root and mount); skipped where it cannot be made."""
    mount = tmp_path / "disk"
    mount.mkdir()
    done = subprocess.run(
        ["mount", "-t", "tmpfs", "-o", "size=160k", "tmpfs", str(mount)], capture_output=True
    )
    if done.returncode != 0:
        pytest.skip("cannot mount a small tmpfs here")
    yield mount
    subprocess.run(["umount", str(mount)], check=False)


# --------------------------------------------------------------------------- user folders
@pytest.mark.parametrize("kind", ["reproduction.md", "legacy-marker", "marker"])
@pytest.mark.parametrize("command", list(FOLDER_WRITERS))
def test_folder_writers_refuse_user_folders(capsys, tmp_path, command, kind):
    folder = user_folder(tmp_path, kind)
    before = snapshot(tmp_path)
    line = refused(capsys, [*FOLDER_WRITERS[command], str(folder)])
    assert "--out" in line and ("precious.txt" in line or "sub" in line)
    assert snapshot(tmp_path) == before


@pytest.mark.parametrize("command", list(FOLDER_WRITERS) + list(FILE_WRITERS))
def test_symlinked_out_is_refused_and_leaves_no_hidden_entry(capsys, tmp_path, command):
    if command in FOLDER_WRITERS:
        target = tmp_path / "real"
        target.mkdir()
        argv = FOLDER_WRITERS[command]
    else:
        target = tmp_path / f"real{SUFFIX[command]}"
        target.write_text("precious")
        argv = FILE_WRITERS[command]
    link = tmp_path / f"link{SUFFIX.get(command, '')}"
    link.symlink_to(target)
    before = snapshot(tmp_path)
    line = refused(capsys, [*argv, str(link)])
    assert "symbolic link" in line
    assert snapshot(tmp_path) == before


@pytest.mark.parametrize("command", list(FILE_WRITERS))
def test_file_writers_refuse_a_folder_and_keep_neighbours(capsys, tmp_path, command):
    folder = tmp_path / f"mine{SUFFIX[command]}"
    folder.mkdir()
    (folder / "precious.txt").write_text("precious")
    (tmp_path / "notes.txt").write_text("beside")
    before = snapshot(tmp_path)
    assert "--" in refused(capsys, [*FILE_WRITERS[command], str(folder)])
    assert snapshot(tmp_path) == before


def test_export_keeps_user_files_beside_the_collection(capsys, tmp_path):
    (tmp_path / "x_0000.vtu").write_text("a user's file with a frame's name")
    before = snapshot(tmp_path)
    for frames in ("2", "3"):
        assert main(["export", *FAST, "--frames", frames, "--out", str(tmp_path / "x.pvd")]) == 0
    after = snapshot(tmp_path)
    assert all(after[name] == content for name, content in before.items())
    assert len(read_series(tmp_path / "x.pvd")) == 4  # 3 frames + the lift-off instant
    # a folder named like a frames folder that twoball did not write: refused, kept
    (tmp_path / "x_frames-000000000000").mkdir()
    (tmp_path / "x_frames-000000000000" / "keep.txt").write_text("mine")
    before = snapshot(tmp_path)
    line = refused(capsys, ["export", *FAST, "--frames", "2", "--out", str(tmp_path / "x.pvd")])
    assert "x_frames-000000000000" in line and snapshot(tmp_path) == before


def test_earlier_twoball_output_is_replaced(capsys, tmp_path):
    out = tmp_path / "rep"
    assert main([*FOLDER_WRITERS["reproduce"], str(out)]) == 0
    assert foreign_entry(out) is None
    listed = json.loads((out / MARKER).read_text())["files"]
    assert sorted(listed) == sorted(p.name for p in out.iterdir() if p.name != MARKER)
    (out / "added-by-user.txt").write_text("mine")
    assert "added-by-user.txt" in refused(capsys, [*FOLDER_WRITERS["reproduce"], str(out)])
    assert (out / "added-by-user.txt").read_text() == "mine"


def test_stale_scratch_of_a_killed_run_is_swept(tmp_path):
    dead = subprocess.Popen([sys.executable, "-c", "pass"])
    dead.wait()
    target = tmp_path / "x.png"
    stale = tmp_path / f".x.png.{SCRATCH_TAG}-{dead.pid}-0badf00d"
    stale.mkdir()
    (stale / "x.png").write_bytes(b"half")
    alive = tmp_path / f".x.png.{SCRATCH_TAG}-{os.getppid()}-0badf00d"
    alive.mkdir()
    assert sweep_stale(target) == [stale]
    assert not stale.exists() and alive.exists()


@pytest.mark.parametrize(
    "argv",
    [
        ["export", "--level", "2", "--frames", "20", "--out", "{disk}/x.xdmf"],
        ["export", "--level", "2", "--frames", "20", "--out", "{disk}/x.pvd"],
        ["render", *FAST, "--out", "{disk}/x.gif", "--frames", "4"],
        ["render", *FAST, "--out", "{disk}/x.mp4", "--frames", "60", "--size", "320x240"],
        ["plot", "pole", *FAST, "--out", "{disk}/p.png"],
        ["sweep", "--param", "damping", "--values", "0.1:0.2:3", "--plot", "{disk}/s.png"],
        ["verify", "--fast", "--out", "{disk}/rep"],
        ["reproduce", "--only", "fig6", "--out", "{disk}/rep"],
    ],
)
def test_full_disk_is_one_line_and_keeps_earlier_output(small_disk, argv):
    (small_disk / "earlier.vtu").write_text("earlier output")
    (small_disk / "filler").write_bytes(b"\0" * 140_000)  # about 16 kB left
    before = snapshot(small_disk)
    process = start([a.format(disk=small_disk) for a in argv])
    _, err = process.communicate(timeout=300)
    lines = messages(err.decode())  # progress lines may come before the error
    assert process.returncode == 2, err.decode()
    assert len(lines) == 1 and "No space left on device" in lines[0], lines
    assert str(small_disk) in lines[0]
    assert snapshot(small_disk) == before  # nothing new, nothing lost, no scratch


def test_same_inputs_give_byte_identical_data_files(capsys, tmp_path):
    runs = {}
    for name in ("a", "b"):
        assert main(["reproduce", "--only", "table2", "--out", str(tmp_path / f"r{name}")]) == 0
        assert main(["verify", "--fast", "--json", "--out", str(tmp_path / f"v{name}")]) == 0
        runs[name] = {
            **{f"r/{p.name}": p.read_bytes() for p in (tmp_path / f"r{name}").iterdir()},
            **{f"v/{p.name}": p.read_bytes() for p in (tmp_path / f"v{name}").iterdir()},
        }
    capsys.readouterr()
    data = [n for n in runs["a"] if n.endswith((".json", ".csv", ".png", MARKER))]
    data = [n for n in data if not n.endswith("provenance.json")]
    assert {"r/reproduction.json", "v/results.json", "v/results.csv", "v/pole.png"} <= set(data)
    for name in data:
        assert runs["a"][name] == runs["b"][name], name
    provenance = json.loads(runs["a"]["v/provenance.json"])
    assert provenance["seconds"]["seconds"] > 0 and "generated" in provenance


# --------------------------------------------------------------------------- read-only mounts
@pytest.fixture
def read_only_mounts(tmp_path):
    """A read-only tmpfs folder and a file bind-mounted read-only (root and mount only)."""
    folder, source, file = tmp_path / "ro-folder", tmp_path / "source.png", tmp_path / "ro.png"
    folder.mkdir()
    source.write_bytes(b"earlier picture")
    file.write_bytes(b"")
    steps = [
        ["mount", "-t", "tmpfs", "-o", "size=64k", "tmpfs", str(folder)],
        ["mount", "-o", "remount,ro", str(folder)],
        ["mount", "--bind", str(source), str(file)],
        ["mount", "-o", "remount,bind,ro", str(file)],
    ]
    for step in steps:
        if subprocess.run(step, capture_output=True).returncode != 0:
            for mounted in (file, folder):
                subprocess.run(["umount", str(mounted)], capture_output=True)
            pytest.skip("cannot mount here")
    yield folder, file
    for mounted in (file, folder):
        subprocess.run(["umount", str(mounted)], check=False)


@pytest.mark.parametrize(
    ("argv", "flag", "which"),
    [
        (FOLDER_WRITERS["converge"], "--out", "folder"),
        (FILE_WRITERS["plot"], "--out", "file"),
        (["liftoff", "--mass-ratio", "0.1", "--modes", "10", "--plot"], "--plot", "file"),
        (["bounce", "--modes", "16", "--render"], "--render", "file"),
    ],
)
def test_an_existing_output_on_a_read_only_mount_is_refused_before_work(
    capsys, read_only_mounts, argv, flag, which
):
    """The rename that would replace a mount point fails: said before any work, naming it."""
    folder, file = read_only_mounts
    target = folder if which == "folder" else file
    line = refused(capsys, [*argv, str(target)])
    assert line.startswith(f"twoball: error: {flag} must be ") and "mount point" in line, line
    assert file.read_bytes() == b"earlier picture"


def test_outputs_onto_inputs_or_each_other_are_refused(capsys, tmp_path):
    """--out onto the --mesh-file, --render onto --plot: refused, nothing replaced."""
    import meshio

    from twoball.fem_membrane.mesh import icosphere

    ball = icosphere(2)
    mesh = tmp_path / "in.vtu"
    meshio.write(mesh, meshio.Mesh(0.12 * ball.points, [("triangle", ball.cells)]))
    (tmp_path / "same.png").write_bytes(b"earlier picture")
    before = snapshot(tmp_path)
    line = refused(capsys, ["export", "--mesh-file", str(mesh), "--out", str(mesh)])
    assert line.startswith("twoball: error: --out must be a path other than the input mesh file")
    same = str(tmp_path / "same.png")
    line = refused(capsys, ["bounce", "--plot", same, "--render", same])
    assert line.startswith("twoball: error: --render must be a path other than the output of")
    assert line.endswith("--plot, got '" + same + "'")
    assert snapshot(tmp_path) == before
