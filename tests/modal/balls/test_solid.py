"""The solid ball on Lamb's modes: its material, its roots and shapes, its drop against Hertz."""

from __future__ import annotations

import math

import numpy as np
import pytest

import twoball
from twoball.modal.balls.solid import (
    MATERIALS,
    hertz_reference,
    lamb_table,
    solid_case,
    surface_compliance,
)
from twoball.modal.solid.lamb import lamb_function, lamb_roots
from twoball.modal.solid.modes import spheroidal_modes

#: The issue's reference roots of omega R / c_s (Lamb 1882; Saviot's calculator).
REFERENCES = {
    0.25: {(2, 1): 2.6399, (2, 2): 4.8653, (3, 1): 3.9163, (0, 1): 4.4400},
    1 / 3: {(2, 1): 2.6501, (3, 1): 3.9502, (0, 1): 5.4874},
}


def test_the_material_and_the_superball_preset():
    material = MATERIALS["superball"]
    assert "assumed" in material.source
    case = twoball.Case.preset("superball")
    assert case.pressure is None and case.damping == 0.0
    # the case's c is the shear speed over the radius (docs/solid.rst, eq. (S1))
    assert case.wave_speed == pytest.approx(material.shear_speed / case.radius, rel=1e-14)
    ball = twoball.SolidBall()
    assert ball.mass(case) == pytest.approx(4 / 3 * math.pi * 0.025**3 * 1100.0, rel=1e-14)
    assert isinstance(ball, twoball.Ball) and isinstance(twoball.FESolidBall(), twoball.Ball)
    with pytest.raises(twoball.ParameterError, match="poisson"):
        twoball.SolidMaterial(density=1000.0, youngs_modulus=1e6, poisson=0.5)
    with pytest.raises(twoball.ParameterError, match="material"):
        twoball.SolidBall().describe(twoball.Case.preset("basketball"))


@pytest.mark.parametrize("poisson", [0.25, 1 / 3, 0.45, 0.1, -0.3])
def test_the_roots_are_lambs(poisson):
    table = lamb_table(poisson, 10, 5)
    for n in range(11):
        chosen = (table.degree == n) & (table.radial_order > 0)
        roots = table.eta[chosen]
        assert roots == pytest.approx(lamb_roots(n, poisson, 5), rel=1e-10, abs=0.0)
        assert np.abs(lamb_function(n, roots, poisson)).max() < 1e-12
    for (n, k), value in REFERENCES.get(poisson, {}).items():
        eta = table.eta[(table.degree == n) & (table.radial_order == k)][0]
        assert abs(eta - value) < 6e-5  # the references' own four decimals


def test_the_shapes_are_the_normalised_modes():
    table = lamb_table(0.45, 12, 3)
    for mode in spheroidal_modes(0.45, [0, 2, 7, 12], 3):
        j = np.flatnonzero(
            (table.degree == mode.degree) & (table.radial_order == mode.radial_order)
        )[0]
        assert table.amplitude_p[j] == pytest.approx(mode.amplitude_p, rel=1e-9)
        assert table.amplitude_s[j] == pytest.approx(mode.amplitude_s, rel=1e-9, abs=1e-300)
        u1, v1 = mode.radial(np.array([1.0]))
        assert (table.surface_u[j], table.surface_v[j]) == pytest.approx((u1[0], v1[0]))


@pytest.mark.parametrize("n", [0, 1, 2, 9])
def test_the_static_correction_completes_the_compliance(n):
    """Eq. (S3): the kept modes plus the correction carry the exact surface compliance."""
    table = lamb_table(0.45, 9, 4, static=True)
    chosen = table.degree == n
    u, v, eta = table.surface_u[chosen], table.surface_v[chosen], table.eta[chosen]
    weight = np.diag([1.0, n * (n + 1)])
    total = sum(
        3 / (2 * n + 1) * np.outer([a, b], [a, b]) @ weight / (e * e - 1e-6)
        for a, b, e in zip(u, v, eta, strict=True)
        if e > 0
    )
    if n == 1:
        total = total - np.outer([1, 1], [1, 1]) @ weight / 1e-6
    exact = surface_compliance(n, 0.45)
    scale = np.abs(exact).max() if n != 1 else 1.0
    rows = 1 if n == 0 else 2
    assert np.abs((total - exact)[:rows, :rows]).max() < 1e-6 * scale
    # without it the truncated ball is too stiff at the surface
    kept = (table.radial_order[chosen] > 0) & (eta > 0)
    assert (table.radial_order[chosen] == -1).sum() >= 1 and kept.sum() == 4


def test_the_description_maps_any_case_unit():
    case = solid_case("superball")
    ball = twoball.SolidBall(modes=12, radial_orders=3)
    described = ball.describe(case)
    t = described.centre
    assert described.masses[t] == 1.0 and described.omega_squared[t] == 0.0
    assert np.all(described.floor_rows[:, t] == 1.0) and described.top[t] == 1.0
    assert described.points == ball.size(case)[1] and described.modes == ball.size(case)[0]
    # another time unit: omega^2 / c^2 scales with (c_s / (R c))^2, the physics does not move
    slower = case.derive(wave_speed=case.wave_speed / 2.0)
    other = ball.describe(slower)
    assert other.omega_squared == pytest.approx(4.0 * described.omega_squared, rel=1e-12)
    # the cap's average tends to the pole's displacement
    assert described.cap_average(1e-4) == pytest.approx(described.top, rel=1e-4, abs=1e-9)
    # u_z = u_r cos(phi) - u_theta sin(phi) at the floor points
    phi = described.phi
    ur, ut = described.modes_at(phi), described.tangential_at(phi)
    uz = ur * np.cos(phi)[:, None] - ut * np.sin(phi)[:, None]
    keep = np.arange(described.modes) != t
    assert uz[:, keep] == pytest.approx(described.floor_rows[:, keep], abs=1e-12)


def test_the_superball_drop_keeps_its_books():
    """D = 0: the energy balances to rounding, the impulse to the floor's."""
    case = solid_case("superball")
    report = twoball.bounce(
        case, solver=twoball.MoreauJean(twoball.SolidBall(modes=32, radial_orders=4))
    )
    energy = report.energy_J
    assert report.left_floor and 0.97 < report.e2 <= 1.0
    assert energy["dissipated_damping"] == 0.0
    assert abs(energy["balance_error"]) < 1e-12 * energy["initial_kinetic"]
    assert report.result.impulse_balance < 1e-12
    after = (
        energy["final_rigid_kinetic"]
        + energy["vibration_after_leaving"]
        + energy["gravity_gained"]
        + energy["lost_impacts"]
    )
    assert after == pytest.approx(energy["initial_kinetic"], rel=1e-10)
    model = report.model
    assert model["ball"] == "solid" and report.pressure is None and model["gas"] == "none"
    assert model["hertz"]["contact_time_s"] == pytest.approx(
        hertz_reference(MATERIALS["superball"], 0.025, 4.1)["contact_time_s"]
    )


def test_an_under_resolved_contact_is_said():
    report = twoball.bounce(
        solid_case("superball", v0=1.0),
        solver=twoball.MoreauJean(twoball.SolidBall(modes=8, radial_orders=2)),
    )
    assert report.model["hertz"]["contact_points_expected"] < 6
    assert any("floor points" in w for w in report.warnings)


def _hertz_errors(v0: float, modes: int) -> tuple[float, float]:
    case = solid_case("superball", v0=v0, g=1e-6)  # gravity out of Hertz's impact
    report = twoball.bounce(case, solver=twoball.MoreauJean(twoball.SolidBall(modes=modes)))
    hertz = report.model["hertz"]
    _, force = report.result.force
    peak = force.max() * report.mass_kg * case.radius * case.wave_speed**2
    time_error = report.contact_time_s / hertz["contact_time_s"] - 1.0
    return time_error, peak / hertz["peak_force_N"] - 1.0


@pytest.mark.slow
def test_the_slow_impact_tends_to_hertz():
    """Contact time and peak force approach Hertz's as |v0| / c_s drops (docs/solid.rst).

    Measured (N for ~6 floor points in the contact, K = 8 with the static
    correction): t_c / t_H - 1 = -8.9 %, -5.9 %, -3.8 % and F / F_H - 1 = +9.2 %,
    +9.4 %, +4.7 % at |v0| / c_s = 0.082, 0.020, 0.005 (t_H / T_2 = 2.1, 2.8, 3.7;
    the peak force carries the ball's vibration, so it need not fall at every step).
    """
    errors = [_hertz_errors(v0, n) for v0, n in ((4.1, 64), (1.0, 112), (0.25, 192))]
    times = [abs(e[0]) for e in errors]
    forces = [abs(e[1]) for e in errors]
    assert times[0] > times[1] > times[2] and forces[0] > forces[2]
    assert times[2] < 0.045 and forces[2] < 0.055


def test_the_materials_derived_moduli_and_speeds():
    """nu = 1/4: Lame's lambda equals mu, so c_p / c_s = sqrt(3); c = c_s / R puts Lamb's
    n = 2 root 2.6399 (the reference value) at omega = eta c_s / R."""
    m = twoball.SolidMaterial(density=1100.0, youngs_modulus=5e6, poisson=0.25)
    mu = m.shear_modulus
    assert mu == pytest.approx(2e6)
    assert m.pressure_speed == pytest.approx(math.sqrt((mu + 2 * mu) / 1100.0))
    assert m.pressure_speed / m.shear_speed == pytest.approx(math.sqrt(3))
    assert m.mass(0.025) == pytest.approx(4 / 3 * math.pi * 0.025**3 * 1100)
    eta = lamb_roots(2, 0.25, 1)[0]
    omega = eta * m.wave_speed(0.025)
    assert omega * 0.025 / m.shear_speed == pytest.approx(2.6399, abs=6e-5)
