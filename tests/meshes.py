"""The user's sphere as a file: a ball of radius 0.12 m off the origin, written by meshio."""

from __future__ import annotations

import warnings

import meshio
import numpy as np

from twoball.fem_membrane.mesh import SphereMesh

RADIUS = 0.12  # m, the lower ball of the paper's case
CENTER = np.array([0.031, -0.052, 0.2])  # m
OFF_NODE_POLES = [(0.31, -0.52, 0.79), (0.8, 0.1, -0.2)]  # directions hitting no node


def on_ball(mesh: SphereMesh) -> np.ndarray:
    """Node coordinates of ``mesh`` on the ball of radius 0.12 m around CENTER [m]."""
    return mesh.points * RADIUS + CENTER


def write(path, points, cells, **kwargs) -> None:
    kind = "triangle" if cells.shape[1] == 3 else "triangle6"
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # meshio's notes on tags, 32-bit indices
        meshio.write(str(path), meshio.Mesh(points, [(kind, cells)]), **kwargs)
