"""``twoball.export`` solves what the main backend needs, and its progress says what it solves."""

from __future__ import annotations

import pytest
from twoball.verify.output.series import read_series

import twoball

MESH = twoball.MeshOptions("sphere", level=1)


def test_closed_form_export_solves_no_finite_elements(tmp_path):
    said: list[str] = []
    result = twoball.export(
        tmp_path / "x.xdmf", mesh=MESH, backend="legendre", frames=2, progress=said.append
    )
    solving = [line for line in said if line.startswith("solving")]
    assert solving == ["solving the closed form (legendre) on sphere L1 P2"], said
    series = read_series(result.files[0])
    assert "u_fem_m" not in series.point_data and "u_diff_m" not in series.point_data
    assert series.point_data["u_m"].tobytes() == series.point_data["u_legendre_m"].tobytes()
    assert "t_liftoff_fem_s" not in series.field_data
    assert series.field_data["t_liftoff_s"] == series.field_data["t_liftoff_legendre_s"]


def test_fem_export_says_it_solves_both(tmp_path):
    said: list[str] = []
    result = twoball.export(tmp_path / "x.xdmf", mesh=MESH, frames=2, progress=said.append)
    solving = [line for line in said if line.startswith("solving")]
    assert solving == [
        "solving the finite elements (fem) and the closed form (legendre) on sphere L1 P2"
    ]
    series = read_series(result.files[0])
    diff = series.point_data["u_fem_m"] - series.point_data["u_legendre_m"]
    assert series.point_data["u_diff_m"].tobytes() == diff.tobytes()


def test_closed_form_export_refuses_the_finite_elements_route(tmp_path):
    with pytest.raises(twoball.ParameterError) as error:
        twoball.export(
            tmp_path / "x.xdmf",
            mesh=MESH,
            backend="legendre",
            stepping=twoball.Stepping(route="full"),
        )
    assert error.value.name == "route"
    assert list(tmp_path.iterdir()) == []
