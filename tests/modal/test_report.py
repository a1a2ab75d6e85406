"""The closed-form lift-off report (modal/report.py) against the paper."""

import numpy as np
import pytest

from twoball.modal.parameters import preset
from twoball.modal.report import legendre_liftoff


def test_basketball_matches_the_paper():
    report = legendre_liftoff(preset("basketball"))
    assert report.result.lifted
    assert report.t_liftoff_s == pytest.approx(0.0099, rel=0.01)  # §4(b): 0.0099 s
    assert report.v_liftoff_m_s == pytest.approx(3.7, rel=0.10)  # §4(b): about 3.7 m/s
    undamped = legendre_liftoff(preset("basketball").derive(damping=0.0))
    assert undamped.ratio == pytest.approx(4.5, rel=0.10)  # §6: "around 4.5"


def test_velocity_converges_as_n_grows():
    base = preset("basketball")
    v = [legendre_liftoff(base.derive(modes=n)).v_liftoff_m_s for n in (30, 60, 120, 240)]
    changes = np.abs(np.diff(v))
    assert np.all(changes[1:] < changes[:-1])
    assert changes[-1] < 0.5 * changes[0]


def test_printed_filter_with_paper_horizon_runs_and_lifts_early():
    report = legendre_liftoff(preset("basketball"), sigma="printed", recontact="paper")
    assert report.result.lifted
    # the printed sigma leaves Gibbs ringing at the pole: lift-off well before the wave arrives
    assert report.t_liftoff_s < 0.002
