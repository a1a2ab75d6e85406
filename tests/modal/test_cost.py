"""The cost model of the closed-form series (modal/cost.py) against measured runs."""

from __future__ import annotations

import pytest

from tests.helpers import peak_child
from twoball._costs import check_series


@pytest.mark.slow
@pytest.mark.parametrize("modes", [1500, 3000])
def test_series_estimate_within_a_factor_of_measurement(modes: int) -> None:
    code = (
        "from twoball.modal.parameters import preset\n"
        "from twoball.modal.report import legendre_liftoff\n"
        f"legendre_liftoff(preset('basketball').derive(modes={modes}))\n"
    )
    peak, wall = peak_child(code)
    estimate = check_series(modes, 4 * 3.141592653589793)
    assert 1 / 2.5 < estimate.memory / peak < 2.5, (estimate, peak)
    assert 1 / 3 < estimate.seconds / wall < 3, (estimate, wall)
