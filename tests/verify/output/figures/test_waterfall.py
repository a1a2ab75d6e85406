"""twoball plot: waterfall (Fig. 6), pole motion and eigenvalue errors as PDF, SVG or PNG files."""

from __future__ import annotations

import matplotlib.image as mpimg
import numpy as np
import pytest
from twoball.fem_membrane.options import MeshOptions
from twoball.modal.parameters import preset
from twoball.verify.output.fields import ball_model, field_mesh
from twoball.verify.output.figures import save_figure
from twoball.verify.output.figures.eigen import eigen_figure, eigen_table
from twoball.verify.output.figures.pole import pole_figure
from twoball.verify.output.figures.style import curves
from twoball.verify.output.figures.waterfall import waterfall_figure, waterfall_times

from twoball._common.errors import ParameterError
from twoball.cli.main import main


@pytest.fixture(scope="module")
def model():
    return ball_model(preset("basketball"), field_mesh(MeshOptions(level=2, order=1)))


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


def test_waterfall_difference_stack_is_fem_minus_closed_form_at_the_nodes(model):
    from twoball.modal.legendre import displacement
    from twoball.verify.output.fields import node_polar_angles

    figure = waterfall_figure(model, 4)
    assert len(figure.axes) == 2  # the waterfall and the stacked differences beside it
    side = figure.axes[1]
    rows = [line for line in side.get_lines() if line.get_marker() == "."]
    assert len(rows) == 4
    times = waterfall_times(model, 4)
    phi = node_polar_angles(model.mesh)
    scale = model.case.scalings
    closed = displacement(model.backends["legendre"].series, times / scale.time, phi)
    expected = model.nodal("fem", times, 0) - closed * scale.length  # m
    unit = side.get_ylabel().rsplit("[", 1)[1].rstrip("]")
    factor = {"m": 1.0, "mm": 1e3, r"$\mu$m": 1e6, "nm": 1e9}[unit]
    offset = rows[1].get_ydata()[0] - expected[1, 0] * factor
    for k, row in enumerate(rows):
        np.testing.assert_allclose(row.get_ydata(), expected[k] * factor + k * offset, atol=1e-9)
    # rows line up with the waterfall: both stacks scale their limits by one factor
    (low, high), (side_low, side_high) = figure.axes[0].get_ylim(), side.get_ylim()
    assert side_low / low == pytest.approx(side_high / high)
    shift_mm = float(figure.axes[0].get_ylabel().split()[3])  # printed to 3 digits
    assert offset == pytest.approx(side_high / high * shift_mm, rel=1e-2)
    single = waterfall_figure(
        ball_model(
            preset("basketball"), field_mesh(MeshOptions(level=1, order=1)), backends=("legendre",)
        ),
        3,
    )
    assert len(single.axes) == 1


def test_waterfall_times():
    model = ball_model(
        preset("basketball"), field_mesh(MeshOptions(level=1, order=1)), backends=("legendre",)
    )
    times = waterfall_times(model)
    assert times.size == 24 and times[0] == 0 and times[-1] == pytest.approx(model.t_end_s)
    with pytest.raises(ParameterError, match="^instants must be an integer >= 2, got 1"):
        waterfall_times(model, 1)
    assert len(waterfall_figure(model, 5).axes[0].get_lines()) >= 5


def test_pole_plot_marks_liftoff(model, tmp_path):
    figure = pole_figure(model)
    assert len(figure.axes) == 6  # u, u_t, u_tt, each with its difference panel below
    top, middle, bottom = figure.axes[0:6:2]
    for name in ("fem", "legendre"):
        t_ms = model.backends[name].report.t_liftoff_s * 1e3
        marked = [
            line
            for line in top.get_lines()
            if line.get_marker() == "o" and line.get_xdata()[0] == pytest.approx(t_ms)
        ]
        assert marked, name
    assert any(np.allclose(line.get_ydata(), -9.81) for line in bottom.get_lines())
    assert "lift-off" in [t.get_text() for t in bottom.get_legend().get_texts()]
    out = save_figure(figure, tmp_path / "pole.png")
    assert drawn(out) > 0.03


def test_pole_difference_panel_is_fem_minus_closed_form(model):
    figure = pole_figure(model, samples=400)
    below_u = figure.axes[1]
    (line,) = curves(below_u)
    t_ms, shown = line.get_data()
    # the same difference evaluated here from the two series, in m
    t = np.asarray(t_ms) * 1e-3 / model.case.scalings.time
    fem = model.backends["fem"].series.pole(t).u
    closed = model.backends["legendre"].series.pole(t).u
    expected_m = (fem - closed) * model.case.radius
    unit = below_u.get_ylabel().split("[")[1].rstrip("]")
    factor = {"m": 1.0, "mm": 1e3, r"$\mu$m": 1e6, "nm": 1e9}[unit]
    np.testing.assert_allclose(shown, expected_m * factor, rtol=1e-12, atol=1e-12)
    # level 1 P1 against the closed form differs by about a millimetre somewhere
    assert 1e-4 < np.abs(expected_m).max() < 1e-2
    single = pole_figure(
        ball_model(
            preset("basketball"), field_mesh(MeshOptions(level=1, order=1)), backends=("legendre",)
        ),
        200,
    )
    assert len(single.axes) == 3  # nothing to compare: no difference panels


@pytest.mark.parametrize(("suffix", "head"), [(".pdf", b"%PDF"), (".svg", b"<svg")])
def test_cli_plot_pole_vector_formats(tmp_path, capsys, suffix, head):
    out = tmp_path / f"pole{suffix}"
    assert main(["plot", "pole", "--level", "1", "--out", str(out)]) == 0
    data = out.read_bytes()
    assert data.startswith(head) if suffix == ".pdf" else head in data[:2000]
    assert out.stat().st_size > 20_000
    assert sorted(p.name for p in tmp_path.iterdir()) == [out.name]


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


@pytest.mark.parametrize("dpi", ["10", "1e4", "nan"])
def test_cli_plot_bad_dpi(tmp_path, capsys, dpi):
    with pytest.raises(SystemExit) as stop:
        main(["plot", "eigen", "--levels", "0", "--dpi", dpi, "--out", str(tmp_path / "e.png")])
    err = capsys.readouterr().err
    assert stop.value.code == 2 and len(err.strip().splitlines()) == 1
    assert err.startswith("twoball: error: --dpi must be") and "[50, 1200]" in err
    assert list(tmp_path.iterdir()) == []


def test_eigen_errors_decrease_with_refinement(tmp_path):
    coarse, fine, quadratic = eigen_table(1, 1), eigen_table(2, 1), eigen_table(1, 2)
    assert coarse.errors[0] < 1e-8  # the constant mode is exact
    assert np.all(fine.errors[1:4] < coarse.errors[1:4])
    assert np.all(quadratic.errors[1:4] < coarse.errors[1:4])
    out = save_figure(eigen_figure([coarse, fine, quadratic]), tmp_path / "eigen.png")
    assert drawn(out) > 0.03


def test_eigen_degree_limits():
    with pytest.raises(ParameterError, match="^max_degree must be at most 5 on this mesh"):
        eigen_table(1, 1, 10)  # 121 eigenvalues > 42 unknowns
    assert eigen_table(1, 1, 2).degrees.tolist() == [0, 1, 2]


def test_save_figure_checks_the_path(model, tmp_path):
    figure = eigen_figure([eigen_table(0, 1, 1)])
    for bad in (tmp_path / "missing" / "a.png", tmp_path / "a.xyz"):
        with pytest.raises(ParameterError, match="out"):
            save_figure(figure, bad)
    assert list(tmp_path.iterdir()) == []


@pytest.mark.parametrize(
    "argv",
    [
        ["waterfall", "--level", "1", "--instants", "6"],
        ["pole", "--level", "1", "--backend", "legendre"],
        ["eigen", "--levels", "0,1", "--orders", "1,2"],
        ["eigen", "--levels", "0,1", "--orders", "3,4"],
    ],
)
def test_cli_plot(tmp_path, capsys, argv):
    out = tmp_path / "plot.png"
    assert main(["plot", *argv, "--out", str(out)]) == 0
    assert drawn(out) > 0.01  # thin lines at 300 dpi
    assert "Plot" in capsys.readouterr().out


@pytest.mark.parametrize(
    ("argv", "flag"),
    [
        (["surface"], "plot kind"),
        (["pole", "--backend", "abaqus"], "--backend"),
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


@pytest.mark.parametrize("name", ["missing/plot.png", "plot.xyz", "plot.pgf"])
def test_cli_plot_bad_out(tmp_path, capsys, name):
    with pytest.raises(SystemExit) as stop:
        main(["plot", "pole", "--level", "1", "--out", str(tmp_path / name)])
    assert stop.value.code == 2 and "--out" in capsys.readouterr().err
