"""Contact events (modal/contact/events.py): energy balance (C4), Newton's impact law, the gap.

Large systems use the local Taylor series and the O(n) product ``A z``, checked
against the dense matrices, scipy's ``expm`` and the dense route.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
import scipy.linalg
import scipy.sparse.linalg

import twoball
import twoball.modal.contact.events as events
from twoball.modal.contact.caps import (
    cap_angle,
    legendre_cap_averages,
)
from twoball.modal.contact.events import LocalSeries, grid_step, integrate, make_phases
from twoball.modal.contact.report import legendre_contact
from twoball.modal.contact.states import modal_states
from twoball.modal.contact.system import ContactSystem
from twoball.modal.legendre import legendre_series
from twoball.modal.parameters import Case
from twoball.modal.series import ModalSeries

BASKETBALL = Case.preset("basketball")


def _system(mass_ratio: float, theta: float, damping: float = 0.13, modes: int = 30):
    series = legendre_series(BASKETBALL.phi_a, damping, "lanczos", modes)
    return series, ContactSystem.from_series(
        series, legendre_cap_averages(theta, modes), mass_ratio, BASKETBALL.gamma
    )


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


BODY = twoball.Body(mass_ratio=0.1)


def random_system(size: int, seed: int = 3) -> ContactSystem:
    rng = np.random.default_rng(seed)
    omega = np.sort(rng.uniform(0.0, 40.0, size))
    omega[0] = 0.0  # the constant mode
    return ContactSystem(
        omega=omega,
        masses=rng.uniform(0.5, 2.0, size),
        contact=rng.normal(size=size),
        initial=rng.normal(size=size) * 1e-2,
        damping=0.13,
        body_mass=4 * np.pi * 0.1,
        gamma=0.3,
    )


@pytest.mark.parametrize("mode", ["flight", "contact"])
def test_apply_is_the_phase_matrix(mode):
    system = random_system(150)
    z = np.random.default_rng(1).normal(size=2 * 150 + 3)
    dense = (system.flight_matrix if mode == "flight" else system.contact_matrix) @ z
    assert system.apply(z, mode) == pytest.approx(dense, rel=1e-12, abs=1e-12 * np.abs(dense).max())


@pytest.mark.parametrize("mode", ["flight", "contact"])
def test_local_series_is_the_matrix_exponential(mode):
    system = random_system(150)
    matrix = system.flight_matrix if mode == "flight" else system.contact_matrix
    z = system.start() + np.random.default_rng(2).normal(size=matrix.shape[0]) * 1e-3
    h = grid_step(system)
    local = LocalSeries(lambda x: system.apply(x, mode), z, h)
    taus = np.linspace(0.0, h, 7)
    reference = np.array([scipy.linalg.expm(matrix * t) @ z for t in taus])
    scale = np.abs(reference).max()
    assert np.abs(local.at(taus) - reference).max() <= 1e-14 * scale * 10
    row = np.random.default_rng(4).normal(size=z.size)
    assert local.scalar(row)(taus) == pytest.approx(reference @ row, rel=1e-12, abs=1e-13)


@pytest.mark.slow
def test_large_closed_form_contact_agrees_with_the_dense_route(monkeypatch):
    """121 Legendre modes (243 states): the large route against the dense one (event by event)."""
    case = twoball.Case.preset("basketball", modes=120)
    fast = legendre_contact(case, BODY, exact=True)
    assert 2 * fast.motion.system.size + 3 > events._DENSE_EXPM_MAX
    monkeypatch.setattr(events, "_DENSE_EXPM_MAX", 10**6)
    dense = legendre_contact(case, BODY, exact=True)
    assert [e.kind for e in fast.history.events] == [e.kind for e in dense.history.events]
    for a, b in zip(fast.history.events, dense.history.events, strict=True):
        assert a.t == pytest.approx(b.t, abs=1e-9)
        assert a.velocity == pytest.approx(b.velocity, rel=1e-9, abs=1e-12)
    assert fast.t_liftoff_s == pytest.approx(dense.t_liftoff_s, rel=1e-11)
    assert fast.v_liftoff_m_s == pytest.approx(dense.v_liftoff_m_s, rel=1e-9)


def test_states_of_a_large_system_match_the_dense_exponential():
    case = twoball.Case.preset("basketball", modes=120)
    report = legendre_contact(case, BODY, exact=True)  # the event-driven solution
    system, history = report.motion.system, report.history
    times = np.linspace(0.0, history.t_end, 9)
    got = modal_states(system, history, times)
    from twoball.modal.contact.trajectory import phases

    segments = phases(system, history)
    starts = np.array([s[0] for s in segments])
    for t, state in zip(times, got.state, strict=True):
        t0, z0, mode = segments[max(np.searchsorted(starts, t, side="right") - 1, 0)]
        matrix = system.flight_matrix if mode == "flight" else system.contact_matrix
        reference = scipy.linalg.expm(matrix * (t - t0)) @ z0
        assert np.abs(state - reference).max() <= 1e-11 * np.abs(reference).max()


def test_a_finite_element_sized_system_forms_no_exponential(monkeypatch):
    """Above the dense walk limit neither expm nor expm_multiply of the n x n matrix runs."""
    system = random_system(400)  # 803 states
    real = scipy.linalg.expm

    def small_only(matrix):
        assert matrix.shape[0] <= events._DENSE_EXPM_MAX, "an n x n exponential was formed"
        return real(matrix)

    monkeypatch.setattr(events, "expm", small_only)

    def refused(*args, **kwargs):
        raise AssertionError("expm_multiply was called")

    monkeypatch.setattr(scipy.sparse.linalg, "expm_multiply", refused)
    history = integrate(system, 2.0)
    states = modal_states(system, history, np.linspace(0.0, 2.0, 5))
    assert np.all(np.isfinite(states.state))
    phases = make_phases(system, grid_step(system))
    assert not phases["flight"].walks_dense and phases["contact"].apply is not None
