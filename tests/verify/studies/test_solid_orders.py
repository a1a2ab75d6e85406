"""The solid ball's finite-element eigenvalues converge to Lamb's roots at O(h^2p)."""

import json

import pytest

from twoball._common.errors import ParameterError
from twoball.cli.main import main
from twoball.verify.studies.orders import OrderBand
from twoball.verify.studies.quantities import QuantitySpec, evaluate_quantity
from twoball.verify.studies.solid_orders import SOLID_BANDS, run_solid_h_study


@pytest.mark.parametrize(
    ("element", "levels", "low", "high"),
    [(1, (2, 3, 4, 5), 1.75, 2.1), (2, (1, 2, 3, 4), 3.65, 4.0)],
)
def test_the_eigenvalues_converge_at_twice_the_element_order(element, levels, low, high):
    """Measured (nu = 0.45, against Lamb's roots squared; the order fitted on the finest
    three levels): P1 levels 2-5 1.82-2.02, P2 levels 1-4 3.71-3.92 (the modes of higher
    degree approach 4 from below); the finest errors: P1 4e-4 to 6e-3, P2 2e-7 to 3e-5."""
    study = run_solid_h_study(0.45, element=element, levels=levels)
    assert study.passed
    orders = [q.checked_order for q in study.quantities]
    assert low < min(orders) and max(orders) < high
    assert all(q.analysis.reference_kind == "exact" for q in study.quantities)
    finest = [q.relative_errors[-1] for q in study.quantities]
    assert max(finest) < (1e-2 if element == 1 else 5e-5)


def test_an_order_above_the_band_fails_too():
    band = SOLID_BANDS[2]
    assert band.contains(4.0) and not band.contains(4.5) and not band.contains(3.4)
    # an error sequence of order 6 (what P3 would give without the arc's limit) fails P2's band
    steps = [0.5, 0.25, 0.125]
    values = [1.0 + h**6 for h in steps]
    spec = QuantitySpec("x", "x", 1.0, band)
    result = evaluate_quantity(spec, ["a", "b", "c"], [1, 2, 3], steps, values, 1.0, "exact")
    assert result.checked_order == pytest.approx(6.0, abs=1e-6) and result.passed is False
    fine = evaluate_quantity(
        QuantitySpec("x", "x", 1.0, OrderBand(6.0)), ["a", "b", "c"], [1, 2, 3], steps, values, 1.0
    )
    assert fine.passed is True


def test_converge_h_ball_solid_cli(capsys, tmp_path):
    out = tmp_path / "solid"
    code = main(["converge", "h", "--ball", "solid", "--out", str(out), "--json"])
    data = json.loads(capsys.readouterr().out)
    assert code == 0 and data["passed"] is True and data["settings"]["element"] == 2
    assert {"report.md", "results.json", "results.csv"} <= {p.name for p in out.iterdir()}
    assert "eta^2 (n = 2, k = 1)" in (out / "report.md").read_text()
    with pytest.raises((ParameterError, SystemExit)):
        main(["converge", "dt", "--ball", "solid"])
    with pytest.raises((ParameterError, SystemExit)):
        main(["converge", "h", "--ball", "solid", "--order", "3"])


def test_the_element_order_is_checked():
    from twoball.fem_solid.eigen import axisymmetric_eigen
    from twoball.fem_solid.mesh import half_disc

    with pytest.raises(ParameterError, match="element"):
        axisymmetric_eigen(half_disc(1), 0.45, 6, element=4)
    with pytest.raises(ParameterError, match="order"):
        run_solid_h_study(0.45, element=3)
