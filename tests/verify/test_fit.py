"""verify/fit: the paper's one-point fit, synthetic round trips, the refusals of bad files.

The numerics below the face (:mod:`twoball.verify.fit`): the reader of measured
rows, the closed-form and whole-bounce models, the least squares with its
standard errors and bootstrap.
"""

from __future__ import annotations

import pickle

import numpy as np
import pytest

from twoball._common.errors import ParameterError
from twoball.modal.balls.membrane import LegendreBall
from twoball.modal.contact.body import Body
from twoball.modal.floor.options import Drop
from twoball.modal.parameters import Case
from twoball.modal.report import legendre_liftoff
from twoball.verify.fit.data import (
    MeasurementError,
    Measurements,
    plausibility_warnings,
    read_measurements,
)
from twoball.verify.fit.models import BounceModel, ClosedModel, parameter_names
from twoball.verify.fit.solve import check_bounds, fit_model

BASKETBALL = Case.preset("basketball")
#: The synthetic data set: eight impact speeds, made by the model at D = 0.17.
SPEEDS = np.linspace(2.5, 5.5, 8)
TRUE_D = 0.17


def closed_rows(damping: float = TRUE_D, wave_speed: float = 320.0) -> dict[str, np.ndarray]:
    """v1 and t_l of the closed form at :data:`SPEEDS` (phi_a by eq. (3.7) at each)."""
    reports = [
        legendre_liftoff(
            BASKETBALL.derive(v0=float(v), damping=damping, wave_speed=wave_speed),
            reference=False,
        )
        for v in SPEEDS
    ]
    return {
        "v0_m_s": SPEEDS,
        "v1_m_s": np.array([r.v_liftoff_m_s for r in reports]),
        "t_liftoff_s": np.array([r.t_liftoff_s for r in reports]),
    }


def write(tmp_path, text: str, name: str = "rows.csv"):
    path = tmp_path / name
    path.write_text(text, encoding="utf-8")
    return path


# --------------------------------------------------------------------------- the paper's fit
def test_the_papers_one_point_fit_gives_reproduces_damping():
    """v1 = 3.7 m/s at |v0| = 4.1 m/s, phi_a = 2.6, c = 320 1/s, R = 0.12 m (§4(b))."""
    from twoball.verify.reproduce.cem.fig11 import _fit_damping

    data = Measurements.from_columns({"v0_m_s": [4.1], "phi_a_rad": [2.6], "v1_m_s": [3.7]})
    case = Case.preset("basketball")
    assert (case.radius, case.wave_speed) == (0.12, 320.0)
    result = fit_model(ClosedModel(case, data, ("damping",)))
    reproduce = _fit_damping(3.7)  # Fig. 11's own bisection (brentq, xtol 1e-7)
    assert result.values["damping"] == pytest.approx(reproduce, abs=2e-7)
    assert result.values["damping"] == pytest.approx(0.13, abs=0.005)  # "D = 0.13" (§4(b))
    assert result.converged and result.dof == 0 and result.residuals.residuals[0, 0] < 1e-9
    assert result.standard_errors["damping"] is None  # one value, one parameter
    assert any("no degrees of freedom" in w for w in result.warnings)


def test_the_one_point_fit_with_an_uncertainty_has_an_error():
    """With sigma_v1_m_s the one point's error is sigma / |dv1/dD| (absolute weighting)."""
    data = Measurements.from_columns(
        {"v0_m_s": [4.1], "phi_a_rad": [2.6], "v1_m_s": [3.7], "sigma_v1_m_s": [0.1]}
    )
    result = fit_model(ClosedModel(BASKETBALL, data, ("damping",)))
    d = result.values["damping"]
    h = 1e-5
    up, down = (
        legendre_liftoff(BASKETBALL.derive(damping=d + s), reference=False).v_liftoff_m_s
        for s in (h, -h)
    )
    slope = (up - down) / (2 * h)
    assert result.absolute
    assert result.standard_errors["damping"] == pytest.approx(0.1 / abs(slope), rel=1e-3)


# --------------------------------------------------------------------------- round trips
def test_synthetic_rows_without_noise_give_d_back_to_the_tolerance():
    data = Measurements.from_columns(closed_rows())
    result = fit_model(ClosedModel(BASKETBALL, data, ("damping",)))
    assert data.rows >= 8
    assert result.values["damping"] == pytest.approx(TRUE_D, abs=1e-9)
    assert result.chi2 < 1e-20 and result.converged
    assert result.at_bound == {"damping": None}


def test_synthetic_rows_with_noise_give_d_back_within_its_standard_error():
    rows = closed_rows()
    rng = np.random.default_rng(20240530)
    noisy = {"v0_m_s": rows["v0_m_s"], "v1_m_s": rows["v1_m_s"] + rng.normal(0.0, 0.05, 8)}
    result = fit_model(ClosedModel(BASKETBALL, Measurements.from_columns(noisy), ("damping",)))
    error = result.standard_errors["damping"]
    assert error is not None and 0.0 < error < 0.01
    assert abs(result.values["damping"] - TRUE_D) < 3.0 * error
    rms = result.rms["v1_m_s"]
    assert 0.02 < rms < 0.08  # the noise's size, 0.05 m/s
    assert result.dof == 7 and result.reduced_chi2 == pytest.approx(result.chi2 / 7)


def test_noise_with_its_sigma_gives_a_chi2_near_the_degrees_of_freedom():
    rows = closed_rows()
    rng = np.random.default_rng(7)
    sigma = 0.05
    noisy = {
        "v0_m_s": rows["v0_m_s"],
        "v1_m_s": rows["v1_m_s"] + rng.normal(0.0, sigma, 8),
        "sigma_v1_m_s": np.full(8, sigma),
    }
    result = fit_model(ClosedModel(BASKETBALL, Measurements.from_columns(noisy), ("damping",)))
    assert result.absolute
    assert 0.5 < result.chi2 < 25.0  # chi^2 with 7 degrees of freedom, 99.9 % range
    assert abs(result.values["damping"] - TRUE_D) < 3.0 * result.standard_errors["damping"]


def test_the_wave_speed_is_fitted_from_lift_off_times():
    rows = closed_rows(wave_speed=300.0)  # phi_a by eq. (3.7) at c = 300 1/s
    data = Measurements.from_columns({"v0_m_s": rows["v0_m_s"], "t_liftoff_s": rows["t_liftoff_s"]})
    model = ClosedModel(BASKETBALL.derive(damping=TRUE_D), data, ("wave-speed",))
    result = fit_model(model)
    assert result.values["wave-speed"] == pytest.approx(300.0, rel=1e-8)
    assert result.notes and "eq. (3.7) at every trial c" in result.notes[0]


def test_damping_and_wave_speed_together():
    data = Measurements.from_columns(closed_rows(damping=0.15, wave_speed=330.0))
    result = fit_model(ClosedModel(BASKETBALL, data, ("damping", "wave-speed")))
    assert result.values["damping"] == pytest.approx(0.15, abs=1e-8)
    assert result.values["wave-speed"] == pytest.approx(330.0, rel=1e-8)
    assert np.all(np.isfinite(result.covariance))


def test_a_fit_that_ends_on_a_bound_says_so():
    data = Measurements.from_columns(closed_rows(damping=0.13))
    model = ClosedModel(BASKETBALL, data, ("damping",))
    result = fit_model(model, bounds={"damping": (0.15, 0.3)}, start={"damping": 0.2})
    assert result.values["damping"] == pytest.approx(0.15)
    assert result.at_bound == {"damping": "lower"}
    assert any("lower bound 0.15" in w for w in result.warnings)


def test_the_bootstrap_gives_a_second_error():
    rows = closed_rows()
    rng = np.random.default_rng(3)
    noisy = {"v0_m_s": rows["v0_m_s"], "v1_m_s": rows["v1_m_s"] + rng.normal(0.0, 0.05, 8)}
    model = ClosedModel(BASKETBALL, Measurements.from_columns(noisy), ("damping",))
    result = fit_model(model, bootstrap=12, seed=1)
    assert result.bootstrap.shape == (12, 1)
    boot = result.bootstrap_errors["damping"]
    assert 0.1 * result.standard_errors["damping"] < boot < 10 * result.standard_errors["damping"]
    again = fit_model(
        ClosedModel(BASKETBALL, Measurements.from_columns(noisy), ("damping",)),
        bootstrap=12,
        seed=1,
    )
    assert np.array_equal(again.bootstrap, result.bootstrap)  # the seed decides


def test_no_lift_off_in_the_model_counts_as_zero_speed():
    """A row the model does not lift off at the optimum is said, with 0 m/s taken."""
    data = Measurements.from_columns({"v0_m_s": [4.1, 4.1], "v1_m_s": [0.0, 0.0]})
    result = fit_model(
        ClosedModel(BASKETBALL, data, ("damping",)),
        bounds={"damping": (0.7, 0.9)},
        start={"damping": 0.8},
    )
    assert result.residuals.undefined.all()
    assert any("no value at the optimum" in w for w in result.warnings)


# --------------------------------------------------------------------------- the whole bounce
SOLVER_BALL = LegendreBall(8)
DT = 4e-5  # s: coarse, quick, and the same for the data and the fit
COIN = Body(0.062, contact_radius=0.01015, restitution=0.46)


def bounce_model(data: Measurements, params=("restitution",), body=COIN) -> BounceModel:
    return BounceModel(
        Case.preset("tennis"), data, params, drop=Drop(), body=body, ball=SOLVER_BALL, dt=DT
    )


def test_the_bounce_model_gives_the_numbers_of_twoball_bounce():
    import twoball

    data = Measurements.from_columns(
        {"gap_m": [0.05], "v1_m_s": [1.0], "v2_m_s": [1.0], "t_liftoff_s": [0.01]}
    )
    predicted = bounce_model(data).predict({"restitution": 0.46})[0]
    solver = twoball.MoreauJean(SOLVER_BALL, dt=DT)
    report = twoball.bounce(Case.preset("tennis"), Drop(gap=0.05), solver=solver, body=COIN)
    assert predicted.tolist() == [report.v1_m_s, report.as_dict()["v2_m_s"], report.t_liftoff_s]


def test_the_restitution_of_the_whole_bounce_comes_back():
    """Two synthetic rows (gaps 50 and 150 mm) made at e12 = 0.46, fitted from 0.3."""
    gaps = [0.05, 0.15]
    made = bounce_model(Measurements.from_columns({"gap_m": gaps, "v1_m_s": [1.0, 1.0]}))
    v1 = made.predict({"restitution": 0.46})[:, 0]
    data = Measurements.from_columns({"gap_m": gaps, "v1_m_s": v1})
    result = fit_model(bounce_model(data), start={"restitution": 0.3})
    # a run is piecewise smooth in e12 (its contacts are counted): back to 1e-3
    assert result.values["restitution"] == pytest.approx(0.46, abs=1e-3)
    assert result.converged and result.model == "bounce"


@pytest.mark.slow
def test_the_restitution_with_noise_comes_back_within_its_error():
    gaps = [0.03, 0.06, 0.1, 0.15, 0.2]
    made = bounce_model(Measurements.from_columns({"gap_m": gaps, "v1_m_s": [1.0] * 5}))
    v1 = made.predict({"restitution": 0.46})[:, 0]
    rng = np.random.default_rng(11)
    data = Measurements.from_columns({"gap_m": gaps, "v1_m_s": v1 + rng.normal(0, 0.005, 5)})
    result = fit_model(bounce_model(data), start={"restitution": 0.3})
    error = result.standard_errors["restitution"]
    assert error is not None and abs(result.values["restitution"] - 0.46) < 3.0 * error


def test_the_bounce_refuses_what_it_cannot_use():
    with pytest.raises(MeasurementError, match="column phi_a_rad: .*closed form"):
        bounce_model(Measurements.from_columns({"phi_a_rad": [2.6], "v1_m_s": [1.0]}))
    with pytest.raises(MeasurementError, match="column v1_m_s: .*need a body"):
        bounce_model(
            Measurements.from_columns({"v2_m_s": [2.0], "v1_m_s": [1.0]}),
            body=None,
            params=("damping",),
        )
    with pytest.raises(ParameterError, match="restitution with a body"):
        bounce_model(Measurements.from_columns({"v2_m_s": [2.0]}), body=None)
    with pytest.raises(MeasurementError, match=r"row 2, column gap_m: .*\[0, 10\]"):
        bounce_model(Measurements.from_columns({"gap_m": [0.1, 20.0], "v1_m_s": [1.0, 1.0]}))


# --------------------------------------------------------------------------- the reader
@pytest.mark.parametrize(
    ("text", "where"),
    [
        ("", "must be a CSV file with a header line"),
        ("4.1,2.6,3.7\n", "line 1: must be a header line"),
        ("v0_m_s,speed\n4.1,3.7\n", "line 1, column speed: must be one of v0_m_s"),
        ("v0_m_s,v1_m_s\n4.1,abc\n", "row 1 (line 2), column v1_m_s: must be a finite number"),
        ("v0_m_s,v1_m_s\n", "at least one row of values"),
        ("# a comment only\n\n", "must be a CSV file with a header line"),
        ("v0_m_s,v1_m_s\n4.1,3.7\n4.1\n", "row 2 (line 3): must be 2 cells"),
        ("v0_m_s,v1_m_s,v1_m_s\n4.1,3.7,3.7\n", "column v1_m_s: must be named once"),
        ("v0_m_s,sigma_v1_m_s\n4.1,0.1\n", "column sigma_v1_m_s: must be given with its column"),
        ("v1_m_s,sigma_v1_m_s\n3.7,0\n", "column sigma_v1_m_s: must be an uncertainty > 0"),
        ("v1_m_s,sigma_v1_m_s\n3.7,\n", "column sigma_v1_m_s: must be given where its column"),
        ("v0_m_s,v1_m_s\n4_1,3.7\n", "row 1 (line 2), column v0_m_s: must be a finite number"),
        ("v0_m_s,v1_m_s\nnan,3.7\n", "column v0_m_s: must be a finite number"),
        ("v1_m_s,t_liftoff_s\n3.7,-1\n", "column t_liftoff_s: must be a time >= 0"),
        ("v0_m_s,,v1_m_s\n4.1,1,3.7\n", "column 2: must be a named column"),
    ],
)
def test_a_bad_file_is_refused_in_one_line_naming_file_row_and_column(tmp_path, text, where):
    path = write(tmp_path, text)
    with pytest.raises(MeasurementError) as caught:
        read_measurements(path)
    message = str(caught.value)
    assert message.startswith(f"data {path}: ") and where in message
    assert "\n" not in message and isinstance(caught.value, ParameterError)


def test_a_missing_file_and_a_folder_are_refused(tmp_path):
    with pytest.raises(MeasurementError, match="no such file"):
        read_measurements(tmp_path / "none.csv")
    with pytest.raises(MeasurementError, match="not a folder"):
        read_measurements(tmp_path)
    with pytest.raises(MeasurementError, match="not empty"):
        read_measurements("")
    with pytest.raises(ParameterError, match="a CSV file path"):
        read_measurements(5)
    binary = tmp_path / "b.csv"
    binary.write_bytes(b"\xff\xfe\x00\x81")
    with pytest.raises(MeasurementError, match="UTF-8"):
        read_measurements(binary)


def test_comments_blank_cells_semicolons_and_a_byte_order_mark_are_read(tmp_path):
    text = "\ufeff# drops of 2024-05-30\nv0_m_s ; v1_m_s ; t_liftoff_s\n3.0;2.6;\n\n4.1; ;0.0099\n"
    data = read_measurements(write(tmp_path, text), name="measured")
    assert data.columns == ("v0_m_s", "v1_m_s", "t_liftoff_s") and data.lines == (3, 5)
    assert data.measured("v1_m_s").tolist() == [True, False]
    assert data.column("gap_m").shape == (2,) and np.isnan(data.column("gap_m")).all()
    assert data.name == "measured"


def test_a_mapping_is_refused_like_a_file():
    with pytest.raises(MeasurementError, match=r"rows: must be columns of one length"):
        Measurements.from_columns({"v0_m_s": [1.0, 2.0], "v1_m_s": [1.0]})
    with pytest.raises(MeasurementError, match=r"rows: row 2, column v1_m_s: must be a finite"):
        Measurements.from_columns({"v1_m_s": [1.0, "abc"]})
    with pytest.raises(MeasurementError, match="column speed"):
        Measurements.from_columns({"speed": [1.0]})
    with pytest.raises(ParameterError, match="mapping of columns"):
        Measurements.from_columns({})


def test_every_row_needs_a_measured_value_and_the_model_a_measured_column():
    with pytest.raises(MeasurementError, match="row 2: must be a row with at least one"):
        ClosedModel(BASKETBALL, Measurements.from_columns({"v1_m_s": [3.7, None]}), ("damping",))
    with pytest.raises(MeasurementError, match="at least one measured column"):
        ClosedModel(BASKETBALL, Measurements.from_columns({"v0_m_s": [4.1]}), ("damping",))
    with pytest.raises(MeasurementError, match="column gap_m: .*model bounce"):
        ClosedModel(
            BASKETBALL, Measurements.from_columns({"gap_m": [0.0], "v1_m_s": [3.0]}), ("damping",)
        )
    with pytest.raises(MeasurementError, match=r"row 1, column v0_m_s: must be a nonzero"):
        ClosedModel(
            BASKETBALL, Measurements.from_columns({"v0_m_s": [0.0], "v1_m_s": [3.0]}), ("damping",)
        )
    with pytest.raises(MeasurementError, match=r"row 1, column phi_a_rad"):
        ClosedModel(
            BASKETBALL,
            Measurements.from_columns({"phi_a_rad": [1.0], "v1_m_s": [3.0]}),
            ("damping",),
        )


def test_parameters_and_bounds_are_checked():
    assert parameter_names("wave_speed", "closed") == ("wave-speed",)
    for bad in ("bogus", [], ["damping", "damping"], 5):
        with pytest.raises(ParameterError, match="params"):
            parameter_names(bad, "closed")
    with pytest.raises(ParameterError, match="model bounce"):
        parameter_names("restitution", "closed")
    assert check_bounds(("damping",), None) == {"damping": (0.0, 0.999)}
    for bad in (
        {"damping": (0.5, 0.1)},
        {"damping": (-1, 0.5)},
        {"wave-speed": (1, 2)},
        {"damping": "x"},
    ):
        with pytest.raises(ParameterError, match="bounds"):
            check_bounds(("damping",), bad)


def test_unit_slips_are_warned_and_errors_pickle():
    data = Measurements.from_columns({"v1_m_s": [3.7], "t_liftoff_s": [9.9]})
    assert "milliseconds?" in plausibility_warnings(data)[0]
    error = MeasurementError(
        "data", "x.csv", "a finite number", "abc", row=2, line=3, column="v1_m_s"
    )
    again = pickle.loads(pickle.dumps(error))
    assert str(again) == str(error) and again.column == "v1_m_s"


@pytest.mark.slow
def test_the_standard_error_covers_the_truth_as_often_as_it_should():
    """Over 30 noisy data sets the error interval holds D about 68 % of the time."""
    rows = closed_rows()
    z = []
    for seed in range(30):
        rng = np.random.default_rng(seed)
        noisy = {"v0_m_s": rows["v0_m_s"], "v1_m_s": rows["v1_m_s"] + rng.normal(0, 0.05, 8)}
        model = ClosedModel(BASKETBALL, Measurements.from_columns(noisy), ("damping",))
        result = fit_model(model)
        z.append((result.values["damping"] - TRUE_D) / result.standard_errors["damping"])
    inside = float(np.mean(np.abs(np.array(z)) < 1.0))
    assert 0.45 < inside < 0.9 and 0.6 < float(np.std(z)) < 1.5
