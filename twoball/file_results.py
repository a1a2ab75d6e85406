"""What :func:`twoball.export`, :func:`twoball.render` and :func:`twoball.plot` return.

Each result lists the files written and the lift-off behind them (SI), the
accuracy warnings, and the provenance (:mod:`twoball.provenance`); ``as_dict()``
gives JSON.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from twoball.modal.report import LiftoffReport

__all__ = ["ExportResult", "PlotResult", "RenderResult"]


@dataclass(frozen=True)
class ExportResult:
    """Files written by :func:`export` and what they hold (SI)."""

    files: list[Path]
    format: str
    times_s: list[float]
    nodes: int
    cells: int
    cell_type: str
    point_data: list[str]
    report: LiftoffReport
    warnings: list[str] = field(default_factory=list)
    provenance: dict[str, Any] | None = None

    def as_dict(self) -> dict[str, Any]:
        """JSON-ready summary with the lift-off of the exported backend."""
        return {
            "provenance": self.provenance,
            "warnings": self.warnings,
            "files": [str(f) for f in self.files],
            "format": self.format,
            "times_s": self.times_s,
            "nodes": self.nodes,
            "cells": self.cells,
            "cell_type": self.cell_type,
            "point_data": self.point_data,
            "liftoff": self.report.as_dict(),
        }


@dataclass(frozen=True)
class RenderResult:
    """The picture or animation written by :func:`render`."""

    file: Path
    times_s: list[float]
    size: tuple[int, int]
    warp: float
    backend: str
    report: LiftoffReport
    warnings: list[str] = field(default_factory=list)
    provenance: dict[str, Any] | None = None

    def as_dict(self) -> dict[str, Any]:
        """JSON-ready summary."""
        return {
            "provenance": self.provenance,
            "warnings": self.warnings,
            "file": str(self.file),
            "times_s": self.times_s,
            "size": list(self.size),
            "warp": self.warp,
            "backend": self.backend,
            "liftoff": self.report.as_dict(),
        }


@dataclass(frozen=True)
class PlotResult:
    """The PNG written by :func:`plot`, with one line per curve family."""

    file: Path
    kind: str
    rows: list[tuple[str, str]] = field(default_factory=list)
    reports: dict[str, LiftoffReport] = field(default_factory=dict)
    warnings: list[str] = field(default_factory=list)
    provenance: dict[str, Any] | None = None

    def as_dict(self) -> dict[str, Any]:
        """JSON-ready summary."""
        return {
            "provenance": self.provenance,
            "warnings": self.warnings,
            "file": str(self.file),
            "kind": self.kind,
            "rows": [list(r) for r in self.rows],
            "liftoff": {name: r.as_dict() for name, r in self.reports.items()},
        }
