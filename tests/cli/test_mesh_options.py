"""The mesh and time options of the command line (twoball/cli/mesh_options.py): refusals.

Each refusal is one line naming the flag, exit status 2, and leaves nothing written.
"""

from __future__ import annotations

from pathlib import Path

import pytest

import twoball
from twoball._common.errors import ParameterError
from twoball.cli.main import main

BASKETBALL = twoball.Case.preset("basketball")
COMMANDS = {
    "export": ["export", "--out", "{out}/x.vtu"],
    "render": ["render", "--size", "64x48", "--out", "{out}/x.png"],
    "plot": ["plot", "pole", "--out", "{out}/p.png"],
}


def refused(argv: list[str], out: Path, capsys) -> str:
    """The one error line of ``argv`` (exit 2, no traceback, nothing written)."""
    out.mkdir()
    with pytest.raises(SystemExit) as stop:
        main([a.replace("{out}", str(out)) for a in argv])
    err = capsys.readouterr().err
    assert stop.value.code == 2
    lines = err.strip().splitlines()
    assert len(lines) == 1 and "Traceback" not in err
    assert list(out.iterdir()) == []
    return lines[0]


@pytest.mark.parametrize(
    ("argv", "flag"),
    [
        (["liftoff", "--backend", "fem", "--level", "-1"], "--level"),
        (["liftoff", "--backend", "fem", "--order", "5"], "--order"),
        (["liftoff", "--backend", "fem", "--dt", "0"], "--dt"),
        (["liftoff", "--backend", "fem", "--dt", "-1e-5"], "--dt"),
        (["liftoff", "--backend", "fem", "--mesh", "axisym", "--elements", "1"], "--elements"),
        (["liftoff", "--backend", "fem", "--mesh", "cube"], "--mesh"),
        (["liftoff", "--backend", "fem", "--scheme", "euler"], "--scheme"),
        (["liftoff", "--backend", "fem", "--damping-model", "viscous"], "--damping-model"),
        (["liftoff", "--backend", "spectral"], "--backend"),
        (["eigen", "--level", "-2"], "--level"),
        (["eigen", "--count", "0"], "--count"),
        (["eigen", "--order", "x"], "--order"),
    ],
)
def test_fem_bad_input_is_one_line_exit_2(capsys, argv, flag):
    with pytest.raises(SystemExit) as stop:
        main(argv)
    err = capsys.readouterr().err.strip().splitlines()
    assert stop.value.code == 2 and len(err) == 1 and flag in err[0], err


@pytest.mark.parametrize(
    ("argv", "flag"),
    [
        (["liftoff", "--backend", "fem", "--mesh", "ring", "--geometry", "exact"], "--geometry"),
        (["eigen", "--mesh", "axisym", "--geometry", "exact"], "--geometry"),
        (["liftoff", "--geometry", "exact"], "--geometry"),
        (["converge", "h", "--mesh", "axisym", "--geometry", "exact"], "--geometry"),
        (["eigen", "--order", "5"], "--order"),
    ],
)
def test_cli_refusals_are_one_line(capsys, argv, flag):
    from twoball.cli.main import main

    with pytest.raises(SystemExit) as stop:
        main(argv)
    err = capsys.readouterr().err
    assert stop.value.code == 2 and err.startswith("twoball: error: " + flag)
    assert err.count("\n") == 1 and "Traceback" not in err


@pytest.mark.parametrize(
    "argv",
    [
        ["export", "--out", "{tmp}/f.vtu", "--route", "bogus"],
        ["render", "--out", "{tmp}/f.png", "--route", "eigen"],
        ["plot", "pole", "--out", "{tmp}/f.png", "--route", "dense"],
        ["plot", "eigen", "--out", "{tmp}/f.png", "--route", "full"],
        ["eigen", "--level", "1", "--order", "1", "--count", "43"],
    ],
)
def test_bad_route_or_count_is_one_line_exit_2(argv, tmp_path, capsys):
    from twoball.cli.main import main

    with pytest.raises(SystemExit) as stop:
        main([a.format(tmp=tmp_path) for a in argv])
    err = capsys.readouterr().err.strip().splitlines()
    assert stop.value.code == 2 and len(err) == 1, err
    flag = "--count" if "--count" in argv else "--route"
    assert err[0].startswith("twoball: error: " + flag), err
    assert not any(tmp_path.iterdir())  # no partial output


@pytest.mark.parametrize(
    "argv",
    [
        ["export", "--level", "1", "--order", "3", "--out", "{tmp}/series.xdmf"],
        ["render", "--level", "1", "--order", "4", "--out", "{tmp}/ball.png"],
    ],
)
def test_field_files_and_pictures_refuse_p3_p4_in_one_line(tmp_path, capsys, argv):
    """No node order for 10/15-node triangles is shared by the writers: refused, exit 2."""
    from twoball.cli.main import main

    with pytest.raises(SystemExit) as stop:
        main([part.format(tmp=tmp_path) for part in argv])
    err = capsys.readouterr().err
    assert stop.value.code == 2
    assert len(err.strip().splitlines()) == 1 and "--order" in err and "Traceback" not in err


@pytest.mark.parametrize("command", COMMANDS)
def test_broken_mesh_is_refused(ball_files, tmp_path, capsys, command):
    line = refused(
        [*COMMANDS[command], "--mesh-file", str(ball_files["hole"])], tmp_path / "o", capsys
    )
    assert "--mesh-file" in line and "closed surface" in line and "boundary edges" in line


@pytest.mark.parametrize("command", COMMANDS)
def test_pole_without_mesh_file_is_refused(tmp_path, capsys, command):
    line = refused([*COMMANDS[command], "--pole", "0,0,1"], tmp_path / "o", capsys)
    assert line.startswith("twoball: error: --pole ") and "mesh is a file" in line


@pytest.mark.parametrize("command", ["export", "render"])
def test_order_3_on_a_file_is_refused(ball_files, tmp_path, capsys, command):
    argv = [*COMMANDS[command], "--mesh-file", str(ball_files["vtu"]), "--order", "3"]
    assert "--order must be 1 or 2 for field files and pictures" in refused(
        argv, tmp_path / "o", capsys
    )


def test_refusals_that_do_not_apply(ball_files, tmp_path, capsys):
    eigen = ["plot", "eigen", "--mesh-file", str(ball_files["vtu"]), "--out", "{out}/p.png"]
    assert "--mesh-file must be left out with kind eigen" in refused(eigen, tmp_path / "a", capsys)
    ring = [*COMMANDS["export"], "--mesh", "ring", "--geometry", "exact"]
    assert "--geometry must be isoparametric with mesh ring" in refused(
        ring, tmp_path / "b", capsys
    )
    level = [*COMMANDS["render"], "--mesh-file", str(ball_files["vtu"]), "--level", "2"]
    assert "--level must be left out with a mesh file" in refused(level, tmp_path / "c", capsys)
    with pytest.raises(ParameterError, match="^pole"):
        twoball.plot(
            "waterfall",
            tmp_path / "w.png",
            BASKETBALL,
            solver=twoball.Superposition(twoball.MeshOptions(pole=(0, 0, 1))),
        )


@pytest.mark.parametrize("command", COMMANDS)
def test_a_body_of_finite_mass_needs_a_generated_mesh(ball_files, tmp_path, capsys, command):
    """A body of finite mass is solved on generated meshes: a file or exact geometry is refused."""
    argv = [*COMMANDS[command], "--mass-ratio", "0.01", "--mesh-file", str(ball_files["vtu"])]
    line = refused(argv, tmp_path / "a", capsys)
    assert line.startswith("twoball: error: --mesh-file must be a generated mesh"), line
    argv = [*COMMANDS[command], "--mass-ratio", "0.01", "--geometry", "exact"]
    line = refused(argv, tmp_path / "b", capsys)
    assert "--geometry must be isoparametric with --mass-ratio" in line, line
