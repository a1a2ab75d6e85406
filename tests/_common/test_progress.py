"""Progress on standard error: lines in a log, nothing with --quiet, the data unchanged.

The commands run in fresh processes with standard output and error piped (not a
terminal), as in a CI log.  Each runs twice at once, with and without ``--quiet``;
the two must write the same data, and only the loud one prints progress lines.
"""

from __future__ import annotations

import io
import json
import math
import os
import re
import subprocess
import sys
import time
from pathlib import Path

import imageio.v3 as iio
import numpy as np
import pytest

from tests import ROOT
from twoball._common.errors import ParameterError
from twoball._common.progress import INTERVAL, Reporter, is_quiet, set_quiet
from twoball.verify.output.report_files import split_provenance
from twoball.verify.output.series import read_series

LINE = re.compile(r"twoball: (?P<name>[\w -]+): (?P<text>.*) \((?P<seconds>\d+) s\)")


def progress_lines(err: str, name: str) -> list[str]:
    return [line for line in err.splitlines() if line.startswith(f"twoball: {name}: ")]


def start(argv: list[str], cwd: Path) -> subprocess.Popen:
    env = dict(os.environ, OPENBLAS_NUM_THREADS="1", PYTHONPATH=str(ROOT))
    return subprocess.Popen(
        [sys.executable, "-m", "twoball", *argv],
        cwd=cwd,
        env=env,
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
    )


def same_json(a: Path, b: Path) -> bool:
    return a.read_bytes() == b.read_bytes()


def same_series(a: Path, b: Path) -> bool:
    x, y = read_series(a), read_series(b)
    return x.field_data == y.field_data and all(
        np.array_equal(x.point_data[n], y.point_data[n]) for n in x.point_data
    )


def same_image(a: Path, b: Path) -> bool:
    return np.array_equal(iio.imread(a), iio.imread(b))


COMMANDS = {
    "verify": (["verify", "--fast", "--json", "--out", "{out}"], "results.json", same_json),
    "converge modes": (
        ["converge", "modes", "--modes-list", "30,60,120", "--out", "{out}"],
        "results.json",
        same_json,
    ),
    "export": (
        ["export", "--level", "1", "--order", "1", "--frames", "2", "--out", "{out}.xdmf"],
        "",
        same_series,
    ),
    "render": (
        ["render", "--level", "1", "--size", "160x120", "--out", "{out}.png"],
        "",
        same_image,
    ),
    "plot eigen": (
        ["plot", "eigen", "--levels", "1", "--orders", "1", "--out", "{out}.png"],
        "",
        same_image,
    ),
}


def test_lines_first_rate_limited_and_last():
    stream = io.StringIO()
    with Reporter("demo", total=50, stream=stream, interval=1e6) as report:
        for k in range(50):
            report(f"step {k}")
    lines = stream.getvalue().splitlines()
    # the first step at once, none of the next 49 (rate limit), then the last line
    assert [LINE.fullmatch(line)["text"] for line in lines] == ["1/50 step 0", "done 50/50"]


def test_a_long_step_gets_periodic_lines():
    stream = io.StringIO()
    with Reporter("demo", stream=stream, interval=0.05) as report:
        report("one long step")
        deadline = time.monotonic() + 30
        while stream.getvalue().count("\n") < 3 and time.monotonic() < deadline:
            time.sleep(0.05)  # the background thread prints while the step runs
    lines = stream.getvalue().splitlines()
    assert len(lines) >= 4 and lines[-1].startswith("twoball: demo: done (")
    assert all(LINE.fullmatch(line)["text"] == "one long step" for line in lines[:-1])


def test_tasks_count_and_quick_or_quiet_work_is_silent():
    stream = io.StringIO()
    with Reporter("demo", stream=stream, interval=1e6) as report:
        update = report.task("solves", 8)
        for k in range(8):
            update(k + 1)
    assert stream.getvalue().splitlines()[0] == "twoball: demo: solves 0/8 (0 s)"
    quick = io.StringIO()
    with Reporter("demo", stream=quick, delay=1e6) as report:
        report("fast")
    set_quiet(True)
    try:
        with Reporter("demo", stream=quick) as report:
            report("anything")
            report.task("solves", 3)(3)
    finally:
        set_quiet(False)
    assert quick.getvalue() == "" and not is_quiet()


def test_errors_leave_no_done_line():
    stream = io.StringIO()
    with pytest.raises(ValueError), Reporter("demo", stream=stream) as report:
        report("about to fail")
        raise ValueError
    assert stream.getvalue().splitlines() == ["twoball: demo: about to fail (0 s)"]


@pytest.mark.parametrize("name", list(COMMANDS))
def test_progress_lines_in_a_log_and_none_when_quiet(tmp_path, name):
    argv, inside, same = COMMANDS[name]
    runs = {}
    for quiet in (False, True):
        out = tmp_path / ("quiet" if quiet else "loud")
        words = [a.format(out=out) for a in argv]
        if quiet:  # --quiet before the subcommand for one command, after it for the others
            words = ["--quiet", *words] if name == "render" else [*words, "--quiet"]
        runs[quiet] = (start(words, tmp_path), out)
    done = {}
    for quiet, (process, out) in runs.items():
        stdout, err = process.communicate(timeout=600)
        assert process.returncode == 0, err
        done[quiet] = (stdout, err, out)
    (loud_out, loud_err, loud), (quiet_out, quiet_err, quiet) = done[False], done[True]
    lines = progress_lines(loud_err, name)
    assert lines and all(LINE.fullmatch(line) for line in lines), loud_err
    assert LINE.fullmatch(lines[-1])["text"].startswith("done")
    seconds = int(LINE.fullmatch(lines[-1])["seconds"])
    assert len(lines) <= 2 + seconds / INTERVAL + 1  # rate-limited: first, periodic, last
    assert progress_lines(quiet_err, name) == []
    # warnings and notes still print with --quiet; progress never goes to standard output
    assert [ln for ln in loud_err.splitlines() if ln not in lines] == quiet_err.splitlines()
    assert "twoball: " + name not in loud_out
    # the data are the same either way
    suffix = "" if inside else Path(argv[-1]).suffix
    first = loud / inside if inside else loud.with_name(loud.name + suffix)
    second = quiet / inside if inside else quiet.with_name(quiet.name + suffix)
    assert same(first, second)
    if name == "verify":  # --json on standard output: equal but for the command line and time
        drop = ("seconds", "provenance", "out")
        a, b = (split_provenance(json.loads(text), drop)[0] for text in (loud_out, quiet_out))
        assert a == b and a["passed"] is True


@pytest.mark.parametrize(
    ("name", "options", "valid"),
    [
        ("total", {"total": -1}, "an integer >= 0"),
        ("total", {"total": 2.5}, "an integer >= 0"),
        ("total", {"total": True}, "an integer >= 0"),
        ("interval", {"interval": math.nan}, "a finite number of seconds > 0"),
        ("interval", {"interval": 0.0}, "a finite number of seconds > 0"),
        ("interval", {"interval": "3"}, "a finite number of seconds > 0"),
        ("delay", {"delay": -1.0}, "a finite number of seconds >= 0"),
        ("delay", {"delay": math.inf}, "a finite number of seconds >= 0"),
    ],
)
def test_a_reporter_refuses_a_bad_argument_when_built(name, options, valid):
    with pytest.raises(ParameterError) as caught:
        Reporter("demo", **options)
    assert caught.value.name == name
    assert str(caught.value).startswith(f"{name} must be {valid}")


def test_a_reporter_keeps_the_edges_of_its_ranges():
    report = Reporter("demo", total=0, interval=1e-9, delay=0)
    assert (report.total, report.interval, report.delay) == (0, 1e-9, 0.0)
