"""twoball plot: figure files from the command line; bad input in one line."""

from __future__ import annotations

import imageio.v3 as iio
import pytest

from tests.helpers import drawn
from twoball.cli.main import main


def test_cli_plot_pole_with_a_mass_ratio(tmp_path, capsys):
    out = tmp_path / "pole.png"
    argv = ["plot", "pole", "--level", "1", "--modes", "10", "--mass-ratio", "0.004"]
    assert main([*argv, "--contact-radius", "0.012", "--dpi", "60", "--out", str(out)]) == 0
    assert iio.imread(out).shape[2] in (3, 4)
    assert "lift-off (legendre)" in capsys.readouterr().out


@pytest.mark.parametrize(("suffix", "head"), [(".pdf", b"%PDF"), (".svg", b"<svg")])
def test_cli_plot_pole_vector_formats(tmp_path, capsys, suffix, head):
    out = tmp_path / f"pole{suffix}"
    assert main(["plot", "pole", "--level", "1", "--out", str(out)]) == 0
    data = out.read_bytes()
    assert data.startswith(head) if suffix == ".pdf" else head in data[:2000]
    assert out.stat().st_size > 20_000
    assert sorted(p.name for p in tmp_path.iterdir()) == [out.name]


@pytest.mark.parametrize("dpi", ["10", "1e4", "nan"])
def test_cli_plot_bad_dpi(tmp_path, capsys, dpi):
    with pytest.raises(SystemExit) as stop:
        main(["plot", "eigen", "--levels", "0", "--dpi", dpi, "--out", str(tmp_path / "e.png")])
    err = capsys.readouterr().err
    assert stop.value.code == 2 and len(err.strip().splitlines()) == 1
    assert err.startswith("twoball: error: --dpi must be") and "[50, 1200]" in err
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
