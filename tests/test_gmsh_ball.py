"""A sphere made by gmsh itself (unstructured, OpenCASCADE geometry) through ``--mesh-file``.

gmsh meshes a ball of radius 0.12 m centred off the origin with the
Frontal-Delaunay algorithm: vertices of valence 4 to 8, meshes that are not
nested, linear or (``setOrder(2)``) quadratic triangles with their edge nodes on
the sphere, plus the line and point elements of the geometry's seam and poles.
Independent value: the Legendre series with the same N and filter (eqs.
(3.12)-(3.16)), the limit of the finite elements as h -> 0.  The step is
h = (4 pi / DOFs)^(1/2), as in ``twoball converge order``, because the meshes
are not nested: t_l at 2p +-0.3 on the finest pair (measured 2.00 for P1, 4.01
for P2), v_l shrinking on every refinement.
"""

from __future__ import annotations

import json
import math
from pathlib import Path

import gmsh
import numpy as np
import pytest

import twoball
from twoball.cli.main import main

RADIUS = 0.12  # m
CENTRE = (0.01, -0.02, 0.03)  # m


def gmsh_ball(path: Path, size: float, order: int) -> Path:
    """Write gmsh's own triangulation of the ball (element size ``size`` in m)."""
    gmsh.initialize()
    try:
        gmsh.option.setNumber("General.Terminal", 0)
        gmsh.model.add("ball")
        gmsh.model.occ.addSphere(*CENTRE, RADIUS)
        gmsh.model.occ.synchronize()
        gmsh.option.setNumber("Mesh.MeshSizeMin", size)
        gmsh.option.setNumber("Mesh.MeshSizeMax", size)
        gmsh.option.setNumber("Mesh.Algorithm", 6)  # Frontal-Delaunay
        gmsh.model.mesh.generate(2)
        if order > 1:
            gmsh.model.mesh.setOrder(order)
        gmsh.write(str(path))
    finally:
        gmsh.finalize()
    return path


def cli_liftoff(capsys, path: Path) -> dict:
    """``twoball liftoff --backend fem --mesh-file PATH --json``, its JSON."""
    assert main(["liftoff", "--backend", "fem", "--mesh-file", str(path), "--json"]) in (0, None)
    return json.loads(capsys.readouterr().out)


def test_gmsh_ball_is_read_with_its_radius_centre_and_order(tmp_path, capsys):
    """A coarse gmsh ball: radius, centre and order found, seam lines and points ignored."""
    exact = twoball.liftoff(twoball.Case.preset("basketball"))
    for order in (1, 2):
        data = cli_liftoff(capsys, gmsh_ball(tmp_path / f"coarse{order}.msh", 0.03, order))
        described = data["mesh_description"]
        assert data["mesh_file"]["radius"] == pytest.approx(RADIUS, rel=1e-9)
        assert np.allclose(data["mesh_file"]["center"], CENTRE, atol=1e-9)
        assert data["mesh_file"]["order"] == order and "ignored cells" in described
        error = data["t_liftoff_s"] / exact.t_liftoff_s - 1.0
        if order == 1:  # 0.03 m triangles: far off (measured -39 %), and the output says so
            assert abs(error) > 0.05 and data["warnings"]
        else:
            assert abs(error) < 0.01


SIZES = {1: (0.012, 0.006, 0.003), 2: (0.024, 0.012, 0.006, 0.003)}  # m, halved


@pytest.mark.slow
@pytest.mark.parametrize("order", [1, 2])
def test_gmsh_ball_converges_at_2p(tmp_path, capsys, order):
    """t_l at 2p +-0.3 on the finest pair; v_l smaller on every refinement."""
    exact = twoball.liftoff(twoball.Case.preset("basketball"))  # Legendre N = 30, Lanczos
    dofs, t_err, v_err = [], [], []
    for size in SIZES[order]:
        data = cli_liftoff(capsys, gmsh_ball(tmp_path / f"ball-{order}-{size}.msh", size, order))
        dofs.append(data["dofs"])
        t_err.append(abs(data["t_liftoff_s"] / exact.t_liftoff_s - 1.0))
        v_err.append(abs(data["v_liftoff_m_s"] / exact.v_liftoff_m_s - 1.0))
    h = np.sqrt(4.0 * np.pi / np.array(dofs, dtype=float))
    finest = math.log(t_err[-2] / t_err[-1]) / math.log(h[-2] / h[-1])
    assert abs(finest - 2 * order) < 0.3, (dofs, t_err)
    assert all(fine < coarse for coarse, fine in zip(v_err[:-1], v_err[1:], strict=True)), v_err
