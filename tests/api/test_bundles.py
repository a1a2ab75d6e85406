"""The keywords of version 0.2 (``twoball/_bundles.py``): a DeprecationWarning, the same numbers.

Each verb called with the old loose keywords must warn once (pointing at the
caller's line) and give bit for bit what the option objects give; the old
keywords that only made sense together are refused as before.
"""

from __future__ import annotations

import warnings

import numpy as np
import pytest

import twoball
from twoball import Body, MeshOptions, PlotOptions, RenderOptions, Stepping

CASE = twoball.Case.preset("basketball")


def old(call, *keywords: str):
    """``call()`` under the deprecated keywords: DeprecationWarnings naming each of them."""
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        result = call()
    deprecations = [w for w in caught if issubclass(w.category, DeprecationWarning)]
    assert deprecations and len(deprecations) == len(caught), [str(w.message) for w in caught]
    text = " ".join(str(w.message) for w in deprecations)
    assert "deprecated" in text and all(k in text for k in keywords), text
    return result


def same_liftoff(a, b) -> None:
    assert (a.t_liftoff_s, a.v_liftoff_m_s) == (b.t_liftoff_s, b.v_liftoff_m_s)
    assert a.provenance["call"] == b.provenance["call"]


def test_liftoff_window_and_body():
    same_liftoff(
        old(lambda: twoball.liftoff(CASE, t_end=0.03), "t_end"),
        twoball.liftoff(CASE, stepping=Stepping(t_end=0.03)),
    )
    same_liftoff(
        old(lambda: twoball.liftoff(CASE, mass_ratio=0.1, contact_radius=0.012), "mass_ratio"),
        twoball.liftoff(CASE, body=Body(0.1, contact_radius=0.012)),
    )


def test_fem_solve_mesh_scheme_and_damping_model():
    same_liftoff(
        old(lambda: twoball.fem.solve(CASE, mesh="axisym", elements=100, order=1), "elements"),
        twoball.fem.solve(CASE, mesh=MeshOptions("axisym", elements=100, order=1)),
    )
    new = twoball.fem.solve(
        CASE,
        mesh=MeshOptions("axisym", elements=60),
        stepping=Stepping(scheme="alpha"),
        damping=twoball.Rayleigh(),
    )
    legacy = old(
        lambda: twoball.fem.solve(
            CASE, mesh="axisym", elements=60, scheme="alpha", damping_model="rayleigh"
        ),
        "damping_model",
        "scheme",
    )
    same_liftoff(legacy, new)
    assert legacy.extra["rayleigh"] == new.extra["rayleigh"]


def test_fem_eigen_mesh_keywords():
    rows = old(lambda: twoball.fem.eigen(mesh="axisym", elements=50, count=4), "elements")
    assert rows == twoball.fem.eigen(MeshOptions("axisym", elements=50), count=4)


def test_sweep_window_and_contact_radius():
    legacy = old(lambda: twoball.sweep({"damping": [0.1, 0.2]}, CASE, t_end=0.03), "t_end")
    new = twoball.sweep({"damping": [0.1, 0.2]}, CASE, stepping=Stepping(t_end=0.03))
    assert [p.as_dict() for p in legacy.points] == [p.as_dict() for p in new.points]
    legacy = old(lambda: twoball.sweep({"mass_ratio": [0.004]}, CASE, contact_radius=0.03), "")
    new = twoball.sweep({"mass_ratio": [0.004]}, CASE, body=Body(0.0, contact_radius=0.03))
    assert legacy.points[0].v_liftoff_m_s == new.points[0].v_liftoff_m_s


def test_export_times_and_mesh_keywords(tmp_path):
    times = [0.0, 0.004]
    old(
        lambda: twoball.export(tmp_path / "old.pvd", CASE, level=1, order=1, times=times),
        "times",
        "level",
    )
    twoball.export(tmp_path / "new.pvd", CASE, mesh=MeshOptions(level=1, order=1), frames=times)
    from twoball.verify.output.series import read_series

    a, b = read_series(tmp_path / "old.pvd"), read_series(tmp_path / "new.pvd")
    assert np.array_equal(a.times, times) and np.array_equal(a.times, b.times)
    for name in a.point_data:
        assert np.array_equal(a.point_data[name], b.point_data[name]), name


def test_render_time_and_view_keywords(tmp_path, monkeypatch):
    monkeypatch.setenv("VTK_DEFAULT_OPENGL_WINDOW", "vtkEGLRenderWindow")
    legacy = old(
        lambda: twoball.render(
            tmp_path / "old.png", CASE, backend="legendre", level=1, time=2e-3, size=(64, 48)
        ),
        "time",
        "size",
        "level",
    )
    new = twoball.render(
        tmp_path / "new.png", CASE, backend="legendre", mesh=MeshOptions(level=1),
        view=RenderOptions(size=(64, 48), frames=[2e-3]),
    )  # fmt: skip
    assert (legacy.times_s, legacy.size, legacy.warp) == (new.times_s, new.size, new.warp)
    assert legacy.times_s == [2e-3] and legacy.size == (64, 48)


def test_plot_figure_keywords(tmp_path):
    options = {"dpi": 60, "levels": [0], "orders": [1], "max_degree": 1}
    legacy = old(lambda: twoball.plot("eigen", tmp_path / "old.png", **options), "dpi")
    new = twoball.plot("eigen", tmp_path / "new.png", figure=PlotOptions(**options))
    assert legacy.rows == new.rows
    assert (tmp_path / "old.png").read_bytes() == (tmp_path / "new.png").read_bytes()


@pytest.mark.parametrize(
    "call",
    [
        lambda tmp: twoball.liftoff(CASE, t_end=0.03),
        lambda tmp: twoball.fem.eigen(mesh="axisym", elements=20, count=2),
        lambda tmp: twoball.sweep({"damping": [0.1]}, CASE, t_end=0.03),
        lambda tmp: twoball.export(tmp / "x.vtu", CASE, backend="legendre", level=1),
        lambda tmp: twoball.export(
            tmp / "y.pvd", CASE, backend="legendre", mesh=MeshOptions(level=1), times=[0.0]
        ),
        lambda tmp: twoball.render(
            tmp / "x.png", CASE, backend="legendre", mesh=MeshOptions(level=1), size=(64, 48)
        ),
        lambda tmp: twoball.render(tmp / "z.png", CASE, backend="legendre", level=1),
        lambda tmp: twoball.plot(
            "pole", tmp / "p.png", CASE, figure=PlotOptions(backends=["legendre"]), level=1
        ),
        lambda tmp: twoball.plot("eigen", tmp / "e.png", dpi=60, levels=[0], orders=[1]),
    ],
    ids=[
        "liftoff",
        "eigen",
        "sweep",
        "export-level",
        "export-times",
        "render",
        "render-level",
        "plot",
        "dpi",
    ],
)
def test_the_warning_points_at_the_callers_line(call, tmp_path, monkeypatch):
    """Attributed to the caller (stacklevel), so Python's default filters show it in scripts."""
    monkeypatch.setenv("VTK_DEFAULT_OPENGL_WINDOW", "vtkEGLRenderWindow")
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        call(tmp_path)
    places = {(w.filename, w.category) for w in caught}
    assert places == {(__file__, DeprecationWarning)}, [(w.filename, w.lineno) for w in caught]


@pytest.mark.parametrize(
    ("call", "name"),
    [
        (lambda: twoball.liftoff(CASE, contact_radius=0.01), "contact_radius"),
        (lambda: twoball.liftoff(CASE, t_end=0.03, stepping=Stepping()), "t_end"),
        (lambda: twoball.liftoff(CASE, mass_ratio=0.1, body=Body(0.1)), "mass_ratio"),
        (lambda: twoball.liftoff(CASE, damping_model="viscous"), "damping_model"),
        (lambda: twoball.fem.solve(CASE, mesh=MeshOptions("axisym"), elements=50), "elements"),
        (lambda: twoball.sweep({"damping": [0.1]}, CASE, contact_radius=0.01), "contact_radius"),
        (lambda: twoball.liftoff(CASE, sigma="none", series=twoball.Series()), "sigma"),
        (lambda: twoball.liftoff(CASE, sigma="gauss"), "sigma"),
        (lambda: twoball.sweep({"damping": [0.1]}, CASE, workers=2, scheduler="::::"), "workers"),
    ],
)
def test_old_keywords_that_conflict_are_refused_by_name(call, name):
    with pytest.warns(DeprecationWarning), pytest.raises(twoball.ParameterError) as error:
        call()
    assert error.value.name == name, str(error.value)


def test_sigma_and_recontact_become_a_series():
    series = twoball.Series(sigma="none", recontact="paper")
    legacy = old(lambda: twoball.liftoff(CASE, sigma="none", recontact="paper"), "sigma")
    new = twoball.liftoff(CASE, series=series)
    assert (legacy.t_liftoff_s, legacy.v_liftoff_m_s) == (new.t_liftoff_s, new.v_liftoff_m_s)
    assert legacy.provenance["call"] == new.provenance["call"]
    assert new.provenance["call"]["arguments"]["series"] == {"sigma": "none", "recontact": "paper"}
    values = {"damping": [0.1, 0.2]}
    legacy = old(lambda: twoball.sweep(values, CASE, recontact="paper"), "recontact")
    new = twoball.sweep(values, CASE, series=twoball.Series(recontact="paper"))
    assert [p.as_dict() for p in legacy.points] == [p.as_dict() for p in new.points]
    legacy = old(
        lambda: twoball.converge(CASE, study="modes", modes_list="30,60,120", sigma="printed"),
        "sigma",
    )
    new = twoball.converge(
        CASE, study="modes", modes_list="30,60,120", series=twoball.Series(sigma="printed")
    )
    strip = [{k: v for k, v in run.items() if k != "seconds"} for run in legacy.runs]
    assert strip == [{k: v for k, v in run.items() if k != "seconds"} for run in new.runs]
    assert legacy.settings == new.settings


def test_format_frames_backends_and_scheduler_moved_into_objects(tmp_path, monkeypatch):
    monkeypatch.setenv("VTK_DEFAULT_OPENGL_WINDOW", "vtkEGLRenderWindow")
    mesh = MeshOptions(level=1)
    written = old(
        lambda: twoball.export(
            tmp_path / "a.vtu", CASE, backend="legendre", mesh=mesh, format="vtu"
        ),
        "format",
    )
    assert written.format == "vtu"
    drawn = old(
        lambda: twoball.render(
            tmp_path / "a.png", CASE, backend="legendre", mesh=mesh, frames=[2e-3], size=(64, 48)
        ),
        "frames",
    )
    assert drawn.times_s == [2e-3]
    plotted = old(
        lambda: twoball.plot("pole", tmp_path / "p.png", CASE, mesh=mesh, backends=["legendre"]),
        "backends",
    )
    assert list(plotted.reports) == ["legendre"]
    with (
        pytest.warns(DeprecationWarning, match="scheduler"),
        pytest.raises(twoball.ParameterError) as caught,
    ):
        twoball.sweep({"damping": [0.1]}, CASE, scheduler="::::")
    assert caught.value.name == "scheduler"


def test_the_warning_names_only_the_bundles_of_the_keywords_given():
    with pytest.warns(DeprecationWarning) as caught:
        twoball.liftoff(CASE, t_end=0.03)
    (text,) = [str(w.message) for w in caught]
    assert text == (
        "twoball.liftoff: the keyword t_end is deprecated; pass stepping=Stepping(...) instead"
    )
    with pytest.warns(DeprecationWarning) as caught:
        twoball.fem.solve(CASE, mesh="axisym", elements=50, t_end=0.03)
    (text,) = [str(w.message) for w in caught]
    assert "mesh=MeshOptions(...) and stepping=Stepping(...)" in text
    assert "Body" not in text and "Rayleigh" not in text


def test_keywords_that_never_existed_are_a_type_error():
    with pytest.raises(TypeError, match="unexpected keyword argument 'levle'"):
        twoball.liftoff(CASE, levle=2)
    with pytest.raises(TypeError, match="unexpected keyword argument 'mass_ratio'"):
        twoball.fem.solve(CASE, mass_ratio=0.1)  # fem.solve takes no body
