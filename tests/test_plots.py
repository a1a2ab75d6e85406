"""twoball plot: waterfall (Fig. 6), pole motion and eigenvalue errors as PNG files."""

from __future__ import annotations

import matplotlib.image as mpimg
import numpy as np
import pytest
from twoball.modal.errors import ParameterError
from twoball.modal.parameters import preset
from twoball.verify.cli.main import main
from twoball.verify.output.fields import ball_model
from twoball.verify.output.figures import save_figure
from twoball.verify.output.figures.eigen import eigen_figure, eigen_table
from twoball.verify.output.figures.pole import pole_figure
from twoball.verify.output.figures.waterfall import waterfall_figure, waterfall_times


@pytest.fixture(scope="module")
def model():
    return ball_model(preset("basketball"), 2, 1)


def drawn(path) -> float:
    """Share of non-white pixels of a PNG."""
    image = mpimg.imread(path)[..., :3]
    return float(np.mean(np.any(image < 0.95, axis=-1)))


def test_waterfall_has_24_curves_of_each_backend(model, tmp_path):
    figure = waterfall_figure(model)
    axis = figure.axes[0]
    lines = [line for line in axis.get_lines() if len(line.get_xdata()) > 2]
    closed = [line for line in lines if line.get_linestyle() == "-"]
    nodes = [line for line in lines if line.get_marker() == "."]
    assert len(closed) == 24 and len(nodes) == 24
    # the first closed-form curve is the initial condition (3.10) in mm: flat to phi_a
    x, y = closed[0].get_data()
    flattened = np.cos(model.case.phi_a) / np.cos(x[x > 2.7]) - 1.0
    assert y[x > 2.7] == pytest.approx(flattened * model.case.radius * 1e3, abs=0.6)
    assert y[x < 2.0] == pytest.approx(0.0, abs=0.2)
    out = save_figure(figure, tmp_path / "waterfall.png")
    assert drawn(out) > 0.03


def test_waterfall_times():
    model = ball_model(preset("basketball"), 1, 1, backends=("legendre",))
    times = waterfall_times(model)
    assert times.size == 24 and times[0] == 0 and times[-1] == pytest.approx(model.t_end_s)
    with pytest.raises(ParameterError, match="--instants"):
        waterfall_times(model, 1)
    assert len(waterfall_figure(model, 5).axes[0].get_lines()) >= 5


def test_pole_plot_marks_liftoff(model, tmp_path):
    figure = pole_figure(model)
    top, middle, bottom = figure.axes[:3]
    for name in ("fem", "legendre"):
        t_ms = model.backends[name].report.t_liftoff_s * 1e3
        marked = [
            line
            for line in top.get_lines()
            if line.get_marker() == "o" and line.get_xdata()[0] == pytest.approx(t_ms)
        ]
        assert marked, name
    assert any(np.allclose(line.get_ydata(), -9.81) for line in bottom.get_lines())
    out = save_figure(figure, tmp_path / "pole.png")
    assert drawn(out) > 0.03


def test_eigen_errors_decrease_with_refinement(tmp_path):
    coarse, fine, quadratic = eigen_table(1, 1), eigen_table(2, 1), eigen_table(1, 2)
    assert coarse.errors[0] < 1e-8  # the constant mode is exact
    assert np.all(fine.errors[1:4] < coarse.errors[1:4])
    assert np.all(quadratic.errors[1:4] < coarse.errors[1:4])
    out = save_figure(eigen_figure([coarse, fine, quadratic]), tmp_path / "eigen.png")
    assert drawn(out) > 0.03


def test_eigen_degree_limits():
    with pytest.raises(ParameterError, match="--max-degree"):
        eigen_table(1, 1, 10)  # 121 eigenvalues > 42 unknowns
    assert eigen_table(1, 1, 2).degrees.tolist() == [0, 1, 2]


def test_save_figure_checks_the_path(model, tmp_path):
    figure = eigen_figure([eigen_table(0, 1, 1)])
    for bad in (tmp_path / "missing" / "a.png", tmp_path / "a.svg"):
        with pytest.raises(ParameterError, match="out"):
            save_figure(figure, bad)
    assert list(tmp_path.iterdir()) == []


@pytest.mark.parametrize(
    "argv",
    [
        ["waterfall", "--level", "1", "--instants", "6"],
        ["pole", "--level", "1", "--backends", "legendre"],
        ["eigen", "--levels", "0,1", "--orders", "1,2"],
        ["eigen", "--levels", "0,1", "--orders", "3,4"],
    ],
)
def test_cli_plot(tmp_path, capsys, argv):
    out = tmp_path / "plot.png"
    assert main(["plot", *argv, "--out", str(out)]) == 0
    assert drawn(out) > 0.03
    assert "Plot" in capsys.readouterr().out


@pytest.mark.parametrize(
    ("argv", "flag"),
    [
        (["surface"], "plot kind"),
        (["pole", "--backends", "abaqus"], "--backends"),
        (["waterfall", "--instants", "1"], "--instants"),
        (["eigen", "--levels", "x"], "--levels"),
        (["eigen", "--orders", "5"], "--orders"),
        (["eigen", "--levels", "1", "--max-degree", "0"], "--max-degree"),
        (["pole", "--level", "-2"], "--level"),
    ],
)
def test_cli_plot_bad_input(tmp_path, capsys, argv, flag):
    out = tmp_path / "plot.png"
    with pytest.raises(SystemExit) as stop:
        main(["plot", *argv, "--out", str(out)])
    err = capsys.readouterr().err
    assert stop.value.code == 2
    assert len(err.strip().splitlines()) == 1 and flag in err and "Traceback" not in err
    assert list(tmp_path.iterdir()) == []


@pytest.mark.parametrize("name", ["missing/plot.png", "plot.jpg"])
def test_cli_plot_bad_out(tmp_path, capsys, name):
    with pytest.raises(SystemExit) as stop:
        main(["plot", "pole", "--level", "1", "--out", str(tmp_path / name)])
    assert stop.value.code == 2 and "--out" in capsys.readouterr().err
