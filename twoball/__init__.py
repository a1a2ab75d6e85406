"""twoball -- the two-ball bounce from first principles: a vibrating ball and a body on it.

The public API is loaded lazily: ``import twoball`` costs almost nothing, and
each name below imports its module on first use::

    import twoball

    case = twoball.Case.preset("basketball", v0=3.0)   # SI; phi_a by eq. (3.7)
    result = twoball.liftoff(case)                      # closed form (Legendre series)
    fe = twoball.liftoff(case, solver=twoball.Superposition("axisym"))
    drop = twoball.bounce(case, solver=twoball.MoreauJean(twoball.FEBall()))
    print(result.t_liftoff_s, result.v_liftoff_m_s, result.case.phi_a_source)

Public names (``twoball.__all__``): the verbs :func:`liftoff`, :func:`bounce`
(the lower ball dropped on the floor, alone or with a body), :func:`sweep`,
:func:`fit` (model parameters fitted to measured rows), :func:`export`,
:func:`render`, :func:`plot`, :func:`converge`, :func:`check`
(every backend against the closed form), :func:`reproduce`, :func:`icm`,
:func:`table1`, :func:`report`, ``fem.eigen``; the solvers :class:`ClosedForm`,
:class:`Superposition`, :class:`GeneralizedAlpha`, :class:`MoreauJean`; the
balls :class:`Ball` (the protocol), :class:`LegendreBall`, :class:`FEBall`, the shell's
:class:`ShellBall` and :class:`FEShellBall` with its :class:`Wall`, the solid's
:class:`SolidBall` and :class:`FESolidBall` with its :class:`SolidMaterial`, the
thick wall's :class:`ThickBall` with its :class:`ThickWall`; the
case and the option and model objects :class:`Case`, :class:`MeshOptions`,
:class:`Body`, :class:`LumpedBody`, :class:`BallBody`, :class:`ContactLaw` (the upper
body: rigid, lumped elastic, a second ball; :func:`body_preset`, :func:`floor_alone`),
:class:`Membrane`, :class:`ModalRatio`, :class:`Rayleigh`,
:class:`Drop`, :class:`RenderOptions`, :class:`PlotOptions`; the results;
:class:`Reporter` (progress), :class:`ParameterError`, :class:`NumericalError`,
``__version__``.  The command line ``twoball`` is a thin layer over these.
"""

from __future__ import annotations

import importlib as _importlib
import os as _os

from twoball._common.lazy import attach as _attach
from twoball._version import __version__

# In a source checkout the parts (modal/, fem_membrane/, verify/) sit beside this
# folder; installed, setuptools maps them to twoball/modal, ... (pyproject.toml).
_HERE = _os.path.dirname(__file__)
if not _os.path.isdir(_os.path.join(_HERE, "modal")):
    __path__.append(_os.path.dirname(_HERE))  # noqa: F821 -- the package's own __path__

_NAMES: dict[str, str | tuple[str, str]] = {
    "Case": "twoball.modal.parameters",
    "LiftoffReport": "twoball.modal.report",
    "ParameterError": "twoball._common.errors",
    "NumericalError": "twoball._common.errors",
    "MeshOptions": "twoball.fem_membrane.options",
    "Body": "twoball.modal.contact.body",
    "LumpedBody": "twoball.modal.upper.options",
    "BallBody": "twoball.modal.upper.options",
    "ContactLaw": "twoball.modal.upper.laws",
    "body_preset": ("twoball.modal.bodies", "preset_body"),
    "floor_alone": "twoball._bodies",
    "AloneResult": "twoball.modal.upper.alone",
    "ModalRatio": "twoball.modal.damping",
    "Rayleigh": "twoball.modal.damping",
    "Membrane": "twoball.modal.membrane",
    "RenderOptions": "twoball.verify.output.options",
    "PlotOptions": "twoball.verify.output.options",
    "ContactReport": "twoball.modal.contact.report",
    "liftoff": "twoball._liftoff",
    "bounce": "twoball._bounce",
    "Drop": "twoball.modal.floor.options",
    "Ball": "twoball.modal.balls.protocol",
    "ModalBall": "twoball.modal.balls.description",
    "LegendreBall": "twoball.modal.balls.membrane",
    "FEBall": "twoball.fem_membrane.ball",
    "Wall": "twoball.modal.balls.shell",
    "ShellBall": "twoball.modal.balls.shell",
    "FEShellBall": "twoball.fem_shell.ball",
    "SolidMaterial": "twoball.modal.balls.solid",
    "SolidBall": "twoball.modal.balls.solid",
    "FESolidBall": "twoball.fem_solid.ball",
    "ThickBall": "twoball.fem_solid.ball",
    "ThickWall": "twoball.fem_solid.ball",
    "drop_elements": "twoball.fem_membrane.ball",
    "ClosedForm": "twoball._solvers",
    "Superposition": "twoball._solvers",
    "GeneralizedAlpha": "twoball._solvers",
    "MoreauJean": "twoball._solvers",
    "BounceReport": "twoball._bounce",
    "BounceSweep": "twoball.verify.sweeps.bounce",
    "sweep": "twoball._sweep",
    "SweepResult": "twoball._sweep",
    "fit": "twoball._fit",
    "FitResult": "twoball.verify.fit.result",
    "converge": "twoball._studies",
    "check": "twoball._studies",
    "export": "twoball._fields",
    "render": "twoball._fields",
    "plot": "twoball._plot",
    "ExportResult": "twoball.verify.output.results",
    "RenderResult": "twoball.verify.output.results",
    "PlotResult": "twoball.verify.output.results",
    "icm": ("twoball.modal.icm.model", "icm"),
    "ICMResult": "twoball.modal.icm.model",
    "table1": ("twoball.modal.icm.table1", "table1_check"),
    "reproduce": "twoball._reproduce",
    "Reproduction": "twoball._reproduce",
    "report": "twoball._common.provenance",
    "Report": "twoball._common.provenance",
    "Reporter": "twoball._common.progress",
}
_getattr, _dir = _attach(__name__, _NAMES)


def __getattr__(name: str) -> object:
    if name == "fem":
        return _importlib.import_module("twoball.fem")
    return _getattr(name)


def __dir__() -> list[str]:
    return sorted([*_dir(), "fem", "__version__"])


__all__ = ["__version__", "fem", *_NAMES]
