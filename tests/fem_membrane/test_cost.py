"""The cost model of the finite elements (fem_membrane/cost.py): sizes and measured runs."""

from __future__ import annotations

import pytest

from tests.helpers import peak_child
from twoball.fem_membrane.cost import fem_dofs, fem_estimate


def test_sizes_in_closed_form_match_the_meshes() -> None:
    from twoball.fem_membrane.build import build_space

    for mesh, level, elements, order in [
        ("sphere", 1, None, 1),
        ("sphere", 2, None, 2),
        ("ring", 2, None, 2),
        ("axisym", None, 40, 2),
    ]:
        space = build_space(mesh, level=level, elements=elements, order=order, phi_a=2.6)
        assert fem_dofs(mesh, level, elements, order) == space.dofs


@pytest.mark.slow
@pytest.mark.parametrize(("level", "order"), [(4, 1), (3, 2)])
def test_fem_estimate_within_a_factor_of_measurement(level: int, order: int) -> None:
    code = (
        "from twoball.fem_membrane.solve import fem_pole_motion\n"
        f"fem_pole_motion(2.6, 0.13, 'lanczos', level={level}, order={order})\n"
    )
    peak, wall = peak_child(code)
    estimate = fem_estimate(fem_dofs("sphere", level, None, order), 30, "krylov")
    assert 1 / 2.5 < estimate.memory / peak < 2.5, (estimate, peak)
    assert 1 / 3 < estimate.seconds / wall < 3, (estimate, wall)
