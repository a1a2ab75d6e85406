"""FE modal lift-off against the Legendre series (lanczos, N = 30, D = 0.13, phi_a = 2.6)."""

from __future__ import annotations

import math

import numpy as np
import pytest
from twoball.fem_membrane.eigen import sphere_degree
from twoball.fem_membrane.initial import initial_load
from twoball.fem_membrane.solve import fem_pole_motion, modal_model
from twoball.modal.filters import SpectralFilter
from twoball.modal.legendre import legendre_coefficients, legendre_series, mean_displacement
from twoball.modal.liftoff import find_liftoff
from twoball.modal.parameters import Case

PHI_A, DAMPING = 2.6, 0.13
FILTER = SpectralFilter("lanczos", 30)
GAMMA = Case().gamma  # 9.81 / (0.12 * 320**2)


@pytest.fixture(scope="module")
def reference():
    return find_liftoff(legendre_series(PHI_A, DAMPING, FILTER), GAMMA)


_MODELS: dict = {}


def model(mesh: str, order: int, size: int):
    """Modal model, cached for the module (sphere levels are expensive)."""
    key = (mesh, order, size)
    if key not in _MODELS:
        where = {"elements": size} if mesh == "axisym" else {"level": size}
        _MODELS[key] = modal_model(PHI_A, DAMPING, FILTER, mesh=mesh, order=order, **where)
    return _MODELS[key]


def difference(result, reference) -> np.ndarray:
    assert result.lifted
    return np.array(
        [abs(result.t / reference.t - 1.0), abs(result.velocity / reference.velocity - 1.0)]
    )


def lift(mesh: str, order: int, size: int, reference) -> np.ndarray:
    return difference(find_liftoff(model(mesh, order, size).series, GAMMA), reference)


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


def test_sphere_clusters_up_to_the_cutoff():
    pairs = model("sphere", 2, 3).pairs
    counts = np.bincount(sphere_degree(pairs.values))
    assert np.array_equal(counts[:16], 2 * np.arange(16) + 1)
    assert pairs.values.max() <= FILTER.omega_cut**2 < pairs.next_value


@pytest.mark.parametrize(
    ("mesh", "order", "size", "tol"), [("axisym", 2, 400, 1e-13), ("sphere", 2, 3, 1e-6)]
)
def test_mean_displacement_is_a0(mesh, order, size, tol):
    # int F dS = 4 pi a_0, eq. (3.13): checks the kink-resolving quadrature of the load
    space = model(mesh, order, size).space
    assert initial_load(space, PHI_A).sum() / (4 * np.pi) == pytest.approx(
        mean_displacement(PHI_A), abs=tol
    )


def test_fem_pole_motion_returns_the_series_and_info():
    motion, info = fem_pole_motion(PHI_A, DAMPING, FILTER, mesh="axisym", elements=60, order=2)
    assert info["dofs"] == 121 and info["order"] == 2 and info["time_scheme"] == "modal"
    assert info["modes_used"] == 30  # the Lanczos weight of n = 30 is zero
    assert info["modes_computed"] == 31
    assert info["omega_next"] > FILTER.omega_cut > math.sqrt(30 * 31)
    assert motion.pole(0.0).u == pytest.approx(motion.pole(np.array([0.0])).u[0])
