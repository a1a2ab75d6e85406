"""The solved ball behind every field output (verify/output/fields.py): shapes, frames, budgets."""

from __future__ import annotations

import numpy as np
import pytest
import pyvista as pv

import twoball
from twoball._common.budget import BudgetError, limits
from twoball.fem_membrane.initial import initial_load
from twoball.fem_membrane.options import MeshOptions
from twoball.fem_membrane.space import sphere_space
from twoball.modal.parameters import preset
from twoball.verify.output.fields import (
    ball_model,
    check_frame_budget,
    field_mesh,
    field_series,
    frame_times,
    frames_estimate,
)
from twoball.verify.output.series import write_series

BASKETBALL = twoball.Case.preset("basketball")


def test_fem_shapes_are_the_eigenvectors_at_the_nodes(sphere):
    """Match dofs to nodes by position (skfem's doflocs, not dof_nodes) and check K, M."""
    fem = sphere.backends["fem"]
    space = sphere_space(sphere.mesh)
    locations = space.basis.doflocs.T  # (dofs, 3)
    distance = np.linalg.norm(locations[:, None, :] - sphere.mesh.points[None, :, :], axis=2)
    node_of_dof = distance.argmin(axis=1)
    assert distance.min(axis=1).max() < 1e-12
    assert sorted(node_of_dof) == list(range(len(sphere.mesh.points)))
    vectors = fem.shapes[:, node_of_dof].T  # (dofs, K)
    K, M = space.stiffness, space.mass
    values = fem.series.omega**2
    residual = K @ vectors - (M @ vectors) * values
    assert np.abs(residual).max() < 1e-8 * max(1.0, values.max())
    assert vectors.T @ (M @ vectors) == pytest.approx(np.eye(values.size), abs=1e-9)
    assert vectors[space.pole] == pytest.approx(fem.series.pole_values, abs=1e-14)
    # the projected initial displacement (3.10), expanded in the modes
    load = initial_load(space, sphere.case.phi_a)
    assert fem.series.coefficients == pytest.approx(vectors.T @ load, abs=1e-12)


def test_frames_are_even_plus_liftoff(sphere, sphere_series):
    report = sphere.backends["fem"].report
    assert len(sphere_series) == 6 and sphere_series.times[0] == 0.0
    assert sphere_series.times[-1] == pytest.approx(sphere.t_end_s)
    assert np.any(sphere_series.times == report.t_liftoff_s)
    pole = sphere.mesh.pole
    k = int(np.flatnonzero(sphere_series.times == report.t_liftoff_s)[0])
    # the pole at the lift-off frame: u and u_t are the lift-off report's values
    scale = sphere.case.scalings
    assert sphere_series.point_data["u_m"][k, pole] == pytest.approx(
        report.result.displacement * scale.length, rel=1e-9
    )
    assert sphere_series.point_data["u_t_m_s"][k, pole] == pytest.approx(
        report.v_liftoff_m_s, rel=1e-9
    )


def test_no_liftoff_is_recorded(tmp_path):
    sphere = ball_model(
        preset("basketball").derive(damping=0.9), field_mesh(MeshOptions(level=1, order=1))
    )
    sphere_series = field_series(sphere, frame_times(sphere, frames=3))
    assert len(sphere_series) == 3  # no lift-off frame to add
    assert (
        sphere_series.field_data["lifted"] == 0.0 and "t_liftoff_s" not in sphere_series.field_data
    )
    out = tmp_path / "calm.pvd"
    write_series(out, sphere_series)
    grid = pv.read(str(out))[0]
    assert grid.field_data["lifted"][0] == 0.0 and "t_liftoff_s" not in grid.field_data


def test_frame_budget_counts_the_file_nodes(ball_files):
    """2000 frames fit on the 642 nodes of the file in a budget that level 3 P2 (2562) exceeds."""
    small = frames_estimate(2000, 642, (BASKETBALL.modes + 1) ** 2).memory
    large = frames_estimate(2000, 2562, (BASKETBALL.modes + 1) ** 2).memory
    with limits(max_memory=(small + large) / 2):
        check_frame_budget(BASKETBALL, 2000, "frames", field_mesh(ball_files["vtu"]))
        with pytest.raises(BudgetError, match="frames"):
            check_frame_budget(BASKETBALL, 2000, "frames", field_mesh(None))
