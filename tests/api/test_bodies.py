"""The elastic bodies at the face: ``twoball.floor_alone`` and ``twoball.bounce(body=...)``.

The JSON of an elastic body (its kind and parameters, ``body_restitution``, the
contact's duration, peak force and disc, the books with its own energy), the
rigid body's JSON untouched, the refusals naming their argument.
"""

from __future__ import annotations

import pytest

import twoball

SOLVER = twoball.MoreauJean(twoball.LegendreBall(16))


def test_floor_alone_gives_back_the_stated_restitution():
    lumped = twoball.floor_alone(pair="tennis-table-tennis")
    assert lumped.kind == "lumped" and lumped.restitution == pytest.approx(0.905, abs=1e-3)
    data = lumped.as_dict()
    assert data["provenance"]["call"]["function"] == "twoball.floor_alone"
    assert data["stated_contact_time_s"] == pytest.approx(data["contact_time_s"], rel=2e-3)
    body = twoball.body_preset("basketball-tennis", "lumped", restitution=0.7)
    assert twoball.floor_alone(body).restitution == pytest.approx(0.7, abs=1e-3)


@pytest.mark.parametrize(
    ("arguments", "name"),
    [
        ({"pair": "tennis-coin", "kind": "rigid"}, "kind"),
        ({"pair": "tennis-coin", "kind": "ball"}, "kind"),
        ({"body": twoball.Body(0.1)}, "body"),
        ({"pair": "tennis-coin", "body": twoball.body_preset("tennis-coin")}, "body"),
        ({"body": twoball.BallBody(), "mass": 0.05}, "mass"),
        ({"pair": "tennis-coin", "case": "tennis"}, "case"),
    ],
)
def test_floor_alone_refusals_name_the_argument(arguments, name):
    with pytest.raises(twoball.ParameterError) as error:
        twoball.floor_alone(**arguments)
    assert error.value.name == name


def test_bounce_with_a_lumped_body_reports_it():
    report = twoball.bounce(pair="basketball-tennis", body="lumped", solver=SOLVER)
    data = report.as_dict()
    body = data["body"]
    assert body["kind"] == "lumped" and body["body_restitution"] == 0.83
    assert body["parameters"]["law"]["law"] == "pressure" and body["pair"] == "basketball-tennis"
    contact = data["body_contact"]
    for key in ("duration_s", "peak_force_N", "disc_max_radius_m", "peak_compression_m"):
        assert contact[key] > 0.0, key
    assert "final_body_internal" in data["energy_J"] and data["energy_J"]["body_dissipated"] > 0
    assert data["provenance"]["call"]["arguments"]["body"] == "lumped"
    assert report.v1_ratio > 1.6  # the rigid body's is 1.4


def test_a_body_object_rides_a_pair_and_alone():
    body = twoball.body_preset("basketball-tennis", "lumped", restitution=0.95)
    with_pair = twoball.bounce(pair="basketball-tennis", body=body, solver=SOLVER)
    alone = twoball.bounce(body=body, solver=SOLVER)  # the basketball by default
    assert with_pair.as_dict()["body"]["body_restitution"] == 0.95
    assert alone.v1_ratio == with_pair.v1_ratio
    assert alone.baselines is None and with_pair.baselines is not None


def test_the_rigid_bodys_json_is_unchanged():
    data = twoball.bounce(pair="basketball-tissue", solver=SOLVER).as_dict()
    assert "kind" not in data["body"] and "body_contact" not in data
    assert "final_body_internal" not in data["energy_J"]
    rigid = twoball.bounce(pair="basketball-tissue", body="rigid", solver=SOLVER).as_dict()
    assert rigid["v1_ratio"] == data["v1_ratio"]


@pytest.mark.parametrize(
    ("arguments", "name"),
    [
        ({"body": "lumped"}, "body"),  # a kind needs a pair
        ({"body": "soft", "pair": "tennis-coin"}, "body"),
        ({"body": "ball", "pair": "tennis-coin"}, "kind"),
        ({"body": object()}, "body"),
        ({"body": twoball.Body(0.1), "pair": "tennis-coin"}, "body"),
    ],
)
def test_bounce_refusals(arguments, name):
    with pytest.raises(twoball.ParameterError) as error:
        twoball.bounce(solver=SOLVER, **arguments)
    assert error.value.name == name


def test_body_objects_check_their_fields():
    law = twoball.ContactLaw("pressure", 0.83, radius=0.0335, pressure=82700.0)
    with pytest.raises(twoball.ParameterError, match="steps"):
        twoball.LumpedBody(0.1, law, steps=2)
    with pytest.raises(twoball.ParameterError, match="law"):
        twoball.LumpedBody(0.1, "pressure")
    with pytest.raises(twoball.ParameterError, match="reach"):
        twoball.BallBody(reach=2.0)
    with pytest.raises(twoball.ParameterError, match="case"):
        twoball.BallBody(case="tennis")
    assert twoball.BallBody().as_dict()["preset"] == "tennis"


@pytest.mark.parametrize("kind", ["lumped", "ball"])
def test_the_report_files_and_light_points_of_an_elastic_body(kind, tmp_path):
    import pickle

    report = twoball.bounce(pair="basketball-tennis", body=kind, solver=SOLVER)
    assert report.plot(tmp_path / "whole.png").is_file()
    written = report.export(tmp_path / "whole.xdmf", frames=3)
    assert [p.name for p in written] == ["whole.xdmf", "whole.h5"]
    light = pickle.loads(pickle.dumps(report.light()))  # a sweep's point
    assert light.v1_ratio == report.v1_ratio and light.result.elastic == report.result.elastic
