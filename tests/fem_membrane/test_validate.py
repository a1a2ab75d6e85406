"""The ranges of the finite-element inputs (fem_membrane/validate.py), checked without reading."""

from __future__ import annotations

import math

import meshio
import pytest
from skfem import MeshTri1, MeshTri2

from twoball import ParameterError
from twoball.fem_membrane.cost import fem_dofs, fem_estimate
from twoball.fem_membrane.mesh import icosphere
from twoball.fem_membrane.validate import (
    LEVEL_RANGE,
    check_level,
    check_mesh_source,
    check_pole,
)


def test_levels_from_0_to_10():
    assert LEVEL_RANGE == (0, 10)
    assert [check_level(v) for v in (0, 10)] == [0, 10]
    for bad in (-1, 11, 1.0, True, "3"):
        with pytest.raises(ParameterError, match=r"^level must be an integer in \[0, 10\]"):
            check_level(bad)


def test_the_top_level_is_where_the_cost_model_leaves_any_machine():
    """Level 10 at P1: 10 4^10 + 2 unknowns, over a hundred GB by the cost model."""
    dofs = fem_dofs("sphere", 10, None, 1)
    assert dofs == 10 * 4**10 + 2
    assert fem_estimate(dofs, 30, "krylov").memory > 100e9


@pytest.mark.parametrize(
    ("pole", "expected"),
    [((0, 0, 1), (0.0, 0.0, 1.0)), ("1, 2,3", (1.0, 2.0, 3.0)), ([0.0, -1e308, 0], (0, -1e308, 0))],
)
def test_a_pole_is_three_finite_numbers(pole, expected):
    assert check_pole(pole) == expected


@pytest.mark.parametrize(
    "pole",
    [(0, 0, 0), (math.nan, 0, 1), (1, math.inf, 0), (1, 2), (1, 2, 3, 4), "north", "1,2", 1.0],
)
def test_a_bad_pole_is_refused_by_name(pole):
    with pytest.raises(ParameterError, match="^pole must be three finite numbers X,Y,Z"):
        check_pole(pole)


def test_mesh_sources_that_exist_are_taken_as_they_are(tmp_path):
    path = tmp_path / "ball.msh"
    path.write_text("read only when the mesh is loaded")
    sphere = icosphere(1)
    for source in (path, str(path), meshio.Mesh(sphere.points, [("triangle", sphere.cells)])):
        assert check_mesh_source(source) is source
    tri = MeshTri1.init_tensor([0.0, 1.0], [0.0, 1.0])
    assert check_mesh_source(tri) is tri
    assert check_mesh_source(MeshTri2.init_sqsymmetric()) is not None
    assert check_mesh_source(sphere) is sphere


@pytest.mark.parametrize("source", [123, [1, 2], b"ball.msh", object(), "", "no/such/ball.msh"])
def test_other_sources_are_refused_before_anything_is_read(source, tmp_path):
    with pytest.raises(ParameterError, match="^file must be a readable mesh file"):
        check_mesh_source(source)
    with pytest.raises(ParameterError, match="^file must be"):
        check_mesh_source(tmp_path)  # a folder
    with pytest.raises(ParameterError, match="^mesh must be"):
        check_mesh_source(tmp_path / ("a" * 300 + ".msh"), "mesh")
