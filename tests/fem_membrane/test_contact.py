"""The finite-element contact (fem_membrane/contact.py): cap functional, agreement with Legendre."""

from __future__ import annotations

import numpy as np
import pytest

import twoball
from twoball import Body
from twoball.fem_membrane.build import build_space
from twoball.fem_membrane.contact import cap_functional
from twoball.fem_membrane.mesh import icosphere
from twoball.fem_membrane.space import sphere_space
from twoball.modal.parameters import Case

BASKETBALL = Case.preset("basketball")


def _on(mesh: twoball.MeshOptions) -> twoball.MoreauJean:
    """The body's contacts stepped on the finite elements of ``mesh``."""
    return twoball.MoreauJean(twoball.FEBall(mesh))


@pytest.mark.parametrize("theta", [0.05, 0.3])
def test_axisym_cap_functional_averages_polynomials(theta):
    """f . u is the cap average: exact for u = cos(phi)^2 (in the P2 space on the line)."""
    space = build_space("axisym", elements=40, order=2)
    x = space.basis.doflocs[0]
    f = cap_functional(space, theta)
    c = np.cos(theta)
    exact = (1 - c**3) / (3 * (1 - c))  # average of x^2 over [cos theta, 1]
    assert f @ (x**2) == pytest.approx(exact, rel=1e-13)
    assert f.sum() == pytest.approx(1.0, rel=1e-14)


def test_sphere_cap_functional_converges_to_the_cap_average():
    """On the P2 icosphere f . u -> <z^2>_cap at the P2 point-value order (3; band 2.5-4.5)."""
    theta = 0.3
    c = np.cos(theta)
    exact = (1 - c**3) / (3 * (1 - c))
    errors = []
    for level in (2, 3):
        mesh = icosphere(level, 2)
        space = sphere_space(mesh)
        z = space.basis.doflocs[2] / np.linalg.norm(space.basis.doflocs, axis=0)
        errors.append(abs(cap_functional(space, theta, mesh) @ (z**2) - exact))
    order = np.log2(errors[0] / errors[1])  # each level halves h
    assert 2.5 < order < 4.5


def test_fem_axisym_agrees_with_legendre_at_finite_mass():
    """mu = 0.1, a = R/10: axisymmetric P2 (400 elements) and Legendre v1 to 1e-4 (both on
    the contact core at its default step)."""
    body = Body(0.1, contact_radius=0.012)
    legendre = twoball.liftoff(BASKETBALL, body=body)
    fem = twoball.liftoff(BASKETBALL, body=body, solver=_on(twoball.MeshOptions("axisym")))
    assert fem.v_liftoff_m_s == pytest.approx(legendre.v_liftoff_m_s, rel=1e-4)
    assert fem.t_liftoff_s == pytest.approx(legendre.t_liftoff_s, rel=1e-4)
    assert len(fem.history.impacts) == len(legendre.history.impacts)


def test_fem_massless_mode_recovers_todays_fem_result():
    """mu = 0, a = 1e-5 m on the axisymmetric line = today's FE pole lift-off to 1e-4."""
    today = twoball.liftoff(BASKETBALL, solver=twoball.Superposition("axisym"))
    cap = twoball.liftoff(
        BASKETBALL, body=Body(0.0, contact_radius=1e-5), solver=twoball.Superposition("axisym")
    )
    assert cap.t_liftoff_s == pytest.approx(today.t_liftoff_s, rel=1e-4)
    assert cap.v_liftoff_m_s == pytest.approx(today.v_liftoff_m_s, rel=1e-4)


@pytest.mark.slow
def test_fem_sphere_agrees_with_legendre_at_finite_mass():
    """mu = 0.1, a = R/10: sphere P2 level 4 and Legendre v1 to 1e-3 (measured 8e-5)."""
    body = Body(0.1, contact_radius=0.012)
    legendre = twoball.liftoff(BASKETBALL, body=body)
    fem = twoball.liftoff(BASKETBALL, body=body, solver=_on(twoball.MeshOptions("sphere", level=4)))
    assert fem.v_liftoff_m_s == pytest.approx(legendre.v_liftoff_m_s, rel=1e-3)


def test_fem_axisym_converges_to_legendre_in_h():
    """mu = 0.101, a = R/10: the P2 line's v1 error falls at about h^4 (eigenvalues); band 3-5."""
    body = Body(0.101, contact_radius=0.012)
    legendre = twoball.liftoff(BASKETBALL, body=body)
    errors = []
    for elements in (25, 100):
        mesh = twoball.MeshOptions("axisym", elements=elements)
        fem = twoball.liftoff(BASKETBALL, body=body, solver=_on(mesh))
        errors.append(abs(fem.v_liftoff_m_s / legendre.v_liftoff_m_s - 1))
    order = np.log2(errors[0] / errors[1]) / 2  # h / 4
    assert 3.0 < order < 5.0
