"""twoball eigen: the JSON table of eigenvalue clusters."""

import json
import subprocess
import sys

from tests.helpers import cli_run


def test_eigen_json_lists_clusters(capsys):
    code, out, _ = cli_run(
        capsys, "eigen", "--mesh", "sphere", "--level", "1", "--count", "8", "--json"
    )
    rows = json.loads(out)["results"]
    assert code == 0 and [r["l"] for r in rows[:4]] == [0, 1, 1, 1]
    assert all(r["multiplicity"] == 2 * r["l"] + 1 for r in rows)


def _cli(*args: str) -> subprocess.CompletedProcess[str]:
    return subprocess.run([sys.executable, "-m", "twoball", "--quiet", *args],
                          capture_output=True, text=True, timeout=300)  # fmt: skip


def test_eigen_command_lists_n_minus_1_n_plus_2():
    done = _cli("eigen", "--mesh", "axisym", "--elements", "50", "--order", "3", "--count", "5",
                "--membrane", "pressurised", "--json")  # fmt: skip
    assert done.returncode == 0, done.stderr
    rows = json.loads(done.stdout)["results"]
    assert [r["exact"] for r in rows] == [-2.0, 0.0, 4.0, 10.0, 18.0, 28.0]
    assert abs(rows[1]["value"]) < 1e-11
