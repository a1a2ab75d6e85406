"""twoball.sweep: the same numbers as the command line and as single runs."""

from __future__ import annotations

import json

import numpy as np
import pytest

import twoball
from tests.helpers import cli_json
from twoball import Body
from twoball.modal.parameters import Case

BASKETBALL = Case.preset("basketball")


def test_sweep_api_equals_cli(capsys):
    cli, err = cli_json(capsys, "sweep", "--param", "v0", "--values", "2:4.1:3")
    api = twoball.sweep({"v0": np.linspace(2.0, 4.1, 3)})
    assert json.loads(json.dumps([p.as_dict() for p in api.points])) == cli
    # one phi_a rule per sweep: eq. (3.7) at the preset's own 4.1 m/s as well
    assert [p["phi_a_source"] for p in cli] == ["eq. (3.7)"] * 3
    assert "note:" in err
    data = api.as_dict()
    assert data["parameters"] == ["v0"] and data["shape"] == [3] and len(data["points"]) == 3


def test_sweep_refuses_unknown_parameters():
    with pytest.raises(twoball.ParameterError) as error:
        twoball.sweep({"mass": [1.0, 2.0]})
    assert error.value.name == "values" and "wave_speed" in str(error.value)


def test_mass_ratio_sweep_equals_single_runs():
    cap = Body(0.0, contact_radius=0.03)  # the other fields of every swept mass ratio
    result = twoball.sweep({"mass_ratio": [0.004, 0.101]}, BASKETBALL, body=cap)
    for point, mu in zip(result.points, (0.004, 0.101), strict=True):
        single = twoball.liftoff(BASKETBALL, body=Body(mu, contact_radius=0.03))
        assert point.v_liftoff_m_s == single.v_liftoff_m_s
        assert point.as_dict()["mass_ratio"] == mu
    with pytest.raises(twoball.ParameterError) as info:
        twoball.sweep({"mass_ratio": [-1.0]}, BASKETBALL)
    assert info.value.name == "mass_ratio"
    with pytest.raises(twoball.ParameterError) as info:
        twoball.sweep({"mass_ratio": [0.1]}, BASKETBALL, body=Body(0.0, contact_radius=0.2))
    assert info.value.name == "contact_radius"  # a >= R = 0.12 m


def test_a_damping_law_applies_at_every_point_as_the_cases_own():
    """``damping=`` gives the points the case would give with that law in it."""
    values = {"v0": [3.0, 4.1]}
    law = twoball.Rayleigh(20.0, 2e-5)
    given = twoball.sweep(values, BASKETBALL, damping=law)
    inside = twoball.sweep(values, BASKETBALL.derive(rayleigh=law))
    assert [p.as_dict() for p in given.points] == [p.as_dict() for p in inside.points]
    assert given.provenance["call"]["arguments"]["damping"] == law.as_dict()
    ratio = twoball.sweep(values, BASKETBALL, damping=twoball.ModalRatio(0.2))
    assert [p.ratio for p in ratio.points] == [
        p.ratio for p in twoball.sweep(values, BASKETBALL.derive(damping=0.2)).points
    ]
    assert ratio.points[0].ratio != given.points[0].ratio


def test_the_solvers_options_act_at_every_point_as_in_a_single_run():
    """The closed form's filter, horizon and window, and the body's Moreau-Jean step, give
    every point what twoball.liftoff gives with the same solver."""
    closed = twoball.ClosedForm(sigma="none", recontact="paper", t_end=0.03)
    result = twoball.sweep({"damping": [0.1, 0.2]}, BASKETBALL, solver=closed)
    for point, damping in zip(result.points, (0.1, 0.2), strict=True):
        single = twoball.liftoff(BASKETBALL.derive(damping=damping), solver=closed)
        assert (point.t_liftoff_s, point.v_liftoff_m_s) == (
            single.t_liftoff_s,
            single.v_liftoff_m_s,
        )
    assert result.provenance["call"]["arguments"]["solver"] == closed.as_dict()
    stepped = twoball.MoreauJean(dt=2.5e-5)  # 0.008 / c, not the default 0.005 / c
    (point,) = twoball.sweep({"mass_ratio": [0.1]}, BASKETBALL, solver=stepped).points
    single = twoball.liftoff(BASKETBALL, body=Body(0.1), solver=stepped)
    assert point.v_liftoff_m_s == single.v_liftoff_m_s
    assert point.as_dict()["dt_s"] == single.extra["dt_s"] == 2.5e-5


@pytest.mark.parametrize(
    ("call", "name"),
    [
        (lambda: twoball.sweep({"v0": [3.0]}, solver=twoball.Superposition("axisym")), "solver"),
        (lambda: twoball.sweep({"v0": [3.0]}, solver=twoball.MoreauJean()), "solver"),
        (lambda: twoball.sweep({"mass_ratio": [0.1]}, solver=twoball.ClosedForm()), "solver"),
        (
            lambda: twoball.sweep({"v0": [3.0]}, body=Body(0.1), solver=twoball.ClosedForm()),
            "solver",
        ),
        (  # the points' N is the case's (or swept): a ball of its own cannot be swept
            lambda: twoball.sweep(
                {"mass_ratio": [0.1]}, solver=twoball.MoreauJean(twoball.LegendreBall(40))
            ),
            "ball",
        ),
        (
            lambda: twoball.sweep(
                {"mass_ratio": [0.1]}, solver=twoball.MoreauJean(twoball.FEBall())
            ),
            "ball",
        ),
        (
            lambda: twoball.sweep({"v0": [3.0]}, drop=twoball.Drop(), solver=twoball.ClosedForm()),
            "solver",
        ),
    ],
)
def test_a_solver_that_does_not_fit_the_points_is_refused_by_name(call, name):
    with pytest.raises(twoball.ParameterError) as caught:
        call()
    assert caught.value.name == name, str(caught.value)
