"""Provenance: twoball.report(), the block every JSON output and file carries, its one shape.

Versions are read with importlib.metadata; the tests compare them with the packages'
own ``__version__`` (imported here, an independent source) and the time with the
clock.
"""

from __future__ import annotations

import json
import platform
import sys
from datetime import UTC, datetime, timedelta

import matplotlib
import meshio
import numpy as np
import pytest
import scipy

import twoball
from twoball._common import provenance
from twoball.cli.main import main
from twoball.verify.output.report_files import PROVENANCE, result_files

KEYS = {"twoball", "versions", "platform", "generated", "command", "call", "case"}


def test_report_lists_the_installed_versions():
    report = twoball.report(additional=["mpmath", "no-such-distribution"])
    packages = report.packages
    assert packages["twoball"] == twoball.__version__
    python = ".".join(map(str, sys.version_info[:3]))
    assert packages["python"] == platform.python_version() == python
    for module in (np, scipy, meshio, matplotlib):
        name = module.__name__
        assert packages[name] == module.__version__, name
    assert packages["mpmath"] is not None and packages["no-such-distribution"] is None
    text = str(report)
    for name in ("twoball", "numpy", "scipy", "scikit-fem", "meshio", "matplotlib", "rich"):
        assert f" {name} : {packages[name]}" in text
    assert "no-such-distribution : not installed" in text
    assert json.loads(json.dumps(report.as_dict()))["packages"] == packages


def test_block_has_time_case_with_units_and_call():
    case = twoball.Case.preset("basketball", v0=3.0)
    before = datetime.now(UTC).replace(microsecond=0)
    data = provenance.block(case, "twoball.liftoff", {"case": case, "t_end": None, "level": 2})
    after = datetime.now(UTC)
    assert set(data) == KEYS
    generated = datetime.fromisoformat(data["generated"])
    assert generated.utcoffset() == timedelta(0) and before <= generated <= after
    assert data["command"] is None  # not run by the CLI
    assert data["call"] == {"function": "twoball.liftoff", "arguments": {"t_end": None, "level": 2}}
    assert data["case"]["v0_m_s"] == 3.0 and data["case"]["radius_m"] == 0.12
    assert data["case"]["phi_a_rad"] == case.phi_a and data["case"]["phi_a_source"] == "eq. (3.7)"
    assert data["versions"]["scikit-fem"] is not None
    json.dumps(data, allow_nan=False)


def test_one_shape_for_dicts_and_lists():
    block = {"twoball": twoball.__version__}
    assert provenance.attach({"a": 1}, block) == {"a": 1, "provenance": block}
    assert provenance.attach([1, 2], block) == {"results": [1, 2], "provenance": block}


@pytest.mark.parametrize(
    ("argv", "listed", "function"),
    [
        (["liftoff", "--v0", "3"], False, "twoball.liftoff"),
        (["eigen", "--level", "1", "--count", "3"], True, "twoball.fem.eigen"),
        (["sweep", "--param", "v0", "--values", "2:3:2"], True, "twoball.sweep"),
        (["icm", "--table1"], True, "twoball.table1"),
        (["icm", "--mu", "0", "--e2", "1", "--e12", "1"], False, "twoball.icm"),
    ],
)
def test_every_json_output_carries_the_provenance(capsys, argv, listed, function):
    assert main([*argv, "--json"]) == 0
    data = json.loads(capsys.readouterr().out)
    block = data["provenance"]
    assert set(block) == KEYS
    assert block["command"] == "twoball " + " ".join([*argv, "--json"])
    assert block["call"]["function"] == function
    assert (set(data) == {"results", "provenance"}) == listed
    if argv[0] in ("liftoff", "sweep"):
        assert block["case"]["v0_m_s"] == (3.0 if argv[0] == "liftoff" else 4.1)


def test_results_json_keeps_the_stable_part_provenance_json_the_whole():
    case = twoball.Case.preset("basketball")
    block = provenance.block(case, "twoball.verify", {"out": "/some/dir"})
    files = result_files({"value": 1.5, "seconds": 2.0, "provenance": block})
    results, whole = json.loads(files["results.json"]), json.loads(files[PROVENANCE])
    assert results == {"value": 1.5, "provenance": provenance.stable(block)}
    assert set(results["provenance"]) == KEYS - {"generated", "command", "call"}
    assert whole == {**block, "seconds": {"seconds": 2.0}}


def test_api_results_carry_their_call():
    solver = twoball.ClosedForm(t_end=0.03)
    report = twoball.liftoff(twoball.Case.preset("basketball"), solver=solver)
    call = report.as_dict()["provenance"]["call"]
    assert call["function"] == "twoball.liftoff"
    assert call["arguments"]["solver"] == {
        "solver": "ClosedForm",
        "sigma": "lanczos",
        "recontact": "window",
        "t_end": 0.03,
    }
    swept = twoball.sweep({"damping": [0.1, 0.2]})
    assert swept.as_dict()["provenance"]["call"]["arguments"]["values"] == {"damping": [0.1, 0.2]}
