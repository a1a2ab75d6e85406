"""The drop's and the whole bounce's figures (verify/output/figures/bounce.py): their forces."""

from __future__ import annotations

import numpy as np
import pytest

import twoball
from twoball.verify.output.figures.bounce import EVENT_LINE, event_clusters, whole_figure
from twoball.verify.output.forces import mean_force


@pytest.fixture(scope="module")
def whole():
    """A whole bounce with a body (coarse: N = 16), its events many and close together."""
    return twoball.bounce(
        solver=twoball.MoreauJean(twoball.LegendreBall(16)), pair="basketball-tennis"
    )


def _line(figure, text):
    for axis in figure.axes:
        for line in axis.get_lines():
            if line.get_label() == text:
                return axis, line
    raise AssertionError(f"no curve {text!r}")


def test_floor_force_stays_positive_through_the_contact(whole):
    figure = whole_figure(whole.result, whole.case, whole.mass_kg, "basketball-tennis")
    axis, line = _line(figure, "floor on the ball")
    t, force = np.asarray(line.get_xdata()), np.asarray(line.get_ydata())
    inside = np.flatnonzero(force > 0.0)
    start, end = inside[0], inside[-1]
    assert end - start > 50  # the contact spans many windows
    # the localised steps at the body's impacts showed 0 N alone; in their window, never
    assert np.all(force[start : end + 1] > 0.0), t[start + np.argmin(force[start : end + 1])]
    # the label says what is drawn: impulse per window, in N
    assert "impulse per" in axis.get_ylabel() and "[N]" in axis.get_ylabel()
    # the areas under the curve are the impulse (N s) of the run's floor, impacts included
    r = whole.result
    total = r.trajectory.impulse[:, r.system.floor].sum()
    unit = whole.mass_kg * whole.case.radius * whole.case.wave_speed  # m2 R c [N s]
    window_ms = t[1] - t[0]
    assert np.sum(force[:-1]) * window_ms * 1e-3 == pytest.approx(total * unit, rel=0.02)


def test_event_marks_stay_behind_the_data(whole):
    figure = whole_figure(whole.result, whole.case, whole.mass_kg, "basketball-tennis")
    for axis in figure.axes:
        data = [ln for ln in axis.get_lines() if len(ln.get_xdata()) > 2]
        marks = [ln for ln in axis.get_lines() if len(ln.get_xdata()) == 2 and ln.get_alpha()]
        marks += list(axis.patches)
        assert marks, "the events are marked"
        lowest = min(ln.get_zorder() for ln in data) if data else 1.0
        for mark in marks:
            assert mark.get_zorder() < min(lowest, 1.0)
            assert mark.get_alpha() <= 0.5
        for line in marks:
            if hasattr(line, "get_linewidth") and line in axis.get_lines():
                assert line.get_linewidth() <= EVENT_LINE["lw"]


def test_mean_force_keeps_every_impulse():
    t = np.array([0.0, 1.0, 1.001, 2.0, 3.0, 3.5])  # a localised step at t = 1
    impulse = np.array([1.0, 0.2, 1.0, 1.0, 0.5])
    impact = np.array([0.0, 0.2, 0.0, 0.0, 0.0])  # all of the short step is an impact
    centres, force = mean_force(t, impulse, impact, 1.0)
    widths = np.diff(np.append(np.arange(0.0, 3.5, 1.0), 3.5))
    assert np.sum(force * widths) == pytest.approx(impulse.sum())
    assert np.all(force > 0.0)
    np.testing.assert_allclose(centres, [0.5, 1.5, 2.5, 3.25])
    # the impact at t = 1 falls in the window that starts there
    assert force[1] == pytest.approx(0.2 + 0.999 * 1.0 / 0.999)


def test_event_clusters():
    assert event_clusters([], 1.0) == []
    assert event_clusters([3.0, 1.0, 1.5], 1.0) == [(1.0, 1.5), (3.0, 3.0)]


def test_bounce_plot_title_names_the_pair(whole, monkeypatch, tmp_path):
    import twoball.verify.output.figures as figures

    drawn = []
    monkeypatch.setattr(figures, "save_figure", lambda figure, *a, **k: drawn.append(figure))
    whole.plot(tmp_path / "whole.png")
    title = drawn[0]._suptitle.get_text()
    assert title.startswith("Whole bounce: basketball-tennis; "), title
    assert "|v_0|" in title  # mathtext, not the ASCII |v0|


def test_exported_and_rendered_forces_are_the_figures(whole):
    """The files' and pictures' frame forces read the figure's curves (no 0 N at touches)."""
    from twoball.fem_membrane.mesh import sphere_mesh
    from twoball.verify.output.drop_fields import drop_series

    r, case = whole.result, whole.case
    figure = whole_figure(r, case, whole.mass_kg, "basketball-tennis")
    curves = {}
    for name in ("floor on the ball", "ball on the body"):
        _, line = _line(figure, name)
        curves[name] = (np.asarray(line.get_xdata()), np.asarray(line.get_ydata()))
    t_ms, floor = curves["floor on the ball"]
    carried = t_ms[floor > 0]
    times_s = np.linspace(carried[0], carried[-1], 97) * 1e-3
    series = drop_series(r, case, sphere_mesh(1), times_s, whole.mass_kg, "x")
    shown = series.frame_data["floor_force_N"]
    assert np.all(shown > 0.0)
    np.testing.assert_allclose(shown, np.interp(times_s * 1e3, t_ms, floor), rtol=1e-9)
    t_body, body = curves["ball on the body"]
    np.testing.assert_allclose(
        series.frame_data["body_force_N"], np.interp(times_s * 1e3, t_body, body), rtol=1e-9
    )
