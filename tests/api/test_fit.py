"""twoball.fit: a file or a mapping in, FitResult out; refusals before work; JSON and figure."""

from __future__ import annotations

import json

import numpy as np
import pytest

import twoball
from twoball.verify.fit.data import MeasurementError

PAPER = {"v0_m_s": [4.1], "phi_a_rad": [2.6], "v1_m_s": [3.7]}


def rows_at(damping: float, speeds=(2.5, 3.0, 3.5, 4.0, 4.5, 5.0, 5.5, 6.0)) -> dict:
    """v1 and t_l of twoball.liftoff at ``speeds`` (the synthetic data of the examples)."""
    case = twoball.Case.preset("basketball", damping=damping)
    reports = [twoball.liftoff(case.derive(v0=v)) for v in speeds]
    return {
        "v0_m_s": list(speeds),
        "v1_m_s": [r.v_liftoff_m_s for r in reports],
        "t_liftoff_s": [r.t_liftoff_s for r in reports],
    }


def csv_text(columns: dict) -> str:
    names = list(columns)
    lines = [",".join(names)]
    for k in range(len(columns[names[0]])):
        lines.append(",".join(repr(float(columns[n][k])) for n in names))
    return "\n".join(lines) + "\n"


def test_the_papers_fit_from_a_file_and_from_a_mapping_agree(tmp_path):
    path = tmp_path / "paper.csv"
    path.write_text("# Berdeni et al. 2015, §4(b)\nv0_m_s,phi_a_rad,v1_m_s\n4.1,2.6,3.7\n")
    from_file = twoball.fit(path, "damping")
    from_rows = twoball.fit(PAPER, ["damping"])
    assert from_file.values == from_rows.values
    assert from_file.values["damping"] == pytest.approx(0.1329, abs=1e-4)
    assert isinstance(from_file, twoball.FitResult)
    data = from_file.as_dict()
    json.dumps(data, allow_nan=False)  # strict JSON
    assert data["data"] == str(path) and data["rows"][0]["line"] == 3
    assert data["provenance"]["call"]["function"] == "twoball.fit"
    assert data["parameters"]["damping"]["standard_error"] is None


def test_a_synthetic_data_set_comes_back_with_and_without_noise(tmp_path):
    rows = rows_at(0.18)
    exact = twoball.fit(rows, "damping")
    assert exact.values["damping"] == pytest.approx(0.18, abs=1e-9)
    rng = np.random.default_rng(5)
    noisy = dict(rows, v1_m_s=list(np.array(rows["v1_m_s"]) + rng.normal(0, 0.04, 8)))
    path = tmp_path / "noisy.csv"
    path.write_text(csv_text(noisy))
    result = twoball.fit(path, "damping")
    error = result.standard_errors["damping"]
    assert abs(result.values["damping"] - 0.18) < 3 * error
    assert len(result.rows()) == 8 and set(result.rms) == {"v1_m_s", "t_liftoff_s"}
    figure = result.plot(tmp_path / "fit.png")
    assert figure.stat().st_size > 10_000


def test_the_wave_speed_and_its_start_and_bounds():
    rows = rows_at(0.13)
    case = twoball.Case.preset("basketball", wave_speed=305.0)
    result = twoball.fit(
        {"v0_m_s": rows["v0_m_s"], "t_liftoff_s": rows["t_liftoff_s"]},
        "wave_speed",
        case=case,
        start={"wave_speed": 310.0},
        bounds={"wave-speed": (250.0, 400.0)},
    )
    # the rows were made at c = 320 1/s (phi_a by eq. (3.7): none is at the preset's 4.1 m/s)
    assert result.values["wave-speed"] == pytest.approx(320.0, rel=1e-9)
    assert result.start == {"wave-speed": 310.0} and result.bounds["wave-speed"] == (250.0, 400.0)
    assert result.units == {"wave-speed": "1/s"}


@pytest.mark.parametrize(
    ("call", "name"),
    [
        (lambda: twoball.fit(PAPER, "bogus"), "params"),
        (lambda: twoball.fit(PAPER, "restitution"), "params"),
        (lambda: twoball.fit(PAPER, "damping", model="other"), "model"),
        (lambda: twoball.fit(PAPER, "damping", pair="basketball-tennis"), "pair"),
        (lambda: twoball.fit(PAPER, "damping", body=twoball.Body(0.1)), "body"),
        (lambda: twoball.fit(PAPER, "damping", drop=twoball.Drop()), "drop"),
        (lambda: twoball.fit(PAPER, "damping", case="basketball"), "case"),
        (lambda: twoball.fit(PAPER, "damping", solver=twoball.MoreauJean()), "solver"),
        (lambda: twoball.fit(PAPER, "damping", start={"damping": 1.5}), "start"),
        (lambda: twoball.fit(PAPER, "damping", start={"wave-speed": 300.0}), "start"),
        (lambda: twoball.fit(PAPER, "damping", bounds={"damping": (0.3, 0.2)}), "bounds"),
        (lambda: twoball.fit(PAPER, "damping", bootstrap=-1), "bootstrap"),
        (lambda: twoball.fit(PAPER, "damping", bootstrap=3), "bootstrap"),  # one row
        (lambda: twoball.fit(PAPER, "damping", tolerance=0.5), "tolerance"),
        (lambda: twoball.fit(PAPER, "damping", progress=3), "progress"),
        (lambda: twoball.fit(PAPER, "damping", bogus=1), "bogus"),
        (lambda: twoball.fit(5, "damping"), "data"),
        (lambda: twoball.fit(PAPER, "damping", model="bounce"), "data"),  # phi_a_rad
    ],
)
def test_bad_arguments_are_refused_naming_them(call, name):
    with pytest.raises(twoball.ParameterError) as caught:
        call()
    assert caught.value.name == name


@pytest.mark.parametrize(
    ("text", "row", "column"),
    [
        ("v0_m_s,v1_m_s\n4.1,3.7\n4.2,x\n", "row 2 (line 3)", "column v1_m_s"),
        ("v0_m_s,width\n4.1,3.7\n", "line 1", "column width"),
        ("v0_m_s,gap_m,v1_m_s\n4.1,0,3.7\n", None, "column gap_m"),
    ],
)
def test_a_bad_file_names_the_file_the_row_and_the_column(tmp_path, text, row, column):
    path = tmp_path / "bad.csv"
    path.write_text(text)
    with pytest.raises(MeasurementError) as caught:
        twoball.fit(path, "damping")
    message = str(caught.value)
    assert str(path) in message and column in message and (row is None or row in message)


def test_the_whole_bounce_fits_e12_of_a_pair():
    """One row at a 50 mm gap, made at e12 = 0.5 with the tennis-coin pair's other values."""
    solver = twoball.MoreauJean(twoball.LegendreBall(8), dt=4e-5)
    pair = twoball.bounce(
        twoball.Case.preset("tennis"),
        twoball.Drop(gap=0.05),
        solver=solver,
        body=twoball.Body(0.062, contact_radius=0.01015, restitution=0.5),
    )
    result = twoball.fit(
        {"gap_m": [0.05], "v1_m_s": [pair.v1_m_s]},
        "restitution",
        model="bounce",
        pair="tennis-coin",
        solver=solver,
    )
    assert result.start == {"restitution": 0.46}  # Table 1's e12
    assert result.values["restitution"] == pytest.approx(0.5, abs=2e-3)
    assert result.solver["pair"] == "tennis-coin" and result.model == "bounce"
