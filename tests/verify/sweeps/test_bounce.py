"""verify/sweeps/bounce.py: sweeps of the drop and the whole bounce against the damping."""

from __future__ import annotations

import pytest

import twoball

SOLVER = twoball.MoreauJean(twoball.LegendreBall(12))


def test_a_damping_sweep_of_the_drop_is_each_damped_drop(tmp_path):
    result = twoball.sweep({"damping": [0.05, 0.3]}, drop=twoball.Drop(), solver=SOLVER)
    assert result.parameter == "damping" and result.values == (0.05, 0.3)
    for value, report in zip(result.values, result.reports, strict=True):
        alone = twoball.bounce(twoball.Case.preset("basketball", damping=value), solver=SOLVER)
        assert report.e2 == alone.e2 and report.case.damping == value
    assert result.reports[1].e2 < result.reports[0].e2  # more damping, less rebound
    figure = result.plot(tmp_path / "drops.png", measured={"v2_m_s": [3.6]})
    assert figure.stat().st_size > 10_000


def test_a_damping_sweep_of_the_whole_bounce_like_the_others(tmp_path):
    result = twoball.sweep(
        {"damping": [0.1, 0.2]}, drop=twoball.Drop(), solver=SOLVER, pair="basketball-tennis"
    )
    assert all(r.has_body for r in result.reports)
    data = result.as_dict()
    assert [p["value"] for p in data["points"]] == [0.1, 0.2]
    assert data["points"][0]["comparisons"]["table1"]["row"] == 4
    assert result.plot(tmp_path / "whole.svg").stat().st_size > 10_000


@pytest.mark.parametrize(
    ("options", "name"),
    [
        ({"damping": twoball.ModalRatio(0.2)}, "damping"),  # the law would replace D
        (
            {"case": twoball.Case.preset("basketball", rayleigh=twoball.Rayleigh(1.0, 1e-5))},
            "param",
        ),  # fmt: skip
    ],
)
def test_a_damping_sweep_refuses_a_law_that_has_no_d(options, name):
    with pytest.raises(twoball.ParameterError) as caught:
        twoball.sweep({"damping": [0.1, 0.2]}, drop=twoball.Drop(), solver=SOLVER, **options)
    assert caught.value.name == name


def test_a_damping_value_out_of_range_is_refused_before_the_first_run():
    with pytest.raises(twoball.ParameterError, match="damping"):
        twoball.sweep({"damping": [0.1, 1.5]}, drop=twoball.Drop(), solver=SOLVER)
