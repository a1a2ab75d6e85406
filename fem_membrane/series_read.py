"""Reading back the series files of :mod:`twoball.fem_membrane.export` (XDMF, VTU).

Here rather than in meshio: meshio's ``TimeSeriesReader`` refuses the XDMF's
grid-centred attributes (the series-wide field data VTK shows), and its VTU reader
refuses VTK string arrays (the ``provenance`` and ``case`` texts).
"""

from __future__ import annotations

import xml.etree.ElementTree as ET
from collections.abc import Mapping
from pathlib import Path
from typing import Any

import meshio
import numpy as np
from twoball.fem_membrane.export import TimeSeries

__all__ = ["read_vtu", "read_xdmf", "stack"]


def _split_text(values: Mapping[str, str]) -> tuple[dict[str, float], dict[str, str]]:
    """``Information`` values: numbers to field data, the rest to texts."""
    numbers, texts = {}, {}
    for name, value in values.items():
        try:
            numbers[name] = float(value)
        except ValueError:
            texts[name] = value
    return numbers, texts


def read_xdmf(path: Path) -> TimeSeries:
    """An XDMF series of :func:`write_xdmf` (also meshio's own layout, with a mesh grid)."""
    import h5py

    root = ET.parse(path).getroot()
    domain = root.find("Domain")
    if domain is None:
        raise ValueError(f"{path}: no XDMF domain")
    collection = next(g for g in domain.iter("Grid") if g.get("GridType") == "Collection")
    steps = collection.findall("Grid")
    mesh = steps[0] if steps[0].find("Geometry") is not None else domain.find("Grid[@Name]")
    files: dict[str, Any] = {}

    def values(item: ET.Element | None) -> np.ndarray:
        if item is None:
            raise ValueError(f"{path}: a data item is missing")
        shape = [int(d) for d in item.get("Dimensions", "").split()]
        if item.get("Format") == "HDF":
            name, _, dataset = (item.text or "").strip().partition(":")
            if name not in files:
                files[name] = h5py.File(path.parent / name, "r")
            return np.asarray(files[name][dataset]).reshape(shape)
        return np.array((item.text or "").split(), dtype=float).reshape(shape)

    try:
        points = values(mesh.find("Geometry/DataItem") if mesh is not None else None)
        cells = values(mesh.find("Topology/DataItem") if mesh is not None else None)
        times = [float(g.find("Time").get("Value", "nan")) for g in steps]  # type: ignore[union-attr]
        frames = [
            {a.get("Name", ""): values(a.find("DataItem")) for a in g.iter("Attribute")
             if a.get("Center") == "Node"}
            for g in steps
        ]  # fmt: skip
    finally:
        for handle in files.values():
            handle.close()
    info = {i.get("Name", ""): i.get("Value", "nan") for i in domain.findall("Information")}
    field_data, text = _split_text(info)
    names = [n for n in text.get("frame_data", "").split(",") if n]
    frame_data = {n: np.array([_step_value(g, n) for g in steps]) for n in names}
    return TimeSeries(
        points, cells.astype(np.int64), times, stack(frames), field_data, text, frame_data
    )


def _step_value(step: ET.Element, name: str) -> float:
    """The scalar grid attribute ``name`` of one XDMF time step (per-frame field data)."""
    for attribute in step.iter("Attribute"):
        if attribute.get("Name") == name and attribute.get("Center") == "Grid":
            return float((attribute.findtext("DataItem") or "nan").strip())
    raise ValueError(f"frame data {name!r} missing in an XDMF time step")


def read_vtu(path: Path) -> tuple[meshio.Mesh, dict[str, float], dict[str, str]]:
    """One VTU: meshio reads mesh and numbers; the string arrays (which meshio refuses) here."""
    import tempfile

    tree = ET.parse(path)
    text = {}
    for holder in tree.getroot().iter("FieldData"):
        for array in list(holder):
            if array.get("type") == "String":
                codes = [int(c) for c in (array.text or "").split()]
                end = codes.index(0) if 0 in codes else len(codes)
                text[array.get("Name", "")] = bytes(codes[:end]).decode("utf-8")
                holder.remove(array)
    if text:
        with tempfile.TemporaryDirectory() as folder:
            plain = Path(folder) / path.name
            tree.write(plain, xml_declaration=True, encoding="utf-8")
            mesh = meshio.read(str(plain), file_format="vtu")
    else:
        mesh = meshio.read(str(path), file_format="vtu")
    fields = {name: float(np.asarray(v).ravel()[0]) for name, v in mesh.field_data.items()}
    return mesh, fields, text


def stack(frames: list[dict[str, np.ndarray]]) -> dict[str, np.ndarray]:
    return {name: np.stack([f[name] for f in frames]) for name in frames[0]}
