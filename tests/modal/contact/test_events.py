"""The upper body of finite mass in unilateral contact (issue 13), Legendre backend.

Independent values: the closed-form cap averages, today's massless lift-off, a
massless particle integrated by explicit stepping over the known cap motion, the
energy balance (C4) and Newton's impact law.
"""

from __future__ import annotations

import math
import subprocess
import sys

import numpy as np
import pytest
from twoball.modal.contact.caps import (
    cap_angle,
    legendre_cap_averages,
    legendre_cap_averages_closed,
)
from twoball.modal.contact.events import integrate
from twoball.modal.contact.system import ContactSystem
from twoball.modal.legendre import legendre_series
from twoball.modal.parameters import Case
from twoball.modal.series import ModalSeries

import twoball
from twoball import Body
from twoball._common.errors import ParameterError

BASKETBALL = Case.preset("basketball")


def _system(mass_ratio: float, theta: float, damping: float = 0.13, modes: int = 30):
    series = legendre_series(BASKETBALL.phi_a, damping, "lanczos", modes)
    return series, ContactSystem.from_series(
        series, legendre_cap_averages(theta, modes), mass_ratio, BASKETBALL.gamma
    )


@pytest.mark.parametrize("theta", [0.3, 0.1, 1e-2])
def test_cap_averages_match_closed_form(theta):
    gauss = legendre_cap_averages(theta, 40)
    closed = legendre_cap_averages_closed(theta, 40)
    # the closed form loses ~eps/theta^2 to cancellation
    assert np.max(np.abs(gauss - closed)) < 50 * np.finfo(float).eps / theta**2
    assert gauss[0] == pytest.approx(1.0, abs=1e-15)


def test_cap_average_tends_to_pole_value():
    theta = 1e-4
    b = legendre_cap_averages(theta, 30)
    n = np.arange(31)
    # <P_n>_cap = 1 - n(n+1) theta^2 / 8 + O(theta^4)
    assert np.max(np.abs(b - (1 - n * (n + 1) * theta**2 / 8))) < 1e-12


def test_massless_mode_recovers_todays_pole_result():
    """mu = 0 on a cap of a = 1e-5 m: the paper's criteria on the cap = today's pole result."""
    today = twoball.liftoff(BASKETBALL)
    massless = twoball.liftoff(BASKETBALL, body=Body(0.0, contact_radius=1e-5))
    assert massless.t_liftoff_s == pytest.approx(today.t_liftoff_s, rel=1e-4)
    assert massless.v_liftoff_m_s == pytest.approx(today.v_liftoff_m_s, rel=1e-4)


def _massless_particle(series: ModalSeries, gamma: float, t_end: float, dt: float):
    """A massless particle on the cap by explicit stepping (O(dt)): last separation."""
    t = np.arange(0.0, t_end, dt)
    u, ut, utt = series.pole(t)
    touching, s, v, last = True, u[0], 0.0, None
    for j in range(1, t.size):
        if touching:
            s, v = u[j], ut[j]
            if utt[j] + gamma < 0.0:  # the cap accelerates down faster than gravity
                touching, last = False, (t[j], ut[j])
        else:
            s, v = s + v * dt - 0.5 * gamma * dt * dt, v - gamma * dt
            if s <= u[j]:  # inelastic impact: the particle takes the cap's velocity
                s, v = u[j], ut[j]
                if utt[j] + gamma >= 0.0:
                    touching = True
                else:
                    last = (t[j], ut[j])
    return None if touching else last


def test_small_mass_limit_is_the_massless_particle():
    """mu -> 0: the dynamics tend to a massless particle over the unchanged cap motion."""
    theta = cap_angle(1e-5, BASKETBALL.radius)
    series, system = _system(1e-7, theta)
    history = integrate(system, 4 * math.pi)
    cap = ModalSeries(
        series.omega, series.coefficients, system.contact, series.damping, series.filter,
        series.mode_norms,
    )  # fmt: skip
    t_ref, v_ref = _massless_particle(cap, BASKETBALL.gamma, 4 * math.pi, 2e-5)
    assert history.lifted
    assert history.t == pytest.approx(t_ref, abs=4e-5)
    assert history.velocity == pytest.approx(v_ref, rel=1e-3)
    # the approach is first order in mu, with relative size ~ mu_t kappa (here ~1e-3 at
    # mu = 1e-6: the point-like cap makes kappa = sum b_k^2 / m_k ~ (N + 1)^2 / (4 pi) large)
    v = {}
    for mu in (1e-6, 1e-8):
        v[mu] = integrate(_system(mu, theta)[1], 4 * math.pi).velocity
    order = math.log10(abs(v[1e-6] - history.velocity) / abs(history.velocity - v[1e-8]))
    assert 0.9 < order < 1.1
    bound = 4 * math.pi * 1e-6 * system.compliance
    assert abs(v[1e-6] / history.velocity - 1) < bound


@pytest.mark.parametrize("restitution", [0.0, 0.5])
def test_energy_conserved_between_impacts_at_zero_damping(restitution):
    """D = 0: E(t_end) = E(0) - sum of impact losses; each loss is (1 - e^2) m_eff g'^2 / 2."""
    _, system = _system(0.05, 0.1, damping=0.0)
    history = integrate(system, 4 * math.pi, restitution)
    impacts = history.impacts
    assert len(impacts) >= 2
    start = float(system.energy(system.start()))
    losses = sum(e.energy_loss for e in impacts)
    end = float(system.energy(history.final_state))
    assert end == pytest.approx(start - losses, rel=1e-9, abs=1e-12 * start)
    for e in impacts:
        # the law applied: e, or 0 at the tail of a Zeno sequence (docs/contact.rst)
        applied = -float(system.gap_rate(e.state_after)) / e.approach
        assert applied == pytest.approx(restitution, abs=1e-9) or abs(applied) < 1e-9
        expected = 0.5 * (1 - applied**2) * system.effective_mass * e.approach**2
        assert e.energy_loss == pytest.approx(expected, rel=1e-8, abs=1e-15)
        # energy just before each impact follows from the start and the earlier losses
        earlier = sum(x.energy_loss for x in impacts if x.t < e.t)
        assert e.energy_before == pytest.approx(start - earlier, rel=1e-9)


def test_damped_energy_only_decreases():
    _, system = _system(0.05, 0.1, damping=0.13)
    history = integrate(system, 4 * math.pi)
    energies = [float(system.energy(system.start()))] + [e.energy_before for e in history.events]
    assert all(b <= a * (1 + 1e-12) for a, b in zip(energies, energies[1:], strict=False))


@pytest.mark.parametrize("restitution", [0.0, 0.3])
def test_impulse_matches_momentum_exchange(restitution):
    """Each impact: body momentum jump P, modal jumps -b_k P, mode 0 + body conserved."""
    _, system = _system(0.1, 0.1, damping=0.0)
    history = integrate(system, 4 * math.pi, restitution=restitution)
    k = system.size
    for e in history.impacts:
        before, after = e.state_before, e.state_after
        body_jump = system.body_mass * (after[2 * k + 1] - before[2 * k + 1])
        assert body_jump == pytest.approx(e.impulse, rel=1e-12, abs=1e-18)
        modal_jump = system.masses * (after[k : 2 * k] - before[k : 2 * k])
        np.testing.assert_allclose(modal_jump, -system.contact * e.impulse, atol=1e-15)
        # b_0 = 1: the breathing mode's momentum and the body's sum to a constant
        total_before = system.masses[0] * before[k] + system.body_mass * before[2 * k + 1]
        total_after = system.masses[0] * after[k] + system.body_mass * after[2 * k + 1]
        assert total_after == pytest.approx(total_before, abs=1e-14)
        # Newton's law: g'+ = -e g'-
        applied = -float(system.gap_rate(after)) / e.approach
        assert applied == pytest.approx(restitution, abs=1e-9) or abs(applied) < 1e-9


def test_gap_never_negative_on_a_fine_grid():
    """The event search misses no contact: g >= 0 in flight between the events."""
    from scipy.linalg import expm

    _, system = _system(0.01, 0.1)
    history = integrate(system, 4 * math.pi)
    events = history.events
    for sep, nxt in zip(events, events[1:], strict=False):
        if sep.kind != "separation":
            continue
        times = np.linspace(0, nxt.t - sep.t, 400)[1:-1]
        states = np.array([expm(system.flight_matrix * t) @ sep.state_after for t in times])
        assert system.gap(states).min() > -1e-12


def test_liftoff_without_mass_ratio_is_unchanged():
    """The contact options leave the massless path bit-identical."""
    from twoball.modal.report import legendre_liftoff

    a = twoball.liftoff(BASKETBALL)
    b = legendre_liftoff(BASKETBALL)
    assert (a.t_liftoff_s, a.v_liftoff_m_s) == (b.t_liftoff_s, b.v_liftoff_m_s)


def test_energy_option_both_deforms_more():
    ball = twoball.liftoff(BASKETBALL, body=Body(0.1))
    both = twoball.liftoff(BASKETBALL, body=Body(0.1, energy="both"))
    assert both.as_dict()["phi_a_rad"] < ball.as_dict()["phi_a_rad"]  # eq. (3.7) at larger v0


def _contact(body: Body, **kwargs):
    return twoball.liftoff(BASKETBALL, body=body, **kwargs)


@pytest.mark.parametrize(
    ("call", "name"),
    [
        (lambda: _contact(Body(-1.0)), "mass_ratio"),
        (lambda: _contact(Body(float("nan"))), "mass_ratio"),
        (lambda: _contact(Body(0.1, contact_radius=0.2)), "contact_radius"),  # a >= R = 0.12 m
        (lambda: _contact(Body(0.1, contact_radius=0.0)), "contact_radius"),
        (lambda: _contact(Body(0.1, restitution=1.5)), "restitution"),
        (lambda: _contact(Body(0.1, energy="all")), "energy"),
        (lambda: _contact(Body(0.1), backend="spectral"), "backend"),
        (
            lambda: _contact(Body(0.1), backend="fem", stepping=twoball.Stepping(scheme="alpha")),
            "scheme",
        ),
        (
            lambda: _contact(Body(0.1), backend="fem", mesh=twoball.MeshOptions("axisym", level=2)),
            "level",
        ),
        (lambda: _contact(Body(0.1), recontact="paper"), "recontact"),
        (lambda: _contact(Body(0.1), damping=twoball.Rayleigh()), "damping"),
    ],
)
def test_bad_contact_input_names_the_parameter(call, name):
    with pytest.raises(twoball.ParameterError) as info:
        call()
    assert info.value.name == name


def _cli(*args):
    return subprocess.run(
        [sys.executable, "-m", "twoball", *args], capture_output=True, text=True, check=False
    )


def test_cli_mass_ratio_json_matches_api():
    import json

    out = _cli("liftoff", "--mass-ratio", "0.004", "--contact-radius", "0.006", "--json")
    assert out.returncode == 0, out.stderr
    data = json.loads(out.stdout)
    api = twoball.liftoff(BASKETBALL, body=Body(0.004, contact_radius=0.006))
    assert data["v_liftoff_m_s"] == api.v_liftoff_m_s
    assert data["impacts"] == len(api.history.impacts)


def test_cli_bad_mass_ratio_is_one_line():
    out = _cli("liftoff", "--mass-ratio", "-1")
    assert out.returncode == 2
    assert out.stdout == ""
    assert (
        out.stderr.strip() == "twoball: error: --mass-ratio must be a number in [0, 100], got -1.0"
    )


def test_converges_in_modes_at_second_order():
    """a = R/10, mu = 0.101: v1(N) converges like N^-2 (the Lanczos filter); band 1.6-2.6."""
    v = {}
    for modes in (30, 60, 120):
        case = BASKETBALL.derive(modes=modes)
        v[modes] = twoball.liftoff(case, body=Body(0.101, contact_radius=0.012)).v_liftoff_m_s
    order = math.log2(abs(v[60] - v[30]) / abs(v[120] - v[60]))
    assert 1.6 < order < 2.6


def test_event_grid_does_not_change_the_result():
    """The events are exact roots: 16, 32 or 64 grid points per period give the same v1."""
    from twoball.modal.contact.report import legendre_contact

    body = Body(0.101, contact_radius=0.012)
    v = [legendre_contact(BASKETBALL, body, samples_per_period=n).v_liftoff_m_s for n in (16, 64)]
    assert v[0] == pytest.approx(v[1], rel=1e-10)


def test_mass_ratio_sweep_equals_single_runs():
    cap = Body(0.0, contact_radius=0.03)  # the other fields of every swept mass ratio
    result = twoball.sweep({"mass_ratio": [0.004, 0.101]}, BASKETBALL, body=cap)
    for point, mu in zip(result.points, (0.004, 0.101), strict=True):
        single = twoball.liftoff(BASKETBALL, body=Body(mu, contact_radius=0.03))
        assert point.v_liftoff_m_s == single.v_liftoff_m_s
        assert point.as_dict()["mass_ratio"] == mu
    with pytest.raises(twoball.ParameterError) as info:
        twoball.sweep({"mass_ratio": [-1.0]}, BASKETBALL)
    assert info.value.name == "mass_ratio"
    with pytest.raises(twoball.ParameterError) as info:
        twoball.sweep({"mass_ratio": [0.1]}, BASKETBALL, body=Body(0.0, contact_radius=0.2))
    assert info.value.name == "contact_radius"  # a >= R = 0.12 m


def test_reproduce_contact_part(tmp_path):
    """The reproduce figure's curve is the API's, and falls with the mass ratio."""
    from twoball.verify.reproduce.common import Context
    from twoball.verify.reproduce.contact import part_contact
    from twoball.verify.sweeps.parallel import Runner

    with Runner(workers=1) as runner:
        section = part_contact(Context(tmp_path, runner))
    ratios = section.data["ratios"]
    assert (tmp_path / "contact_mass_ratio.png").stat().st_size > 0
    mu = section.data["mass_ratios"][-1]
    assert ratios[-1] == twoball.liftoff(BASKETBALL, body=Body(mu)).ratio
    assert all(b < a for a, b in zip(ratios, ratios[1:], strict=False))


def test_trajectory_follows_the_events():
    """The sampled path: gap >= 0, body on the cap in contact phases, event values hit."""
    report = twoball.liftoff(BASKETBALL, body=Body(0.004))
    data = report.trajectory_si(400)
    gap = data["body_height_m"] - data["cap_displacement_m"]
    assert gap.min() > -1e-12 * BASKETBALL.radius
    on = data["contact"]
    assert on.any() and (~on).any()
    np.testing.assert_allclose(gap[on], 0.0, atol=1e-12 * BASKETBALL.radius)
    final = report.events_si()[-1]
    after = data["t_s"] > final["t_s"]
    t = data["t_s"][after] - final["t_s"]
    g = BASKETBALL.g
    expected = final["height_m"] + final["velocity_m_s"] * t - 0.5 * g * t * t
    np.testing.assert_allclose(data["body_height_m"][after], expected, rtol=1e-9, atol=1e-12)


def test_cli_plot_contact_sequence(tmp_path):
    target = tmp_path / "sequence.png"
    out = _cli("liftoff", "--mass-ratio", "0.004", "--plot", str(target))
    assert out.returncode == 0, out.stderr
    assert target.stat().st_size > 0
    bad = _cli("liftoff", "--plot", str(tmp_path / "x.png"))
    assert bad.returncode == 2
    assert bad.stderr.strip() == (
        "twoball: error: --plot must be given only with a mass ratio > 0 (the body's path is "
        f"drawn), got '{tmp_path / 'x.png'}'"
    )


@pytest.mark.parametrize("mass_ratio", [0.0, 0.1])
def test_a_body_on_a_stiff_ball_is_refused_not_solved_as_a_membrane(mass_ratio):
    """The contact system holds the membrane's modes only: bending or gas would be dropped."""
    with pytest.raises(ParameterError, match="mass_ratio.*bending or gas"):
        twoball.liftoff(Case.preset("tennis"), body=Body(mass_ratio))
    with pytest.raises(ParameterError, match="mass_ratio.*bending or gas"):
        twoball.sweep({"mass_ratio": [0.01]}, Case.preset("volleyball"))
