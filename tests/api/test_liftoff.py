"""The public Python API: the same numbers as the command line, bit for bit; the phi_a rule.

Every comparison with the CLI is ``==`` on floats: the CLI is a thin layer over
these functions, so anything but identity is a defect.  The phi_a rule is checked
against eq. (3.7) evaluated forwards (an independent formula) and against the
preset's measured angle.
"""

from __future__ import annotations

import json
import math
import os
import re
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest
from twoball.modal.parameters import Case

import twoball
from twoball._common.errors import ParameterError
from twoball.cli.main import main

ROOT = Path(__file__).resolve().parents[1]


def cli_json(capsys, *argv: str) -> tuple[object, str]:
    """Run ``twoball ARGV --json`` in process; the parsed JSON and standard error."""
    code = main([*argv, "--json"])
    captured = capsys.readouterr()
    assert code == 0, captured.err
    data = json.loads(captured.out)
    # every JSON output names its command line; a list comes as {"results", "provenance"}
    assert data["provenance"]["command"] == "twoball " + " ".join([*argv, "--json"])
    if set(data) == {"results", "provenance"}:
        return data["results"], captured.err
    return data, captured.err


def same_numbers(api: dict, cli: dict) -> None:
    """API and CLI results identical, bit for bit (wall-clock timings, provenance aside)."""
    api = json.loads(json.dumps(api))  # the CLI's own serialisation: repr round-trips floats
    assert api["provenance"]["call"]["function"].startswith("twoball.")
    assert api["provenance"]["case"] == cli["provenance"]["case"]
    for data in (api, cli):
        data.pop("seconds", None)
        data.pop("provenance")
    assert api == cli
    assert api["t_liftoff_s"] == cli["t_liftoff_s"] and api["v_liftoff_m_s"] == cli["v_liftoff_m_s"]


def v0_of_phi_a(phi_a: float, radius: float = 0.12, wave_speed: float = 320.0) -> float:
    """Eq. (3.7) forwards: the impact speed [m/s] that flattens the ball up to phi_a."""
    c = math.cos(phi_a)
    return radius * wave_speed * math.sqrt((-1 + 2 * c**3 + 3 * c**2) / (6 * c))


# --------------------------------------------------------------------------- API = CLI
@pytest.mark.parametrize(
    ("argv", "case"),
    [
        ((), lambda: twoball.Case.preset("basketball")),
        (("--v0", "3"), lambda: twoball.Case.preset("basketball", v0=3.0)),
        (("--phi-a", "2.5"), lambda: twoball.Case.preset("basketball", phi_a=2.5)),
        (("--v0", "4.1"), lambda: twoball.Case.preset("basketball")),
        (
            ("--pressure", "77200", "--mass", "0.567"),
            lambda: twoball.Case.from_pressure(77200, 0.567),
        ),
        (("--damping", "0.2", "--modes", "60"), lambda: twoball.Case(damping=0.2, modes=60)),
    ],
    ids=["default", "v0-3", "phi-a-2.5", "preset-own-v0", "pressure-mass", "damping-modes"],
)
def test_closed_form_api_equals_cli(capsys, argv, case):
    cli, _ = cli_json(capsys, "liftoff", *argv)
    api = twoball.liftoff(case())
    same_numbers(api.as_dict(), cli)


def test_default_is_the_basketball_preset_with_its_pinned_numbers(capsys):
    result = twoball.liftoff(twoball.Case.preset("basketball"))
    assert result.t_liftoff_s * 1e3 == pytest.approx(9.8825, abs=5e-5)
    assert result.v_liftoff_m_s == pytest.approx(3.8322, abs=5e-5)
    again, first = twoball.liftoff().as_dict(), result.as_dict()
    assert again.pop("provenance")["case"] == first.pop("provenance")["case"]
    assert again == first
    cli, err = cli_json(capsys, "liftoff", "--v0", "4.1")
    assert cli["phi_a_source"] == "measured (basketball)" and cli["phi_a_rad"] == 2.6
    assert err == ""  # the preset's own value: nothing to note


def test_fem_axisym_api_equals_cli(capsys):
    cli, _ = cli_json(capsys, "liftoff", "--backend", "fem", "--mesh", "axisym")
    api = twoball.liftoff(twoball.Case.preset("basketball"), backend="fem", mesh="axisym")
    same_numbers(api.as_dict(), cli)
    assert cli["backend"] == "fem" and cli["mesh"].startswith("axisym")


def test_fem_sphere_api_equals_cli(capsys):
    argv = ("--backend", "fem", "--mesh", "sphere", "--level", "2", "--order", "2", "--v0", "3")
    cli, _ = cli_json(capsys, "liftoff", *argv)
    case = twoball.Case.preset("basketball", v0=3.0)
    api = twoball.fem.solve(case, mesh=twoball.MeshOptions("sphere", level=2, order=2))
    same_numbers(api.as_dict(), cli)
    assert cli["phi_a_source"] == "eq. (3.7)" and cli["notes"]
    # the FE lift-off agrees with the closed form to its discretisation error (sphere L2 P2)
    closed = twoball.liftoff(case)
    assert api.t_liftoff_s == pytest.approx(closed.t_liftoff_s, rel=0.05)


def test_sweep_api_equals_cli(capsys):
    cli, err = cli_json(capsys, "sweep", "--param", "v0", "--values", "2:4.1:3")
    api = twoball.sweep({"v0": np.linspace(2.0, 4.1, 3)})
    assert json.loads(json.dumps([p.as_dict() for p in api.points])) == cli
    assert [p["phi_a_source"] for p in cli] == ["eq. (3.7)", "eq. (3.7)", "measured (basketball)"]
    assert "note:" in err
    data = api.as_dict()
    assert data["parameters"] == ["v0"] and data["shape"] == [3] and len(data["points"]) == 3


def test_eigen_api_equals_cli(capsys):
    cli, _ = cli_json(capsys, "eigen", "--mesh", "axisym", "--elements", "50", "--count", "5")
    assert twoball.fem.eigen(twoball.MeshOptions("axisym", elements=50), count=5) == cli
    # l (l + 1), eq. (3.11): P2 in x = cos(phi) holds P_1, P_2 exactly; l <= 5 to 1e-4
    assert all(r["relative_error"] < 1e-10 for r in cli[1:3])
    assert all(r["relative_error"] < 1e-4 for r in cli[3:])


# --------------------------------------------------------------------------- mesh files
@pytest.fixture(scope="module")
def ball_file(tmp_path_factory):
    """An icosphere of level 2 as a 0.12 m ball centred at (1, 2, 3), written by meshio."""
    import meshio
    from twoball.fem_membrane.mesh import icosphere

    mesh = icosphere(2, 1)
    points = mesh.points * 0.12 + np.array([1.0, 2.0, 3.0])
    path = tmp_path_factory.mktemp("mesh") / "ball.vtu"
    meshio.write(path, meshio.Mesh(points, [("triangle", mesh.cells)]))
    return path, points, mesh.cells


def test_mesh_file_api_equals_cli(capsys, ball_file):
    path, points, cells = ball_file
    argv = ("--backend", "fem", "--mesh-file", str(path), "--order", "2", "--v0", "3")
    cli, _ = cli_json(capsys, "liftoff", *argv)
    case = twoball.Case.preset("basketball", v0=3.0)
    api = twoball.liftoff(case, backend="fem", mesh=twoball.MeshOptions(file=str(path), order=2))
    same_numbers(api.as_dict(), cli)
    assert cli["mesh_file"]["radius"] == pytest.approx(0.12, rel=1e-12)
    assert cli["mesh_file"]["center"] == pytest.approx([1.0, 2.0, 3.0], rel=1e-12)
    # the same mesh as an object (meshio.Mesh, scikit-fem MeshTri): the same numbers up to
    # round-off (the readers hand over the points in different layouts)
    import meshio
    from skfem import MeshTri1

    for source in (meshio.read(path), MeshTri1(points.T, cells.T)):
        again = twoball.fem.solve(case, mesh=twoball.MeshOptions(file=source, order=2))
        assert again.t_liftoff_s == pytest.approx(api.t_liftoff_s, rel=1e-12)
        assert again.v_liftoff_m_s == pytest.approx(api.v_liftoff_m_s, rel=1e-12)
    # second method: the generated icosphere it was written from, up to round-off of the
    # translation and scaling (a discretisation difference would be ~1e-3)
    generated = twoball.fem.solve(case, mesh=twoball.MeshOptions("sphere", level=2, order=2))
    assert api.t_liftoff_s == pytest.approx(generated.t_liftoff_s, rel=1e-9)
    assert api.v_liftoff_m_s == pytest.approx(generated.v_liftoff_m_s, rel=1e-9)


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
    with pytest.raises(twoball.ParameterError) as error:  # generated icospheres only
        twoball.plot("eigen", "x.png", mesh=path)
    assert error.value.name == "mesh" and not Path("x.png").exists()


# --------------------------------------------------------------------------- phi_a rule
def test_phi_a_rule_given_measured_or_eq_3_7():
    assert twoball.Case().phi_a_source == "measured (basketball)" and twoball.Case().phi_a == 2.6
    assert twoball.Case(v0=-4.1) == twoball.Case.preset("basketball")  # sign ignored
    given = twoball.Case(phi_a=2.5)
    assert (given.phi_a, given.phi_a_source, given.phi_a_note) == (2.5, "given", None)
    derived = twoball.Case(v0=3.0)  # today's Case(v0=3.0) no longer keeps 2.6 silently
    assert derived.phi_a_source == "eq. (3.7)"
    assert v0_of_phi_a(derived.phi_a) == pytest.approx(3.0, rel=1e-12)
    assert derived.phi_a_note.startswith(f"phi_a = {derived.phi_a:.4f} rad from eq. (3.7)")
    assert "|v0| = 3 m/s" in derived.phi_a_note and "measured 2.6 rad" in derived.phi_a_note


def test_phi_a_rule_through_derive_and_sweeps():
    base = twoball.Case.preset("basketball")
    there_and_back = base.derive(v0=3.0).derive(v0=4.1)
    assert there_and_back == base and there_and_back.phi_a_source == "measured (basketball)"
    assert base.derive(damping=0.2).phi_a_source == "measured (basketball)"
    kept = base.derive(v0=3.0).derive(damping=0.2)
    assert kept.phi_a_source == "eq. (3.7)" and kept.phi_a == base.derive(v0=3.0).phi_a
    assert base.derive(phi_a=2.5).derive(damping=0.2).phi_a_source == "given"
    wider = base.derive(radius=0.2)
    assert "R = 0.2 m" in wider.phi_a_note
    assert v0_of_phi_a(wider.phi_a, radius=0.2) == pytest.approx(4.1, rel=1e-12)
    explicit = base.derive(phi_a="eq. (3.7)")  # eq. (3.7) even at the preset's own values
    assert explicit.phi_a_source == "eq. (3.7)" and v0_of_phi_a(explicit.phi_a) == pytest.approx(
        4.1
    )


def test_own_measurements_have_no_preset_and_no_note():
    case = twoball.Case.from_measurements(radius=0.12, v0=4.1, pressure=77200, mass=0.567)
    assert case.preset_name is None and case.phi_a_source == "eq. (3.7)" and case.phi_a_note is None
    assert twoball.Case(preset_name=None).phi_a_source == "eq. (3.7)"


def test_results_state_phi_a_source_and_notes(capsys):
    result = twoball.liftoff(twoball.Case(v0=3.0))
    data = result.as_dict()
    assert data["phi_a_source"] == "eq. (3.7)" and data["notes"] == [result.case.phi_a_note]
    code = main(["liftoff", "--v0", "3"])
    captured = capsys.readouterr()
    assert code == 0 and "phi_a from" in captured.out and "eq. (3.7)" in captured.out
    assert captured.err.startswith("twoball: note: phi_a = ")


@pytest.mark.parametrize(
    "changes",
    [
        {"phi_a": 2.5, "phi_a_source": "measured (basketball)"},
        {"phi_a": 2.5, "phi_a_source": "eq. (3.7)"},
        {"phi_a": 2.6, "phi_a_source": "measured (basketball)", "v0": 3.0},
    ],
)
def test_phi_a_source_cannot_be_faked(changes):
    with pytest.raises(twoball.ParameterError) as error:
        twoball.Case(**changes)
    assert error.value.name == "phi_a_source"


def test_sweep_refuses_unknown_parameters():
    with pytest.raises(twoball.ParameterError) as error:
        twoball.sweep({"mass": [1.0, 2.0]})
    assert error.value.name == "values" and "wave_speed" in str(error.value)


# --------------------------------------------------------------------------- refusals
@pytest.mark.parametrize(
    ("call", "name"),
    [
        (lambda: twoball.liftoff(mesh=twoball.MeshOptions(level=2)), "mesh"),
        (lambda: twoball.liftoff(mesh="axisym"), "mesh"),
        (lambda: twoball.liftoff(backend="spectral"), "backend"),
        (lambda: twoball.fem.solve(mesh=twoball.MeshOptions("axisym", level=2)), "level"),
        (lambda: twoball.fem.solve(mesh=twoball.MeshOptions("sphere", elements=100)), "elements"),
        (lambda: twoball.fem.solve(mesh="axisym", stepping=twoball.Stepping(dt=1e-5)), "dt"),
        (lambda: twoball.liftoff(stepping=twoball.Stepping(scheme="alpha")), "scheme"),
        (lambda: twoball.liftoff(body=twoball.Body(-0.1)), "mass_ratio"),
        (lambda: twoball.fem.solve(mesh="cube"), "mesh"),
        (lambda: twoball.Case(damping=2.0), "damping"),
        (lambda: twoball.Case.preset("squash"), "preset"),
        (lambda: twoball.Case.preset("basketball", pressure=7e4), "pressure"),
    ],
)
def test_api_errors_name_parameters(call, name):
    with pytest.raises(twoball.ParameterError) as error:
        call()
    assert error.value.name == name and str(error.value).startswith(f"{name} must be ")


@pytest.mark.parametrize(
    ("argv", "line"),
    [
        (["liftoff", "--level", "2"], "--level must be left out with backend legendre"),
        (["liftoff", "--backend", "fem", "--mesh", "axisym", "--level", "2"], "--level must be"),
        (["liftoff", "--backend", "fem", "--elements", "50"], "--elements must be left out"),
        (["liftoff", "--backend", "fem", "--dt", "1e-5"], "--dt must be left out with scheme"),
        (["eigen", "--mesh", "sphere", "--elements", "9"], "--elements must be left out"),
        (["liftoff", "--phi-a", "3.5"], "--phi-a must be in (pi/2, pi - 1e-6]"),
    ],
)
def test_cli_refuses_options_that_do_not_apply(capsys, argv, line):
    with pytest.raises(SystemExit) as stop:
        main(argv)
    err = capsys.readouterr().err
    assert stop.value.code == 2 and err.startswith(f"twoball: error: {line}")
    assert err.count("\n") == 1


# --------------------------------------------------------------------------- package surface
def test_verify_is_callable_and_the_subpackage(tmp_path):
    # twoball.verify is both the verb and the subpackage twoball.verify.* (already imported)
    import twoball.verify.checks.run as checks

    assert twoball.verify.checks.run is checks
    result = twoball.verify(fast=True, out=tmp_path / "report")
    assert result.passed and (tmp_path / "report" / "report.md").is_file()
    settings = result.as_dict()["settings"]
    assert settings["phi_a_source"] == "measured (basketball)"
    assert callable(twoball.converge) and callable(twoball.fem.solve)


def test_public_names_and_version():
    for name in ("Case", "liftoff", "sweep", "fem", "converge", "verify", "export", "render"):
        assert name in dir(twoball) and getattr(twoball, name) is not None
    assert twoball.ParameterError is twoball._common.errors.ParameterError
    assert re.fullmatch(r"\d+\.\d+(\.\d+)?\S*", twoball.__version__)


def _modules_after(code: str) -> set[str]:
    env = {**os.environ, "PYTHONPATH": str(ROOT), "OPENBLAS_NUM_THREADS": "1"}
    script = code + "\nimport sys, json; print(json.dumps(sorted(sys.modules)))"
    proc = subprocess.run(
        [sys.executable, "-c", script], capture_output=True, text=True, cwd=ROOT, env=env
    )
    assert proc.returncode == 0, proc.stderr
    return set(json.loads(proc.stdout.splitlines()[-1]))


def test_import_twoball_is_light():
    assert "numpy" not in _modules_after("import twoball")


def test_closed_form_loads_no_plotting_or_fem():
    loaded = _modules_after(
        "import contextlib, io\nfrom twoball.cli.main import main\n"
        "with contextlib.redirect_stdout(io.StringIO()):\n    main(['liftoff', '--json'])"
    )
    assert not {"matplotlib", "skfem", "pyvista"} & loaded


# --------------------------------------------------------------------------- docs examples
def quickstart_blocks() -> list[str]:
    """The ``.. code-block:: python`` examples of docs/quickstart.rst, dedented."""
    text = (ROOT / "docs" / "quickstart.rst").read_text()
    blocks = []
    for match in re.finditer(r"\.\. code-block:: python\n\n((?:(?:    .*)?\n)+)", text):
        lines = [line[4:] for line in match.group(1).splitlines()]
        blocks.append("\n".join(lines).strip() + "\n")
    return blocks


def test_quickstart_examples_run(tmp_path, monkeypatch, capsys):
    blocks = quickstart_blocks()
    assert len(blocks) >= 4
    monkeypatch.chdir(tmp_path)
    namespace: dict[str, object] = {}
    for block in blocks:
        exec(compile(block, "docs/quickstart.rst", "exec"), namespace)  # noqa: S102
    assert "t_l =" in capsys.readouterr().out


@pytest.mark.parametrize(
    "call",
    [
        lambda: twoball.export(Case.preset("basketball"), "a.vtu"),  # arguments swapped
        lambda: twoball.render(3, "a.png"),
        lambda: twoball.plot("pole", None),
    ],
)
def test_an_output_that_is_not_a_path_is_refused_by_name(call, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    with pytest.raises(ParameterError, match=r"^out must be a file path \(str or os.PathLike\)"):
        call()
    assert not any(tmp_path.iterdir())
