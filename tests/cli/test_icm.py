"""twoball icm: Table 1 and single cases of the independent collision model; bad input."""

import json

import pytest

from tests.helpers import cli_run
from twoball.cli.main import main


def test_icm_table1_rows_1_to_3_match(capsys):
    code, out, _ = cli_run(capsys, "icm", "--table1", "--json")
    rows = json.loads(out)["results"]
    assert code == 0 and len(rows) == 6
    for row in rows[:3]:
        assert not row["v1_differs"] and not row["v2_differs"]
        assert row["ours_v1_rounded"] == row["icm_v1"]
    assert any(r["v1_differs"] or r["v2_differs"] for r in rows[3:])
    code, out, _ = cli_run(capsys, "icm", "--table1")
    assert code == 0 and "DIFFERS" in out and "Table 1 recomputed" in out
    assert "0.488 *" in out and "1.516 *" not in out


def test_icm_single_case(capsys):
    # elastic, light upper ball, touching: v1 -> -3 v0 (eq. (2.7))
    code, out, _ = cli_run(capsys, "icm", "--mu", "0", "--e2", "1", "--e12", "1", "--json")
    data = json.loads(out)
    assert code == 0 and data["v1_ratio"] == pytest.approx(3.0)


@pytest.mark.parametrize(
    ("argv", "flag"),
    [
        (["icm", "--mu", "0.1"], "--e2"),
        (["icm", "--mu", "-1", "--e2", "0.5", "--e12", "0.5"], "--mu"),
        (["icm", "--mu", "0.1", "--e2", "1.5", "--e12", "0.5"], "--e2"),
        (["icm", "--mu", "0.1", "--e2", "0.5", "--e12", "-0.5"], "--e12"),
        (["icm", "--mu", "0.1", "--e2", "0.5", "--e12", "0.5", "--dx", "-1"], "--dx"),
    ],
)
def test_icm_bad_input(capsys, argv, flag):
    with pytest.raises(SystemExit) as stop:
        main(argv)
    err = capsys.readouterr().err.strip().splitlines()
    assert stop.value.code == 2 and len(err) == 1 and flag in err[0]
