"""``twoball.bounce``: the drop in SI, its refusals, and its two backends against each other."""

from __future__ import annotations

import json
import math

import numpy as np
import pytest

import twoball

BASKETBALL = twoball.Case.preset("basketball")
QUICK = twoball.Drop(modes=16)


def test_report_in_si_with_books_and_provenance():
    report = twoball.bounce(drop=QUICK)
    data = report.as_dict()
    for key in (
        "contact_time_s",
        "v2_m_s",
        "e2",
        "phi_a_max_rad",
        "flattening_max_m",
        "t_max_compression_s",
        "floor_impulse_N_s",
        "events",
        "energy_J",
        "warnings",
        "provenance",
    ):
        assert key in data, key
    json.dumps(data)  # JSON-ready
    assert data["provenance"]["call"]["function"] == "twoball.bounce"
    m2 = report.mass_kg
    assert m2 == pytest.approx(2 * math.pi * 0.12 * 77200 / 320**2, rel=1e-14)
    weight = m2 * 9.81 * report.contact_time_s
    assert report.floor_impulse_N_s == pytest.approx(m2 * (report.v2_m_s + 4.1) + weight, rel=1e-10)
    assert report.e2 == pytest.approx(report.v2_m_s / 4.1, rel=1e-14)
    energy = report.energy_J
    spent = sum(
        energy[k]
        for k in (
            "final_rigid_kinetic",
            "final_membrane_kinetic",
            "final_membrane_elastic",
            "final_gas",
            "gravity_gained",
            "dissipated_damping",
            "lost_impacts",
            "held_arrivals",
        )
    )
    assert spent == pytest.approx(energy["initial_kinetic"], rel=1e-12)
    assert data["events"][0]["kind"] == "touch" and data["events"][-1]["kind"] == "separation"
    assert data["events"][-1]["t_s"] == pytest.approx(report.contact_time_s, rel=1e-14)


def test_drop_height_sets_the_impact_speed():
    """|v0| = sqrt(2 g H), eq. (2.1), with H the lowest point's height (as twoball icm)."""
    report = twoball.bounce(drop=twoball.Drop(drop_height=0.5, modes=16))
    assert report.case.v0 == pytest.approx(math.sqrt(2 * 9.81 * 0.5), rel=1e-15)
    assert report.as_dict()["drop_height_m"] == 0.5
    assert abs(twoball.icm(0.5, 0.8, 0.9, drop_height=0.5).v0) == pytest.approx(report.case.v0)


def test_restitution_one_keeps_the_mechanical_energy():
    report = twoball.bounce(
        drop=twoball.Drop(modes=16, floor_restitution=1.0), damping=twoball.ModalRatio(0.0)
    )
    assert report.energy_J["lost_impacts"] < 1e-12 * report.energy_J["initial_kinetic"]
    assert report.energy_J["dissipated_damping"] == 0.0


def test_paper_membrane_without_gas_is_warned_pressurised_refused():
    report = twoball.bounce(drop=twoball.Drop(modes=16, gas="none", membrane="paper"))
    assert any("omega_0 = 0" in w for w in report.warnings)
    with pytest.raises(twoball.ParameterError, match="^gas must be isothermal or adiabatic"):
        twoball.bounce(drop=twoball.Drop(gas="none", membrane="pressurised"))


@pytest.mark.parametrize(
    ("name", "call"),
    [
        ("drop_height", lambda: twoball.Drop(drop_height=-1.0)),
        ("drop_height", lambda: twoball.Drop(drop_height=0.0)),
        ("floor_restitution", lambda: twoball.Drop(floor_restitution=2.0)),
        ("modes", lambda: twoball.Drop(modes=4)),
        ("membrane", lambda: twoball.Drop(membrane="flat")),
        ("gas", lambda: twoball.Drop(gas="helium")),
        ("drop", lambda: twoball.bounce(drop="high")),
        ("case", lambda: twoball.bounce("basketball")),
        ("backend", lambda: twoball.bounce(backend="sphere")),
        ("mesh", lambda: twoball.bounce(mesh="axisym")),
        ("mesh", lambda: twoball.bounce(backend="fem", mesh="sphere")),
        ("modes", lambda: twoball.bounce(drop=QUICK, backend="fem")),
        ("scheme", lambda: twoball.bounce(stepping=twoball.Stepping(scheme="alpha", dt=1e-5))),
        ("route", lambda: twoball.bounce(stepping=twoball.Stepping(route="full"))),
        ("dt", lambda: twoball.bounce(stepping=twoball.Stepping(scheme="moreau-jean", dt=1.0))),
        ("t_end", lambda: twoball.bounce(stepping=twoball.Stepping(t_end=1e-9))),
        (
            "pressure",
            lambda: twoball.bounce(
                twoball.Case.from_measurements(radius=0.1, v0=3, wave_speed=300)
            ),
        ),
    ],
)
def test_bad_input_is_refused_naming_the_parameter(name, call):
    with pytest.raises(twoball.ParameterError) as caught:
        call()
    assert caught.value.name == name, str(caught.value)


def test_both_backends_agree_at_their_defaults():
    """Basketball at 4.1 m/s: Legendre N = 192 and axisymmetric P2 E = 96 (the same floor
    point spacing) agree on t_c, e2 and phi_a,max to 1e-3."""
    modal = twoball.bounce()
    fe = twoball.bounce(backend="fem")
    for name in ("contact_time_s", "e2", "phi_a_max_rad"):
        a, b = getattr(modal, name), getattr(fe, name)
        assert abs(a / b - 1.0) < 1e-3, (name, a, b)
    assert not modal.warnings and not fe.warnings


@pytest.mark.slow
def test_both_backends_agree_pressurised_and_causal():
    for drop, damping in (
        (twoball.Drop(membrane="pressurised"), None),
        (twoball.Drop(), twoball.Rayleigh()),
    ):
        modal = twoball.bounce(drop=drop, damping=damping)
        fe = twoball.bounce(drop=drop, damping=damping, backend="fem")
        for name in ("contact_time_s", "e2", "phi_a_max_rad"):
            a, b = getattr(modal, name), getattr(fe, name)
            assert abs(a / b - 1.0) < 1e-3, (drop, damping, name, a, b)


def test_figure_fields_and_pictures_of_the_drop(tmp_path):
    """plot, export (XDMF/PVD/VTU through the field machinery) and render of one drop."""
    from twoball.verify.output.series import read_series

    report = twoball.bounce(drop=QUICK)
    assert report.plot(tmp_path / "drop.svg").stat().st_size > 1000
    files = report.export(tmp_path / "drop.pvd", frames=4, mesh=twoball.MeshOptions(level=1))
    series = read_series(files[0])
    assert len(series) == 4 and series.times[0] == 0.0
    height = series.point_data["height_m"]
    # the floor holds its points; between them the coarse field (N = 16) may dip a little
    assert height.min() > -0.01 * 0.12
    centre = series.frame_data["Z_m"]
    assert centre[0] == pytest.approx(0.12, rel=1e-12)  # undeformed, the pole touching
    # the whole motion: the centre's fall plus the radial displacement
    top = int(np.argmax(series.points[:, 2]))
    lift = series.point_data["displacement_m"][:, top, 2]
    np.testing.assert_allclose(lift, centre - 0.12 + series.point_data["u_m"][:, top], atol=1e-12)
    one = report.export(tmp_path / "drop.vtu", frames=1, mesh=twoball.MeshOptions(level=1))
    assert one[0].name == "drop.vtu"
    picture = report.render(tmp_path / "drop.png", mesh=twoball.MeshOptions(level=1))
    assert picture.stat().st_size > 1000


def test_sweep_of_the_drop():
    """twoball.sweep with a Drop: one drop per speed; the flattening grows with |v0|."""
    result = twoball.sweep({"v0": [2.0, 4.1]}, drop=QUICK)
    assert result.parameter == "v0" and result.errors == [None, None]
    low, high = result.reports
    assert low.flattening_max_m < high.flattening_max_m and low.e2 > high.e2
    heights = twoball.sweep({"drop_height": [0.5]}, drop=QUICK)
    assert heights.reports[0].case.v0 == pytest.approx(math.sqrt(2 * 9.81 * 0.5))
    data = result.as_dict()
    assert [p["value"] for p in data["points"]] == [2.0, 4.1] and data["provenance"]
    with pytest.raises(twoball.ParameterError) as caught:
        twoball.sweep({"damping": [0.1]}, drop=QUICK)
    assert caught.value.name == "param"
