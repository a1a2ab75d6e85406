"""The contact sequence of a body of finite mass in plot pole, render and export (issue 13).

Real runs on a small case (N = 10 Legendre modes; finite elements on the sphere
of level 1, P2, every eigenpair below the cutoff).  The figure's body path and
event markers, the exported per-frame body data and events, and the coupled
membrane field are checked against the contact solver's own trajectory
(:func:`twoball.modal.contact.trajectory.sample`, one matrix exponential per
time), against the free flight in closed form, against the massless field and
against the gap condition (C3) of docs/contact.rst.
"""

from __future__ import annotations

import json

import imageio.v3 as iio
import numpy as np
import pytest
from twoball.modal.contact.trajectory import sample
from twoball.modal.parameters import preset
from twoball.verify.output.fields import contact_scene, coupled_model
from twoball.verify.output.figures.contact_pole import BODY_GID, EVENT_GID, contact_pole_figure
from twoball.verify.output.figures.style import curves
from twoball.verify.output.series import read_series

import twoball
from twoball.cli.main import main

CASE = preset("basketball").derive(modes=10)
MU = 0.1
#: A small cap, so that the cap average and the pole value agree to ~1e-9 (b_n = 1 - O(theta^2)).
SMALL_CAP = 1e-6  # m
#: Instants [s] inside the three contact phases of MU on SMALL_CAP (0-0.97, 1.70-2.88,
#: 10.37-11.86 ms), and two in the final flight.
IN_CONTACT = (0.5e-3, 2.0e-3, 11.0e-3)
IN_FLIGHT = (20e-3, 30e-3)
LEVEL_1 = twoball.MeshOptions("sphere", level=1)


@pytest.fixture(scope="module")
def model():
    mesh = twoball.MeshOptions("sphere", level=1, order=2)
    return coupled_model(CASE, ("fem", "legendre"), twoball.Body(0.004), mesh)


def _trajectory(report, times_s):
    """The contact solver's own sample of the body (SI)."""
    scale = report.case.scalings
    data = sample(report.system, report.history, np.asarray(times_s) / scale.time)
    return data["body_height"] * scale.length, data["body_velocity"] * scale.velocity


def test_plot_pole_draws_the_path_and_one_marker_per_event(model):
    samples = 400
    figure = contact_pole_figure(model, samples)
    displacement, velocity = figure.axes[0], figure.axes[2]  # difference rows between
    assert len(figure.axes) == 6
    for name in ("fem", "legendre"):
        report = model.contact(name)
        events = report.events_si()
        assert len(events) == len(report.history.events) >= 3
        for axis, key, factor in ((displacement, "height_m", 1e3), (velocity, "velocity_m_s", 1.0)):
            marks = [
                line for line in axis.get_lines() if str(line.get_gid()).endswith(f"-{name}")
                and str(line.get_gid()).startswith(EVENT_GID)
            ]  # fmt: skip
            assert sum(len(line.get_xdata()) for line in marks) == len(events)
            for kind in ("impact", "separation"):
                (line,) = [m for m in marks if m.get_gid() == f"{EVENT_GID}-{kind}-{name}"]
                chosen = [e for e in events if e["kind"] == kind]
                assert np.allclose(line.get_xdata(), [e["t_s"] * 1e3 for e in chosen])
                assert np.allclose(line.get_ydata(), [e[key] * factor for e in chosen])
        # the body's path is the solver's trajectory at the same times
        (path,) = [
            line for line in displacement.get_lines() if line.get_gid() == f"{BODY_GID}-{name}"
        ]
        data = report.trajectory_si(samples)
        assert np.allclose(path.get_xdata(), data["t_s"] * 1e3, rtol=1e-12)
        scale = np.abs(data["body_height_m"]).max()
        assert np.abs(path.get_ydata() / 1e3 - data["body_height_m"]).max() < 1e-12 * scale
    assert all(len(curves(a)) <= 6 for a in figure.axes)
    labels = [t.get_text() for t in velocity.get_legend().get_texts()]
    assert {"impact", "separation", "lift-off (final separation)"} <= set(labels)


def test_cli_plot_pole_with_a_mass_ratio(tmp_path, capsys):
    out = tmp_path / "pole.png"
    argv = ["plot", "pole", "--level", "1", "--modes", "10", "--mass-ratio", "0.004"]
    assert main([*argv, "--contact-radius", "0.012", "--dpi", "60", "--out", str(out)]) == 0
    assert iio.imread(out).shape[2] in (3, 4)
    assert "lift-off (legendre)" in capsys.readouterr().out


def test_one_vtu_holds_the_lift_off(tmp_path):
    """A single VTU is the final separation: the body there is the last event's."""
    result = twoball.export(
        tmp_path / "one.vtu", CASE, backend="legendre", mesh=LEVEL_1, body=twoball.Body(MU)
    )
    series = read_series(tmp_path / "one.vtu")
    last = result.report.events_si()[-1]
    assert last["kind"] == "separation" and series.times[0] == last["t_s"]
    assert series.frame_data["s_m"][0] == pytest.approx(last["height_m"], rel=1e-14)
    assert series.frame_data["s_t_m_s"][0] == pytest.approx(last["velocity_m_s"], rel=1e-14)
    assert series.frame_data["contact"][0] == 0.0


@pytest.fixture(scope="module")
def exported(tmp_path_factory):
    folder = tmp_path_factory.mktemp("export")
    times = sorted(IN_CONTACT + IN_FLIGHT)
    result = twoball.export(
        folder / "x.xdmf", CASE, backend="legendre", mesh=LEVEL_1, frames=times,
        body=twoball.Body(MU, contact_radius=SMALL_CAP),
    )  # fmt: skip
    return result, read_series(folder / "x.xdmf"), times


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


def test_small_mass_approaches_the_massless_field(tmp_path):
    """Both backends' coupled fields tend to the free membrane at first order in mu."""
    times = [0.0, 2e-3, 6e-3, 12e-3]
    common = {"backend": "legendre", "mesh": LEVEL_1, "frames": times}
    twoball.export(tmp_path / "free.pvd", CASE, **common)
    free = read_series(tmp_path / "free.pvd")
    assert not free.frame_data
    errors = {}
    for mu in (1e-9, 1e-6):
        twoball.export(tmp_path / "light.pvd", CASE, body=twoball.Body(mu), **common)
        light = read_series(tmp_path / "light.pvd")
        assert "s_m" in light.frame_data
        for name in ("u_fem_m", "u_legendre_m", "u_t_m_s"):
            size = np.abs(free.point_data[name]).max()
            errors[mu, name] = np.abs(light.point_data[name] - free.point_data[name]).max() / size
            # measured 2-3 mu for u, 16 mu for u_t
            assert 0.0 < errors[mu, name] < 30 * mu, (name, errors[mu, name])
    for name in ("u_fem_m", "u_legendre_m", "u_t_m_s"):
        order = np.log10(errors[1e-6, name] / errors[1e-9, name]) / 3.0
        assert abs(order - 1.0) < 0.01, (name, order)


def test_render_draws_the_body_and_its_contact(model, tmp_path, monkeypatch):
    monkeypatch.setenv("VTK_DEFAULT_OPENGL_WINDOW", "vtkEGLRenderWindow")
    times = np.array([0.2e-3, model.t_end_s])
    scene = contact_scene(model, times, "legendre")
    assert np.array_equal(scene.body, model.motion("legendre", times)["s_m"])
    assert list(scene.contact) == [True, False]
    assert "IN CONTACT" in scene.caption(0, 1.0) and "in flight" in scene.caption(1, 1.0)
    out = tmp_path / "ball.png"
    result = twoball.render(
        out, CASE, backend="legendre", mesh=LEVEL_1, frames=[0.2e-3],
        view=twoball.RenderOptions(size=(320, 240)), body=twoball.Body(0.004),
    )  # fmt: skip
    image = iio.imread(out)
    assert image.shape[:2] == (240, 320)
    assert float(np.mean(np.any(image[..., :3] < 245, axis=-1))) > 0.1  # not blank
    assert result.report.mass_ratio == 0.004
    assert list(tmp_path.iterdir()) == [out]  # no scratch files left
    gif = tmp_path / "bounce.gif"
    twoball.render(
        gif, CASE, backend="legendre", mesh=LEVEL_1, frames=3,
        view=twoball.RenderOptions(size=(160, 120)), body=twoball.Body(0.004),
    )  # fmt: skip
    assert iio.imread(gif, index=None).shape[:3] == (3, 120, 160)


REFUSED = [
    (["plot", "eigen", "--mass-ratio", "0.1"], "--mass-ratio"),
    (["plot", "waterfall", "--mass-ratio", "0.1"], "--mass-ratio"),
    (["plot", "pole", "--mass-ratio", "0.1", "--contact-radius", "1"], "--contact-radius"),
    (["export", "--contact-radius", "0.01"], "--contact-radius"),
    (["export", "--mass-ratio", "0"], "--mass-ratio"),
    (["export", "--mass-ratio", "0.1", "--route", "krylov"], "--route"),
    (["render", "--mass-ratio", "0.1", "--recontact", "paper"], "--recontact"),
    (["render", "--mass-ratio", "-1"], "--mass-ratio"),
]


@pytest.mark.parametrize(("argv", "flag"), REFUSED)
def test_options_that_do_not_apply_are_refused(argv, flag, tmp_path, capsys):
    out = tmp_path / {"export": "x.xdmf", "render": "x.png", "plot": "p.png"}[argv[0]]
    with pytest.raises(SystemExit) as stop:
        main([*argv, "--out", str(out)])
    assert stop.value.code == 2
    err = capsys.readouterr().err.strip()
    assert err.count("\n") == 0 and flag in err, err
    assert list(tmp_path.iterdir()) == []


def test_cli_option_constants_match_the_model():
    """The option group offers the model's own limits (defined once, in modal/contact/body.py)."""
    from twoball.modal.contact import body

    from twoball import _choices
    from twoball.cli.main import full_parser

    assert _choices.MAX_MASS_RATIO is body.MAX_MASS_RATIO == 100.0
    assert _choices.ENERGY_OPTIONS is body.ENERGY_OPTIONS == ("ball", "both")
    (sub,) = (a for a in full_parser()._actions if hasattr(a, "choices") and a.choices)
    energy = next(a for a in sub.choices["liftoff"]._actions if "--energy" in a.option_strings)
    assert "ball or both" in energy.help
