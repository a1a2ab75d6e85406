"""The finite elements from Python (twoball.liftoff with Superposition, twoball.fem.eigen):
the same numbers as the command line, bit for bit."""

from __future__ import annotations

import json
import math
from pathlib import Path

import pytest

import twoball
from tests.helpers import cli_json, same_numbers
from twoball.cli.main import main


def test_fem_sphere_api_equals_cli(capsys):
    argv = ("--backend", "fem", "--mesh", "sphere", "--level", "2", "--order", "2", "--v0", "3")
    cli, _ = cli_json(capsys, "liftoff", *argv)
    case = twoball.Case.preset("basketball", v0=3.0)
    solver = twoball.Superposition(twoball.MeshOptions("sphere", level=2, order=2))
    api = twoball.liftoff(case, solver=solver)
    same_numbers(api.as_dict(), cli)
    assert cli["phi_a_source"] == "eq. (3.7)" and cli["notes"]
    # the FE lift-off agrees with the closed form to its discretisation error (sphere L2 P2)
    closed = twoball.liftoff(case)
    assert api.t_liftoff_s == pytest.approx(closed.t_liftoff_s, rel=0.05)


def test_eigen_api_equals_cli(capsys):
    cli, _ = cli_json(capsys, "eigen", "--mesh", "axisym", "--elements", "50", "--count", "5")
    assert twoball.fem.eigen(twoball.MeshOptions("axisym", elements=50), count=5) == cli
    # l (l + 1), eq. (3.11): P2 in x = cos(phi) holds P_1, P_2 exactly; l <= 5 to 1e-4
    assert all(r["relative_error"] < 1e-10 for r in cli[1:3])
    assert all(r["relative_error"] < 1e-4 for r in cli[3:])


def test_mesh_file_eigen_and_refusals(capsys, ball_file):
    path = ball_file[0]
    cli, _ = cli_json(capsys, "eigen", "--mesh-file", str(path), "--count", "3")
    assert twoball.fem.eigen(mesh=path, count=3) == cli
    assert [r["l"] for r in cli] == [0, 1, 1, 1]
    for argv, line in (
        (["--level", "2"], "--level must be left out with a mesh file"),
        (["--pole", "1,0"], "--pole must be"),
    ):
        with pytest.raises(SystemExit) as stop:
            main(["liftoff", "--backend", "fem", "--mesh-file", str(path), *argv])
        err = capsys.readouterr().err
        assert stop.value.code == 2 and err.startswith(f"twoball: error: {line}"), err
    with pytest.raises(SystemExit):
        main(["liftoff", "--mesh-file", str(path)])
    assert capsys.readouterr().err.startswith("twoball: error: --mesh-file must be left out")
    with pytest.raises(twoball.ParameterError) as error:  # its own levels and orders only
        twoball.plot("eigen", "x.png", solver=twoball.Superposition(path))
    assert error.value.name == "solver" and not Path("x.png").exists()


def test_cli_equals_api_with_the_exact_geometry(capsys):
    """Same inputs, bit-identical numbers: liftoff --geometry exact against twoball.liftoff."""

    def solve(case, mesh):
        return twoball.liftoff(case, solver=twoball.Superposition(mesh))

    code = main(["liftoff", "--backend", "fem", "--level", "1", "--order", "3",
                 "--geometry", "exact", "--json"])  # fmt: skip
    cli = json.loads(capsys.readouterr().out)
    exact = twoball.MeshOptions("sphere", level=1, order=3, geometry="exact")
    api = solve(twoball.Case.preset("basketball"), mesh=exact).as_dict()
    assert code == 0 and cli["geometry"] == "exact" and cli["order"] == 3
    assert cli["t_liftoff_s"] == api["t_liftoff_s"] and cli["v_liftoff_m_s"] == api["v_liftoff_m_s"]
    iso = solve(twoball.Case.preset("basketball"), mesh=twoball.MeshOptions(level=1, order=3))
    iso = iso.as_dict()
    assert iso["geometry"] == "isoparametric" and not math.isclose(
        iso["t_liftoff_s"], api["t_liftoff_s"], rel_tol=1e-12
    )
