"""FE eigenpairs of the elastic ball against Lamb's closed form and other exact solutions.

References: Lamb's roots from :mod:`twoball.modal.solid` (its own tests check them
against published values and a 30-digit second formulation); the torsional equation
(n - 1) j_n(y) = y j_{n+1}(y) and the hollow sphere's breathing equation, both solved
here with scipy's brentq.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.optimize import brentq
from scipy.special import spherical_jn, spherical_yn

from twoball.fem_solid.eigen import axisymmetric_eigen, ball_eigen
from twoball.fem_solid.mesh import ball, half_annulus, half_disc, half_disc_gmsh
from twoball.modal.solid.lamb import lamb_roots, speed_ratio
from twoball.modal.solid.modes import spheroidal_modes

NU = 0.25
COUNT = 14


@pytest.fixture(scope="module")
def levels():
    return {level: axisymmetric_eigen(half_disc(level), NU, COUNT) for level in (2, 3, 4)}


def lamb(n: int, k: int) -> float:
    return 0.0 if k == 0 else float(lamb_roots(n, NU, k)[-1])


def test_classification_matches_lamb(levels):
    """Each FE mode's (degree, radial order) names a Lamb root within 1e-4 (level 4); the
    axial translation is the only rigid mode; every surface field is >99.9 % one degree."""
    e = levels[4]
    assert e.rigid.sum() == 1 and e.degree[0] == 1 and e.radial_order[0] == 0
    assert e.eta[0] < 1e-6
    for i in range(COUNT):
        exact = lamb(int(e.degree[i]), int(e.radial_order[i]))
        assert abs(e.eta[i] - exact) < 1e-4 * max(exact, 1.0)
        assert e.purity[i] > 0.999
    # the same modes as the closed form's below the 14th eigenvalue, none missing
    closed = sorted(
        float(r) for n in range(0, 12) for r in lamb_roots(n, NU, 4) if r < e.eta[-1] + 1e-3
    )
    np.testing.assert_allclose(e.eta[1:], closed, rtol=1e-4)


def test_order_four_in_h(levels):
    """P2 on curved P2 geometry: eta^2 errors fall as h^4 (observed order in [3.5, 4.6])."""
    errors = []
    for level in (2, 3, 4):
        e = levels[level]
        exact = np.array(
            [lamb(int(n), int(k)) for n, k in zip(e.degree, e.radial_order, strict=True)]
        )
        errors.append(np.abs(e.eigenvalues[1:8] - exact[1:8] ** 2))
    orders = np.log2(np.array(errors[:-1]) / np.array(errors[1:]))
    assert np.all((orders > 3.5) & (orders < 4.6)), orders


def test_modal_mass_and_surface_against_closed_form(levels):
    """FE vectors in unit modal mass (ball's mass) have the closed form's pole displacement."""
    e = levels[4]
    modes = {(m.degree, m.radial_order): m for m in spheroidal_modes(NU, range(0, 6), 2)}
    from skfem import FacetBasis

    mesh = e.basis.mesh
    tip = mesh.facets_satisfying(lambda x: (x[0] < 0.05) & (x[1] > 0.9), boundaries_only=True)
    fb = FacetBasis(mesh, e.basis.elem, facets=tip)
    for i in range(1, 8):
        key = (int(e.degree[i]), int(e.radial_order[i]))
        if key not in modes:
            continue
        # mean u_z over the boundary facets next to the north pole (the surface and the
        # axis) vs the closed form at the same points
        x = np.asarray(fb.global_coordinates())
        uz_fe = np.asarray(fb.interpolate(e.vectors[:, i]))[1]
        phi = np.arctan2(x[0], x[1])
        ur, ut = modes[key].displacement(np.hypot(x[0], x[1]), phi)
        uz_cf = ur * np.cos(phi) - ut * np.sin(phi)
        ratio = np.sum(uz_fe * fb.dx) / np.sum(uz_cf * fb.dx)
        assert abs(abs(ratio) - 1.0) < 5e-4, (key, ratio)  # measured <= 2.9e-4 (level 4)


def hollow_breathing(inner: float, nu: float) -> float:
    """First n = 0 root of the hollow sphere: sigma_rr = 0 at both radii.

    phi = A j_0(h r) + B y_0(h r), u_r = phi'; sigma_rr / (mu h^2) = -[(c_p/c_s)^2 f_0(z)
    - 4 f_1(z)/z] for f = j, y; the 2x2 determinant over z = h, h * inner vanishes.
    """
    ratio = speed_ratio(nu)

    def g(f0, f1, z):
        return ratio**2 * f0(0, z) - 4 * f1(1, z) / z

    def det(eta):
        xo = eta / ratio
        xi = inner * xo
        return g(spherical_jn, spherical_jn, xo) * g(spherical_yn, spherical_yn, xi) - g(
            spherical_yn, spherical_yn, xo
        ) * g(spherical_jn, spherical_jn, xi)

    grid = np.linspace(0.05, 8.0, 800)
    values = np.array([det(e) for e in grid])
    i = np.flatnonzero(np.sign(values[:-1]) != np.sign(values[1:]))[0]
    return brentq(det, grid[i], grid[i + 1], xtol=1e-14)


def test_hollow_ball_breathing_mode():
    """Half annulus (inner radius 0.5): the n = 0 mode at the exact hollow-sphere root."""
    exact = hollow_breathing(0.5, NU)
    e = axisymmetric_eigen(half_annulus(0.5, 8, 48), NU, 12)
    (found,) = e.eta[(e.degree == 0) & (e.radial_order == 1)]
    assert abs(found - exact) < 1e-5 * exact  # measured 1.8e-6 on this mesh
    assert circle_on_axis_free(e)


def circle_on_axis_free(e) -> bool:
    """u_r = 0 on the axis (imposed) for every vector."""
    axis = e.basis.get_dofs(lambda x: np.abs(x[0]) < 1e-12).all("u^1")
    return bool(np.all(e.vectors[axis] == 0.0))


def torsional_root(n: int) -> float:
    """First root of the torsional equation (n - 1) j_n(y) - y j_{n+1}(y) = 0 (Lamb 1882)."""

    def f(y):
        return (n - 1) * spherical_jn(n, y) - y * spherical_jn(n + 1, y)

    grid = np.linspace(0.5, 10, 1000)
    v = f(grid)
    i = np.flatnonzero(np.sign(v[:-1]) != np.sign(v[1:]))[0]
    return brentq(f, grid[i], grid[i + 1])


def test_three_d_ball_rigid_modes_and_multiplets():
    """3-D P2 ball (level 2): six rigid modes (3 translations, 3 rotations), then the
    torsional n = 2 quintuplet and the spheroidal n = 2 quintuplet, n = 1 triplet, each near
    its exact value (coarse mesh: 5e-3 relative)."""
    e = ball_eigen(ball(2), NU, 24, max_degree=6)
    kinds = np.array(e.kind)
    assert e.rigid.sum() == 6 and np.all(e.eigenvalues[:6] < 1e-8)
    assert sorted(kinds[e.rigid]) == ["spheroidal"] * 3 + ["torsional"] * 3
    assert np.all(e.degree[e.rigid] == 1) and np.all(e.radial_order[e.rigid] == 0)
    tors2 = e.eta[(kinds == "torsional") & (e.degree == 2)]
    sph2 = e.eta[(kinds == "spheroidal") & (e.degree == 2) & (e.radial_order == 1)]
    sph1 = e.eta[(kinds == "spheroidal") & (e.degree == 1) & (e.radial_order == 1)]
    assert len(tors2) == 5 and len(sph2) == 5 and len(sph1) == 3
    np.testing.assert_allclose(tors2, torsional_root(2), rtol=5e-3)
    np.testing.assert_allclose(sph2, lamb(2, 1), rtol=5e-3)
    np.testing.assert_allclose(sph1, lamb(1, 1), rtol=5e-3)
    assert np.all(e.purity[6:] > 0.99)


@pytest.mark.slow
def test_three_d_order_four():
    """3-D P2 ball: levels 2 -> 3 reduce the n = 2 spheroidal eta^2 error ~16x (order in
    [3.3, 4.7]; a single pair of levels)."""
    errors = []
    for level in (2, 3):
        e = ball_eigen(ball(level), NU, 22, max_degree=4)
        kinds = np.array(e.kind)
        sph2 = e.eigenvalues[(kinds == "spheroidal") & (e.degree == 2) & (e.radial_order == 1)]
        errors.append(abs(sph2.mean() - lamb(2, 1) ** 2))
    order = math.log2(errors[0] / errors[1])
    assert 3.3 < order < 4.7, order


@pytest.mark.slow
def test_axisymmetric_degree_30():
    """Degrees 0..30 (first radial order) on a half disc graded to the arc agree with Lamb
    to 1e-4 (measured 9.0e-5 at n = 30; about 20 s)."""
    e = axisymmetric_eigen(half_disc_gmsh(0.04, 0.01), NU, 170, max_degree=40)
    for n in range(31):
        found = e.eta[(e.degree == n) & (e.radial_order == 1)]
        assert len(found) == 1
        assert abs(found[0] - lamb(n, 1)) < 1e-4 * lamb(n, 1)


@pytest.mark.parametrize("nu", [-0.3, 0.1, 0.45])
def test_other_poisson_ratios_against_lamb(nu):
    """Unlisted Poisson ratios: the lowest 12 axisymmetric FE modes (level 4) carry the labels
    of Lamb's roots for that nu to 5e-4 (measured 2.2e-4 at nu = 0.45, n = 7)."""
    e = axisymmetric_eigen(half_disc(4), nu, 12)
    assert e.rigid.sum() == 1
    for i in np.flatnonzero(~e.rigid):
        exact = float(lamb_roots(int(e.degree[i]), nu, int(e.radial_order[i]))[-1])
        assert abs(e.eta[i] / exact - 1) < 5e-4, (nu, e.degree[i], e.radial_order[i])


def test_unit_modal_mass_three_d():
    """x^T M x = volume of the mesh (unit modal mass in units of the ball's mass)."""
    from twoball.fem_solid.assembly import elasticity_matrices
    from twoball.fem_solid.forms import lame

    mesh = ball(1)
    e = ball_eigen(mesh, NU, 12, max_degree=4)
    _, m, _ = elasticity_matrices(mesh, *lame(NU))
    gram = e.vectors.T @ (m @ e.vectors)
    volume = gram[0, 0]
    assert volume == pytest.approx(4 * math.pi / 3, rel=5e-2)  # the coarse mesh's volume
    np.testing.assert_allclose(gram / volume, np.eye(12), atol=1e-9)


def test_three_d_p1_ball():
    """P1 tetrahedra on the same ball's vertices: six rigid modes, the n = 2 multiplets, and
    the spheroidal n = 2 eigenvalue above Lamb's (conforming P1 is stiffer) within 25 %."""
    from twoball.fem_solid.mesh import linear

    e = ball_eigen(linear(ball(2)), NU, 16, max_degree=4)
    kinds = np.array(e.kind)
    assert e.rigid.sum() == 6
    sph2 = e.eigenvalues[(kinds == "spheroidal") & (e.degree == 2) & (e.radial_order == 1)]
    assert len(sph2) == 5
    assert np.all((sph2 / lamb(2, 1) ** 2 - 1 > 0) & (sph2 / lamb(2, 1) ** 2 - 1 < 0.25))


@pytest.mark.slow
def test_three_d_p1_rate():
    """P1 levels 2 -> 3 -> 4: the n = 2 eta^2 error falls by 2.84 and 2.76 (measured; order
    1.5, not yet the asymptotic 2 on these meshes); the band [1.2, 2.2] holds both steps."""
    from twoball.fem_solid.mesh import linear

    errors = []
    for level in (2, 3, 4):
        e = ball_eigen(linear(ball(level)), NU, 16, max_degree=4)
        kinds = np.array(e.kind)
        sph2 = e.eigenvalues[(kinds == "spheroidal") & (e.degree == 2) & (e.radial_order == 1)]
        errors.append(abs(sph2.mean() - lamb(2, 1) ** 2))
    orders = np.log2(np.array(errors[:-1]) / np.array(errors[1:]))
    assert np.all((orders > 1.2) & (orders < 2.2)), orders
