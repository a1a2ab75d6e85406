"""Outputs never lose data: user folders, symbolic links, interrupts, full disks, workers.

Every writing subcommand is pointed at folders holding a user's files; the
interrupt tests run ``python -m twoball`` in a subprocess that stops at a named
stage of :mod:`twoball._common.staging` (``TWOBALL_TEST_PAUSE``) and signal it there.
"""

from __future__ import annotations

import json
import os
import re
import select
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest
from twoball.verify.output.series import read_series

from twoball._common.staging import MARKER, SCRATCH_TAG, foreign_entry, sweep_stale
from twoball.cli.main import main

ROOT = Path(__file__).resolve().parents[1]
FAST = ["--level", "1"]

# subcommand -> argv writing to OUT (a file path for file writers, a folder otherwise)
FILE_WRITERS = {
    "export": ["export", *FAST, "--frames", "2", "--out"],
    "render": ["render", *FAST, "--size", "64x48", "--out"],
    "plot": ["plot", "pole", *FAST, "--out"],
    "sweep": ["sweep", "--param", "damping", "--values", "0.1:0.2:2", "--plot"],
}
SUFFIX = {"export": ".pvd", "render": ".png", "plot": ".png", "sweep": ".png"}
FOLDER_WRITERS = {
    "verify": ["verify", "--fast", "--out"],
    "converge": ["converge", "modes", "--modes-list", "30,60,120", "--out"],
    "reproduce": ["reproduce", "--only", "table2", "--out"],
}


def snapshot(folder: Path) -> dict[str, bytes | None]:
    """Every entry below ``folder``: file contents, None for folders, link targets as bytes."""
    entries: dict[str, bytes | None] = {}
    for path in sorted(folder.rglob("*")):
        name = path.relative_to(folder).as_posix()
        if path.is_symlink():
            entries[name] = b"->" + os.fsencode(os.readlink(path))
        elif path.is_dir():
            entries[name] = None
        else:
            entries[name] = path.read_bytes()
    return entries


#: A progress line (twoball._common.progress): ``twoball: verify: 3/12 ... (14 s)``.
PROGRESS = re.compile(r"twoball: [\w -]+: .*\(\d+ s\)$")


def messages(err: str) -> list[str]:
    """The lines of standard error that are not progress lines."""
    return [line for line in err.strip().splitlines() if line and not PROGRESS.fullmatch(line)]


def refused(capsys, argv: list[str]) -> str:
    """Run ``argv`` in process; it must exit 2 with one line; return that line."""
    capsys.readouterr()  # earlier runs' output
    with pytest.raises(SystemExit) as stop:
        main(argv)
    err = capsys.readouterr().err.strip().splitlines()
    assert stop.value.code == 2 and len(err) == 1, err
    return err[0]


def user_folder(tmp_path: Path, kind: str) -> Path:
    """A user's folder that merely looks like twoball output."""
    folder = tmp_path / "notes"
    (folder / "sub").mkdir(parents=True)
    (folder / "sub" / "data.txt").write_text("mine")
    (folder / "precious.txt").write_text("precious")
    if kind == "reproduction.md":
        (folder / "reproduction.md").write_text("my own notes")
    elif kind == "legacy-marker":
        (folder / ".twoball-report").write_text("")
        (folder / "report.md").write_text("")
    else:  # a marker that does not list the user's files
        (folder / MARKER).write_text(json.dumps({"written_by": "x", "files": ["report.md"]}))
        (folder / "report.md").write_text("")
    return folder


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
    (tmp_path / "x_frames-000000000000").mkdir()  # looks like ours, has no marker
    (tmp_path / "x_frames-000000000000" / "keep.txt").write_text("mine")
    before = snapshot(tmp_path)
    for frames in ("2", "3"):
        assert main(["export", *FAST, "--frames", frames, "--out", str(tmp_path / "x.pvd")]) == 0
    after = snapshot(tmp_path)
    assert all(after[name] == content for name, content in before.items())
    assert len(read_series(tmp_path / "x.pvd")) == 4  # 3 frames + the lift-off instant
    capsys.readouterr()


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


# --------------------------------------------------------------------------- subprocesses
def start(argv: list[str], pause: str | None = None, **kwargs) -> subprocess.Popen:
    env = dict(os.environ, OPENBLAS_NUM_THREADS="1", PYTHONPATH=str(ROOT))
    env.pop("TWOBALL_TEST_PAUSE", None)
    if pause is not None:
        env["TWOBALL_TEST_PAUSE"] = pause
    return subprocess.Popen(
        [sys.executable, "-m", "twoball", *argv],
        cwd=ROOT,
        env=env,
        stdout=kwargs.pop("stdout", subprocess.DEVNULL),
        stderr=subprocess.PIPE,
        **kwargs,
    )


def wait_for_pause(process: subprocess.Popen, stage: str, timeout: float = 120.0) -> None:
    """Read standard error until the process says it stopped at ``stage``."""
    end = time.monotonic() + timeout
    line = b""
    while time.monotonic() < end:
        ready, _, _ = select.select([process.stderr], [], [], 0.5)
        if ready:
            line = process.stderr.readline()
            if line.strip() == f"twoball-test-pause: {stage}".encode():
                return
            if not line and process.poll() is not None:
                break
    process.kill()
    raise AssertionError(f"never reached {stage}: {line!r}, status {process.poll()}")


def children(pid: int) -> list[int]:
    found = []
    for entry in Path("/proc").iterdir():
        if entry.name.isdigit():
            try:
                fields = (entry / "stat").read_text().rsplit(")", 1)[1].split()
            except OSError:
                continue
            if int(fields[1]) == pid:
                found.append(int(entry.name))
    return found


def running(pid: int) -> bool:
    try:
        state = Path(f"/proc/{pid}/stat").read_text().rsplit(")", 1)[1].split()[0]
    except OSError:
        return False
    return state not in ("Z", "X")


def interrupt(argv: list[str], stage: str, signum: int) -> tuple[int, list[int]]:
    """Run ``argv`` to ``stage``, send ``signum``; return the status and the children seen."""
    process = start(argv, stage)
    wait_for_pause(process, stage)
    kids = children(process.pid)
    process.send_signal(signum)
    _, err = process.communicate(timeout=60)
    lines = messages(err.decode())  # progress lines may come before the interrupt
    assert "Traceback" not in err.decode(), err.decode()
    assert lines == ["twoball: interrupted"], lines
    return process.returncode, kids


def no_scratch(folder: Path) -> None:
    assert [p.name for p in folder.iterdir() if SCRATCH_TAG in p.name] == []


SIGNALS = [(signal.SIGINT, 130), (signal.SIGTERM, 143)]
POOL_SWEEP = ["sweep", "--param", "damping", "--values", "0:0.3:40", "--workers", "2"]


@pytest.mark.parametrize("stage", ["begin", "staged", "commit"])
@pytest.mark.parametrize(("signum", "status"), SIGNALS)
def test_interrupted_pvd_export_keeps_a_whole_collection(tmp_path, stage, signum, status):
    out = tmp_path / "x.pvd"
    assert start(["export", *FAST, "--frames", "2", "--out", str(out)]).wait() == 0
    old = snapshot(tmp_path)
    code, _ = interrupt(["export", *FAST, "--frames", "3", "--out", str(out)], stage, signum)
    assert code == status
    no_scratch(tmp_path)
    now = snapshot(tmp_path)
    frames = [p for p in tmp_path.iterdir() if p.name.startswith("x_frames-")]
    assert len(frames) == 1 and foreign_entry(frames[0]) is None  # one collection, whole
    if stage == "commit":  # signals wait for the commit: the new collection is in place
        assert len(read_series(out)) == 4
    else:
        assert now == old


@pytest.mark.parametrize(("signum", "status"), SIGNALS)
def test_interrupted_xdmf_export_keeps_the_pair(tmp_path, signum, status):
    out = tmp_path / "x.xdmf"
    assert start(["export", *FAST, "--frames", "2", "--out", str(out)]).wait() == 0
    old = snapshot(tmp_path)
    code, _ = interrupt(["export", *FAST, "--frames", "3", "--out", str(out)], "staged", signum)
    assert code == status and snapshot(tmp_path) == old


@pytest.mark.parametrize(
    ("command", "stage", "signum", "status"),
    [
        ("verify", "staged", signal.SIGINT, 130),
        ("verify", "commit", signal.SIGTERM, 143),
        ("reproduce", "begin", signal.SIGTERM, 143),
        ("reproduce", "commit", signal.SIGINT, 130),
    ],
)
def test_interrupted_report_folder_is_old_or_new_whole(tmp_path, command, stage, signum, status):
    out = tmp_path / "out"
    assert start([*FOLDER_WRITERS[command], str(out)]).wait() == 0
    old = snapshot(tmp_path)
    code, _ = interrupt([*FOLDER_WRITERS[command], str(out)], stage, signum)
    assert code == status
    no_scratch(tmp_path)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["out"]
    assert foreign_entry(out) is None
    listed = json.loads((out / MARKER).read_text())["files"]
    assert all((out / name).is_file() for name in listed)  # complete, old or new
    if stage != "commit":
        assert snapshot(tmp_path) == old


@pytest.mark.parametrize(("signum", "status"), SIGNALS)
def test_interrupted_render_leaves_the_earlier_picture(tmp_path, signum, status):
    out = tmp_path / "ball.png"
    out.write_bytes(b"an earlier picture")
    code, _ = interrupt([*FILE_WRITERS["render"], str(out)], "staged", signum)
    assert code == status and out.read_bytes() == b"an earlier picture"
    no_scratch(tmp_path)


@pytest.mark.parametrize(
    ("argv", "signum", "status"),
    [
        (POOL_SWEEP, signal.SIGINT, 130),
        (POOL_SWEEP, signal.SIGTERM, 143),
        (["reproduce", "--only", "table2", "--workers", "2"], signal.SIGTERM, 143),
    ],
)
def test_interrupt_ends_pool_workers(tmp_path, argv, signum, status):
    extra = ["--plot", str(tmp_path / "s.png")] if argv[0] == "sweep" else []
    extra = extra or ["--out", str(tmp_path / "rep")]
    code, kids = interrupt([*argv, *extra], "pool", signum)
    assert code == status and len(kids) >= 2
    end = time.monotonic() + 10
    while any(running(k) for k in kids) and time.monotonic() < end:
        time.sleep(0.05)
    assert not any(running(k) for k in kids)
    assert list(tmp_path.iterdir()) == []


def test_workers_die_with_a_killed_parent(tmp_path):
    process = start(POOL_SWEEP, "pool")
    wait_for_pause(process, "pool")
    kids = children(process.pid)
    process.kill()  # SIGKILL: no finally runs; PR_SET_PDEATHSIG ends the workers
    process.wait()
    end = time.monotonic() + 10
    while any(running(k) for k in kids) and time.monotonic() < end:
        time.sleep(0.05)
    assert len(kids) >= 2 and not any(running(k) for k in kids)


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


@pytest.mark.parametrize(
    "argv",
    [["liftoff", "--json"], ["sweep", "--param", "damping", "--values", "0.1:0.2:2", "--json"]],
)
def test_full_stdout_is_one_line(argv):
    with open("/dev/full", "wb") as full:
        process = start(argv, stdout=full)
        _, err = process.communicate(timeout=120)
    lines = err.decode().strip().splitlines()
    assert process.returncode == 2 and lines == [
        "twoball: error: cannot write standard output: No space left on device"
    ]


def test_an_unfinished_mp4_is_an_error_not_a_file(tmp_path):
    from twoball.verify.output.render import _check_mp4, _mp4_boxes

    box = (16).to_bytes(4, "big") + b"ftyp" + b"isom" + b"\0" * 4
    whole = tmp_path / "whole.mp4"
    whole.write_bytes(box + (8).to_bytes(4, "big") + b"moov")
    assert _mp4_boxes(whole) == [b"ftyp", b"moov"]
    _check_mp4(whole)
    cut = tmp_path / "cut.mp4"  # ffmpeg could not write its trailer (index)
    cut.write_bytes(box + (4096).to_bytes(4, "big") + b"mdat" + b"\0" * 100)
    with pytest.raises(OSError, match="cut.mp4"):
        _check_mp4(cut)


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
