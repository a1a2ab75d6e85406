"""twoball.render: pictures of the solved ball."""

import pytest

import twoball
from twoball._common.errors import ParameterError


def test_an_output_that_is_not_a_path_is_refused_by_name(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    with pytest.raises(ParameterError, match=r"^out must be a file path \(str or os.PathLike\)"):
        twoball.render(3, "a.png")
    assert not any(tmp_path.iterdir())


def test_the_frames_and_the_damping_law_given(tmp_path, monkeypatch):
    """``view.frames`` sets the instants; ``damping=`` is the case's own law, bit for bit."""
    import imageio.v3 as iio
    import numpy as np

    monkeypatch.setenv("VTK_DEFAULT_OPENGL_WINDOW", "vtkEGLRenderWindow")
    case = twoball.Case.preset("basketball")
    law = twoball.Rayleigh(20.0, 2e-5)
    solver = twoball.Superposition(twoball.MeshOptions("sphere", level=1))
    view = twoball.RenderOptions(size=(64, 48), frames=[0.004], warp=1.0)
    options = {"backend": "legendre", "solver": solver, "view": view}
    given = twoball.render(tmp_path / "a.png", case, damping=law, **options)
    inside = twoball.render(tmp_path / "b.png", case.derive(rayleigh=law), **options)
    assert given.times_s == [0.004] and given.size == (64, 48)
    assert np.array_equal(iio.imread(given.file), iio.imread(inside.file))
    assert given.provenance["call"]["arguments"]["view"]["frames"] == [0.004]
