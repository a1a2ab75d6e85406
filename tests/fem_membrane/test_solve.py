"""Finite-element lift-off (fem_membrane/solve.py) against the Legendre series.

Eqs. (3.9)-(3.16): modal superposition and generalized-alpha, P1 to P4, routes.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from tests.fem_membrane.helpers import model
from tests.helpers import rates
from twoball._common.errors import ParameterError
from twoball.fem_membrane.alpha import automatic_step
from twoball.fem_membrane.solve import alpha_motion, fem_pole_motion, modal_model
from twoball.modal.filters import SpectralFilter
from twoball.modal.legendre import legendre_coefficients, legendre_series
from twoball.modal.liftoff import SampledPoleMotion, find_liftoff
from twoball.modal.parameters import Case

PHI_A, DAMPING = 2.6, 0.13


def pole_difference(axisym_model, motion) -> np.ndarray:
    exact = axisym_model.series.pole(motion.times)
    sampled = motion.pole(motion.times)
    return np.array([np.abs(a - b).max() for a, b in zip(sampled, exact, strict=True)])


FILTER = SpectralFilter("lanczos", 30)
GAMMA = Case().gamma  # 9.81 / (0.12 * 320**2)


@pytest.fixture(scope="module")
def reference():
    return find_liftoff(legendre_series(PHI_A, DAMPING, FILTER), GAMMA)


def difference(result, reference) -> np.ndarray:
    assert result.lifted
    return np.array(
        [abs(result.t / reference.t - 1.0), abs(result.velocity / reference.velocity - 1.0)]
    )


def lift(mesh: str, order: int, size: int, reference) -> np.ndarray:
    return difference(find_liftoff(model(mesh, order, size).series, GAMMA), reference)


@pytest.mark.parametrize("rho_inf", [1.0, 0.5])
def test_alpha_matches_modal_at_order_2(axisym_model, rho_inf):
    differences = []
    for steps in (1000, 2000, 4000):
        motion, info = alpha_motion(axisym_model, dt=4 * np.pi / steps, rho_inf=rho_inf)
        assert isinstance(motion, SampledPoleMotion) and info["steps"] == steps
        differences.append(pole_difference(axisym_model, motion))
    differences = np.array(differences)  # rows: dt; columns: u, u_t, u_tt
    orders = np.log2(differences[:-1] / differences[1:])
    assert np.all((orders > 1.8) & (orders < 2.2)), orders


def test_alpha_liftoff_converges_to_modal_liftoff_at_order_2(axisym_model):
    # the step samples go through per-field splines, so t_l and v_l inherit O(dt^2)
    reference = find_liftoff(axisym_model.series, GAMMA)
    gaps = []
    for steps in (1000, 2000, 4000):
        motion, _ = alpha_motion(axisym_model, dt=4 * np.pi / steps)
        result = find_liftoff(motion, GAMMA)
        gaps.append(
            [abs(result.t / reference.t - 1), abs(result.velocity / reference.velocity - 1)]
        )
    gaps = np.array(gaps)
    orders = np.log2(gaps[:-1] / gaps[1:])
    assert np.all((orders > 1.8) & (orders < 2.2)), orders
    assert np.all(gaps[-1] < 1e-4)


def test_fem_pole_motion_alpha_with_automatic_step():
    motion, info = fem_pole_motion(
        PHI_A, DAMPING, "lanczos", mesh="axisym", elements=40, order=2, scheme="alpha"
    )
    assert info["time_scheme"] == "alpha" and info["rho_inf"] == 1.0
    assert info["dt"] * info["omega_cut"] <= 0.2 + 1e-12
    assert info["steps"] * info["dt"] == pytest.approx(4 * np.pi)
    assert motion.times[-1] >= 4 * np.pi
    assert automatic_step(31.0, 4 * np.pi) * 31.0 <= 0.2


@pytest.mark.parametrize(
    ("options", "flag", "valid"),
    [
        ({"mesh": "sphere", "level": -1}, "level", "an integer in [0, 10]"),
        ({"mesh": "sphere", "level": 1.5}, "level", "an integer in [0, 10]"),
        ({"mesh": "axisym", "order": 5}, "order", "1, 2, 3 or 4"),
        ({"mesh": "axisym", "order": 0}, "order", "1, 2, 3 or 4"),
        ({"mesh": "axisym", "elements": 1}, "elements", "an integer >= 2"),
        ({"mesh": "axisym", "scheme": "alpha", "dt": 0.0}, "dt", "a finite number > 0"),
        ({"mesh": "axisym", "scheme": "alpha", "dt": -1e-3}, "dt", "a finite number > 0"),
        ({"mesh": "axisym", "scheme": "alpha", "dt": float("nan")}, "dt", "a finite number > 0"),
        ({"mesh": "cube"}, "mesh", "one of sphere, ring, axisym"),
        ({"mesh": "axisym", "scheme": "euler"}, "scheme", "one of modal, alpha"),
        ({"mesh": "axisym", "damping_model": "viscous"}, "damping_model", "one of"),
        ({"mesh": "axisym", "scheme": "alpha", "rho_inf": 1.5}, "rho_inf", "in [0, 1]"),
        ({"mesh": "axisym", "scheme": "alpha", "t_end": -1.0}, "t_end", "a finite time > 0"),
        ({"mesh": "axisym", "initial": "exact"}, "initial", "one of projection, interpolation"),
    ],
)
def test_fem_pole_motion_rejects(options, flag, valid):
    with pytest.raises(ParameterError) as error:
        fem_pole_motion(PHI_A, DAMPING, "lanczos", **options)
    assert error.value.name == flag
    assert valid in str(error.value) and flag in str(error.value)


def test_physical_parameters_are_checked():
    with pytest.raises(ParameterError, match="phi_a"):
        fem_pole_motion(1.0, DAMPING, mesh="axisym")
    with pytest.raises(ParameterError, match="damping"):
        fem_pole_motion(PHI_A, 1.0, mesh="axisym")
    with pytest.raises(ParameterError, match="sigma"):
        fem_pole_motion(PHI_A, DAMPING, "gaussian", mesh="axisym")


@pytest.mark.parametrize("order", [3, 4])
def test_axisymmetric_liftoff_matches_legendre(order):
    reference = find_liftoff(legendre_series(PHI_A, DAMPING, FILTER), GAMMA)
    model = modal_model(PHI_A, DAMPING, FILTER, mesh="axisym", order=order, elements=100)
    result = find_liftoff(model.series, GAMMA)
    tolerance = {3: 1e-8, 4: 1e-11}[order]  # measured 3.6e-10 | 4.3e-10 and 1.2e-13 | 1.3e-13
    assert abs(result.t / reference.t - 1.0) < tolerance
    assert abs(result.velocity / reference.velocity - 1.0) < tolerance


def test_routes_agree_at_p3():
    """Full eigen and Krylov routes give the same lift-off on a P3 sphere (level 1)."""
    full = modal_model(PHI_A, DAMPING, FILTER, mesh="sphere", order=3, level=1, route="full")
    krylov = modal_model(PHI_A, DAMPING, FILTER, mesh="sphere", order=3, level=1, route="krylov")
    a, b = find_liftoff(full.series, GAMMA), find_liftoff(krylov.series, GAMMA)
    assert a.lifted and b.lifted
    assert abs(a.t / b.t - 1.0) < 1e-9 and abs(a.velocity / b.velocity - 1.0) < 1e-8


@pytest.mark.slow
def test_sphere_liftoff_at_level_3_is_closer_to_legendre_at_higher_order():
    """P2, P3, P4 on the level-3 icosphere against the Legendre series (Krylov route).

    Measured (relative, t_l | v_l): P2 1.3e-4 | 1.1e-5, P3 3.5e-6 | 2.8e-5,
    P4 3.5e-9 | 2.0e-7.  The P3 velocity is not better than P2's: its
    geometric error is O(h^4), like P2's.
    """
    reference = find_liftoff(legendre_series(PHI_A, DAMPING, FILTER), GAMMA)
    diffs = {}
    for order in (2, 3, 4):
        model = modal_model(
            PHI_A, DAMPING, FILTER, mesh="sphere", order=order, level=3, route="krylov"
        )
        result = find_liftoff(model.series, GAMMA)
        diffs[order] = np.array(
            [abs(result.t / reference.t - 1.0), abs(result.velocity / reference.velocity - 1.0)]
        )
    assert diffs[3][0] < diffs[2][0] / 10 and np.all(diffs[3] < 1e-4)
    assert np.all(diffs[4] < diffs[2] / 50) and np.all(diffs[4] < 1e-6)


@pytest.mark.parametrize("order", [3, 4])
def test_generalized_alpha_matches_the_modal_series_at_order_2_in_dt(order):
    """The time-stepping route on P3/P4 (axisymmetric, 30 elements) against modal superposition."""
    from twoball.fem_membrane.solve import alpha_motion

    model = modal_model(PHI_A, DAMPING, FILTER, mesh="axisym", order=order, elements=30)
    differences = []
    for steps in (500, 1000, 2000):
        motion, _ = alpha_motion(model, dt=2 * np.pi / steps, t_end=2 * np.pi)
        exact = model.series.pole(motion.times)
        sampled = motion.pole(motion.times)
        differences.append([np.abs(a - b).max() for a, b in zip(sampled, exact, strict=True)])
    observed = rates(np.array(differences))
    assert np.all(np.abs(observed - 2.0) < 0.2), observed


def test_legendre_reference(reference):
    assert reference.t == pytest.approx(3.1624, abs=1e-4)
    assert reference.velocity == pytest.approx(0.0998, abs=1e-4)


def test_axisymmetric_p2_400_to_1e6(reference):
    assert np.all(lift("axisym", 2, 400, reference) < 1e-6)


def test_axisymmetric_modes_are_the_legendre_terms():
    series = model("axisym", 2, 400).series
    assert series.omega.size == 31  # n = 0 .. 30, nothing of n = 31
    assert np.allclose(
        series.omega, np.sqrt(np.arange(31) * np.arange(1, 32)), rtol=1e-5, atol=1e-5
    )
    # pole amplitude of each M-orthonormal mode = a_n of eq. (3.12)
    amplitude = series.coefficients * series.pole_values
    assert np.abs(amplitude - legendre_coefficients(PHI_A, 30)).max() < 1e-8


def test_axisymmetric_difference_shrinks_at_order_2_for_p1(reference):
    diffs = np.array([lift("axisym", 1, e, reference) for e in (100, 200, 400)])
    rates = np.log2(diffs[:-1] / diffs[1:])
    assert np.all((rates > 1.5) & (rates < 2.6)), rates


def test_sphere_p2_level3_to_1e3_and_shrinking(reference):
    coarse = lift("sphere", 2, 2, reference)
    fine = lift("sphere", 2, 3, reference)
    assert np.all(fine < 1e-3)
    assert np.all(fine < coarse / 8)


@pytest.mark.slow
def test_sphere_p1_level4_to_2_percent_and_shrinking(reference):
    coarse = lift("sphere", 1, 3, reference)
    fine = lift("sphere", 1, 4, reference)
    assert np.all(fine < 0.02)
    assert np.all(fine < coarse)


@pytest.mark.slow
def test_sphere_p2_level4_to_1e4(reference):
    fine = lift("sphere", 2, 4, reference)
    assert np.all(fine < 1e-4)
    assert np.all(fine < lift("sphere", 2, 3, reference))


@pytest.mark.slow
def test_ring_sphere_p2_level3_to_1e3(reference):
    assert np.all(lift("ring", 2, 3, reference) < 1e-3)


def test_fem_pole_motion_returns_the_series_and_info():
    motion, info = fem_pole_motion(PHI_A, DAMPING, FILTER, mesh="axisym", elements=60, order=2)
    assert info["dofs"] == 121 and info["order"] == 2 and info["time_scheme"] == "modal"
    assert info["modes_used"] == 30  # the Lanczos weight of n = 30 is zero
    assert info["modes_computed"] == 31
    assert info["omega_next"] > FILTER.omega_cut > math.sqrt(30 * 31)
    assert motion.pole(0.0).u == pytest.approx(motion.pole(np.array([0.0])).u[0])
