"""The pole figure with a body of finite mass (verify/output/figures/contact_pole.py)."""

from __future__ import annotations

import numpy as np

from twoball.verify.output.figures.contact_pole import BODY_GID, EVENT_GID, contact_pole_figure
from twoball.verify.output.figures.style import curves


def test_plot_pole_draws_the_path_and_one_marker_per_event(coupled):
    samples = 400
    figure = contact_pole_figure(coupled, samples)
    displacement, velocity = figure.axes[0], figure.axes[2]  # difference rows between
    assert len(figure.axes) == 6
    for name in ("fem", "legendre"):
        report = coupled.contact(name)
        events = report.events_si()
        assert len(events) == len(report.history.events) >= 3
        for axis, key, factor in ((displacement, "height_m", 1e3), (velocity, "velocity_m_s", 1.0)):
            marks = [
                line for line in axis.get_lines() if str(line.get_gid()).endswith(f"-{name}")
                and str(line.get_gid()).startswith(EVENT_GID)
            ]  # fmt: skip
            assert sum(len(line.get_xdata()) for line in marks) == len(events)
            for kind in ("impact", "separation"):
                (line,) = [m for m in marks if m.get_gid() == f"{EVENT_GID}-{kind}-{name}"]
                chosen = [e for e in events if e["kind"] == kind]
                assert np.allclose(line.get_xdata(), [e["t_s"] * 1e3 for e in chosen])
                assert np.allclose(line.get_ydata(), [e[key] * factor for e in chosen])
        # the body's path is the solver's trajectory at the same times
        (path,) = [
            line for line in displacement.get_lines() if line.get_gid() == f"{BODY_GID}-{name}"
        ]
        data = report.trajectory_si(samples)
        assert np.allclose(path.get_xdata(), data["t_s"] * 1e3, rtol=1e-12)
        scale = np.abs(data["body_height_m"]).max()
        assert np.abs(path.get_ydata() / 1e3 - data["body_height_m"]).max() < 1e-12 * scale
    assert all(len(curves(a)) <= 6 for a in figure.axes)
    (legend,) = figure.legends  # one legend below every panel
    labels = [t.get_text() for t in legend.get_texts()]
    assert {"impact", "separation", "lift-off (final separation)"} <= set(labels)
