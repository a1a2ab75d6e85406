"""Start-up: what each command imports (a fresh process each), and the scipy-free paths.

Wall times are measured in benchmarks/bench_startup.py, never asserted here.  These
tests pin the cause instead: which heavy libraries a command loads.  Each command
runs through ``twoball.cli.main.main`` in a child ``python -c`` started in
the repository root, so the checkout's code is the one imported; the child reports
``sys.modules`` after the command has finished.
"""

from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest
import scipy

from tests import ROOT
from twoball.cli.main import COMMANDS
from twoball.modal.initial import phi_a_from_v0
from twoball.modal.parameters import preset
from twoball.modal.report import legendre_liftoff


def _modules_after(code: str) -> set[str]:
    env = {**os.environ, "PYTHONPATH": str(ROOT), "OPENBLAS_NUM_THREADS": "1"}
    script = code + "\nimport sys, json; print(json.dumps(sorted(sys.modules)))"
    proc = subprocess.run(
        [sys.executable, "-c", script], capture_output=True, text=True, cwd=ROOT, env=env
    )
    assert proc.returncode == 0, proc.stderr
    return set(json.loads(proc.stdout.splitlines()[-1]))


HEAVY = ("scipy", "skfem", "matplotlib", "pyvista", "vtk", "dask", "distributed", "meshio", "rich")
CHILD = r"""
import contextlib, io, json, sys
argv = json.loads(sys.argv[1])
stdout, status = io.StringIO(), None
with contextlib.redirect_stdout(stdout):
    if argv is None:
        import twoball
    else:
        from twoball.cli.main import main
        try:
            status = main(argv)
        except SystemExit as exit:
            status = exit.code
import twoball
print(json.dumps({"modules": sorted(sys.modules), "status": status,
                  "stdout": stdout.getvalue(), "twoball": twoball.__file__}))
"""


def imported_by(argv: list[str] | None) -> tuple[set[str], dict]:
    """Top-level packages in ``sys.modules`` of a fresh child after ``twoball argv``.

    ``argv`` None: only ``import twoball``.  Also returns the child's report.
    """
    done = subprocess.run(
        [sys.executable, "-c", CHILD, json.dumps(argv)],
        cwd=ROOT,
        capture_output=True,
        text=True,
        timeout=300,
    )
    assert done.returncode == 0, done.stderr
    report = json.loads(done.stdout)
    # the checkout under test, not an installed copy
    assert Path(report["twoball"]).resolve() == ROOT / "twoball" / "__init__.py"
    return {name.split(".")[0] for name in report["modules"]}, report


def test_import_twoball_is_light():
    assert "numpy" not in _modules_after("import twoball")


def test_closed_form_loads_no_plotting_or_fem():
    loaded = _modules_after(
        "import contextlib, io\nfrom twoball.cli.main import main\n"
        "with contextlib.redirect_stdout(io.StringIO()):\n    main(['liftoff', '--json'])"
    )
    assert not {"matplotlib", "skfem", "pyvista"} & loaded


def test_import_twoball_loads_no_numerical_library():
    packages, _ = imported_by(None)
    assert not packages & {"numpy", *HEAVY}, sorted(packages & {"numpy", *HEAVY})


@pytest.mark.parametrize("argv", [["--help"], [], ["--version"]])
def test_help_loads_no_numerical_library(argv):
    packages, report = imported_by(argv)
    assert report["status"] == 0
    assert "liftoff" in report["stdout"] or "twoball" in report["stdout"]
    assert not packages & {"numpy", *HEAVY}, sorted(packages & {"numpy", *HEAVY})


@pytest.mark.parametrize("command", sorted(COMMANDS))
def test_subcommand_help_loads_no_numerical_library(command):
    """Each ``--help`` takes its choices and defaults from twoball/_common/choices.py."""
    packages, report = imported_by([command, "--help"])
    assert report["status"] == 0
    assert f"usage: twoball {command}" in report["stdout"]
    assert not packages & {"numpy", *HEAVY}, sorted(packages & {"numpy", *HEAVY})


def test_closed_form_liftoff_json_loads_numpy_only():
    packages, report = imported_by(["liftoff", "--json"])
    assert report["status"] == 0
    assert "numpy" in packages  # it did compute
    assert not packages & set(HEAVY), sorted(packages & set(HEAVY))
    # the child's answer is the API's, bit for bit (JSON floats round-trip exactly)
    data = json.loads(report["stdout"])
    api = legendre_liftoff(preset("basketball"))
    assert data["t_liftoff_s"] == api.t_liftoff_s
    assert data["v_liftoff_m_s"] == api.v_liftoff_m_s
    assert data["t_liftoff_s"] == pytest.approx(9.8825e-3, abs=5e-8)  # §4(b), 9.8825 ms
    # the provenance names libraries it did not import (importlib.metadata)
    versions = data["provenance"]["versions"]
    assert versions["numpy"] == np.__version__ and versions["scipy"] == scipy.__version__
    assert data["provenance"]["command"] == "twoball liftoff --json"


def test_liftoff_json_with_derived_phi_a_loads_no_scipy():
    packages, report = imported_by(["liftoff", "--v0", "3.0", "--json"])
    assert report["status"] == 0
    assert not packages & set(HEAVY), sorted(packages & set(HEAVY))
    assert json.loads(report["stdout"])["phi_a_rad"] == phi_a_from_v0(3.0, 0.12, 320.0)


def test_fem_liftoff_json_loads_no_plotting_rendering_or_dask():
    packages, report = imported_by(["liftoff", "--backend", "fem", "--mesh", "axisym", "--json"])
    assert report["status"] == 0
    assert {"numpy", "scipy", "skfem"} <= packages  # the finite elements did run
    assert not packages & {"matplotlib", "pyvista", "vtk", "dask", "distributed", "meshio", "rich"}
    assert json.loads(report["stdout"])["backend"] == "fem"


def _missing_numpy(tmp_path: Path, *argv: str) -> subprocess.CompletedProcess[str]:
    """``python -m twoball ARGV`` in the source tree, where ``import numpy`` fails as if
    numpy were not installed (a package of that name on PYTHONPATH that raises)."""
    fake = tmp_path / "numpy"
    fake.mkdir(parents=True)
    (fake / "__init__.py").write_text(
        'raise ModuleNotFoundError("No module named \'numpy\'", name="numpy")\n'
    )
    env = {**os.environ, "PYTHONPATH": f"{tmp_path}{os.pathsep}{ROOT}"}
    return subprocess.run(
        [sys.executable, "-m", "twoball", *argv],
        capture_output=True,
        text=True,
        cwd=ROOT,
        env=env,
        timeout=120,
    )


def test_python_m_twoball_without_numpy_says_what_to_install(tmp_path):
    proc = _missing_numpy(tmp_path, "liftoff")
    assert proc.returncode == 2, proc.stderr
    assert proc.stdout == ""
    assert proc.stderr == "twoball: numpy is missing; install with: pip install .\n"
    # the help needs no numerical library: it still prints
    helped = _missing_numpy(tmp_path / "help", "--help")
    assert helped.returncode == 0 and "liftoff" in helped.stdout, helped.stderr


def test_missing_message_names_the_extra():
    from twoball.__main__ import missing_message

    assert missing_message("rich.console").startswith("twoball: rich is missing; install with: ")
    assert "[render]'" in missing_message("pyvista")
    assert missing_message("twoball.modal") is None
