"""The automatic warp of an animation shows the vibration, not only the initial flattening.

Reference: the displacements of the frames themselves.  The old rule drew the
largest displacement of all frames (the 17 mm flattening at t = 0) at 15 % of
R: x1.07, and the ~1 mm waves after pi/c stayed invisible.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest
from twoball.verify.output.fields import ball_model, ball_scene, field_mesh
from twoball.verify.output.render import AUTO_WARP_LIMIT, AUTO_WARP_SHARE

import twoball

CASE = twoball.Case.preset("basketball")
MESH = twoball.MeshOptions("sphere", level=1)
FRAMES = 12


def test_animation_warp_makes_the_wave_visible(tmp_path: Path) -> None:
    model = ball_model(CASE, field_mesh(MESH), backends=("fem",))
    times = np.linspace(0.0, model.t_end_s, FRAMES)
    scene = ball_scene(model, times, "fem")
    radius = CASE.radius
    largest = float(np.abs(scene.u).max())
    wave = float(np.abs(scene.u[times >= math.pi / CASE.wave_speed]).max())
    warp = scene.auto_warp()
    assert warp == pytest.approx(
        min(AUTO_WARP_SHARE * radius / wave, AUTO_WARP_LIMIT * radius / largest), rel=1e-12
    )
    assert largest > 10 * wave  # the flattening dwarfs the waves ...
    assert warp > 5 * AUTO_WARP_SHARE * radius / largest  # ... and no longer sets the warp
    assert warp * wave > 0.04 * radius  # the wave drawn at >= 4 % of R (old: < 1 %)
    assert warp * largest <= AUTO_WARP_LIMIT * radius * (1 + 1e-12)  # the ball never folds
    result = twoball.render(
        tmp_path / "ball.gif", mesh=MESH, frames=FRAMES, view=twoball.RenderOptions(size="64x48")
    )
    assert result.warp == pytest.approx(warp, rel=1e-12)


def test_a_single_late_picture_keeps_the_old_rule() -> None:
    model = ball_model(CASE, field_mesh(MESH), backends=("fem",))
    scene = ball_scene(model, np.array([0.02]), "fem")
    largest = float(np.abs(scene.u).max())
    assert scene.auto_warp() == pytest.approx(AUTO_WARP_SHARE * CASE.radius / largest)
