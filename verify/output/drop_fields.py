"""The drop on the floor as a field on a sphere mesh, in SI, for files and pictures.

The drop's trajectory (:class:`~twoball.modal.floor.drop.DropResult`) holds the
centre's height Z and the membrane's modal amplitudes at every step; here they
are read at the nodes of a sphere mesh (:mod:`twoball.fem_membrane.mesh`, the
pole on +z) at chosen instants and written through the field machinery of
:mod:`twoball.verify.output.series` (XDMF, PVD, VTU) and
:mod:`twoball.verify.output.render` (PNG, GIF, MP4).  Point data:

``u_m``
    The radial displacement from the centre [m] (the flattening shows at the bottom).
``displacement_m``
    The whole motion from the ball resting undeformed with its pole on the
    floor: ``(Z - R) e_z + u n`` [m] (shape (F, P, 3)); ParaView's "Warp By
    Vector" draws the ball falling, flattening and leaving.
``height_m``
    Each node's height above the floor [m]: >= 0 at the floor points; a node
    between them may dip below by the resolution's error.

Frame data: ``Z_m`` (the centre's height) and ``floor_force_N``; with an upper
body (the whole bounce) also ``body_height_m`` (the body's lowest point above
the floor), ``body_gap_m`` (its gap above the ball's top, eq. (B2)) and
``body_force_N`` (the contact force between them).  The forces are the
impulse per 0.1 ms window (:mod:`twoball.verify.output.forces`), read at the
frame's instant: a step cut short at a touch shows no force of its own.

Field data: ``contact_time_s``, ``e2``, ``phi_a_max_rad``; with a body
``mass_ratio``, ``gap_m``, ``cap_angle_rad``, ``v1_ratio``, ``v2_ratio``,
``t_liftoff_s``.  The events of both contacts (every touch and separation:
``contact`` floor or body, ``kind``, ``t_s``, ``velocity_m_s`` of the centre,
``body_velocity_m_s``) are the text ``contact_events``, a JSON list stored as
its UTF-8 bytes (what meshio, pyvista and VTK all read back:
:func:`twoball.verify.output.series.text_value`), with the counts ``events``,
``floor_contacts`` and ``body_contacts`` as numbers.
"""

from __future__ import annotations

import json
from dataclasses import dataclass
from typing import Any

import numpy as np

from twoball.fem_membrane.mesh import SphereMesh
from twoball.modal.floor.drop import DropResult
from twoball.modal.parameters import Case
from twoball.verify.output.forces import contact_forces
from twoball.verify.output.render import BallScene
from twoball.verify.output.series import TimeSeries

__all__ = ["DropScene", "body_frames", "drop_frames", "drop_scene", "drop_series"]

#: The drop's footer in two lines below the floor (characters per line at the default size).
DROP_FOOTER_CHARS = 64


def _meridian(normal: np.ndarray) -> np.ndarray:
    """The unit vector ``e_phi`` (increasing polar angle) at points of outward ``normal``.

    ``(cos phi cos a, cos phi sin a, -sin phi)``; at the poles, where axisymmetry makes
    the meridional displacement vanish, any unit vector in the plane (x here).
    """
    rho = np.hypot(normal[:, 0], normal[:, 1])
    safe = np.where(rho > 0.0, rho, 1.0)
    out = np.column_stack(
        [normal[:, 2] * normal[:, 0] / safe, normal[:, 2] * normal[:, 1] / safe, -rho]
    )
    out[rho == 0.0] = (1.0, 0.0, 0.0)
    return out


def drop_frames(result: DropResult, count: int, case: Case) -> np.ndarray:
    """``count`` instants [s] equally spaced from the first touch to the end of the run."""
    end = float(result.trajectory.t[-1]) / case.wave_speed
    return np.linspace(0.0, end, int(count))


def _states(result: DropResult, times_s: np.ndarray, case: Case) -> tuple[np.ndarray, ...]:
    """Z, the ball's coordinates at ``times_s`` (linear between step ends), and the force."""
    q, f = _coordinates(result, times_s, case)
    system = result.system
    return q[:, system.centre], q[:, : system.ball.modes], f


def _coordinates(
    result: DropResult, times_s: np.ndarray, case: Case
) -> tuple[np.ndarray, np.ndarray]:
    """Every coordinate at ``times_s`` (linear between step ends) and the floor force."""
    tr = result.trajectory
    t = np.asarray(times_s, dtype=float) * case.wave_speed
    q = np.column_stack([np.interp(t, tr.t, tr.q[:, j]) for j in range(tr.q.shape[1])])
    mid, force = contact_forces(result, case)[1]["floor"]
    return q, np.interp(t, mid, force, left=0.0, right=0.0)


def body_frames(
    result: DropResult, times_s: np.ndarray, case: Case, mass: float
) -> dict[str, np.ndarray]:
    """The body's frame data at ``times_s`` [s] (SI; empty without a body)."""
    system = result.system
    if system.body is None:
        return {}
    q, _ = _coordinates(result, times_s, case)
    t = np.asarray(times_s, dtype=float) * case.wave_speed
    mid, force = contact_forces(result, case)[1]["body"]
    force_unit = mass * case.radius * case.wave_speed**2
    return {
        "body_height_m": q[:, system.body_coordinate] * case.radius,
        "body_gap_m": system.body_gap(q) * case.radius,
        "body_force_N": np.interp(t, mid, force, left=0.0, right=0.0) * force_unit,
    }


def drop_series(
    result: DropResult,
    case: Case,
    mesh: SphereMesh,
    times_s: np.ndarray,
    mass: float,
    text: str,
    events: list[dict[str, Any]] | None = None,
) -> TimeSeries:
    """The drop at the nodes of ``mesh`` (unit sphere) at ``times_s`` [s], in SI.

    ``events``: the touches and separations in SI (:attr:`twoball.BounceReport.events`:
    ``contact``, ``kind``, ``t_s``, ``velocity_m_s`` and, with a body,
    ``body_velocity_m_s``), written as the text ``contact_events`` (JSON) with
    the counts ``events``, ``floor_contacts`` and ``body_contacts`` as field data.
    """
    ball = result.system.ball
    points = np.asarray(mesh.points, dtype=float)
    normal = points / np.linalg.norm(points, axis=1, keepdims=True)
    phi = np.arccos(np.clip(normal[:, 2], -1.0, 1.0))
    z, a, force = _states(result, times_s, case)
    # the deformation (radial and meridional; the translation's columns are 0) at the nodes
    u = a @ ball.modes_at(phi).T  # (F, P), units R
    w = a @ ball.tangential_at(phi).T
    meridian = _meridian(normal)
    radius = case.radius
    lift = (z - 1.0)[:, None, None] * np.array([0.0, 0.0, 1.0])[None, None, :]
    moved = u[:, :, None] * normal[None, :, :] + w[:, :, None] * meridian[None, :, :]
    displacement = (lift + moved) * radius
    height = (z[:, None] + normal[None, :, 2] + moved[:, :, 2]) * radius
    force_unit = mass * radius * case.wave_speed**2
    numbers = {
        "contact_time_s": np.nan
        if result.contact_time is None
        else result.contact_time / case.wave_speed,
        "e2": np.nan if result.e2 is None else result.e2,
        "phi_a_max_rad": result.phi_a_max,
    }
    texts = {"case": text, "mesh": json.dumps({"label": ball.label})}
    body = result.system.body
    if body is not None and result.body is not None:
        b, v0 = result.body, result.settings.v0
        numbers |= {
            "mass_ratio": body.mass,
            "gap_m": body.gap * radius,
            "cap_angle_rad": body.cap_angle,
            "v1_ratio": np.nan if b.v1 is None else b.v1 / v0,
            "v2_ratio": np.nan if b.v2 is None else b.v2 / v0,
            "t_liftoff_s": np.nan if b.t_liftoff is None else b.t_liftoff / case.wave_speed,
        }
        texts["body"] = json.dumps({"restitution": body.restitution, "sequence": b.sequence})
    if events is not None:
        texts["contact_events"] = json.dumps(events)
        numbers["events"] = float(len(events))
        for contact in ("floor", "body"):
            touches = [e for e in events if e.get("contact", "floor") == contact]
            if contact == "floor" or body is not None:
                numbers[f"{contact}_contacts"] = float(
                    sum(1 for e in touches if e["kind"] == "touch")
                )
    return TimeSeries(
        points * radius,
        mesh.cells,
        np.asarray(times_s, dtype=float),
        {"u_m": u * radius, "displacement_m": displacement, "height_m": height},
        numbers,
        texts,
        {
            "Z_m": z * radius,
            "floor_force_N": force * force_unit,
            **body_frames(result, times_s, case, mass),
        },
    )


@dataclass(frozen=True)
class DropScene(BallScene):
    """A picture of the drop: the membrane's flattening in the centre's frame (SI).

    ``u`` is the radial displacement from the centre, ``body`` the top's, and
    ``t_liftoff`` the separation from the floor; ``floor_force`` (F,) [N] and
    ``centre`` (F,) the centre's height above R [m] go into the caption; the
    floor is drawn at :meth:`floor_level`.
    """

    floor_force: np.ndarray = None  # type: ignore[assignment]
    centre: np.ndarray = None  # type: ignore[assignment]
    body_force: np.ndarray | None = None
    t_body: float | None = None

    def caption(self, k: int, warp: float) -> str:
        """Short lines: time, the floor's force (or "left"), the centre's height, the body's
        force (or "lifted off"), warp."""
        t = float(self.times[k])
        left = self.t_liftoff is not None and t >= self.t_liftoff
        floor = "left" if left else f"{self.floor_force[k]:.0f} N"
        text = f"t = {t * 1e3:.2f} ms\nfloor: {floor}\nZ - R: {self.centre[k] * 1e3:+.1f} mm"
        if self.body_force is not None:
            lifted = self.t_body is not None and t >= self.t_body
            body = "lifted off" if lifted else f"{self.body_force[k]:.0f} N"
            text += f"\nbody: {body}"
        return text + (f"\nwarp x{warp:.3g}" if warp != 1.0 else "")

    def floor_level(self, k: int, warp: float) -> float:
        """The floor in the centre's frame, magnified like the membrane: ``-R - warp (Z - R)``
        [m] (a floor point in contact has ``u = Z - R``, drawn at ``-R - warp u``)."""
        return -self.radius - warp * float(self.centre[k])


def drop_scene(
    result: DropResult, case: Case, mesh: SphereMesh, times_s: np.ndarray, mass: float, label: str
) -> Any:
    """What :func:`twoball.verify.output.render.render_scene` draws of the drop (SI)."""
    series = drop_series(result, case, mesh, times_s, mass, label)
    u = series.point_data["u_m"]
    top = int(np.argmax(np.asarray(mesh.points)[:, 2]))
    t_left = None if result.contact_time is None else result.contact_time / case.wave_speed
    frames = series.frame_data
    body, body_force, t_body = u[:, top], None, None
    if "body_height_m" in frames:  # the body's lowest point above the undeformed top
        body = frames["body_height_m"] - frames["Z_m"] - case.radius
        body_force = frames["body_force_N"]
        lift = None if result.body is None else result.body.t_liftoff
        t_body = None if lift is None else lift / case.wave_speed
    return DropScene(
        series.points,
        series.cells,
        series.times,
        u,
        body,
        case.radius,
        t_left,
        label,
        floor_force=frames["floor_force_N"],
        centre=frames["Z_m"] - case.radius,
        body_force=body_force,
        t_body=t_body,
        footer_chars=DROP_FOOTER_CHARS,
    )
