"""The shell ball through the drop and the whole bounce, unchanged.

The wall, the closed-form ball's description, the books at D = 0 and e = 1 on
both backends, the backends' agreement, the large gap against the ICM with the
run's own coefficients, and causality in the drop: after the first floor touch
the top stays still until the in-plane wave can have arrived, where the
membrane's top moves down at once (the degree-1 artefact).
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np
import pytest

import twoball
from twoball.fem_shell.ball import FEShellBall
from twoball.modal.balls.shell import WALLS, ShellBall, Wall, shell_ball
from twoball.modal.shell import ShellParameters, shell_modes
from twoball.verify.studies.shell import WithoutGas


def _case(name: str = "basketball", **changes: Any) -> twoball.Case:
    return twoball.Case.preset(name, **changes)


# --- the wall ---------------------------------------------------------------------------


@pytest.mark.parametrize(
    ("fields", "name"),
    [
        ({"youngs_modulus": 6e6}, "thickness"),
        ({"thickness": 3e-3}, "youngs_modulus"),
        ({}, "wall_stiffness_ratio"),
        ({"youngs_modulus": -1.0, "thickness": 3e-3}, "youngs_modulus"),
        ({"youngs_modulus": 6e6, "thickness": 0.0}, "thickness"),
        ({"youngs_modulus": 6e6, "thickness": 3e-3, "poisson": 0.6}, "poisson"),
        (
            {"youngs_modulus": 6e6, "thickness": 3e-3, "wall_stiffness_ratio": 3.0},
            "wall_stiffness_ratio",
        ),
        ({"youngs_modulus": 6e6, "thickness": 3e-3, "thickness_ratio": 0.03}, "thickness_ratio"),
        ({"wall_stiffness_ratio": 0.0}, "wall_stiffness_ratio"),
        ({"wall_stiffness_ratio": math.nan}, "wall_stiffness_ratio"),
        ({"wall_stiffness_ratio": 3.0, "thickness_ratio": 0.6}, "thickness_ratio"),
        ({"wall_stiffness_ratio": 3.0, "poisson": 0.0}, "poisson"),
    ],
)
def test_a_wall_is_validated_when_built_naming_the_field(fields, name):
    with pytest.raises(twoball.ParameterError) as error:
        Wall(**fields)
    assert error.value.name == name


def test_si_and_ratios_give_the_same_shell():
    case = _case("tennis")
    si = WALLS["tennis"]
    ratio = si.stiffness(case) / si.tension(case)
    same = Wall(wall_stiffness_ratio=ratio, thickness_ratio=3.2e-3 / case.radius)
    a, b = si.parameters(case), same.parameters(case)
    for field in ("poisson", "bending", "prestress", "gas"):
        assert getattr(a, field) == pytest.approx(getattr(b, field), rel=1e-13)
    # the tennis preset's wall: C = E h / (1 - nu^2) = 25.6 kN/m, N0 = P R / 2
    assert si.stiffness(case) == pytest.approx(6e6 * 3.2e-3 / 0.75)
    assert ratio == pytest.approx(25600.0 / (82700.0 * 0.0335 / 2.0))
    summary = si.summary(case)
    assert summary["in_plane_arrival_s"] == pytest.approx(1.3305e-3, rel=1e-4)  # pi R / c_e
    assert summary["extensional_speed_m_s"] == pytest.approx(79.10, rel=1e-3)


def test_a_too_soft_wall_or_a_thick_one_is_refused_with_the_case():
    case = _case("tennis")
    with pytest.raises(twoball.ParameterError, match="thickness") as error:
        Wall(youngs_modulus=6e6, thickness=0.02).parameters(case)
    assert error.value.name == "thickness"
    with pytest.raises(twoball.ParameterError) as error:  # no gas: 2 (1 + nu) - 2 p <= 0
        Wall(wall_stiffness_ratio=0.5).parameters(case, gas="none")
    assert error.value.name == "wall_stiffness_ratio"
    with pytest.raises(twoball.ParameterError) as error:
        ShellBall(wall="soft")
    assert error.value.name == "wall"
    with pytest.raises(twoball.ParameterError) as error:  # the default basketball has no P
        ShellBall().describe(_case())
    assert error.value.name == "pressure"


# --- the description --------------------------------------------------------------------


def test_the_translation_is_the_centre_and_the_rows_are_vertical_displacements():
    parameters = ShellParameters.from_ratios(0.5, 0.05, 10.0, gas=0.4)
    ball = shell_ball(parameters, 24, twoball.ModalRatio(0.1))
    modes = shell_modes(parameters, 24)
    k = ball.centre
    assert k == modes.translation == 1 and ball.modes == 49
    assert np.all(ball.masses == 1.0)  # every mode has the ball's mass
    assert ball.omega_squared[k] == 0.0 and ball.decay[k] == 0.0
    assert np.all(ball.floor_rows[:, k] == 1.0) and ball.top[k] == 1.0
    assert ball.cap_average(0.2)[k] == 1.0
    # omega^2 in units of c^2 is Omega^2 / p; the gas's share sits on the breathing mode
    p = parameters.prestress
    np.testing.assert_allclose(ball.omega_squared[2:], modes.omega[2:] ** 2 / p, rtol=1e-14)
    assert ball.gas_squared[0] == pytest.approx(0.4 / p) and np.all(ball.gas_squared[1:] == 0)
    np.testing.assert_allclose(ball.decay[2:], 0.2 * modes.omega[2:] / math.sqrt(p), rtol=1e-14)
    # the floor rows are u_z = w cos(phi) - v sin(phi) at the Gauss-Radau nodes
    phi = ball.phi
    expected = (modes.radial(phi) * np.cos(phi) - modes.meridional(phi) * np.sin(phi)).T
    expected[:, k] = 1.0
    np.testing.assert_allclose(ball.floor_rows, expected, atol=1e-12)
    assert phi[-1] == math.pi and phi[0] > math.pi / 2
    # the deformation's samplers leave the translation out; the meridional one exists
    assert np.all(ball.modes_at(phi)[:, k] == 0.0)
    assert np.abs(ball.tangential_at(phi)).max() > 0.1 and ball.bending


def test_the_fe_ball_has_the_same_description_to_its_resolution():
    case = _case("tennis")
    legendre = ShellBall(modes=16).describe(case)
    fe = FEShellBall(elements=32).describe(case)
    k = fe.centre
    assert np.all(fe.floor_rows[:, k] == 1.0) and fe.omega_squared[k] == 0.0
    assert np.all(fe.masses == 1.0)
    # the lowest vibrating frequencies (n = 2 lower, ...) agree
    low_l = np.sort(legendre.omega_squared)[1:6]
    low_f = np.sort(fe.omega_squared)[1:6]
    np.testing.assert_allclose(low_f, low_l, rtol=1e-3)  # P2 on 32 elements: 1.5e-4
    assert fe.phi[0] > math.pi / 2 and fe.phi[-1] == pytest.approx(math.pi)


def test_the_shell_balls_are_balls_with_their_json():
    for ball in (ShellBall(), FEShellBall()):
        assert isinstance(ball, twoball.Ball) and ball.kind == "shell"
    assert ShellBall(modes=64).as_dict() == {
        "ball": "shell",
        "discretisation": "legendre",
        "modes": 64,
        "wall": None,
    }
    with pytest.raises(twoball.ParameterError) as error:
        ShellBall(modes=2000)
    assert error.value.name == "modes"
    with pytest.raises(twoball.ParameterError) as error:
        FEShellBall(elements=2)
    assert error.value.name == "elements"


# --- the drop and the whole bounce ------------------------------------------------------

BALLS = [
    pytest.param(ShellBall(modes=16), id="legendre"),
    pytest.param(FEShellBall(elements=8), id="fem"),
]


@pytest.mark.parametrize("ball", BALLS)
def test_the_books_close_at_d0_and_e1(ball):
    """D = 0, every contact elastic: energy to rounding, momentum (floor impulse) to 1e-10.

    The body of Table 1's row 1 on the tennis shell; the window holds the floor
    contact and the body's (the books close at every step, not only at the end).
    """
    case = _case("tennis", damping=0.0)
    body = twoball.Body(0.062, contact_radius=0.01015, restitution=1.0)
    drop = twoball.Drop(floor_restitution=1.0)
    solver = twoball.MoreauJean(ball, t_end=0.012)  # the floor contact and the body's
    report = twoball.bounce(case, drop, solver=solver, body=body)
    data = report.as_dict()
    assert data["body_contacts"] >= 1
    assert report.result.impulse_balance < 1e-10  # floor impulse = both momenta + weights
    books = data["energy_J"]
    assert abs(books["lost_impacts"]) < 1e-12 * books["initial_kinetic"]
    assert abs(books["dissipated_damping"]) < 1e-14 * books["initial_kinetic"]
    final = (
        books["final_rigid_kinetic"]
        + books["final_membrane_kinetic"]
        + books["final_membrane_elastic"]
        + books["final_gas"]
        + books["final_body_kinetic"]
        + books["gravity_gained"]
        + books["body_gravity_gained"]
    )
    spent = books["lost_impacts"] + books["dissipated_damping"] + books["held_arrivals"]
    # E + W_damp + W_imp + W_held = E0 (held: the arrivals localised inside a step)
    assert final + spent == pytest.approx(books["initial_kinetic"], rel=1e-12)
    assert abs(books["held_arrivals"]) < 1e-9 * books["initial_kinetic"]
    assert books["balance_error"] < 1e-13 * books["initial_kinetic"]
    assert data["model"]["ball"] == "shell" and data["backend"] == ball.backend


@pytest.mark.parametrize("ball", BALLS)
def test_the_drop_alone_keeps_its_momentum_books(ball):
    report = twoball.bounce(_case("tennis"), solver=twoball.MoreauJean(ball))
    weight = report.mass_kg * 9.81 * report.contact_time_s
    change = report.mass_kg * (report.v2_m_s + report.case.v0)
    assert report.floor_impulse_N_s == pytest.approx(change + weight, rel=1e-12)
    assert 0.5 < report.e2 < 1.0


def test_the_json_has_the_membranes_keys_and_the_wall():
    membrane = twoball.bounce(solver=twoball.MoreauJean(twoball.LegendreBall(16))).as_dict()
    shell = twoball.bounce(solver=twoball.MoreauJean(ShellBall(modes=16))).as_dict()
    assert set(membrane) <= set(shell)
    assert set(membrane["model"]) <= set(shell["model"])
    model = shell["model"]
    wall = model["wall"]
    assert wall["wall_stiffness_ratio"] == pytest.approx(4.0)  # the basketball's stated wall
    assert model["in_plane_arrival_s"] == pytest.approx(math.pi / (320.0 * math.sqrt(4.0)))
    assert model["pressure_wave_arrival_s"] == pytest.approx(math.pi / 320.0)
    assert shell["mass_kg"] == pytest.approx(membrane["mass_kg"])


@pytest.mark.parametrize("gap", [0.05])
def test_the_backends_agree_on_the_tennis_shell(gap):
    """Legendre N = 128 and P2 on 64 elements (the defaults): 1e-3 on the tennis ball."""
    runs = [
        twoball.bounce(
            drop=twoball.Drop(gap=gap), solver=twoball.MoreauJean(ball), pair="tennis-coin"
        )
        for ball in (ShellBall(), FEShellBall())
    ]
    for name in ("contact_time_s", "e2", "v1_ratio", "v2_ratio", "t_liftoff_s"):
        a, b = (getattr(r, name) for r in runs)
        assert b == pytest.approx(a, rel=1e-3), name


AGREEMENT = [
    ("basketball", None, 0.0),
    ("basketball", "basketball-tennis", 0.0),
    ("basketball", "basketball-tennis", 0.05),
    ("tennis", None, 0.0),
    ("tennis", "tennis-coin", 0.0),
    ("tennis", "tennis-coin", 0.05),
]


@pytest.mark.slow
@pytest.mark.parametrize(("preset", "pair", "gap"), AGREEMENT)
def test_the_backends_agree_to_1e3(preset, pair, gap):
    """Legendre N = 256 and P2 on 192 elements: t_c, e2, v1, v2, t_l within 1e-3.

    e2 of the whole bounce at 50 mm (the floor release while the body strikes) jumps
    by ~1e-3 with the floor point released last: P2 on 64, 128, 192 elements give
    0.71890, 0.71876, 0.71785 against Legendre 0.71793, 0.71792, 0.71773 (N = 128,
    256, 384).
    """
    runs = []
    for ball in (ShellBall(modes=256), FEShellBall(elements=192)):
        given = {"pair": pair} if pair else {"case": _case(preset)}
        solver = twoball.MoreauJean(ball)
        runs.append(twoball.bounce(drop=twoball.Drop(gap=gap), solver=solver, **given))
    names = ["contact_time_s", "e2"]
    if pair:
        names += ["v1_ratio", "v2_ratio", "t_liftoff_s"]
    for name in names:
        a, b = (getattr(r, name) for r in runs)
        assert b == pytest.approx(a, rel=1e-3), name


@pytest.mark.parametrize("ball", BALLS)
def test_a_large_gap_is_the_icm_with_the_runs_own_coefficients(ball):
    """The ball leaves the floor before the body touches: (2.5) with e2 and e12_effective."""
    case = _case("basketball", g=1e-6)  # no weight: exact to the momentum books
    body = twoball.Body(0.101, contact_radius=0.0262, restitution=0.89)
    drop = twoball.Drop(gap=0.2)
    report = twoball.bounce(case, drop, solver=twoball.MoreauJean(ball), body=body)
    data = report.as_dict()
    assert data["sequence"] == "independent" and not data["body_left_first"]
    icm = data["icm_solver"]
    assert icm is not None and 0.0 < icm["e12"] < 1.0
    assert report.v1_ratio == pytest.approx(icm["v1_ratio"], abs=1e-8)  # g t_c / |v0| ~ 4e-9
    assert report.v2_ratio == pytest.approx(icm["v2_ratio"], abs=1e-8)


def test_a_large_gap_under_gravity_is_the_icm_within_g_tc():
    case = _case("tennis")
    body = twoball.Body(0.062, contact_radius=0.01015, restitution=0.46)
    report = twoball.bounce(
        case, twoball.Drop(gap=0.15), solver=twoball.MoreauJean(ShellBall(modes=16)), body=body
    )
    icm = report.icm_solver
    assert report.as_dict()["sequence"] == "independent"
    tolerance = case.g * report.contact_time_s / case.v0
    assert abs(report.v1_ratio - icm["v1_ratio"]) < tolerance
    assert abs(report.v2_ratio - icm["v2_ratio"]) < tolerance


# --- causality in the drop --------------------------------------------------------------


def top_over_centre(ball: Any, case: twoball.Case, cap: float | None, t_end: float | None = None):
    """Times (units 1/c) and the top's vertical displacement over the centre's, both
    measured from the free fall the floor interrupts; ``cap`` a contact radius [m] (None:
    the pole)."""
    report = twoball.bounce(case, solver=twoball.MoreauJean(ball, t_end=t_end))
    result = report.result
    trajectory, description = result.trajectory, result.system.ball
    c, t = description.centre, trajectory.t
    q = trajectory.q[:, : description.modes].copy()
    free = q[0, c] - result.settings.v0 * t - 0.5 * result.settings.gamma * t * t
    q[:, c] -= free
    row = description.top if cap is None else description.cap_average(math.asin(cap / case.radius))
    ratio = (q @ row) / np.where(q[:, c] == 0.0, 1.0, q[:, c])
    return t, ratio, report


@pytest.mark.parametrize(
    ("ball", "quiet_from"),
    [(WithoutGas(FEShellBall()), 0.0), (WithoutGas(ShellBall()), 0.05)],
    ids=["fem", "legendre"],
)
def test_the_top_stays_still_until_the_in_plane_wave_arrives(ball, quiet_from):
    """Basketball wall, D = 0, no gas: |top / centre| < 1e-3 up to 0.5 pi R / c_e, then up.

    The top is the tennis ball's contact cap (26.2 mm).  The Legendre series starts
    with the truncated point impulse's reach to the top (0.57 at N = 128, 0.48 at
    256), gone by 0.05 pi R / c_e; the finite elements' local mass has none.
    """
    case = _case("basketball", damping=0.0)
    ta = math.pi / math.sqrt(WALLS["basketball"].wall_stiffness_ratio)  # pi R / c_e, units 1/c
    t, ratio, report = top_over_centre(ball, case, 0.0262, t_end=2.0 * ta / case.wave_speed)
    quiet = (t > quiet_from * ta) & (t <= 0.5 * ta)
    assert np.abs(ratio[quiet]).max() < 1e-3
    later = np.interp(1.5 * ta, t, ratio)
    assert later > 0.3  # it moves with the centre, once the wave is there
    assert report.model["in_plane_arrival_s"] * case.wave_speed == pytest.approx(ta)


def test_the_membranes_top_moves_down_at_once():
    """The radial membrane: the top starts at about -2 times the centre (the degree-1 artefact)."""
    case = _case("basketball", damping=0.0)
    t, ratio, _ = top_over_centre(twoball.LegendreBall(64), case, 0.0262, t_end=0.5 / 320.0)
    assert np.interp(0.1, t, ratio) < -1.5
