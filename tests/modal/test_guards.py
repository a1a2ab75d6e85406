"""Accuracy guards of the closed form (modal/guards.py).

Truncation in N and the re-contact window.
"""

from __future__ import annotations

import math

import pytest
from twoball.modal.converged import converged_legendre
from twoball.modal.guards import TRUNCATION_WARNING, truncation, window_warnings
from twoball.modal.parameters import preset
from twoball.modal.report import legendre_liftoff

from tests.helpers import assert_printed, run_json


def test_legendre_default_is_quiet_and_reports_the_converged_series(capsys) -> None:
    data, lines = run_json(capsys)
    assert data["warnings"] == [] and lines == []
    block = data["truncation"]
    reference = converged_legendre(preset("basketball"))
    scale = preset("basketball").scalings
    assert block["converged"] and block["converged_modes"] == reference.modes
    assert block["t_liftoff_s"] == pytest.approx(reference.t * scale.time, rel=1e-12)
    assert block["v_liftoff_m_s"] == pytest.approx(reference.velocity * scale.velocity, rel=1e-12)
    # N = 30 is 2.9 % below the converged series in v_l (3.9454 m/s at N = 120)
    assert block["v_difference"] == pytest.approx(data["v_liftoff_m_s"] / 3.9454 - 1, abs=2e-4)
    assert -0.030 < block["v_difference"] < -0.028
    assert abs(block["v_difference"]) < TRUNCATION_WARNING


def test_truncation_warns_above_five_percent() -> None:
    coarse = legendre_liftoff(preset("basketball").derive(modes=20))
    (text,) = coarse.warnings
    assert text.startswith("N = 20 truncation: t_l ") and text.endswith(
        "; raise the number of modes N"
    )
    assert coarse.extra["truncation"]["v_difference"] < -TRUNCATION_WARNING  # -6.3 %
    fine = legendre_liftoff(preset("basketball").derive(modes=60))
    assert fine.warnings == ()
    assert abs(fine.extra["truncation"]["v_difference"]) < 0.01


def test_truncation_difference_shrinks_with_n() -> None:
    case = preset("basketball")
    gaps = [
        abs(
            truncation(
                case.derive(modes=n), legendre_liftoff(case.derive(modes=n)).result
            ).v_difference
        )
        for n in (15, 30, 60)
    ]
    assert gaps[0] > gaps[1] > gaps[2] > 0


def test_short_window_warns(capsys) -> None:
    data, lines = run_json(capsys, "--t-end", "0.005")
    assert data["lifted"] and data["t_liftoff_s"] == pytest.approx(4.8e-4, rel=0.01)
    assert_printed(data, lines)
    window, falling = data["warnings"][:2]
    assert window.startswith("window too short for the re-contact check")
    assert "2 pi / c = 19.6 ms" in window
    assert falling.startswith("the body is falling back at the end of the window")


def test_window_criterion_edges() -> None:
    """Quiet from one refocusing period after t_l on, while the body still rises."""
    case = preset("basketball")
    base = legendre_liftoff(case).result
    t_l = base.t
    enough = type(base)(**{**base.__dict__, "t_end": t_l + 2 * math.pi * 1.01})
    short = type(base)(**{**base.__dict__, "t_end": t_l + 2 * math.pi * 0.99})
    assert window_warnings(case, enough) == []
    assert len(window_warnings(case, short)) == 1
