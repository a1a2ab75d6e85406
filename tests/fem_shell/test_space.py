"""The shell's finite-element space: pole conditions, matrices, quadrature, the translation."""

from __future__ import annotations

import math

import numpy as np
import pytest
from skfem import Basis, BilinearForm, ElementLineHermite, MeshLine1, asm

from twoball.fem_shell.space import ElementLineHermiteLocal, shell_space
from twoball.modal.shell.parameters import ShellParameters

SHELL = ShellParameters(0.3, bending=1e-3, prestress=0.05, gas=1.0)


def test_local_hermite_is_scikit_fems_hermite():
    """Same functions, derivatives and matrices as ElementLineHermite on a graded mesh."""
    nodes = np.linspace(0.0, 1.0, 7) ** 1.3 * math.pi
    mesh = MeshLine1.init_tensor(nodes)
    ours = Basis(mesh, ElementLineHermiteLocal(), intorder=8)
    theirs = Basis(mesh, ElementLineHermite(), intorder=8)

    @BilinearForm
    def form(u, v, w):
        return u.hess[0, 0] * v.hess[0, 0] + u.grad[0] * v.grad[0] + u * v

    assert np.allclose(asm(form, ours).toarray(), asm(form, theirs).toarray(), atol=1e-10)
    points = np.array([[0.0, 0.3, 1.0, 2.2, math.pi]])
    assert np.allclose(ours.probes(points).toarray(), theirs.probes(points).toarray(), atol=1e-12)


def test_local_hermite_interpolates_cubics_exactly_on_a_fine_mesh():
    """Where the global power basis loses ~1e-9 (256 elements), the local one is exact."""
    space = shell_space(SHELL, 256)
    basis = space.radial_basis
    nodes = space.nodes
    cubic = [1.0, -0.5, 0.25, 0.1]  # u = 1 - x/2 + x^2/4 + x^3/10
    value = np.polynomial.polynomial.polyval(nodes, cubic)
    slope = np.polynomial.polynomial.polyval(nodes, np.polynomial.polynomial.polyder(cubic))
    coefficients = np.zeros(basis.N)
    coefficients[basis.nodal_dofs[0]] = value
    coefficients[basis.nodal_dofs[1]] = slope
    x = np.linspace(0.0, math.pi, 1001)
    got = basis.probes(x[None, :]) @ coefficients
    assert np.max(np.abs(got - np.polynomial.polynomial.polyval(x, cubic))) < 1e-13


def test_pole_conditions_remove_w_slope_and_v_at_both_poles():
    space = shell_space(SHELL, 8)
    n_w, n_v = space.sizes
    assert (n_w, n_v) == (18, 17)
    removed = np.setdiff1d(np.arange(n_w + n_v), space.free)
    w_nodal = space.radial_basis.nodal_dofs
    v_nodal = space.meridional_basis.nodal_dofs
    expected = sorted([w_nodal[1, 0], w_nodal[1, -1], n_w + v_nodal[0, 0], n_w + v_nodal[0, -1]])
    assert removed.tolist() == expected


def test_matrices_are_symmetric_and_the_mass_of_a_uniform_w_is_4_pi():
    space = shell_space(SHELL, 12)
    stiffness, mass = space.stiffness, space.mass
    assert np.allclose(stiffness, stiffness.T, atol=1e-12 * np.abs(stiffness).max())
    assert np.allclose(mass, mass.T, atol=1e-15)
    uniform = np.zeros(mass.shape[0])
    uniform[space.radial_basis.nodal_dofs[0]] = 1.0  # w = 1, w' = 0, v = 0
    assert uniform @ mass @ uniform == pytest.approx(4 * math.pi, rel=1e-14)
    assert space.volume_vector @ uniform == pytest.approx(4 * math.pi, rel=1e-14)
    # the breathing mode's energy: (2 (1 + nu) - 2 p + g) 4 pi, exact in this space
    energy = uniform @ stiffness @ uniform
    assert energy == pytest.approx(SHELL.breathing_squared * 4 * math.pi, rel=1e-13)
    free = space.free
    assert np.all(np.linalg.eigvalsh(mass[np.ix_(free, free)]) > 0)


def test_translation_carries_no_stiffness_and_the_ball_mass():
    """K t = 0, t K t = 0, t M t = 4 pi, m . t = 0 by the same quadrature (to rounding)."""
    for elements in (4, 64, 256):
        space = shell_space(SHELL, elements)
        k_t, m_t, t_k_t, t_m_t, gas_t = space.translation_couplings
        assert np.max(np.abs(k_t)) < 1e-13  # the prestress coupling's quadrature (h = pi/4)
        assert abs(t_k_t) < 1e-14 and abs(gas_t) < 1e-15
        assert t_m_t == pytest.approx(4 * math.pi, rel=1e-14)
        # M t against t's interpolant: its mass 4 pi, up to the interpolation error
        interpolant = np.zeros(space.mass.shape[0])
        interpolant[space.radial_basis.nodal_dofs[0]] = np.cos(space.nodes)
        interpolant[space.radial_basis.nodal_dofs[1]] = -np.sin(space.nodes)
        n_w = space.sizes[0]
        middle = 0.5 * (space.nodes[:-1] + space.nodes[1:])  # P2's interior dof: the midpoint
        interpolant[n_w + space.meridional_basis.nodal_dofs[0]] = -np.sin(space.nodes)
        interpolant[n_w + space.meridional_basis.interior_dofs[0]] = -np.sin(middle)
        tolerance = 1e-3 if elements == 4 else 1e-6
        assert interpolant @ m_t == pytest.approx(4 * math.pi, rel=tolerance)


def test_quadrature_is_below_the_discretisation_error():
    """Gauss degree 12 against 20 on the same mesh: the lowest 10 eigenvalues move by < 1e-12.

    (All of them by < 1e-10, the highest, unresolved ones included; the
    discretisation error of the lowest is 1e-5 on this mesh.)
    """
    from twoball.fem_shell.modes import fem_shell_modes

    a = fem_shell_modes(SHELL, 16, intorder=12).omega ** 2
    b = fem_shell_modes(SHELL, 16, intorder=20).omega ** 2
    change = np.abs(a - b) / np.maximum(b, 1.0)
    assert np.max(change[:10]) < 1e-12
    assert np.max(change) < 1e-10


def test_bad_inputs():
    with pytest.raises(ValueError):
        shell_space(SHELL, 1)
    with pytest.raises(ValueError):
        shell_space(SHELL, 8, v_order=4)
    with pytest.raises(ValueError):
        shell_space(SHELL, 8).sample_rows(np.array([-0.1]))
