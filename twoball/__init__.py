"""twoball -- lift-off from a vibrating spherical membrane (the two-ball bounce).

The public API is loaded lazily: ``import twoball`` costs almost nothing, and
each name below imports its module on first use::

    import twoball

    case = twoball.Case.preset("basketball", v0=3.0)   # SI; phi_a by eq. (3.7)
    result = twoball.liftoff(case)                      # closed form (Legendre series)
    fe = twoball.liftoff(case, backend="fem", mesh="axisym")
    print(result.t_liftoff_s, result.v_liftoff_m_s, result.case.phi_a_source)

Public names (``twoball.__all__``): the verbs :func:`liftoff`, :func:`sweep`,
``fem.solve``, ``fem.eigen``, :func:`export`, :func:`render`, :func:`plot`,
:func:`converge`, :func:`verify`, :func:`reproduce`, :func:`icm`,
:func:`table1`, :func:`report`, :func:`bounce` (the lower ball dropped on the
floor); the case and the option and model objects :class:`Case`,
:class:`MeshOptions`, :class:`Stepping`, :class:`Body`, :class:`Membrane`,
:class:`ModalRatio`, :class:`Rayleigh`, :class:`Series`, :class:`Drop`,
:class:`RenderOptions`, :class:`PlotOptions`; the results; :class:`Reporter` (progress),
:class:`ParameterError`, :class:`NumericalError`, ``__version__``.  The
command line ``twoball`` is a thin layer over these.
"""

from __future__ import annotations

import importlib as _importlib
import os as _os
import types as _types

from twoball._common.lazy import attach as _attach
from twoball._version import __version__

# Annotations only: nothing numerical is imported with the package, nor typing
# (``twoball --help`` stays fast); type checkers read the block below.
_TYPE_CHECKING = False
if _TYPE_CHECKING:
    import os
    from collections.abc import Callable

    from twoball.modal.damping import ModalRatio
    from twoball.modal.parameters import Case
    from twoball.modal.series_options import Series
    from twoball.verify.checks.results import VerifyResult

# In a source checkout the parts (modal/, fem_membrane/, verify/) sit beside this
# folder; installed, setuptools maps them to twoball/modal, ... (pyproject.toml).
_HERE = _os.path.dirname(__file__)
if not _os.path.isdir(_os.path.join(_HERE, "modal")):
    __path__.append(_os.path.dirname(_HERE))  # noqa: F821 -- the package's own __path__

from twoball import verify  # noqa: E402 -- a light package; made callable below

_NAMES: dict[str, str | tuple[str, str]] = {
    "Case": "twoball.modal.parameters",
    "LiftoffReport": "twoball.modal.report",
    "ParameterError": "twoball._common.errors",
    "NumericalError": "twoball._common.errors",
    "MeshOptions": "twoball.fem_membrane.options",
    "Stepping": "twoball.modal.stepping",
    "Body": "twoball.modal.contact.body",
    "ModalRatio": "twoball.modal.damping",
    "Rayleigh": "twoball.modal.damping",
    "Series": "twoball.modal.series_options",
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
    "drop_elements": "twoball.fem_membrane.ball",
    "ClosedForm": "twoball._solvers",
    "Superposition": "twoball._solvers",
    "GeneralizedAlpha": "twoball._solvers",
    "MoreauJean": "twoball._solvers",
    "BounceReport": "twoball._bounce",
    "BounceSweep": "twoball.verify.sweeps.bounce",
    "sweep": "twoball._sweep",
    "SweepResult": "twoball._sweep",
    "converge": "twoball._studies",
    "export": "twoball._files",
    "render": "twoball._files",
    "plot": "twoball._files",
    "ExportResult": "twoball._files",
    "RenderResult": "twoball._files",
    "PlotResult": "twoball._files",
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


class _VerifyPackage(_types.ModuleType):
    """The subpackage :mod:`twoball.verify`, callable as the verb :func:`twoball.verify`.

    A function and a subpackage cannot share the name ``twoball.verify``: the
    import system sets the attribute to the subpackage whenever one of its
    modules is imported.  So the subpackage itself is made callable here.
    """

    def __call__(
        self,
        case: Case | None = None,
        *,
        thorough: bool = False,
        fast: bool = False,
        damping: ModalRatio | None = None,
        series: Series | None = None,
        t_end: float | None = None,
        out: str | os.PathLike[str] | None = None,
        progress: Callable[[str], None] | None = None,
        **deprecated: object,
    ) -> VerifyResult:
        """Every backend against the closed form, with PASS/FAIL per check.

        Parameters
        ----------
        case : Case, optional
            The impact (default the basketball preset).
        thorough : bool
            Finer meshes as well (minutes, not seconds).
        fast : bool
            The small configuration of the test suite.
        damping : ModalRatio, optional
            The paper's ratio D on every mode (a Rayleigh law is refused by
            name: the checks measure against eq. (3.16) with the ratio D).
        series : Series, optional
            Filter and re-contact horizon, as in :func:`twoball.liftoff`.
        t_end : float, optional
            The modelled window [s] (default 4 pi / c).
        out : path, optional
            Report directory to write (report.md, results.json, CSV, PNG).
        progress : callable, optional
            Called with a short text as each step starts (:class:`twoball.Reporter`).
        **deprecated
            ``sigma`` and ``recontact`` of version 0.2, with a :class:`DeprecationWarning`.

        Returns
        -------
        VerifyResult
            ``passed`` only if every check passes.

        The Examples are those of the function this calls, :func:`twoball._studies.verify`.
        """
        from twoball._studies import verify as run_verify

        return run_verify(
            case,
            thorough=thorough,
            fast=fast,
            damping=damping,
            series=series,
            t_end=t_end,
            out=out,
            progress=progress,
            **deprecated,
        )


verify.__class__ = _VerifyPackage


def __getattr__(name: str) -> object:
    if name == "fem":
        return _importlib.import_module("twoball.fem")
    return _getattr(name)


def __dir__() -> list[str]:
    return sorted([*_dir(), "fem", "verify", "__version__"])


__all__ = ["__version__", "fem", "verify", *_NAMES]
