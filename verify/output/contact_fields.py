"""The membrane under a body of finite mass, for files, pictures and plots (issue 13).

With ``mass_ratio`` the field commands (``export``, ``render``, ``plot pole``)
draw the *coupled* motion: each backend's modes go through the contact solver of
:mod:`twoball.modal.contact` (eqs. (C1)-(C5) of docs/contact.rst), and the
membrane field is rebuilt from the solver's modal state,
``u(x, t) = sum_k q_k(t) phi_k(x)``, in closed form between the events
(:func:`twoball.modal.contact.states.modal_states`).  So the membrane feels the
contact force, and the body's height ``s(t)`` equals the cap average of that
same field while the body is on.

:class:`CoupledModel` is a :class:`~twoball.verify.output.fields.BallModel`
whose ``nodal`` and ``body_height`` are the coupled ones: the exports
(:func:`~twoball.verify.output.fields.field_series`) and the scenes
(:func:`~twoball.verify.output.fields.ball_scene`) work on it unchanged;
:func:`contact_series` adds the body's path and the events to an export.
Dimensionless inside, SI at the edges.
"""

from __future__ import annotations

import json
import os
from collections.abc import Sequence
from dataclasses import dataclass, field, replace
from typing import Any

import numpy as np
from twoball.modal.contact.report import (
    MAX_MASS_RATIO,
    check_contact_options,
    membrane_case,
)
from twoball.modal.contact.states import ModalStates, modal_states
from twoball.modal.parameters import Case
from twoball.verify.output.fields import Backend, BallModel, build_mesh, node_polar_angles
from twoball.verify.output.series import TimeSeries

from twoball._common.errors import ParameterError, refuse_given
from twoball._common.progress import Step, silent

#: Per-frame field data of an export with a body of finite mass (name: unit).
FRAME_FIELDS: dict[str, str] = {
    "s_m": "the body's height above the undeformed pole [m]",
    "s_t_m_s": "the body's velocity [m/s]",
    "contact": "1 while the body is on the membrane, 0 in flight",
}


@dataclass(frozen=True)
class ContactOptions:
    """The finite-mass options of a field command, checked (SI: ``contact_radius`` in m)."""

    mass_ratio: float
    contact_radius: float | None
    restitution: float
    energy: str

    def as_dict(self) -> dict[str, Any]:
        """For the provenance and the contact report's call."""
        return {
            "mass_ratio": self.mass_ratio,
            "contact_radius": self.contact_radius,
            "restitution": self.restitution,
            "energy": self.energy,
        }


def contact_options(
    case: Case,
    mass_ratio: float | None,
    contact_radius: float | None,
    restitution: float | None,
    energy: str | None,
    *,
    recontact: str | None = None,
    route: str = "auto",
) -> ContactOptions | None:
    """Check the finite-mass options of ``export``, ``render`` or ``plot pole``.

    None without ``mass_ratio`` (then the other three must be left out).  With
    it: the checks of :func:`~twoball.modal.contact.report.check_contact_options`
    (ranges; no bending or gas), ``mass_ratio > 0`` (0, the massless criteria,
    has no body to draw), the ``window`` re-contact horizon (events are
    simulated), a route giving every eigenpair (``auto`` or ``full``: the field
    is rebuilt from the modes).
    """
    if mass_ratio is None:
        refuse_given(
            "given only with mass_ratio",
            contact_radius=contact_radius,
            restitution=restitution,
            energy=energy,
        )
        return None
    restitution = 0.0 if restitution is None else restitution
    energy = "ball" if energy is None else energy
    check_contact_options(case, mass_ratio, contact_radius, restitution, energy)
    if mass_ratio == 0.0:
        valid = f"in (0, {MAX_MASS_RATIO:g}] for fields and plots (0 has no body to draw)"
        raise ParameterError("mass_ratio", valid, mass_ratio)
    if recontact not in (None, "window"):
        valid = "window with mass_ratio (events are simulated)"
        raise ParameterError("recontact", valid, recontact)
    if route not in ("auto", "full"):
        raise ParameterError("route", "auto or full with mass_ratio (every eigenpair)", route)
    return ContactOptions(float(mass_ratio), contact_radius, float(restitution), energy)


@dataclass(frozen=True)
class CoupledModel(BallModel):
    """A :class:`BallModel` whose fields are the membrane coupled to the body.

    Each backend's ``report`` is its :class:`~twoball.modal.contact.report.ContactReport`
    (``system`` and ``history`` of the contact solver), ``shapes`` its modes at
    the mesh nodes, one row per mode of ``report.system``.
    """

    _states: dict = field(default_factory=dict, init=False, compare=False, repr=False)

    def contact(self, name: str) -> Any:
        """The contact report of backend ``name``."""
        return self.backend(name).report

    def states(self, name: str, times_s: np.ndarray) -> ModalStates:
        """Modal state of backend ``name`` at ``times_s`` [s] (dimensionless values).

        Computed once per backend and times (matrix exponentials are the cost of an
        export: measured 21 of 24 s at level 2 before this was kept).
        """
        t = np.atleast_1d(np.asarray(times_s, dtype=float)) / self.case.scalings.time
        key = (name, t.tobytes())  # u, u_t, u_tt, the body and the caption share one solve
        if key not in self._states:
            report = self.contact(name)
            self._states[key] = modal_states(report.system, report.history, t)
        return self._states[key]

    def nodal(self, name: str, times_s: np.ndarray, derivative: int = 0) -> np.ndarray:
        """Coupled u [m], u_t [m/s] or u_tt [m/s^2] at the nodes, shape (T, P).

        ``u = sum_k q_k phi_k`` with ``q`` from the contact solver: eq. (C1) with
        the contact force while the body is on.
        """
        scale = self.case.scalings
        unit = (scale.length, scale.velocity, scale.acceleration)[derivative]
        modal = self.states(name, times_s).modal(derivative)
        return modal @ self.backend(name).shapes * unit

    def body_height(self, name: str, times_s: np.ndarray) -> np.ndarray:
        """The body's height s [m] above the undeformed pole (the contact solution)."""
        return self.states(name, times_s).body_height * self.case.scalings.length

    def motion(self, name: str, times_s: np.ndarray) -> dict[str, np.ndarray]:
        """Cap-averaged membrane and body at ``times_s`` [s], in SI.

        Keys: ``cap_m``, ``cap_t_m_s``, ``cap_tt_m_s2`` (``b . q`` and its
        derivatives, the cap average of eq. (C3)), ``s_m``, ``s_t_m_s``,
        ``s_tt_m_s2`` (the body), ``contact`` (bool).
        """
        scale = self.case.scalings
        states = self.states(name, times_s)
        b = self.contact(name).system.contact
        return {
            "cap_m": states.modal(0) @ b * scale.length,
            "cap_t_m_s": states.modal(1) @ b * scale.velocity,
            "cap_tt_m_s2": states.modal(2) @ b * scale.acceleration,
            "s_m": states.body_height * scale.length,
            "s_t_m_s": states.body_velocity * scale.velocity,
            "s_tt_m_s2": states.body_acceleration * scale.acceleration,
            "contact": states.contact,
        }


def coupled_model(
    case: Case,
    backends: Sequence[str],
    options: ContactOptions,
    *,
    mesh: str = "sphere",
    level: int = 3,
    order: int = 2,
    initial: str = "projection",
    sigma: str = "lanczos",
    t_end_s: float | None = None,
    progress: Step | None = None,
) -> CoupledModel:
    """Solve the contact problem with ``backends`` and put their modes on one sphere mesh.

    ``fem``: :func:`twoball.fem_membrane.contact_fields.fem_contact_fields` (full
    eigen route on the mesh of ``mesh``/``level``/``order``); its nodes carry
    the fields.  ``legendre``: :func:`twoball.modal.contact.report.legendre_contact`
    with ``P_n(cos phi)`` at the same nodes (or at the generated mesh's nodes).
    """
    from twoball.modal.contact.report import legendre_contact
    from twoball.modal.filters import SpectralFilter
    from twoball.modal.legendre import legendre_series, legendre_shapes
    from twoball.modal.report import t_end_dimensionless

    t_end = t_end_dimensionless(case, t_end_s)
    say = progress or silent
    solved: dict[str, Backend] = {}
    mu = options.mass_ratio
    common = {
        "sigma": sigma,
        "restitution": options.restitution,
        "energy": options.energy,
        "t_end_s": t_end_s,
    }
    if "fem" in backends:
        from twoball.fem_membrane.contact_fields import fem_contact_fields

        say(f"contact of a body of mass ratio {mu:g} on the finite elements")
        nodes, shapes, series, report = fem_contact_fields(
            case, mu, options.contact_radius, **common, mesh=mesh, level=level, order=order,
            initial=initial,
        )  # fmt: skip
        details = {k: float(v) for k, v in report.extra.items() if isinstance(v, (int, float))}
        solved["fem"] = Backend("fem", series, shapes, report, details)
    else:
        nodes = build_mesh(membrane_case(case, mu, options.energy), level, order, mesh)
    if "legendre" in backends:
        say(f"contact of a body of mass ratio {mu:g} on the closed form")
        report = legendre_contact(case, mu, options.contact_radius, **common)
        membrane = report.membrane or case
        series = legendre_series(membrane.phi_a, case.damping, SpectralFilter(sigma, case.modes))
        shapes = legendre_shapes(node_polar_angles(nodes), case.modes)
        solved["legendre"] = Backend("legendre", series, shapes, report, {"modes": case.modes})
    return CoupledModel(case, nodes, solved, t_end, sigma, "window")


def contact_series(series: TimeSeries, model: CoupledModel, backend: str) -> TimeSeries:
    """``series`` with the body's path of ``backend`` and its events (SI).

    Frame data (:data:`FRAME_FIELDS`): ``s_m`` [m], ``s_t_m_s`` [m/s],
    ``contact`` (1 or 0).  Field data: ``mass_ratio``, ``contact_radius_m`` [m],
    ``restitution``, ``impacts``, ``events``.  Texts ``upper_body`` (the options and
    the frame data's units) and ``contact_events``: the JSON
    list of :meth:`~twoball.modal.contact.report.ContactReport.events_si`
    (``kind``, ``t_s``, ``height_m``, ``velocity_m_s``, ``impulse_N_s`` and
    ``energy_loss_J`` per kg of membrane mass).
    """
    report = model.contact(backend)
    motion = model.motion(backend, series.times)
    frame_data = {
        "s_m": motion["s_m"],
        "s_t_m_s": motion["s_t_m_s"],
        "contact": motion["contact"].astype(float),
    }
    field_data = {
        **series.field_data,
        "mass_ratio": report.mass_ratio,
        "contact_radius_m": report.contact_radius_m,
        "restitution": report.restitution,
        "impacts": float(len(report.history.impacts)),
        "events": float(len(report.history.events)),
    }
    described = "; ".join(f"{name}: {text}" for name, text in FRAME_FIELDS.items())
    text = {
        **series.text,
        "contact_events": json.dumps(report.events_si()),
        "upper_body": (
            f"upper body of mass ratio {report.mass_ratio:g} ({backend}), contact radius "
            f"{report.contact_radius_m:g} m, restitution {report.restitution:g}, energy "
            f"{report.energy}; the membrane is coupled to it (docs/contact.rst); per frame "
            f"{described}; contact_events: JSON list of the events (SI)"
        ),
    }
    return replace(series, field_data=field_data, text=text, frame_data=frame_data)


def contact_scene(model: CoupledModel, times_s: np.ndarray, backend: str) -> Any:
    """The scene of :func:`~twoball.verify.output.fields.ball_scene` with the body's contact.

    The membrane is the coupled field, the body at its height ``s(t)``; the
    caption marks the frames in contact (:class:`twoball.verify.output.render.ContactScene`).
    """
    from twoball.verify.output.fields import ball_scene
    from twoball.verify.output.render import ContactScene

    scene = ball_scene(model, times_s, backend)
    report = model.contact(backend)
    impacts = [e["t_s"] for e in report.events_si() if e["kind"] == "impact"]
    return ContactScene(
        scene.points, scene.cells, scene.times, scene.u, scene.body, scene.radius,
        scene.t_liftoff, f"{scene.label}, mu = {report.mass_ratio:g}",
        contact=model.states(backend, scene.times).contact, impacts=np.array(impacts),
        mass_ratio=report.mass_ratio,
    )  # fmt: skip


def plot_contact(
    kind: str,
    case: Case | None,
    mass_ratio: float | None,
    contact_radius: float | None,
    restitution: float | None,
    energy: str | None,
    *,
    recontact: str | None,
    route: str,
) -> ContactOptions | None:
    """The finite-mass options of ``twoball.plot``: ``pole`` only, else refused."""
    if kind != "pole":
        refuse_given(
            f"left out with kind {kind} (pole only)",
            mass_ratio=mass_ratio,
            contact_radius=contact_radius,
            restitution=restitution,
            energy=energy,
        )
        return None
    case = Case.preset("basketball") if case is None else case
    return contact_options(
        case, mass_ratio, contact_radius, restitution, energy, recontact=recontact, route=route
    )


def model_of(
    case: Case,
    backends: Sequence[str],
    contact: ContactOptions | None,
    field_mesh: Any,
    **options: Any,
) -> BallModel:
    """:func:`twoball.verify.output.fields.ball_model_of` without a body; the coupled model with one.

    ``field_mesh`` is the :class:`twoball.verify.output.fields.FieldMesh` of the options;
    ``options`` are those of ``ball_model_of`` (initial, sigma, recontact,
    t_end, progress, route), checked the same way.  A body of finite mass is
    solved on generated meshes (icosphere or ring, isoparametric); a mesh file or
    the exact geometry with it is refused.
    """
    from twoball.fem_membrane.options import FILE
    from twoball.modal.report import t_end_dimensionless
    from twoball.verify.output.fields import ball_model_of, check_initial

    if contact is None:
        return ball_model_of(case, backends, field_mesh, **options)
    spec = field_mesh.spec
    if spec.kind == FILE:
        valid = "a generated mesh (sphere or ring) with mass_ratio, not a mesh file"
        path = isinstance(spec.source, str | os.PathLike)
        raise ParameterError("mesh", valid, os.fspath(spec.source) if path else "a mesh object")
    if spec.geometry != "isoparametric":
        raise ParameterError("geometry", "isoparametric with mass_ratio", spec.geometry)
    initial = check_initial(options.get("initial"), backends)
    t_end_dimensionless(case, options.get("t_end"))  # checked before any progress line
    return coupled_model(
        case, backends, contact, mesh=spec.kind, level=spec.level, order=spec.order,
        initial=initial, sigma=options.get("sigma", "lanczos"), t_end_s=options.get("t_end"),
        progress=options.get("progress"),
    )  # fmt: skip
