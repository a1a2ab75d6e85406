"""The user's mesh file shared by the tests of the verbs."""

import numpy as np
import pytest


@pytest.fixture(scope="package")
def ball_file(tmp_path_factory):
    """An icosphere of level 2 as a 0.12 m ball centred at (1, 2, 3), written by meshio."""
    import meshio

    from twoball.fem_membrane.mesh import icosphere

    mesh = icosphere(2, 1)
    points = mesh.points * 0.12 + np.array([1.0, 2.0, 3.0])
    path = tmp_path_factory.mktemp("mesh") / "ball.vtu"
    meshio.write(path, meshio.Mesh(points, [("triangle", mesh.cells)]))
    return path, points, mesh.cells
