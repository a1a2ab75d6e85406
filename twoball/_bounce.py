"""``twoball.bounce``: one drop of the lower ball on a rigid floor, alone or with a body, in SI.

The command line (``twoball bounce``) calls exactly this function, so the same
inputs give bit-identical numbers in Python and in a shell.  The model and its
run live below the face (:mod:`twoball.modal.floor.bounce`: the problem
resolved, then simulated and reported in SI); here are the verb, its refusal
before work (the budget), the monitor that watches the run (time limit,
interrupts, progress) and the report's files (figure, fields, pictures).
docs/bounce.rst and docs/whole_bounce.rst explain the model.
"""

from __future__ import annotations

import os
from dataclasses import dataclass, replace
from pathlib import Path
from typing import Any

from twoball._common.errors import ParameterError
from twoball._common.keywords import checked
from twoball._common.staging import check_path_type
from twoball.modal.floor.bounce import CAVEATS, OVERLAP_NOTE
from twoball.modal.floor.options import Drop
from twoball.modal.floor.report import BounceReport as Numbers
from twoball.modal.parameters import Case

__all__ = [
    "CAVEATS",
    "OVERLAP_NOTE",
    "BounceReport",
    "bounce",
    "check_field_targets",
]


@checked
def bounce(
    case: Case | None = None,
    drop: Drop | None = None,
    *,
    solver: Any = None,
    body: Any = None,
    pair: str | None = None,
    damping: Any = None,
) -> BounceReport:
    """Drop the lower ball on a rigid floor, alone or with a body on top, in SI.

    The ball starts undeformed, its lowest point touching the floor, its centre
    falling at ``|v0|``; its centre of mass carries the translation (mass m2,
    gravity), its modes the deformation, and the floor holds every point of the
    lower hemisphere at height >= 0 (docs/bounce.rst, eqs. (F1)-(F3)).  With an
    upper body (the whole two-ball bounce, docs/whole_bounce.rst, eqs.
    (B1)-(B2)) a rigid body of mass ``mu m2`` starts ``drop.gap`` above the
    ball's top, falling at the same speed, and touches the top over a cap of
    radius a with Newton's e12.  The run ends when everything has moved apart
    for good, or at the window.

    Parameters
    ----------
    case : Case, optional
        The ball and its impact speed ``|v0|`` (default the basketball preset,
        or the pair's lower ball).  Its excess pressure P (the preset's
        measured one when the case has none) sets the membrane's mass ``m2 = 2 pi
        R P / c^2`` and the gas.
    drop : Drop, optional
        Drop height, gas, floor restitution, membrane operator, gap Delta x [m]
        (:class:`~twoball.Drop`; default: the case's ``|v0|``, its gas or else the
        adiabatic gas, e = 0, the pressurised operator, touching).
    solver : MoreauJean, optional
        The nonsmooth steps and the ball they step (:class:`~twoball.MoreauJean`:
        ``ball`` :class:`~twoball.LegendreBall` (default, N = 192),
        :class:`~twoball.FEBall` (the axisymmetric line, 96 P2 elements) or any
        :class:`~twoball.Ball`; ``dt`` [s], default 0.005 / c; ``t_end`` [s],
        default 10 pi / c plus twice the gap's closing time ``Delta x / |v0|``).
    body : Body, LumpedBody, BallBody or str, optional
        The upper body: rigid (:class:`~twoball.Body`: ``mass_ratio`` mu in (0,
        100], ``contact_radius`` a [m] (default R / 10), ``restitution`` e12,
        Newton's at its impacts), lumped elastic (:class:`~twoball.LumpedBody`:
        mu and its own contact law) or a second ball (:class:`~twoball.BallBody`);
        with ``pair``, a kind name (``"rigid"``, ``"lumped"``, ``"ball"``) takes the
        pair's preset body of that kind (docs/bodies.rst).
    pair : str, optional
        A Table 1 pair (``"basketball-tennis"``, ...; :data:`twoball.modal.pairs.PAIRS`):
        the lower ball's preset, mu, e12 and a; refused with a body object.
    damping : ModalRatio or Rayleigh, optional
        The damping law (default the case's own: its ratio D on every mode, eq.
        (3.14), or its ``rayleigh``); ``Rayleigh()`` is fitted to D as
        :attr:`twoball.Case.damping_law` fits it; Rayleigh's alpha [1/s] and
        beta [s] are SI.

    Returns
    -------
    BounceReport
        ``contact_time_s``, ``v2_m_s``, ``e2``, ``phi_a_max_rad``,
        ``flattening_max_m``, ``t_max_compression_s``, ``floor_impulse_N_s``,
        ``events``, ``energy_J``, ``warnings``; with a body also ``v1_m_s``,
        ``v1_ratio``, ``v2_ratio``, ``t_liftoff_s``, ``body_left_first``,
        ``e12_effective`` and the lumped baselines; ``as_dict()`` for JSON.

    Examples
    --------
    >>> import twoball
    >>> report = twoball.bounce(solver=twoball.MoreauJean(twoball.LegendreBall(16)))
    >>> round(report.contact_time_s * 1e3, 1), round(report.e2, 2)
    (16.3, 0.87)
    >>> weight = report.mass_kg * 9.81 * report.contact_time_s  # the impulse balance
    >>> change = report.mass_kg * (report.v2_m_s + 4.1)
    >>> abs(report.floor_impulse_N_s - change - weight) < 1e-12
    True
    >>> solver = twoball.MoreauJean(twoball.LegendreBall(24))
    >>> whole = twoball.bounce(solver=solver, pair="basketball-tennis")
    >>> round(whole.v1_ratio, 1), whole.body_left_first
    (1.4, True)
    """
    from twoball._solvers import MoreauJean
    from twoball.modal.floor.bounce import bounce_problem, simulate

    if solver is None:
        solver = MoreauJean()
    elif not isinstance(solver, MoreauJean):
        raise ParameterError("solver", "a twoball.MoreauJean (the drop's steps)", solver)
    if solver.sigma is not None:
        valid = "left out for the drop (it starts undeformed: nothing to filter)"
        raise ParameterError("sigma", valid, solver.sigma)
    _check_options(body, damping)
    problem = bounce_problem(
        case,
        drop,
        ball=solver.ball,
        body=body,
        pair=pair,
        dt=solver.dt,
        t_end=solver.t_end,
        damping=damping,
    )
    from twoball._costs import check_bounce_cost

    check_bounce_cost(problem)
    from twoball._common.watch import Watch

    numbers = simulate(problem, Watch())
    arguments: dict[str, Any] = {"drop": problem.drop.as_dict(), "solver": solver.as_dict()}
    if body is not None:
        arguments["body"] = body if isinstance(body, str) else body.as_dict()
    if damping is not None:
        arguments["damping"] = damping.as_dict()
    if pair is not None:
        arguments["pair"] = pair
    from twoball._common.provenance import block

    report = BounceReport(**{f: getattr(numbers, f) for f in _FIELDS})
    return replace(report, provenance=block(problem.case, "twoball.bounce", arguments))


def _check_options(body: Any, damping: Any) -> None:
    """The types of the body and the damping law (the rest is checked below the face)."""
    from twoball.modal.contact.body import Body
    from twoball.modal.damping import ModalRatio, Rayleigh
    from twoball.modal.upper.options import BODY_KINDS, BallBody, LumpedBody

    if isinstance(body, str):  # a kind: the pair's preset body (checked with the pair)
        if body not in BODY_KINDS:
            raise ParameterError("body", "a body object or one of " + ", ".join(BODY_KINDS), body)
    elif body is not None and not isinstance(body, (Body, LumpedBody, BallBody)):
        valid = "a twoball.Body, LumpedBody or BallBody (or a kind with pair)"
        raise ParameterError("body", valid, type(body).__name__)
    if damping is not None and not isinstance(damping, (ModalRatio, Rayleigh)):
        raise ParameterError("damping", "a twoball.ModalRatio or twoball.Rayleigh", damping)


def check_field_targets(
    export: str | os.PathLike[str] | None,
    render: str | os.PathLike[str] | None,
    frames: int | None,
) -> tuple[Path | None, Path | None, int]:
    """The files of ``twoball bounce --export/--render`` checked before any work.

    Returns the export path (``.xdmf``, ``.pvd`` or one ``.vtu`` frame), the
    picture path (``.png``, ``.gif``, ``.mp4``) and the number of instants
    (default 40; 1 for a ``.vtu``).  Refuses a folder, a link, an existing
    side file twoball did not write, an unknown suffix, and ``frames`` without
    a file; a picture whose drawing cannot fit the budget (time, memory).
    """
    from twoball._common.staging import check_file, check_path_type
    from twoball.verify.output.fields import check_frames
    from twoball.verify.output.render import image_kind
    from twoball.verify.output.series import check_side_entries, series_format

    count = check_frames(frames) if frames is not None else 40
    target = picture = None
    if export is not None:
        check_path_type(export, "export")
        try:
            fmt = series_format(export, None)
        except ParameterError as error:  # named after the API's "out"
            raise ParameterError("export", error.valid, os.fspath(export)) from None
        target = check_file(export, "export")
        check_side_entries(target, fmt, "export")
        if fmt == "vtu":
            if frames not in (None, 1):
                raise ParameterError("frames", "1 for a single .vtu file", frames)
            count = 1
    if render is not None:
        check_path_type(render, "render")
        kind = image_kind(render, "render")
        picture = check_file(render, "render")
        from twoball._fields import check_render_budget
        from twoball.verify.output.render import DEFAULT_SIZE

        check_render_budget(1 if kind == ".png" else count, DEFAULT_SIZE, kind)  # its drawing
    if frames is not None and target is None and picture is None:
        raise ParameterError("frames", "given with export or render", frames)
    return target, picture, count


@checked
@dataclass(frozen=True)
class BounceReport(Numbers):
    """One drop of the lower ball on the floor, in SI, with its files.

    The numbers are those of :class:`twoball.modal.floor.report.BounceReport`
    (``contact_time_s``, ``v2_m_s``, ``e2``, ..., ``as_dict()``); here are the
    figure (:meth:`plot`), the fields on a sphere mesh (:meth:`export`) and the
    pictures (:meth:`render`).

    Examples
    --------
    >>> import tempfile, pathlib, twoball
    >>> report = twoball.bounce(solver=twoball.MoreauJean(twoball.LegendreBall(16)))
    >>> report.left_floor, 0.8 < report.e2 < 1.0
    (True, True)
    >>> folder = pathlib.Path(tempfile.mkdtemp())
    >>> report.plot(folder / "drop.svg").name
    'drop.svg'
    >>> [p.name for p in report.export(folder / "drop.xdmf", frames=3)]
    ['drop.xdmf', 'drop.h5']
    """

    # --- files ------------------------------------------------------------------------
    @checked
    def plot(
        self, out: str | os.PathLike[str], *, dpi: float | None = None, measured: Any = None
    ) -> Path:
        """Figure of the drop: floor force, contact angle, centre height, energy books.

        With a body (the whole bounce): heights, both contact forces, both
        velocities (with the ICM's of :attr:`icm_solver`), the energy books, every
        event marked.  ``out``'s suffix chooses the format (``.png``, ``.pdf``, ...).
        ``measured`` (a CSV path or a mapping of columns, as :func:`twoball.fit`
        reads them): the rows at this drop's ``|v0|`` (and gap) drawn over it,
        v1 and v2 on the velocities, the lift-off time, phi_a on the contact angle.
        """
        from twoball.verify.output.figures import figure_format, save_figure
        from twoball.verify.output.figures.bounce import drop_figure, whole_figure

        figure_format(Path(check_path_type(out)), "out")  # before the figure is drawn
        self._require_history()
        title = f"{self._subject}; {self.backend}, {self._physics}"
        if self.has_body:
            icm = self.icm_solver
            lines = None if icm is None else (icm["v1_m_s"], icm["v2_m_s"])
            figure = whole_figure(self.result, self.case, self.mass_kg, title, lines)
        else:
            figure = drop_figure(self.result, self.case, self.mass_kg, title)
        if measured is not None:
            from twoball._fit import read_measured
            from twoball.verify.output.figures.measured import draw_overlay, overlay_for

            draw_overlay(figure, overlay_for(self, read_measured(measured, "measured")))
        return save_figure(figure, out, "plot", dpi)

    def _require_history(self) -> None:
        """Refuse a light report (a sweep point): a usage error, not a numerical one."""
        if not self.result.has_history:
            raise ParameterError(
                "report",
                "one of twoball.bounce with its history for a figure, fields or pictures "
                "(a sweep point keeps none: run twoball.bounce at its value)",
                "a light report",
            )

    def _mesh_and_times(self, mesh: Any, frames: int) -> tuple[Any, Any]:
        from twoball.fem_membrane.mesh import sphere_mesh
        from twoball.fem_membrane.options import MeshOptions
        from twoball.verify.output.drop_fields import drop_frames
        from twoball.verify.output.fields import check_frames

        self._require_history()
        spec = MeshOptions.of(mesh).require(("sphere",), files=False)
        if spec.order > 2:
            raise ParameterError("order", "1 or 2 for field files and pictures", spec.order)
        count = check_frames(frames)
        return sphere_mesh(spec.level, spec.order, None), drop_frames(self.result, count, self.case)

    @checked
    def export(
        self,
        out: str | os.PathLike[str],
        *,
        mesh: Any = None,
        frames: int = 40,
        format: str | None = None,
        view: str = "surface",
    ) -> list[Path]:
        """Write the drop on a sphere mesh: XDMF (+ HDF5), PVD (+ VTUs) or one VTU frame.

        Point data ``u_m``, ``displacement_m`` (the centre's fall and the
        membrane's flattening: warp by it), ``height_m``; frame data ``Z_m``,
        ``floor_force_N`` (with a body ``body_height_m``, ``body_gap_m``,
        ``body_force_N``); field data the results and the events of both
        contacts (the text ``contact_events``, JSON of :attr:`events`, and their
        counts); every field in SI (:mod:`twoball.verify.output.drop_fields`).
        ``mesh``: a sphere (default the level-3 P2 icosphere); ``frames``
        instants from the first touch to the end of the run.  ``view="cut"`` (a
        ball with a volume: solid, thick): the meridian plane through the volume
        instead of the surface, with the wave's ``speed_m_s``
        (:mod:`twoball.verify.output.solid_cut`).
        """
        import json

        from twoball.verify.output.drop_fields import drop_series
        from twoball.verify.output.series import write_series

        check_path_type(out)
        sphere, times = self._mesh_and_times(mesh, frames)
        if _view(view, mesh) == "cut":
            from twoball.verify.output.solid_cut import cut_series

            series = cut_series(self.result, self.case, times, self.mass_kg, self._text)
        else:
            series = drop_series(
                self.result, self.case, sphere, times, self.mass_kg, self._text, self.events
            )
        if self.provenance is not None:
            series = replace(
                series, text={**series.text, "provenance": json.dumps(self.provenance)}
            )
        return write_series(out, series, format)

    @checked
    def render(
        self,
        out: str | os.PathLike[str],
        *,
        mesh: Any = None,
        frames: int = 40,
        warp: float | None = None,
        size: Any = None,
        fps: float = 20.0,
        view: str = "surface",
    ) -> Path:
        """Picture (``.png``: the largest compression) or animation (``.gif``, ``.mp4``).

        The membrane's displacement from the centre, coloured, in the centre's
        frame: the bottom flattens on the floor and springs back; the caption
        gives the time, the floor force, the centre's height above R and
        whether the ball is on the floor.  ``view="cut"``: the meridian plane through
        a ball with a volume, coloured by the displacement along the radius (the
        compression wave inside).
        """
        from twoball._common.watch import Watch
        from twoball._fields import check_render_budget
        from twoball.verify.output.drop_fields import drop_scene
        from twoball.verify.output.render import DEFAULT_SIZE, image_kind, render_scene

        check_path_type(out)
        kind = image_kind(out, "render")
        check_render_budget(1 if kind == ".png" else frames, size or DEFAULT_SIZE, kind)
        sphere, times = self._mesh_and_times(mesh, frames)
        if Path(out).suffix.lower() == ".png":  # one picture: the largest compression
            times = times[:1] * 0.0 + self.t_max_compression_s
        if _view(view, mesh) == "cut":
            from twoball.verify.output.solid_cut import cut_scene

            scene = cut_scene(self.result, self.case, times, self.mass_kg, self._text)
        else:
            scene = drop_scene(self.result, self.case, sphere, times, self.mass_kg, self._text)
        size = size or DEFAULT_SIZE
        return render_scene(out, scene, warp=warp, size=size, fps=fps, monitor=Watch())

    @property
    def _subject(self) -> str:
        """What was dropped, for titles: the Table 1 pair, the lower ball's preset or
        ``custom ball``."""
        arguments = ((self.provenance or {}).get("call") or {}).get("arguments") or {}
        if arguments.get("pair"):
            return str(arguments["pair"])
        return self.case.preset_name or "custom ball"

    @property
    def _physics(self) -> str:
        """``pressurised membrane`` (the operator), or the ball's kind."""
        operator = self.model.get("membrane")
        return f"{operator} membrane" if operator else str(self.model.get("ball", "ball"))

    @property
    def _text(self) -> str:
        c = self.case
        return (
            f"twoball bounce, {self.model['resolution']}: R = {c.radius:g} m, "
            f"c = {c.wave_speed:g} 1/s, v0 = {c.v0:g} m/s, {self._physics}, "
            f"{self.model['gas']} gas"
        )


def _view(view: object, mesh: Any) -> str:
    """``surface`` or ``cut`` (the volume's meridian plane: no sphere mesh to give)."""
    if view not in ("surface", "cut"):
        raise ParameterError("view", "surface or cut", view)
    if view == "cut" and mesh is not None:
        raise ParameterError("mesh", "left out with view cut (the ball's own plane)", mesh)
    return str(view)


_FIELDS = tuple(f for f in Numbers.__dataclass_fields__)
