"""What the field verbs return: the files written, with the lift-off they show (SI).

:func:`twoball.export` returns an :class:`ExportResult`, :func:`twoball.render`
a :class:`RenderResult`, :func:`twoball.plot` a :class:`PlotResult`; each has
``file``/``files`` and ``as_dict()`` for JSON.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from twoball._common.keywords import checked

__all__ = ["ExportResult", "PlotResult", "RenderResult"]


@checked
@dataclass(frozen=True)
class ExportResult:
    """Files written by :func:`export` and what they hold (SI).

    Like every result that writes files, it has ``files`` (every one) and
    ``file`` (the main one).

    Examples
    --------
    >>> import tempfile, pathlib, twoball
    >>> out = pathlib.Path(tempfile.mkdtemp()) / "ball.vtu"
    >>> solver = twoball.Superposition(twoball.MeshOptions("sphere", level=1))
    >>> result = twoball.export(out, solver=solver)
    >>> result.format, result.nodes, result.cell_type, len(result.times_s)
    ('vtu', 162, 'triangle6', 1)
    """

    files: list[Path]
    format: str
    times_s: list[float]
    nodes: int
    cells: int
    cell_type: str
    point_data: list[str]
    report: Any
    warnings: list[str] = field(default_factory=list)
    provenance: dict[str, Any] | None = None

    @property
    def file(self) -> Path:
        """The main file (``.xdmf``, ``.pvd`` or ``.vtu``); :attr:`files` lists every one."""
        return self.files[0]

    def as_dict(self) -> dict[str, Any]:
        """JSON-ready summary with the lift-off of the exported backend."""
        return {
            "provenance": self.provenance,
            "warnings": self.warnings,
            "file": str(self.file),
            "files": [str(f) for f in self.files],
            "format": self.format,
            "times_s": self.times_s,
            "nodes": self.nodes,
            "cells": self.cells,
            "cell_type": self.cell_type,
            "point_data": self.point_data,
            "liftoff": self.report.as_dict(),
        }


@checked
@dataclass(frozen=True)
class RenderResult:
    """The picture or animation written by :func:`render`: ``file`` (and ``files``, one).

    Examples
    --------
    >>> import tempfile, pathlib, twoball
    >>> out = pathlib.Path(tempfile.mkdtemp()) / "ball.png"
    >>> solver = twoball.Superposition(twoball.MeshOptions("sphere", level=1))
    >>> result = twoball.render(out, solver=solver, view=twoball.RenderOptions(frames=[0.005]))
    >>> result.times_s, result.backend
    ([0.005], 'fem')
    """

    file: Path
    times_s: list[float]
    size: tuple[int, int]
    warp: float
    backend: str
    report: Any
    warnings: list[str] = field(default_factory=list)
    provenance: dict[str, Any] | None = None

    @property
    def files(self) -> list[Path]:
        """Every file written (one: :attr:`file`), as :attr:`ExportResult.files`."""
        return [self.file]

    def as_dict(self) -> dict[str, Any]:
        """JSON-ready summary."""
        return {
            "provenance": self.provenance,
            "warnings": self.warnings,
            "file": str(self.file),
            "files": [str(f) for f in self.files],
            "times_s": self.times_s,
            "size": list(self.size),
            "warp": self.warp,
            "backend": self.backend,
            "liftoff": self.report.as_dict(),
        }


@checked
@dataclass(frozen=True)
class PlotResult:
    """The figure written by :func:`plot` (``file``, and ``files``, one), with one line per
    curve family.

    Examples
    --------
    >>> import tempfile, pathlib, twoball
    >>> out = pathlib.Path(tempfile.mkdtemp()) / "eigen.png"
    >>> figure = twoball.PlotOptions(levels=[1], orders=[1], dpi=72)
    >>> result = twoball.plot("eigen", out, figure=figure)
    >>> result.kind, result.rows[0][0]
    ('eigen', 'P1, level 1 (42 unknowns)')
    """

    file: Path
    kind: str
    rows: list[tuple[str, str]] = field(default_factory=list)
    reports: dict[str, Any] = field(default_factory=dict)
    warnings: list[str] = field(default_factory=list)
    provenance: dict[str, Any] | None = None

    @property
    def files(self) -> list[Path]:
        """Every file written (one: :attr:`file`), as :attr:`ExportResult.files`."""
        return [self.file]

    def as_dict(self) -> dict[str, Any]:
        """JSON-ready summary."""
        return {
            "provenance": self.provenance,
            "warnings": self.warnings,
            "file": str(self.file),
            "files": [str(f) for f in self.files],
            "kind": self.kind,
            "rows": [list(r) for r in self.rows],
            "liftoff": {name: r.as_dict() for name, r in self.reports.items()},
        }
