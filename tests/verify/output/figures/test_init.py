"""Saving figures (verify/output/figures/__init__.py): paths and formats."""

from __future__ import annotations

import pytest

from twoball._common.errors import ParameterError
from twoball.verify.output.figures import save_figure
from twoball.verify.output.figures.eigen import eigen_figure, eigen_table


def test_save_figure_checks_the_path(model, tmp_path):
    figure = eigen_figure([eigen_table(0, 1, 1)])
    for bad in (tmp_path / "missing" / "a.png", tmp_path / "a.xyz"):
        with pytest.raises(ParameterError, match="out"):
            save_figure(figure, bad)
    assert list(tmp_path.iterdir()) == []
