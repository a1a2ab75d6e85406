"""twoball -- lift-off from a vibrating spherical membrane (the two-ball bounce).

The public API is loaded lazily: ``import twoball`` costs almost nothing, and
each name below imports its module on first use::

    import twoball

    case = twoball.Case.preset("basketball", v0=3.0)   # SI; phi_a by eq. (3.7)
    result = twoball.liftoff(case)                      # closed form (Legendre series)
    fe = twoball.liftoff(case, backend="fem", mesh="axisym")
    print(result.t_liftoff_s, result.v_liftoff_m_s, result.case.phi_a_source)

Public names: :class:`Case`, :func:`liftoff`, :func:`sweep`, :mod:`fem`
(``fem.solve``, ``fem.eigen``), :func:`converge`, :func:`verify`,
:func:`export`, :func:`render`, :func:`plot`, :class:`LiftoffReport`,
:class:`MeshOptions`, :class:`ParameterError`, :class:`NumericalError`,
:func:`report` (versions and platform), :mod:`provenance`, :mod:`progress`,
``__version__``.  The command line ``twoball`` is a thin layer over these.
"""

from __future__ import annotations

import importlib as _importlib
import os as _os

from twoball._lazy import attach as _attach
from twoball._version import __version__

# In a source checkout the parts (modal/, fem_membrane/, verify/) sit beside this
# folder; installed, setuptools maps them to twoball/modal, ... (pyproject.toml).
_HERE = _os.path.dirname(__file__)
if not _os.path.isdir(_os.path.join(_HERE, "modal")):
    __path__.append(_os.path.dirname(_HERE))  # noqa: F821 -- the package's own __path__

_NAMES: dict[str, str] = {
    "Case": ".modal.parameters",
    "LiftoffReport": ".modal.report",
    "ParameterError": ".modal.errors",
    "NumericalError": ".modal.errors",
    "MeshOptions": ".mesh_options",
    "liftoff": ".solvers",
    "sweep": ".solvers",
    "SweepResult": ".solvers",
    "converge": ".reports",
    "export": ".files",
    "render": ".files",
    "plot": ".files",
    "report": ".provenance",
    "Report": ".provenance",
}
# ``verify`` is the subpackage twoball.verify, callable as twoball.reports.verify (the
# import system would replace a function of that name by the subpackage anyway).
_SUBMODULES = ("fem", "verify", "provenance", "progress")
_getattr, _dir = _attach(__name__, _NAMES)


def __getattr__(name: str) -> object:
    if name in _SUBMODULES:
        return _importlib.import_module(f".{name}", __name__)
    return _getattr(name)


def __dir__() -> list[str]:
    return sorted([*_dir(), *_SUBMODULES, "__version__"])


__all__ = ["__version__", *_NAMES, *_SUBMODULES]
