"""twoball eigen: the JSON table of eigenvalue clusters."""

import json

from tests.helpers import cli_run


def test_eigen_json_lists_clusters(capsys):
    code, out, _ = cli_run(
        capsys, "eigen", "--mesh", "sphere", "--level", "1", "--count", "8", "--json"
    )
    rows = json.loads(out)["results"]
    assert code == 0 and [r["l"] for r in rows[:4]] == [0, 1, 1, 1]
    assert all(r["multiplicity"] == 2 * r["l"] + 1 for r in rows)
