"""The Legendre contact solution (modal/contact/report.py) of a body of finite mass."""

from __future__ import annotations

import math

import numpy as np
import pytest

import twoball
from twoball import Body
from twoball._common.errors import ParameterError
from twoball.modal.contact.report import CONTACT_WARNING, legendre_contact
from twoball.modal.parameters import Case, preset

BASKETBALL = Case.preset("basketball")


def test_massless_mode_recovers_todays_pole_result():
    """mu = 0 on a cap of a = 1e-5 m: the paper's criteria on the cap = today's pole result."""
    today = twoball.liftoff(BASKETBALL)
    massless = twoball.liftoff(BASKETBALL, body=Body(0.0, contact_radius=1e-5))
    assert massless.t_liftoff_s == pytest.approx(today.t_liftoff_s, rel=1e-4)
    assert massless.v_liftoff_m_s == pytest.approx(today.v_liftoff_m_s, rel=1e-4)


def test_energy_option_both_deforms_more():
    ball = twoball.liftoff(BASKETBALL, body=Body(0.1))
    both = twoball.liftoff(BASKETBALL, body=Body(0.1, energy="both"))
    assert both.as_dict()["phi_a_rad"] < ball.as_dict()["phi_a_rad"]  # eq. (3.7) at larger v0


@pytest.mark.slow
def test_converges_in_modes_at_second_order():
    """a = R/10, mu = 0.101: v1(N) converges like N^-2 (the Lanczos filter); band 1.6-2.6."""
    v = {}
    for modes in (30, 60, 120):
        case = BASKETBALL.derive(modes=modes)
        v[modes] = twoball.liftoff(case, body=Body(0.101, contact_radius=0.012)).v_liftoff_m_s
    order = math.log2(abs(v[60] - v[30]) / abs(v[120] - v[60]))
    assert 1.6 < order < 2.6


def test_event_grid_does_not_change_the_result():
    """The exact solver's events are roots: 16 or 64 grid points per period give the same v1."""
    from twoball.modal.contact.caps import cap_angle, legendre_cap_averages
    from twoball.modal.contact.events import integrate
    from twoball.modal.contact.system import ContactSystem
    from twoball.modal.legendre import legendre_series

    modes = BASKETBALL.modes
    series = legendre_series(BASKETBALL.phi_a, BASKETBALL.damping, "lanczos", modes)
    cap = legendre_cap_averages(cap_angle(0.012, BASKETBALL.radius), modes)
    system = ContactSystem.from_series(series, cap, 0.101, BASKETBALL.gamma)
    runs = [integrate(system, 4.0 * math.pi, samples_per_period=n) for n in (16, 64)]
    assert all(run.lifted for run in runs)
    assert runs[0].velocity == pytest.approx(runs[1].velocity, rel=1e-10)
    assert runs[0].t == pytest.approx(runs[1].t, rel=1e-10)


def _path_against_events(report, gap_floor: float, flight: float) -> None:
    """The sampled path: gap >= -gap_floor [m], the body on the cap within it in contact
    phases, and after the last event the free flight from its values within ``flight`` [m]."""
    data = report.trajectory_si(400)
    gap = data["body_height_m"] - data["cap_displacement_m"]
    assert gap.min() > -gap_floor
    on = data["contact"]
    assert on.any() and (~on).any()
    np.testing.assert_allclose(gap[on], 0.0, atol=gap_floor)
    final = report.events_si()[-1]
    after = data["t_s"] > final["t_s"]
    assert after.any()
    t = data["t_s"][after] - final["t_s"]
    g = BASKETBALL.g
    expected = final["height_m"] + final["velocity_m_s"] * t - 0.5 * g * t * t
    np.testing.assert_allclose(data["body_height_m"][after], expected, rtol=1e-9, atol=flight)


def test_trajectory_follows_the_events():
    """The exact (event-driven) path: gap >= 0 and event values hit to rounding."""
    report = legendre_contact(BASKETBALL, Body(0.004), reference=False, exact=True)
    _path_against_events(report, 1e-12 * BASKETBALL.radius, 1e-12)


def test_stepped_trajectory_follows_its_events_within_the_step():
    """The default (Moreau-Jean, dt = 0.005 / c) path of the same body: the contact holds at
    the velocity level, so the gap may close by O(dt^2) between step ends (measured -8.0e-10 m,
    7e-9 R); the flight after the last separation starts from the separation's interpolated
    values (measured 1.3e-10 m off the parabola).  Bounds: 1e-9 m and 2e-10 m."""
    report = twoball.liftoff(BASKETBALL, body=Body(0.004))
    assert report.extra["integrator"] == "moreau-jean"
    _path_against_events(report, 1e-9, 2e-10)


@pytest.mark.parametrize("mass_ratio", [0.1, pytest.param(0.004, marks=pytest.mark.slow)])
def test_the_stepped_contact_converges_to_the_exact_event_driven_solution(mass_ratio):
    """The default (Moreau-Jean, dt = 0.005 / c) against ``exact=True``, basketball, N = 30,
    a = R/10: the same events; measured t_l -2.4e-5 and -1.1e-4, v1 +3.7e-4 and +3.3e-4
    (mu = 0.1, 0.004; the largest of mu = 0.1, 0.01, 0.004: t_l 1.1e-4, v1 4.6e-4), held
    within 1.5e-4 and 6e-4; v1's error falls by 3.9 and 2.9 when dt halves (second order;
    separations are not localised, so t_l has no clean order): held above 2.5."""
    body = Body(mass_ratio)
    exact = legendre_contact(BASKETBALL, body, reference=False, exact=True)
    stepped = legendre_contact(BASKETBALL, body, reference=False)
    half = legendre_contact(BASKETBALL, body, reference=False, dt=0.0025)
    kinds = [e.kind for e in exact.history.events]
    assert [e.kind for e in stepped.history.events] == kinds and kinds[-1] == "separation"
    assert abs(stepped.t_liftoff_s / exact.t_liftoff_s - 1.0) < 1.5e-4
    errors = [abs(r.v_liftoff_m_s / exact.v_liftoff_m_s - 1.0) for r in (stepped, half)]
    assert errors[0] < 6e-4 and errors[0] / errors[1] > 2.5


@pytest.mark.parametrize("mass_ratio", [0.0, 0.1])
def test_a_body_on_a_stiff_ball_is_refused_not_solved_as_a_membrane(mass_ratio):
    """The contact system holds the membrane's modes only: bending or gas would be dropped."""
    with pytest.raises(ParameterError, match="mass_ratio.*bending or gas"):
        twoball.liftoff(Case.preset("tennis"), body=Body(mass_ratio))
    with pytest.raises(ParameterError, match="mass_ratio.*bending or gas"):
        twoball.sweep({"mass_ratio": [0.01]}, Case.preset("volleyball"))


# --- The contact mode carries the massless path's trust warnings: truncation, mesh, window

BODY = twoball.Body(mass_ratio=0.1)


def test_too_few_modes_is_warned_against_the_finer_solution() -> None:
    coarse = legendre_contact(preset("basketball").derive(modes=3), BODY)
    assert not coarse.lifted
    (text,) = coarse.warnings
    assert text.startswith("N = 3 finds no lift-off, but the contact solution with N = 60")
    assert "11.79 ms" in text
    converged = legendre_contact(preset("basketball").derive(modes=240), BODY, reference=False)
    assert converged.lifted and converged.t_liftoff_s == pytest.approx(0.011785, rel=1e-4)


def test_default_is_quiet_and_its_block_estimates_the_error() -> None:
    report = legendre_contact(preset("basketball"), BODY)
    assert report.warnings == ()
    block = report.extra["truncation"]
    assert block["checked"] and block["reference_modes"] == 60
    converged = legendre_contact(preset("basketball").derive(modes=240), BODY, reference=False)
    error = report.v_liftoff_m_s / converged.v_liftoff_m_s - 1  # -2.0 %
    # the difference to 2N is most of the error (O(N^-2): 3/4 of it)
    assert 0.6 * abs(error) < abs(block["v_difference"]) <= abs(error)
    assert abs(block["v_difference"]) < CONTACT_WARNING


def test_a_body_falling_with_the_membrane_has_not_lifted(capsys) -> None:
    """--t-end 0.005: the body leaves the cap at 3.78 ms moving down (v1 = -0.028 m/s)."""
    report = twoball.liftoff(body=BODY, solver=twoball.MoreauJean(t_end=0.005))
    last = report.events_si()[-1]
    assert last["kind"] == "separation" and last["velocity_m_s"] < 0
    assert not report.lifted and report.t_liftoff_s is None and report.v_liftoff_m_s is None
    assert any("moving down" in w and "not a lift-off" in w for w in report.warnings)
    default = twoball.liftoff(body=BODY)
    assert default.lifted and default.v_liftoff_m_s > 0 and default.t_liftoff_s > 0.005


def test_coarse_fem_mesh_is_warned() -> None:
    """Icosphere level 0, P1: 2.85 ms against 11.8 ms."""
    mesh = twoball.MeshOptions("sphere", level=0, order=1)
    report = twoball.liftoff(solver=twoball.MoreauJean(twoball.FEBall(mesh)), body=BODY)
    assert report.t_liftoff_s == pytest.approx(2.85e-3, rel=0.01)
    assert any(w.startswith("mesh under-resolves") for w in report.warnings)
    (text,) = [w for w in report.warnings if w.startswith("the fem result is t_l -7")]
    assert "truncation and discretisation" in text
    axisym = twoball.FEBall(twoball.MeshOptions("axisym"))
    fine = twoball.liftoff(solver=twoball.MoreauJean(axisym), body=BODY)
    assert fine.warnings == ()


def test_sweep_points_keep_the_window_warnings_without_the_reference() -> None:
    solver = twoball.MoreauJean(t_end=0.005)
    result = twoball.sweep({"mass_ratio": [0.1]}, solver=solver, body=BODY)
    (point,) = result.points
    assert "truncation" not in point.report.extra
    assert any("not a lift-off" in w for w in point.report.warnings)
