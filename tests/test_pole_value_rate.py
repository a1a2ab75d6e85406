"""What limits v_l at P3 and P4 on the icosphere: the value of the modes at the pole.

The lift-off velocity is a point value (u_t at the pole).  A finite-element
function converges there at the pointwise rate of Lagrange elements -- p + 1,
and p + 2 at mesh vertices for even p -- not at the 2p of the eigenvalues.
Independent values: the Legendre series with the same N and filter (eqs.
(3.12)-(3.16)), and a smooth datum with the same Legendre coefficients as F,
which has no kink at phi_a.  With the exact geometry, so that the geometric error
of the isoparametric sphere (Demlow 2009: also p + 1 | p + 2) is not mixed in,
t_l converges at 2p while v_l converges at the pointwise rate; and the per-degree
pole amplitudes of the kinked F and of the smooth datum carry the same error, so
the kink is not what limits v_l.  Numbers: docs/verification.rst.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.special import eval_legendre
from skfem import CellBasis, LinearForm
from twoball.fem_membrane.solve import modal_model
from twoball.fem_membrane.space import pole_value
from twoball.modal.filters import SpectralFilter
from twoball.modal.legendre import legendre_coefficients

import twoball

BAND = 0.3
POINTWISE_RATE = {3: 4.0, 4: 6.0}  # p + 1 for odd p, p + 2 at a vertex for even p


def relative_errors(
    case: twoball.Case, reference: twoball.LiftoffReport, order: int, level: int
) -> tuple[float, float]:
    """|t_l| and |v_l| errors of the exact-geometry sphere against the Legendre ``reference``."""
    mesh = twoball.MeshOptions("sphere", level=level, order=order, geometry="exact")
    fem = twoball.liftoff(case, backend="fem", mesh=mesh, stepping=twoball.Stepping(route="krylov"))
    return (
        abs(fem.t_liftoff_s / reference.t_liftoff_s - 1.0),
        abs(fem.v_liftoff_m_s / reference.v_liftoff_m_s - 1.0),
    )


@pytest.mark.parametrize("order", [3, 4])
def test_t_l_converges_at_2p_and_v_l_at_the_pointwise_rate(order):
    """Exact sphere, levels 3 -> 4: t_l at 2p, v_l at p + 1 | p + 2 (each +-0.3)."""
    case = twoball.Case.preset("basketball")
    reference = twoball.liftoff(case)  # Legendre, N = 30, Lanczos
    (t3, v3), (t4, v4) = (relative_errors(case, reference, order, level) for level in (3, 4))
    t_rate, v_rate = math.log2(t3 / t4), math.log2(v3 / v4)
    assert abs(t_rate - 2 * order) < BAND, (t3, t4, t_rate)
    assert abs(v_rate - POINTWISE_RATE[order]) < BAND, (v3, v4, v_rate)


def test_the_kink_of_f_is_not_what_limits_the_pole_amplitudes():
    """P4 level 2: per-degree pole amplitudes of F and of a smooth twin err alike.

    The smooth twin g = sum_n a_n P_n(cos phi) has the Legendre coefficients a_n of
    F (n <= 30) and no kink.  For each degree l the finite-element pole amplitude
    is sum over the cluster of (datum, phi_k) phi_k(pole); its error against a_l is
    the same for F and g to within 40 % (measured 25 %) over l = 1..20.
    """
    case = twoball.Case.preset("basketball")
    model = modal_model(case.phi_a, case.damping, SpectralFilter("lanczos", case.modes),
                        mesh="sphere", level=2, order=4, route="full")  # fmt: skip
    a = legendre_coefficients(case.phi_a, case.modes)
    basis = model.space.basis
    fine = CellBasis(basis.mesh, basis.elem, mapping=basis.mapping, intorder=19, dofs=basis.dofs)

    @LinearForm
    def smooth_twin(v, w):
        z = w.x[2] / np.sqrt((w.x**2).sum(0))
        return sum(a[n] * eval_legendre(n, z) for n in range(a.size)) * v

    vectors = model.pairs.vectors
    at_pole = np.asarray(pole_value(model.space.pole_row, vectors))
    kinked = model.series.coefficients * at_pole
    smooth = (vectors.T @ smooth_twin.assemble(fine)) * at_pole
    degree = np.rint(0.5 * (np.sqrt(1.0 + 4.0 * model.pairs.values) - 1.0)).astype(int)
    degrees = range(1, 21)
    err_kinked = np.array([kinked[degree == n].sum() - a[n] for n in degrees])
    err_smooth = np.array([smooth[degree == n].sum() - a[n] for n in degrees])
    assert np.linalg.norm(err_smooth) > 1e-3 * np.abs(a).max()  # an error to compare
    assert np.linalg.norm(err_kinked - err_smooth) < 0.4 * np.linalg.norm(err_smooth)
