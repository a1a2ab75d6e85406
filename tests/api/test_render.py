"""twoball.render: pictures of the solved ball."""

import pytest

import twoball
from twoball._common.errors import ParameterError


def test_an_output_that_is_not_a_path_is_refused_by_name(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    with pytest.raises(ParameterError, match=r"^out must be a file path \(str or os.PathLike\)"):
        twoball.render(3, "a.png")
    assert not any(tmp_path.iterdir())
