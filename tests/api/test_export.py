"""twoball.export: the fields in SI, the backends it solves, a body's path, the user's mesh."""

from __future__ import annotations

import json

import numpy as np
import pytest

import twoball
from tests.meshes import CENTER, OFF_NODE_POLES, RADIUS
from twoball._common.errors import ParameterError
from twoball.modal.filters import SpectralFilter
from twoball.modal.legendre import displacement, legendre_series
from twoball.modal.parameters import Case, preset
from twoball.verify.output.series import read_series

CASE = preset("basketball").derive(modes=10)
MU = 0.1


#: A small cap, so that the cap average and the pole value agree to ~1e-9 (b_n = 1 - O(theta^2)).
SMALL_CAP = 1e-6  # m
#: Instants [s] inside the three contact phases of MU on SMALL_CAP (0-0.97, 1.70-2.88,
#: 10.37-11.86 ms), and two in the final flight.
IN_CONTACT = (0.5e-3, 2.0e-3, 11.0e-3)
IN_FLIGHT = (20e-3, 30e-3)


LEVEL_1 = twoball.Superposition(twoball.MeshOptions("sphere", level=1))


def _trajectory(report, times_s):
    """The contact solver's own sample of the body (SI)."""
    scale = report.case.scalings
    data = report.motion.sample(np.asarray(times_s) / scale.time)
    return data["body_height"] * scale.length, data["body_velocity"] * scale.velocity


@pytest.fixture(scope="module")
def exported(tmp_path_factory):
    folder = tmp_path_factory.mktemp("export")
    times = sorted(IN_CONTACT + IN_FLIGHT)
    result = twoball.export(
        folder / "x.xdmf", CASE, backend="legendre", solver=LEVEL_1, frames=times,
        body=twoball.Body(MU, contact_radius=SMALL_CAP),
    )  # fmt: skip
    return result, read_series(folder / "x.xdmf"), times


BASKETBALL = twoball.Case.preset("basketball")
MM = 1000.0  # the .msh file is in millimetres


def pole_at_liftoff(series, report) -> float:
    """u_m [m] at the pole node (the point on +z) in the frame at t_l of ``report``."""
    frame = int(np.argmin(np.abs(series.times - report.t_liftoff_s)))
    assert series.times[frame] == pytest.approx(report.t_liftoff_s, rel=1e-12)
    pole = int(np.argmax(series.points[:, 2]))
    assert np.allclose(series.points[pole], [0.0, 0.0, BASKETBALL.radius], atol=1e-12)
    return float(series.point_data["u_m"][frame, pole])


def closed_form(points_m: np.ndarray, times_s: np.ndarray) -> np.ndarray:
    """u [m] of eq. (3.16) at the nodes' polar angles from +z, independently of the exporter."""
    scale = BASKETBALL.scalings
    series = legendre_series(
        BASKETBALL.phi_a, BASKETBALL.damping, SpectralFilter("lanczos", BASKETBALL.modes)
    )
    phi = np.arccos(points_m[:, 2] / np.linalg.norm(points_m, axis=1))
    return displacement(series, times_s / scale.time, phi) * scale.length


def test_an_output_that_is_not_a_path_is_refused_by_name(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    with pytest.raises(ParameterError, match=r"^out must be a file path \(str or os.PathLike\)"):
        twoball.export(Case.preset("basketball"), "a.vtu")  # arguments swapped
    assert not any(tmp_path.iterdir())


def test_one_vtu_holds_the_lift_off(tmp_path):
    """A single VTU is the final separation: the body there is the last event's."""
    result = twoball.export(
        tmp_path / "one.vtu", CASE, backend="legendre", solver=LEVEL_1, body=twoball.Body(MU)
    )
    series = read_series(tmp_path / "one.vtu")
    last = result.report.events_si()[-1]
    assert last["kind"] == "separation" and series.times[0] == last["t_s"]
    assert series.frame_data["s_m"][0] == pytest.approx(last["height_m"], rel=1e-14)
    assert series.frame_data["s_t_m_s"][0] == pytest.approx(last["velocity_m_s"], rel=1e-14)
    assert series.frame_data["contact"][0] == 0.0


def test_export_carries_the_body_path_and_the_events(exported):
    result, series, times = exported
    report = result.report
    assert np.array_equal(series.times, times)
    height, speed = _trajectory(report, times)
    assert np.abs(series.frame_data["s_m"] - height).max() < 1e-12 * np.abs(height).max()
    assert np.abs(series.frame_data["s_t_m_s"] - speed).max() < 1e-12 * np.abs(speed).max()
    assert list(series.frame_data["contact"]) == [1.0, 1.0, 1.0, 0.0, 0.0]
    # independent of the solver's sampling: the final flight is a parabola under g
    final = report.events_si()[-1]
    dt = np.array(IN_FLIGHT) - final["t_s"]
    flight = final["height_m"] + final["velocity_m_s"] * dt - 0.5 * CASE.g * dt**2
    assert np.allclose(series.frame_data["s_m"][-2:], flight, rtol=1e-12, atol=0.0)
    # the events, as the lift-off API gives them for the same body
    events = json.loads(series.text["contact_events"])
    assert events == report.events_si()
    alone = twoball.liftoff(CASE, body=twoball.Body(MU, contact_radius=SMALL_CAP))
    assert events == alone.events_si()
    assert series.field_data["events"] == len(events)
    assert series.field_data["mass_ratio"] == MU
    assert series.field_data["t_liftoff_s"] == alone.t_liftoff_s


def test_exported_membrane_carries_the_body_while_in_contact(exported):
    result, series, _ = exported
    pole = int(np.argmax(series.points[:, 2]))  # the node at the top
    u_pole = series.point_data["u_m"][:, pole]
    s = series.frame_data["s_m"]
    touching = series.frame_data["contact"] == 1.0
    gap = np.abs(u_pole - s)[touching] / np.abs(s[touching])
    assert gap.max() < 2e-9, gap  # the cap average of a 1e-6 m cap is the pole value (1e-9)
    assert np.all(u_pole[~touching] < s[~touching])  # in flight the body is above


#: Distance of the coupled fields of a body of mu = 1e-9 from the free membrane: the
#: Moreau-Jean steps of the body's contact (dt = 0.005 / c) against the closed-form free
#: motion, relative to the largest |u| or |u_t| (measured 4.0e-5 P2, 3.2e-5 Legendre,
#: 1.46e-4 u_t; held below 1.5 times that).  The event-driven solver had none.
STEPPED_FROM_FREE = {"u_fem_m": 6e-5, "u_legendre_m": 5e-5, "u_t_m_s": 2.2e-4}


def test_small_mass_approaches_the_massless_field(tmp_path):
    """Both backends' coupled fields tend to the free membrane, and move at first order in mu.

    The finite elements are the main backend, so the files hold both backends' u.  The body's
    contact is stepped: the lightest body's fields are the free membrane up to the steps'
    error (:data:`STEPPED_FROM_FREE`), and the fields of heavier ones move away from them
    linearly in mu (the same steps: their error cancels in the difference).
    """
    times = [0.0, 2e-3, 6e-3, 12e-3]
    window = twoball.Superposition(LEVEL_1.mesh, t_end=0.0125)  # the frames' (the same fields)
    common = {"backend": "fem", "solver": window, "frames": times}
    twoball.export(tmp_path / "free.pvd", CASE, **common)
    free = read_series(tmp_path / "free.pvd")
    assert not free.frame_data
    light = {}
    for mu in (1e-9, 1e-7, 1e-6):
        twoball.export(tmp_path / f"light{mu:g}.pvd", CASE, body=twoball.Body(mu), **common)
        light[mu] = read_series(tmp_path / f"light{mu:g}.pvd")
        assert "s_m" in light[mu].frame_data
    for name in ("u_fem_m", "u_legendre_m", "u_t_m_s"):
        size = np.abs(free.point_data[name]).max()
        stepped = np.abs(light[1e-9].point_data[name] - free.point_data[name]).max() / size
        assert 0.0 < stepped < STEPPED_FROM_FREE[name], (name, stepped)
        moved = {}
        for mu in (1e-7, 1e-6):
            change = light[mu].point_data[name] - light[1e-9].point_data[name]
            moved[mu] = np.abs(change).max() / size
            # measured 2.1 (P2) and 3.1 (Legendre) times mu - 1e-9 for u, 17.5 for u_t
            assert 0.0 < moved[mu] < 30 * (mu - 1e-9), (name, mu, moved[mu])
        order = np.log10(moved[1e-6] / moved[1e-7]) / np.log10((1e-6 - 1e-9) / (1e-7 - 1e-9))
        assert abs(order - 1.0) < 0.01, (name, order)


@pytest.mark.parametrize(("name", "suffix"), [("vtu", "vtu"), ("msh", "xdmf")])
def test_export_matches_the_liftoff_on_the_same_file(
    ball_files, ball_files_liftoff, tmp_path, name, suffix
):
    out = tmp_path / f"fields.{suffix}"
    frames = None if suffix == "vtu" else 3  # a .vtu holds the lift-off frame alone
    solver = twoball.Superposition(ball_files[name])
    result = twoball.export(out, BASKETBALL, solver=solver, frames=frames)
    series = read_series(out)
    fem = ball_files_liftoff[name]
    scale = fem.case.scalings
    # SI, in the case's frame: R times the unit sphere whatever the file's radius and unit
    radii = np.linalg.norm(series.points, axis=1)
    assert np.allclose(radii, BASKETBALL.radius, rtol=1e-12)
    assert series.cells.shape[1] == (6 if name == "vtu" else 3)
    u_pole = pole_at_liftoff(series, fem)
    assert u_pole == pytest.approx(fem.result.displacement * scale.length, rel=1e-9, abs=1e-15)
    assert series.field_data["t_liftoff_s"] == pytest.approx(fem.t_liftoff_s, rel=1e-12)
    assert result.report.v_liftoff_m_s == pytest.approx(fem.v_liftoff_m_s, rel=1e-12)
    legendre = closed_form(series.points, series.times)
    assert np.allclose(series.point_data["u_legendre_m"], legendre, rtol=1e-10, atol=1e-14)
    # the file's own radius, centre and pole (its unit) in the metadata and the provenance
    unit = MM if name == "msh" else 1.0
    assert series.field_data["mesh_file_radius"] == pytest.approx(RADIUS * unit, rel=1e-12)
    centre = [series.field_data[f"mesh_file_center_{a}"] for a in "xyz"]
    assert np.allclose(centre, CENTER * unit, rtol=1e-12, atol=1e-12 * unit)
    assert [series.field_data[f"mesh_file_pole_{a}"] for a in "xyz"] == [0.0, 0.0, 1.0]
    text = json.loads(series.text["mesh_file"])
    assert text["path"] == str(ball_files[name].resolve()) and text["source_order"] == (
        2 if name == "vtu" else 1
    )
    assert result.provenance["mesh_file"]["radius"] == pytest.approx(RADIUS * unit, rel=1e-12)
    assert json.loads(series.text["provenance"])["mesh_file"]["path"] == text["path"]


def test_exact_geometry_and_pole_inside_an_element(ball_files, tmp_path):
    """--geometry exact with the pole off every node: t_l and v_l as twoball.liftoff's."""
    pole = OFF_NODE_POLES[1]
    mesh = twoball.MeshOptions(file=ball_files["vtu"], pole=pole, geometry="exact")
    fem = twoball.liftoff(BASKETBALL, solver=twoball.Superposition(mesh))
    out = tmp_path / "exact.pvd"
    result = twoball.export(out, BASKETBALL, solver=twoball.Superposition(mesh), frames=2)
    assert not fem.extra["mesh_file"]["pole_at_node"]
    assert result.report.t_liftoff_s == pytest.approx(fem.t_liftoff_s, rel=1e-12)
    assert result.report.v_liftoff_m_s == pytest.approx(fem.v_liftoff_m_s, rel=1e-12)
    assert result.provenance["mesh_file"]["geometry"] == "exact"
    series = read_series(out)
    assert np.allclose(np.linalg.norm(series.points, axis=1), BASKETBALL.radius, rtol=1e-12)


def test_warnings_of_a_file_are_those_of_its_liftoff(ball_files, ball_files_liftoff, tmp_path):
    """The same warnings, in the same order, as the lift-off on that file; level 1 warns."""
    solver = twoball.Superposition(ball_files["msh"])
    result = twoball.export(tmp_path / "x.vtu", BASKETBALL, solver=solver)
    assert result.warnings == list(ball_files_liftoff["msh"].warnings)
    coarse = twoball.export(
        tmp_path / "y.vtu",
        BASKETBALL,
        solver=twoball.Superposition(twoball.MeshOptions(level=1, order=1)),
    )
    assert any("under-resolves" in w for w in coarse.warnings)


MESH = twoball.MeshOptions("sphere", level=1)
ON_MESH = twoball.Superposition(MESH)


def test_closed_form_export_solves_no_finite_elements(tmp_path):
    said: list[str] = []
    result = twoball.export(
        tmp_path / "x.xdmf", solver=ON_MESH, backend="legendre", frames=2, progress=said.append
    )
    solving = [line for line in said if line.startswith("solving")]
    assert solving == ["solving the closed form (legendre) on sphere L1 P2"], said
    series = read_series(result.files[0])
    assert "u_fem_m" not in series.point_data and "u_diff_m" not in series.point_data
    assert series.point_data["u_m"].tobytes() == series.point_data["u_legendre_m"].tobytes()
    assert "t_liftoff_fem_s" not in series.field_data
    assert series.field_data["t_liftoff_s"] == series.field_data["t_liftoff_legendre_s"]


def test_fem_export_says_it_solves_both(tmp_path):
    said: list[str] = []
    result = twoball.export(tmp_path / "x.xdmf", solver=ON_MESH, frames=2, progress=said.append)
    solving = [line for line in said if line.startswith("solving")]
    assert solving == [
        "solving the finite elements (fem) and the closed form (legendre) on sphere L1 P2"
    ]
    series = read_series(result.files[0])
    diff = series.point_data["u_fem_m"] - series.point_data["u_legendre_m"]
    assert series.point_data["u_diff_m"].tobytes() == diff.tobytes()


def test_closed_form_export_refuses_the_finite_elements_route(tmp_path):
    with pytest.raises(twoball.ParameterError) as error:
        twoball.export(
            tmp_path / "x.xdmf",
            backend="legendre",
            solver=twoball.Superposition(MESH, route="full"),
        )
    assert error.value.name == "route"
    assert list(tmp_path.iterdir()) == []


def test_a_damping_law_and_the_series_rules_act_as_in_the_case(tmp_path):
    """``damping=`` gives the fields the case's own law gives; the solver's filter acts."""
    law = twoball.Rayleigh(20.0, 2e-5)
    rules = twoball.Superposition(MESH, sigma="none")
    options = {"backend": "legendre", "frames": 2}
    given = twoball.export(tmp_path / "a.pvd", BASKETBALL, damping=law, solver=rules, **options)
    inside = twoball.export(
        tmp_path / "b.pvd", BASKETBALL.derive(rayleigh=law), solver=rules, **options
    )
    a, b = read_series(given.file), read_series(inside.file)
    for name in a.point_data:
        assert np.array_equal(a.point_data[name], b.point_data[name]), name
    plain = twoball.export(tmp_path / "c.pvd", BASKETBALL, solver=ON_MESH, **options)
    assert not np.array_equal(a.point_data["u_m"], read_series(plain.file).point_data["u_m"])
    assert given.provenance["call"]["arguments"]["solver"] == rules.as_dict()
    assert given.report.sigma == "none"
