"""``--ball solid|thick`` on the command line: drop, lift-off, spectrum, refusals."""

from __future__ import annotations

import pytest

import twoball
from tests._common.commands import refused
from tests.helpers import cli_json, cli_run
from twoball.modal.balls.solid import solid_case
from twoball.modal.solid.lamb import lamb_function, lamb_roots

SMALL = ("--modes", "16", "--radial-orders", "3")


def test_bounce_with_the_superball(capsys):
    data, _ = cli_json(capsys, "bounce", "--ball", "solid", *SMALL)
    ball = twoball.SolidBall(modes=16, radial_orders=3)
    api = twoball.bounce(solid_case("superball"), solver=twoball.MoreauJean(ball)).as_dict()
    assert data["e2"] == api["e2"] and data["contact_time_s"] == api["contact_time_s"]
    model = data["model"]
    assert model["ball"] == "solid" and model["material"]["poisson"] == 0.45
    assert model["time_unit"]["ratio"] == pytest.approx(1.0, rel=1e-14)
    assert set(model["hertz"]) >= {"contact_time_s", "peak_force_N", "quasi_static_ratio"}
    assert data["pressure_Pa"] is None and data["mass_kg"] == pytest.approx(0.0719948, rel=1e-5)
    code, out, _ = cli_run(capsys, "bounce", "--ball", "solid", *SMALL)
    assert code == 0 and "Hertz [ms]" in out and "pressure x area" not in out


def test_a_material_of_ones_own_and_the_fem_backend(capsys):
    data, _ = cli_json(
        capsys, "bounce", "--ball", "solid", "--youngs-modulus", "2e6", "--poisson", "0.3",
        "--density", "900", "--radius", "0.03", "--v0", "2", *SMALL,
    )  # fmt: skip
    material = twoball.SolidMaterial(density=900.0, youngs_modulus=2e6, poisson=0.3)
    assert data["model"]["material"]["shear_speed_m_s"] == pytest.approx(material.shear_speed)
    assert data["provenance"]["case"]["wave_speed_1_s"] == pytest.approx(material.wave_speed(0.03))
    fe, _ = cli_json(capsys, "bounce", "--ball", "solid", "--backend", "fem", "--level", "2")
    assert fe["backend"] == "fem" and fe["model"]["resolution"] == "solid axisym level 2 P2"
    whole, _ = cli_json(
        capsys, "bounce", "--ball", "solid", "--mass-ratio", "0.01", "--gap", "0.001", *SMALL
    )
    assert whole["v1_m_s"] > 0.0 and whole["baselines"] is None


def test_liftoff_of_a_massless_body_on_the_dropped_superball(capsys):
    data, _ = cli_json(capsys, "liftoff", "--ball", "solid", *SMALL)
    assert data["lifted"] and data["backend"] == "legendre"
    assert data["t_liftoff_from_touch_s"] == pytest.approx(
        data["t_liftoff_s"] + data["t_max_compression_s"], rel=1e-12
    )
    assert data["drop"]["left_floor"] and data["model"]["ball"] == "solid"
    ball = twoball.SolidBall(modes=16, radial_orders=3)
    api = twoball.liftoff(solid_case("superball"), solver=twoball.MoreauJean(ball))
    assert data["t_liftoff_s"] == api.t_liftoff_s and data["v_liftoff_m_s"] == api.v_liftoff_m_s
    fe, _ = cli_json(capsys, "liftoff", "--ball", "solid", "--backend", "fem", "--level", "2")
    assert fe["lifted"] and fe["backend"] == "fem" and fe["before_floor_release"]
    assert fe["interpolation"] in ("splines", "hermite")


@pytest.mark.parametrize(("poisson", "count", "top"), [(0.1, 6, 12), (-0.2, 3, 5), (0.4, 4, 8)])
def test_eigen_rows_against_lambs_equation(capsys, poisson, count, top):
    rows, _ = cli_json(
        capsys, "eigen", "--ball", "solid", f"--poisson={poisson}", "--count", str(count),
        "--max-degree", str(top),
    )  # fmt: skip
    assert len(rows) == (top + 1) * count
    for row in rows:
        assert set(row) >= {"degree", "radial_order", "value", "exact"}
        n, k = row["degree"], row["radial_order"]
        assert row["exact"] == lamb_roots(n, poisson, count)[k - 1]
        assert row["value"] == pytest.approx(row["exact"], rel=1e-10)
        assert abs(lamb_function(n, [row["value"]], poisson)[0]) < 1e-12


def test_eigen_rows_of_the_finite_elements(capsys):
    rows, _ = cli_json(
        capsys, "eigen", "--ball", "solid", "--backend", "fem", "--poisson", "0.25",
        "--count", "2", "--max-degree", "3", "--level", "3",
    )  # fmt: skip
    assert len(rows) == 8 and all(r["value"] is not None for r in rows)
    assert max(r["relative_error"] for r in rows) < 1e-3  # level 3 (measured 2.4e-4)
    assert min(r["value"] / r["exact"] for r in rows) > 1.0 - 1e-12  # from above (Ritz)


def test_bounce_with_the_thick_wall(capsys):
    data, _ = cli_json(capsys, "bounce", "--ball", "thick", "--elements", "24")
    assert data["model"]["ball"] == "thick" and data["mass_kg"] == pytest.approx(0.0577)
    assert data["model"]["resolution"] == "thick axisym 2 x 24 P2" and data["left_floor"]
    pair, _ = cli_json(capsys, "bounce", "--ball", "thick", "--elements", "24", "--pair",
                       "tennis-coin")  # fmt: skip
    assert pair["body"]["pair"] == "tennis-coin" and pair["v1_ratio"] > 0.5


@pytest.mark.parametrize(
    ("argv", "name"),
    [
        (["bounce", "--ball", "solid", "--pair", "tennis-coin"], "pair"),
        (["bounce", "--ball", "solid", "--pressure", "1e4", "--mass", "0.1"], "pressure"),
        (["bounce", "--ball", "solid", "--wave-speed", "300"], "wave_speed"),
        (["bounce", "--ball", "solid", "--youngs-modulus", "1e6"], "density"),
        (["bounce", "--ball", "solid", "--level", "2"], "level"),
        (["bounce", "--ball", "solid", "--backend", "fem", "--modes", "16"], "modes"),
        (["bounce", "--radial-orders", "4"], "radial_orders"),
        (["bounce", "--ball", "solid", "--gas", "adiabatic"], "gas"),
        (["liftoff", "--ball", "solid", "--mass-ratio", "0.1"], "mass_ratio"),
        (["liftoff", "--ball", "shell"], "ball"),
        (["eigen", "--ball", "solid", "--poisson", "0.5"], "poisson"),
        (["eigen", "--ball", "solid", "--level", "2"], "level"),
    ],
)
def test_refusals_by_name(capsys, argv, name):
    line = refused(capsys, argv)
    assert name.replace("_", "-") in line or name in line


def test_the_cut_through_the_volume(capsys, tmp_path):
    target = tmp_path / "cut.xdmf"
    code, _, _ = cli_run(
        capsys, "bounce", "--ball", "solid", "--backend", "fem", "--level", "2", "--export",
        str(target), "--view", "cut", "--frames", "3",
    )  # fmt: skip
    assert code == 0 and target.exists()
    from twoball.verify.output.series import read_series

    series = read_series(target)
    assert set(series.point_data) >= {"displacement_m", "u_m", "speed_m_s"}
    assert abs(series.points[:, 1]).max() == 0.0  # the plane y = 0
    # the wave: the deformation's speed is not zero inside once the floor has pushed
    assert series.point_data["speed_m_s"][1].max() > 0.0
    line = refused(capsys, ["bounce", "--ball", "solid", "--view", "cut"])
    assert "view" in line
    membrane = twoball.bounce(solver=twoball.MoreauJean(twoball.LegendreBall(16)))
    with pytest.raises(twoball.ParameterError, match="view"):
        membrane.export(tmp_path / "m.xdmf", frames=2, view="cut")
