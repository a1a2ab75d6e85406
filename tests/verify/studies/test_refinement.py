"""Mesh and order refinement studies (verify/studies/refinement.py): observed orders."""

import numpy as np
import pytest

from tests.helpers import by_key
from twoball.modal.parameters import preset
from twoball.verify.studies.refinement import run_h_study, run_order_study


@pytest.mark.parametrize(("order", "expected"), [(1, 2.0), (2, 4.0)])
def test_axisym_h_study_orders(order, expected):
    study = run_h_study(preset("basketball"), mesh="axisym", order=order, levels=(1, 2, 3, 4))
    assert study.passed, [(q.spec.key, q.checked_order) for q in study.quantities if not q.passed]
    q = by_key(study)
    assert q["lambda_6"].checked_order == pytest.approx(expected, abs=0.1)
    assert q["t_l"].checked_order == pytest.approx(expected, abs=0.2)
    assert q["v_l"].analysis.reference_kind == "reference"  # the Legendre series, same filter
    # P_1(x) = x (and P_2 for P2) lies in the space: those eigenvalues are exact
    assert q["lambda_1"].remark == "exact to round-off"
    assert (q["lambda_2"].remark == "exact to round-off") == (order == 2)
    assert q["strain_energy"].checked_order == pytest.approx(order + 1.0, abs=0.3)


def test_axisym_order_study_compares_p1_to_p4_at_equal_dofs():
    study = run_order_study(preset("basketball"), mesh="axisym", levels=(2, 3, 4))
    assert study.passed
    keys = {q.spec.key for q in study.quantities}
    assert {"v_l (P1)", "v_l (P2)", "lambda_6 (P1)", "lambda_6 (P2)"} <= keys
    assert {"t_l (P3)", "t_l (P4)", "pole_l2 (P3)", "pole_l2 (P4)"} <= keys
    assert any("times smaller with P2" in note for note in study.notes)
    q = by_key(study)
    # equal unknowns (P3 up to rounding of 2E/3 elements), and each order's own 2p
    for p in (1, 2, 3, 4):
        assert np.allclose(q[f"t_l (P{p})"].dofs, q["t_l (P2)"].dofs, rtol=0.01)
    assert q["pole_l2 (P3)"].checked_order == pytest.approx(6.0, abs=0.5)
    assert q["pole_l2 (P4)"].checked_order == pytest.approx(8.0, abs=0.6)
    # at equal unknowns (401) each order lowers the t_l error by orders of magnitude, down to
    # round-off (measured 9.0e-6, 2.2e-9, 1.0e-12, 1.1e-13)
    finest = [q[f"t_l (P{p})"].relative_errors[-1] for p in (1, 2, 3, 4)]
    assert finest[0] > 100 * finest[1] > 1e4 * finest[2] and finest[3] <= finest[2], finest
    assert all("seconds" in row for row in study.runs[1:])


@pytest.mark.parametrize(("order", "levels"), [(3, (0, 1, 2, 3)), (4, (0, 1, 2))])
def test_axisym_h_study_at_p3_p4_converges_at_2p(order, levels):
    """The line has no geometric error: t_l, v_l and the trajectory at 2p (+-0.5)."""
    study = run_h_study(preset("basketball"), mesh="axisym", order=order, levels=levels)
    assert study.passed, [(q.spec.key, q.checked_order) for q in study.quantities if not q.passed]
    q = by_key(study)
    for key in ("t_l", "v_l", "pole_l2"):
        assert q[key].checked_order == pytest.approx(2.0 * order, abs=0.5), key
    assert q["strain_energy"].checked_order == pytest.approx(order + 1.0, abs=0.5)


@pytest.mark.slow
@pytest.mark.parametrize(
    ("order", "levels", "expected"), [(1, (2, 3, 4), 2.0), (2, (1, 2, 3), 4.0)]
)
def test_sphere_h_study_eigenvalue_orders(order, levels, expected):
    study = run_h_study(preset("basketball"), mesh="sphere", order=order, levels=levels)
    q = by_key(study)
    for degree in range(1, 7):
        assert q[f"lambda_{degree}"].checked_order == pytest.approx(expected, abs=0.35)
    assert q["v_l"].relative_errors[-1] < q["v_l"].relative_errors[0]
    assert np.isfinite(q["v_l"].checked_order)
