"""Running the checks of verify (verify/checks/run.py).

Every check passes, rows state both references.
"""

import pytest

from twoball.modal.parameters import preset
from twoball.verify.checks.config import config
from twoball.verify.checks.run import run_verify


@pytest.fixture(scope="module")
def fast_result():
    return run_verify(preset("basketball"), configuration=config("fast"))


def test_fast_configuration_passes_every_check(fast_result):
    assert fast_result.passed, [c.name for c in fast_result.checks if not c.passed]
    names = {c.name.split(" ")[0] for c in fast_result.checks}
    assert {"lift-off", "eigenvalues", "spectrum", "energy", "alpha", "modal"} <= names
    backends = [r.backend for r in fast_result.rows]
    assert backends[:2] == ["legendre", "legendre N->inf"]
    assert "fem modal" in backends and "fem alpha" in backends


def test_rows_state_differences_to_both_references(fast_result):
    n30, limit = fast_result.rows[0], fast_result.rows[1]
    assert n30.t_diff == 0.0 and n30.v_diff == 0.0
    assert limit.v_diff_converged == 0.0
    assert n30.v_diff_converged == pytest.approx(-0.0287, abs=5e-4)  # N = 30 truncation
    axisym = next(r for r in fast_result.rows if r.mesh == "axisym P2 100 el.")
    assert abs(axisym.t_diff) < 1e-5 and abs(axisym.v_diff) < 1e-5
    assert axisym.ratio == pytest.approx(axisym.v_l_m_s / 4.1)


def test_thorough_runs_p3_and_p4_and_their_line_checks_pass():
    """verify --thorough has P3 and P4 on the line and the sphere (full and Krylov routes).

    The line's P3/P4 targets are run here through the same checks (measured
    lift-off 6.6e-12 and 1.3e-13, eigenvalues 6.3e-12 and 2.0e-13 against their
    bounds); the sphere targets belong to the thorough run (minutes).
    """
    thorough = config("thorough")
    specs = [t.spec for t in thorough.fem]
    assert {(s.mesh, s.order) for s in specs} >= {
        ("axisym", 3), ("axisym", 4), ("sphere", 3), ("sphere", 4)
    }  # fmt: skip
    assert {(t.spec.order, t.spec.geometry) for t in thorough.krylov} >= {
        (4, "isoparametric"), (4, "exact")
    }  # fmt: skip
    line = tuple(t for t in thorough.fem if t.spec.mesh == "axisym" and t.spec.order > 2)
    small = type(thorough)("p34", line, ())
    result = run_verify(preset("basketball"), configuration=small)
    assert result.passed, [(c.name, c.value) for c in result.checks if not c.passed]
    names = {c.name for c in result.checks}
    assert {"lift-off axisym P3 200 el.", "eigenvalues axisym P4 100 el."} <= names
