"""The contact mode carries the massless path's trust warnings: truncation, mesh, window.

Independent values: the closed-form contact solution with many more modes
(N = 240, 0.4346 m/s at 11.79 ms for mu = 0.1), the default window's lift-off,
and the mesh guard's estimate for generated meshes.
"""

from __future__ import annotations

import pytest
from twoball.modal.contact.report import CONTACT_WARNING, legendre_contact
from twoball.modal.parameters import preset

import twoball

BODY = twoball.Body(mass_ratio=0.1)


def test_too_few_modes_is_warned_against_the_finer_solution() -> None:
    coarse = legendre_contact(preset("basketball").derive(modes=3), BODY)
    assert not coarse.lifted
    (text,) = coarse.warnings
    assert text.startswith("N = 3 finds no lift-off, but the contact solution with N = 60")
    assert "11.79 ms" in text
    converged = legendre_contact(preset("basketball").derive(modes=240), BODY, reference=False)
    assert converged.lifted and converged.t_liftoff_s == pytest.approx(0.011785, rel=1e-4)


def test_default_is_quiet_and_its_block_estimates_the_error() -> None:
    report = legendre_contact(preset("basketball"), BODY)
    assert report.warnings == ()
    block = report.extra["truncation"]
    assert block["checked"] and block["reference_modes"] == 60
    converged = legendre_contact(preset("basketball").derive(modes=240), BODY, reference=False)
    error = report.v_liftoff_m_s / converged.v_liftoff_m_s - 1  # -2.0 %
    # the difference to 2N is most of the error (O(N^-2): 3/4 of it)
    assert 0.6 * abs(error) < abs(block["v_difference"]) <= abs(error)
    assert abs(block["v_difference"]) < CONTACT_WARNING


def test_a_body_falling_with_the_membrane_has_not_lifted(capsys) -> None:
    """--t-end 0.005: the body leaves the cap at 3.78 ms moving down (v1 = -0.028 m/s)."""
    report = twoball.liftoff(body=BODY, stepping=twoball.Stepping(t_end=0.005))
    last = report.events_si()[-1]
    assert last["kind"] == "separation" and last["velocity_m_s"] < 0
    assert not report.lifted and report.t_liftoff_s is None and report.v_liftoff_m_s is None
    assert any("moving down" in w and "not a lift-off" in w for w in report.warnings)
    default = twoball.liftoff(body=BODY)
    assert default.lifted and default.v_liftoff_m_s > 0 and default.t_liftoff_s > 0.005


def test_coarse_fem_mesh_is_warned() -> None:
    """Icosphere level 0, P1: 2.85 ms against 11.8 ms."""
    mesh = twoball.MeshOptions("sphere", level=0, order=1)
    report = twoball.liftoff(backend="fem", mesh=mesh, body=BODY)
    assert report.t_liftoff_s == pytest.approx(2.85e-3, rel=0.01)
    assert any(w.startswith("mesh under-resolves") for w in report.warnings)
    (text,) = [w for w in report.warnings if w.startswith("the fem result is t_l -7")]
    assert "truncation and discretisation" in text
    fine = twoball.liftoff(backend="fem", mesh=twoball.MeshOptions("axisym"), body=BODY)
    assert fine.warnings == ()


def test_sweep_points_keep_the_window_warnings_without_the_reference() -> None:
    result = twoball.sweep({"mass_ratio": [0.1]}, stepping=twoball.Stepping(t_end=0.005), body=BODY)
    (point,) = result.points
    assert "truncation" not in point.report.extra
    assert any("not a lift-off" in w for w in point.report.warnings)
