"""Large contact systems: the local Taylor series and the O(n) product ``A z``.

Finite-element spheres give contact systems of ~1600 states; forming
``exp(A h)`` (O(n^3)) and ``expm_multiply`` per root step made an export with a
body 10x slower than one without.  Each piece is checked against an independent
value: ``A z`` against the dense matrices, the series against scipy's dense
``expm``, and a whole integration against the dense route on the same system.
"""

from __future__ import annotations

import numpy as np
import pytest
import scipy.linalg
import scipy.sparse.linalg
import twoball.modal.contact.events as events
from twoball.modal.contact.events import LocalSeries, grid_step, integrate, make_phases
from twoball.modal.contact.report import legendre_contact
from twoball.modal.contact.states import modal_states
from twoball.modal.contact.system import ContactSystem

import twoball

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


def test_large_closed_form_contact_agrees_with_the_dense_route(monkeypatch):
    """121 Legendre modes (243 states): the large route against the dense one."""
    case = twoball.Case.preset("basketball", modes=120)
    fast = legendre_contact(case, BODY)
    assert 2 * fast.system.size + 3 > events._DENSE_EXPM_MAX
    monkeypatch.setattr(events, "_DENSE_EXPM_MAX", 10**6)
    dense = legendre_contact(case, BODY)
    assert [e.kind for e in fast.history.events] == [e.kind for e in dense.history.events]
    for a, b in zip(fast.history.events, dense.history.events, strict=True):
        assert a.t == pytest.approx(b.t, abs=1e-9)
        assert a.velocity == pytest.approx(b.velocity, rel=1e-9, abs=1e-12)
    assert fast.t_liftoff_s == pytest.approx(dense.t_liftoff_s, rel=1e-11)
    assert fast.v_liftoff_m_s == pytest.approx(dense.v_liftoff_m_s, rel=1e-9)


def test_states_of_a_large_system_match_the_dense_exponential():
    case = twoball.Case.preset("basketball", modes=120)
    report = legendre_contact(case, BODY)
    system, history = report.system, report.history
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
