"""The eigenvalue-error figure (verify/output/figures/eigen.py)."""

from __future__ import annotations

import numpy as np
import pytest

from tests.helpers import drawn
from twoball._common.errors import ParameterError
from twoball.verify.output.figures import save_figure
from twoball.verify.output.figures.eigen import eigen_figure, eigen_table


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
