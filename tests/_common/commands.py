"""The writing subcommands and the helpers that run them, for the staging and signal tests.

Every writing subcommand is pointed at folders holding a user's files; the
interrupt tests run ``python -m twoball`` in a subprocess that stops at a named
stage of :mod:`twoball._common.staging` (``TWOBALL_TEST_PAUSE``) and signal it there.
"""

from __future__ import annotations

import json
import os
import re
import select
import subprocess
import sys
import time
from pathlib import Path

import pytest

from tests import ROOT
from twoball._common.staging import MARKER, SCRATCH_TAG
from twoball.cli.main import main

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
    # during a commit too (the output complete): the summary's warnings may come first
    assert lines[-1:] == ["twoball: interrupted"], lines
    assert all(line.startswith("twoball: warning: ") for line in lines[:-1]), lines
    return process.returncode, kids


def no_scratch(folder: Path) -> None:
    assert [p.name for p in folder.iterdir() if SCRATCH_TAG in p.name] == []
