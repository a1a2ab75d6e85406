"""Where a result came from: versions, platform, command line or API call, UTC time, case.

:func:`report` describes the installation (in the spirit of ``pyvista.Report``);
:func:`block` is the provenance every machine-readable output carries: the JSON of
every ``--json`` (a top-level ``"provenance"`` key; list outputs become
``{"results": [...], "provenance": {...}}``, see :func:`attach`), report folders
(``provenance.json``) and exported fields (VTU field data, XDMF attributes).

Versions are read from the installed ``*.dist-info`` folder names, never by
importing the packages (or :mod:`importlib.metadata`), so ``twoball liftoff
--json`` still loads numpy only.  ``scooby`` is
not needed (nor imported).
"""

from __future__ import annotations

import functools
import math
import os
import platform
import re
import shlex
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from datetime import UTC, datetime
from pathlib import PurePath
from typing import Any

from twoball._common.keywords import checked
from twoball._version import __version__

__all__ = [
    "PACKAGES",
    "Report",
    "attach",
    "block",
    "case_block",
    "report",
    "set_command",
    "stable",
]

#: Distributions reported, in order: the required ones, then the optional ones.
PACKAGES: tuple[str, ...] = (
    "numpy",
    "scipy",
    "scikit-fem",
    "meshio",
    "h5py",
    "matplotlib",
    "rich",
    "threadpoolctl",
)
OPTIONAL: tuple[str, ...] = ("pyvista", "vtk", "imageio", "imageio-ffmpeg", "dask", "distributed")

_COMMAND: list[str] | None = None  # the command line, when the CLI runs (set_command)


def set_command(argv: Sequence[str] | None) -> None:
    """Record the command line being run (the CLI calls this; ``None`` clears it)."""
    global _COMMAND
    _COMMAND = None if argv is None else ["twoball", *argv]


def command() -> str | None:
    """The recorded command line, shell-quoted (``twoball liftoff --json``), or None."""
    return None if _COMMAND is None else shlex.join(_COMMAND)


def _normalise(name: str) -> str:
    return re.sub(r"[-_.]+", "_", name).lower()


@functools.cache
def _installed() -> dict[str, str]:
    """Normalised distribution name -> version, from the ``*.dist-info`` folder names.

    Installers name the folder ``NAME-VERSION.dist-info`` (PEP 376/627), so one
    listing of each ``sys.path`` folder gives every version without importing
    :mod:`importlib.metadata` (34 ms with what it imports: the start-up of
    ``twoball liftoff --json`` would feel it) or any package.  The first folder
    on ``sys.path`` wins, as for imports.
    """
    import sys

    found: dict[str, str] = {}
    for entry in sys.path:
        try:
            names = os.listdir(entry or ".")
        except OSError:
            continue
        for name in names:
            stem, dot, suffix = name.rpartition(".")
            if suffix not in ("dist-info", "egg-info") or not dot:
                continue
            distribution, dash, version = stem.partition("-")
            if dash and version:
                found.setdefault(_normalise(distribution), version.split("-")[0])
    return found


def _version(distribution: str) -> str | None:
    """The installed version of ``distribution`` (None: not installed); nothing is imported."""
    return _installed().get(_normalise(distribution))


def versions(extra: Sequence[str] = ()) -> dict[str, str | None]:
    """twoball, Python and each distribution's version (None: not installed)."""
    names = dict.fromkeys([*PACKAGES, *OPTIONAL, *extra])
    return {
        "twoball": __version__,
        "python": platform.python_version(),
        **{name: _version(name) for name in names},
    }


@functools.cache
def platform_info() -> dict[str, Any]:
    """Operating system, machine and CPU count (cheap, no subprocess)."""
    return {
        "system": platform.system(),
        "release": platform.release(),
        "machine": platform.machine(),
        "cpus": os.cpu_count(),
        "python_implementation": platform.python_implementation(),
    }


def case_block(case: Any) -> dict[str, Any] | None:
    """The case in SI with the unit in every key (``radius_m``, ``phi_a_rad``, ...).

    :meth:`twoball.Case.as_dict`, the one SI form of a case (bending and gas keys
    only for a stiffened ball).
    """
    return None if case is None else case.as_dict()


def _plain(value: Any) -> Any:
    """An argument as JSON: paths as text, numpy values as Python, others by repr."""
    if value is None or isinstance(value, (bool, int, str)):
        return value
    if isinstance(value, float):
        return value if math.isfinite(value) else repr(value)
    if isinstance(value, PurePath):
        return str(value)
    if isinstance(value, Mapping):
        return {str(k): _plain(v) for k, v in value.items()}
    if isinstance(value, (list, tuple, set, frozenset)):
        return [_plain(v) for v in value]
    if hasattr(value, "tolist"):  # numpy scalars and arrays
        return _plain(value.tolist())
    if callable(value):
        return getattr(value, "__qualname__", type(value).__name__)
    return repr(value)


def block(
    case: Any = None,
    call: str | None = None,
    arguments: Mapping[str, Any] | None = None,
) -> dict[str, Any]:
    """The provenance of one result.

    Parameters
    ----------
    case : Case, optional
        The case computed (SI, see :func:`case_block`).
    call : str, optional
        The public function that computed it (``"twoball.liftoff"``).
    arguments : mapping, optional
        Its keyword arguments (the case left out: it is ``case``).

    Returns
    -------
    dict
        ``twoball``, ``versions`` (with Python's), ``platform``, ``generated`` (UTC,
        ISO 8601), ``command`` (the command line when run by the ``twoball``
        CLI, else None), ``call`` (function and arguments) and ``case``.
    """
    args = {k: _plain(v) for k, v in (arguments or {}).items() if k != "case"}
    return {
        "twoball": __version__,
        "versions": versions(),
        "platform": platform_info(),
        "generated": datetime.now(UTC).isoformat(timespec="seconds"),
        "command": command(),
        "call": None if call is None else {"function": call, "arguments": args},
        "case": case_block(case),
    }


#: Keys of a provenance block that change from run to run (time, command line, paths).
RUN_KEYS: tuple[str, ...] = ("generated", "command", "call")


def stable(provenance: Mapping[str, Any]) -> dict[str, Any]:
    """The part of a block that is the same for the same inputs on one installation."""
    return {k: v for k, v in provenance.items() if k not in RUN_KEYS}


def attach(data: Any, provenance: Mapping[str, Any] | None) -> Any:
    """``data`` with its provenance: a dict gains a ``"provenance"`` key, a list becomes
    ``{"results": data, "provenance": ...}`` (the one shape of every JSON output)."""
    if provenance is None:
        return data
    if isinstance(data, dict):
        return {**data, "provenance": dict(provenance)}
    return {"results": list(data), "provenance": dict(provenance)}


# --------------------------------------------------------------------------- report()
@checked
@dataclass(frozen=True)
class Report:
    """The installation: platform, Python and package versions (``print(twoball.report())``).

    Attributes
    ----------
    platform : dict
        System, release, machine, CPU count, Python implementation.
    packages : dict
        twoball, python and each distribution -> version (None: not installed).

    Examples
    --------
    >>> import twoball
    >>> report = twoball.report()
    >>> report.packages["twoball"] == twoball.__version__
    True
    """

    platform: dict[str, Any]
    packages: dict[str, str | None]
    generated: str

    def as_dict(self) -> dict[str, Any]:
        """JSON-ready dictionary."""
        return {"generated": self.generated, "platform": self.platform, "packages": self.packages}

    def __str__(self) -> str:
        rows = [("Date", self.generated)]
        rows += [
            ("OS", f"{self.platform['system']} {self.platform['release']}"),
            ("Machine", str(self.platform["machine"])),
            ("CPU(s)", str(self.platform["cpus"])),
            ("Python", f"{self.packages['python']} ({self.platform['python_implementation']})"),
        ]
        rows += [
            (name, version or "not installed")
            for name, version in self.packages.items()
            if name != "python"
        ]
        width = max(len(name) for name, _ in rows)
        line = "-" * 60
        body = "\n".join(f"{name:>{width + 2}} : {value}" for name, value in rows)
        return f"{line}\n{body}\n{line}"

    def __repr__(self) -> str:
        return str(self)

    def _repr_html_(self) -> str:
        cells = "".join(
            f"<tr><th style='text-align:right'>{k}</th><td>{v or 'not installed'}</td></tr>"
            for k, v in {**self.platform, **self.packages}.items()
        )
        return f"<table><caption>twoball report {self.generated}</caption>{cells}</table>"


@checked
def report(additional: str | Sequence[str] = ()) -> Report:
    """Versions of twoball, Python and its dependencies, and the platform.

    Parameters
    ----------
    additional : str or sequence of str
        More distributions to list (names as installed, e.g. ``"pandas"``; one
        name alone is one distribution).

    Returns
    -------
    Report
        ``print()`` it for a table; ``as_dict()`` for JSON.

    Examples
    --------
    >>> import twoball
    >>> print(twoball.report())  # doctest: +SKIP
    >>> sorted(twoball.report().as_dict())[:2]
    ['generated', 'packages']
    """
    from twoball._common.errors import ParameterError

    valid = "distribution names (a str or a sequence of str)"
    names = (additional,) if isinstance(additional, str) else additional
    try:
        names = tuple(names)
    except TypeError:  # not iterable
        raise ParameterError("additional", valid, additional) from None
    if not all(isinstance(name, str) and name for name in names):
        raise ParameterError("additional", valid, additional)
    return Report(
        dict(platform_info()),
        versions(names),
        datetime.now(UTC).isoformat(timespec="seconds"),
    )
