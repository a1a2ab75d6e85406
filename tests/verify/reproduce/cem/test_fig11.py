"""Fig. 11 of the paper (verify/reproduce/cem/fig11.py): the fitted damping."""

import pytest

from twoball.verify.reproduce.cem.fig11 import _fit_damping


def test_fitted_damping_and_liftoff_at_0_13():
    assert _fit_damping(3.7) == pytest.approx(0.1329, abs=5e-4)
