"""A cut through an elastic ball's volume during the drop: the wave inside, in SI.

The solid ball and the thick wall move through their volume; the drop's surface
fields (:mod:`twoball.verify.output.drop_fields`) show only their skin.  Here the
meridian plane y = 0 (the axisymmetric field swept to both sides, x = +-r) is
triangulated and every coordinate's interior displacement is read there:

* Lamb's modes (:class:`~twoball.modal.balls.solid.SolidBall`): eq. (M1) on a
  polar grid (the static correction's coordinates carry no interior field here);
* the finite elements (:class:`~twoball.fem_solid.ball.FESolidBall`,
  :class:`~twoball.fem_solid.ball.ThickBall`): the nodal vectors at the mesh's
  vertices, on its own triangles.

A ball registers its cut when it is described
(:func:`~twoball.modal.balls.solid.register_cut`); a drop whose
ball has none (a membrane, a shell) is refused by name.  Point data:
``displacement_m`` (F, P, 3) (the centre's fall and the deformation: "Warp By
Vector" in ParaView), ``u_m`` (the displacement along the radius from the
centre: compression negative), ``speed_m_s`` (the deformation's speed: the
wave).  Frame data ``Z_m`` and ``floor_force_N`` as for the surface.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from twoball._common.errors import ParameterError

__all__ = ["cut_scene", "cut_series"]


def _grid(result: Any) -> Any:
    from twoball.modal.balls.solid import cut_of

    grid = cut_of(result.system.ball)
    if grid is None:
        valid = "a ball with a volume (solid or thick) for a cut view"
        raise ParameterError("view", valid, result.system.ball.label)
    return grid


def cut_series(result: Any, case: Any, times_s: np.ndarray, mass: float, text: str) -> Any:
    """The drop on the meridian plane at ``times_s`` [s] (both sides of the axis), in SI."""
    import json

    from twoball.verify.output.drop_fields import _coordinates
    from twoball.verify.output.series import TimeSeries

    grid = _grid(result)
    system = result.system
    k = system.ball.modes
    q, force = _coordinates(result, times_s, case)
    tr = result.trajectory
    t = np.asarray(times_s, dtype=float) * case.wave_speed
    v = np.column_stack([np.interp(t, tr.t, tr.v[:, j]) for j in range(k)])
    z = q[:, system.centre]
    a = q[:, :k]
    # the plane y = 0: the half disc at x = r and its mirror at x = -r (the axis nodes twice)
    half = grid.points.shape[0]
    points = np.vstack(
        [
            np.column_stack([grid.points[:, 0], np.zeros(half), grid.points[:, 1]]),
            np.column_stack([-grid.points[:, 0], np.zeros(half), grid.points[:, 1]]),
        ]
    )
    cells = np.vstack([grid.triangles, grid.triangles[:, ::-1] + half])
    ur, uz = a @ grid.radial.T, a @ grid.axial.T  # (F, P/2)
    vr, vz = v @ grid.radial.T, v @ grid.axial.T
    ux = np.hstack([ur, -ur])
    uy = np.zeros_like(ux)
    uzz = np.hstack([uz, uz])
    radius = case.radius
    lift = (z - 1.0)[:, None]
    displacement = np.stack([ux, uy, uzz + lift], axis=-1) * radius
    norm = np.linalg.norm(points, axis=1)
    safe = np.where(norm > 0.0, norm, 1.0)
    along = (ux * points[:, 0] + uzz * points[:, 2]) / safe * radius
    speed = np.hypot(np.hstack([vr, -vr]), np.hstack([vz, vz])) * radius * case.wave_speed
    force_unit = mass * radius * case.wave_speed**2
    return TimeSeries(
        points * radius,
        cells,
        np.asarray(times_s, dtype=float),
        {"displacement_m": displacement, "u_m": along, "speed_m_s": speed},
        {"e2": np.nan if result.e2 is None else result.e2},
        {"case": text, "mesh": json.dumps({"label": system.ball.label, "view": "cut"})},
        {"Z_m": z * radius, "floor_force_N": force * force_unit},
    )


def cut_scene(result: Any, case: Any, times_s: np.ndarray, mass: float, label: str) -> Any:
    """The cut drawn by :func:`twoball.verify.output.render.render_scene` (radial ``u``)."""
    from twoball.verify.output.drop_fields import DROP_FOOTER_CHARS, DropScene

    series = cut_series(result, case, times_s, mass, label)
    u = series.point_data["u_m"]
    points = series.points.copy()
    centre = np.linalg.norm(points, axis=1) == 0.0  # no radius to move along: lift it a hair
    points[centre, 2] = 1e-9 * case.radius
    frames = series.frame_data
    top = int(np.argmax(series.points[:, 2]))
    t_left = None if result.contact_time is None else result.contact_time / case.wave_speed
    return DropScene(
        points,
        series.cells,
        series.times,
        u,
        u[:, top],
        case.radius,
        t_left,
        label,
        floor_force=frames["floor_force_N"],
        centre=frames["Z_m"] - case.radius,
        footer_chars=DROP_FOOTER_CHARS,
    )
