"""twoball.plot: figure options and the user's mesh file."""

from __future__ import annotations

import matplotlib.image as mpimg
import pytest

import twoball
from tests.meshes import RADIUS
from twoball._common.errors import ParameterError
from twoball.verify.output.figures.eigen import eigen_figure, eigen_table

BASKETBALL = twoball.Case.preset("basketball")
MM = 1000.0  # the .msh file is in millimetres


def test_plot_pole_on_the_file_mesh(ball_files, ball_files_liftoff, tmp_path):
    out = tmp_path / "pole.png"
    result = twoball.plot("pole", out, BASKETBALL, solver=twoball.Superposition(ball_files["msh"]))
    assert out.stat().st_size > 0
    fem = ball_files_liftoff["msh"]
    assert result.reports["fem"].t_liftoff_s == pytest.approx(fem.t_liftoff_s, rel=1e-12)
    assert result.provenance["mesh_file"]["radius"] == pytest.approx(RADIUS * MM, rel=1e-12)


def test_plot_api_dpi_sets_raster_size(tmp_path):
    from twoball import PlotOptions, plot

    figure_inches = eigen_figure([eigen_table(0, 1, 1)]).get_size_inches()
    for dpi in (100, 200):
        figure = PlotOptions(dpi=dpi, levels=[0], orders=[1], max_degree=1)
        out = plot("eigen", tmp_path / f"e{dpi}.png", figure=figure)
        height, width = mpimg.imread(out.file).shape[:2]
        assert (width, height) == tuple(round(x * dpi) for x in figure_inches)
    for bad in (10, 5000, float("nan"), "300", True):
        with pytest.raises(ParameterError, match="dpi"):
            plot("eigen", tmp_path / "bad.png", figure=PlotOptions(dpi=bad, levels=[0], orders=[1]))
    assert not (tmp_path / "bad.png").exists()


def test_an_output_that_is_not_a_path_is_refused_by_name(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    with pytest.raises(ParameterError, match=r"^out must be a file path \(str or os.PathLike\)"):
        twoball.plot("pole", None)
    assert not any(tmp_path.iterdir())


def test_the_precursor_draws_the_damping_law_given(tmp_path):
    """``damping=Rayleigh()`` on the precursor is the case's Rayleigh law, row for row."""
    law = twoball.Rayleigh()
    given = twoball.plot("precursor", tmp_path / "a.png", BASKETBALL, damping=law)
    inside = twoball.plot("precursor", tmp_path / "b.png", BASKETBALL.derive(rayleigh=law))
    assert given.rows == inside.rows
    plain = twoball.plot("precursor", tmp_path / "c.png", BASKETBALL)
    assert given.rows != plain.rows


def test_one_backend_may_be_given_as_a_name(tmp_path):
    """``backends="legendre"`` is the closed form alone, as ``["legendre"]`` (never its letters)."""
    mesh = twoball.Superposition(twoball.MeshOptions("sphere", level=1))
    named = twoball.plot(
        "pole",
        tmp_path / "a.png",
        BASKETBALL,
        solver=mesh,
        figure=twoball.PlotOptions(backends="legendre"),
    )
    listed = twoball.plot(
        "pole",
        tmp_path / "b.png",
        BASKETBALL,
        solver=mesh,
        figure=twoball.PlotOptions(backends=["legendre"]),
    )
    assert list(named.reports) == list(listed.reports) == ["legendre"]
    assert named.reports["legendre"].t_liftoff_s == listed.reports["legendre"].t_liftoff_s
    with pytest.raises(ParameterError, match=r"^backends must be .*got 'fme'$"):
        twoball.PlotOptions(backends="fme")
