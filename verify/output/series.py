"""Write a sphere mesh with time-dependent point data: XDMF + HDF5, PVD + VTU, or one VTU.

The writers store whatever numbers they are given; the ``twoball export`` command
passes SI values (node coordinates in m, displacements in m, velocities in m/s,
accelerations in m/s^2, times in s), see :func:`twoball.verify.output.fields.field_series`.

Three layouts, chosen by :func:`series_format` from ``format`` or the suffix:

``xdmf``
    ``NAME.xdmf`` (XML) with its arrays in ``NAME.h5`` beside it, written with
    :class:`meshio.xdmf.TimeSeriesWriter`.  meshio puts the HDF5 file into the
    *current directory* (meshio issue #1442); :class:`_XdmfWriter` puts it next to
    the XML file instead.  Every time step is one uniform grid whose geometry and
    topology point at the same two HDF5 datasets (no separate mesh grid, so readers
    see one block, not a duplicate).  Series-wide scalars (lift-off time, case, ...)
    and texts (provenance JSON, case) are grid-centred attributes, which VTK's
    ``vtkXdmfReader`` (ParaView, ``pyvista.read``) shows as field data (texts as
    ``UChar`` arrays of their UTF-8 bytes).  They sit in ``<Information>``
    holders of the domain and each step pulls them in with ``xi:include``:
    VTK's reader resolves the inclusion, meshio's ``TimeSeriesReader`` skips it
    (it refuses grid-centred attributes among a step's own children).  The
    same values are also ``<Information Name= Value=>`` elements of the domain
    and attributes of the HDF5 root group, which carries :data:`H5_MARK` too.
``pvd``
    ``NAME.pvd`` (a ParaView collection, written here) listing one VTU per frame
    in the folder ``NAME_frames-ID/`` beside it (``NAME_0000.vtu``, ...), where
    ID is the first 12 hex digits of the SHA-256 of the frames: the same
    frames get the same folder, and a new run never changes an earlier run's
    frames, so replacing ``NAME.pvd`` switches between complete collections.
``vtu``
    A single frame in one ``.vtu`` file.

Every VTU carries the series-wide scalars as VTK field data plus ``TimeValue``
(the frame's time, which ParaView shows), and the texts as ``UInt8`` arrays of
their UTF-8 bytes: meshio's VTU reader refuses VTK string arrays (and
``meshio.read`` then exits the interpreter), so texts are numbers in every
format; :func:`text_value` turns such an array back into text.  All files go
through :mod:`twoball._common.staging`: written into a scratch folder beside the
target and moved into place only when complete, so an interrupted or failed run
leaves the earlier output intact and no partial files.  Side entries the user
did not name (``NAME.h5``, ``NAME_frames-*``) are replaced only if twoball wrote
them (:func:`check_side_entries`).  The same series gives byte-identical files.
"""

from __future__ import annotations

import contextlib
import copy
import hashlib
import math
import os
import re
import xml.etree.ElementTree as ET
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import meshio
import numpy as np
from meshio._common import write_xml
from meshio.xdmf import TimeSeriesWriter

from twoball._common.choices import FORMATS
from twoball._common.errors import ParameterError
from twoball._common.staging import staged_collection, staged_file, write_marker

SUFFIXES: dict[str, str] = {"xdmf": ".xdmf", "vtu": ".vtu", "pvd": ".pvd"}
CELL_TYPES: dict[int, str] = {3: "triangle", 6: "triangle6"}
TIME_VALUE = "TimeValue"  # the VTK/ParaView name of a dataset's time in field data
FRAME_DATA = "frame_data"  # the text listing the names of per-frame field data
#: Attribute of the HDF5 root group that marks ``NAME.h5`` as written by :func:`write_xdmf`.
H5_MARK = "twoball_series"
H5_MARK_VALUE = "twoball.verify.output.series xdmf+h5"
XINCLUDE = "http://www.w3.org/2001/XInclude"
#: Names of the domain's ``<Information>`` holders of grid-centred attributes (XDMF).
SERIES_HOLDER = "twoball:series-attributes"
STEP_HOLDER = "twoball:step-attributes:{k}"


@dataclass(frozen=True)
class TimeSeries:
    """A fixed mesh with point data at a sequence of times (units: the caller's; SI in twoball).

    Parameters
    ----------
    points : ndarray, shape (P, 3)
        Node coordinates.
    cells : ndarray, shape (T, 3) or (T, 6)
        Triangles (``triangle``) or quadratic triangles (``triangle6``, meshio/VTK
        node order: vertices, then the nodes on edges 01, 12, 20).
    times : ndarray, shape (F,)
        Frame times, increasing.
    point_data : dict of str -> ndarray
        Per-frame nodal values, shape (F, P) for scalars or (F, P, 3) for vectors.
    field_data : dict of str -> float
        Scalars describing the whole series (e.g. ``t_liftoff_s``).  VTU files
        leave out non-finite entries (VTK cannot parse ``nan`` in field data).
    text : dict of str -> str
        Texts describing the whole series (``provenance`` JSON, ``case``).
    frame_data : dict of str -> ndarray, shape (F,)
        Scalars of each frame (e.g. the upper body's height ``s_m``): field data
        of each VTU, a grid attribute of each XDMF step; their names are listed in
        the text ``frame_data`` (comma-separated) so that readers tell them apart.
    """

    points: np.ndarray
    cells: np.ndarray
    times: np.ndarray
    point_data: dict[str, np.ndarray]
    field_data: dict[str, float] = field(default_factory=dict)
    text: dict[str, str] = field(default_factory=dict)
    frame_data: dict[str, np.ndarray] = field(default_factory=dict)

    def __post_init__(self) -> None:
        points = np.ascontiguousarray(self.points, dtype=float)
        cells = np.ascontiguousarray(self.cells, dtype=np.int64)
        times = np.atleast_1d(np.asarray(self.times, dtype=float))
        if points.ndim != 2 or points.shape[1] != 3:
            raise ValueError("points must have shape (P, 3)")
        if cells.ndim == 2 and cells.shape[1] in (10, 15):  # P3/P4: no shared node order
            order = 3 if cells.shape[1] == 10 else 4
            raise ParameterError("order", "1 or 2 for field files and pictures", order)
        if cells.ndim != 2 or cells.shape[1] not in CELL_TYPES:
            raise ValueError("cells must have shape (T, 3) or (T, 6)")
        if times.ndim != 1 or times.size < 1 or np.any(np.diff(times) <= 0):
            raise ValueError("times must be a non-empty increasing 1-D array")
        data = {}
        for name, values in self.point_data.items():
            values = np.ascontiguousarray(values, dtype=float)
            if values.shape[:2] != (times.size, points.shape[0]) or values.ndim not in (2, 3):
                raise ValueError(f"point data {name!r} must have shape (F, P) or (F, P, 3)")
            data[name] = values
        object.__setattr__(self, "points", points)
        object.__setattr__(self, "cells", cells)
        object.__setattr__(self, "times", times)
        object.__setattr__(self, "point_data", data)
        object.__setattr__(
            self, "field_data", {k: float(v) for k, v in dict(self.field_data).items()}
        )
        text = {str(k): str(v) for k, v in dict(self.text).items()}
        frame_data = {k: np.asarray(v, dtype=float) for k, v in dict(self.frame_data).items()}
        if any(v.shape != times.shape for v in frame_data.values()):
            raise ValueError("frame data must have one value per frame, shape (F,)")
        if frame_data:
            text[FRAME_DATA] = ",".join(frame_data)
        object.__setattr__(self, "text", text)
        object.__setattr__(self, "frame_data", frame_data)

    @property
    def cell_type(self) -> str:
        """meshio cell type: ``triangle`` (P1) or ``triangle6`` (P2)."""
        return CELL_TYPES[self.cells.shape[1]]

    def __len__(self) -> int:
        return int(self.times.size)

    def frame(self, k: int) -> dict[str, np.ndarray]:
        """Point data of frame ``k``: name -> (P,) or (P, 3)."""
        return {name: values[k] for name, values in self.point_data.items()}

    def frame_fields(self, k: int) -> dict[str, float]:
        """Field data of frame ``k``: the series-wide scalars, its frame data, ``TimeValue``."""
        own = {name: float(values[k]) for name, values in self.frame_data.items()}
        return {**self.field_data, **own, TIME_VALUE: float(self.times[k])}

    def select(self, frames: Sequence[int]) -> TimeSeries:
        """The series restricted to the frames with the given indices."""
        index = np.asarray(frames, dtype=int)
        return TimeSeries(
            self.points,
            self.cells,
            self.times[index],
            {name: values[index] for name, values in self.point_data.items()},
            self.field_data,
            self.text,
            {name: values[index] for name, values in self.frame_data.items()},
        )


# --------------------------------------------------------------------------- paths
def series_format(path: str | os.PathLike[str], fmt: str | None = None) -> str:
    """The output format: ``fmt`` if given (must match the suffix), else from the suffix.

    Raises
    ------
    ParameterError
        ``format`` unknown, or ``out`` with a suffix that is not ``.FORMAT``.
    """
    suffix = Path(path).suffix.lower()
    if fmt is not None:
        if fmt not in FORMATS:
            raise ParameterError("format", "one of " + ", ".join(FORMATS), fmt)
        if suffix != SUFFIXES[fmt]:
            raise ParameterError("out", f"a file name ending in {SUFFIXES[fmt]}", str(path))
        return fmt
    for name, ending in SUFFIXES.items():
        if suffix == ending:
            return name
    raise ParameterError("out", "a file name ending in " + ", ".join(SUFFIXES.values()), str(path))


# --------------------------------------------------------------------------- texts
def text_value(array: Any) -> str:
    """A text of the field data as any reader returns it: its UTF-8 bytes as numbers.

    Accepts a numpy array of bytes (``uint8`` or ``int8``: meshio, pyvista, VTK
    through ``vtk.util.numpy_support``), a VTK string array's value as a str, or
    a sequence of numbers.

    Examples
    --------
    >>> import numpy as np
    >>> text_value(np.frombuffer("R = 0.12 m".encode(), dtype=np.uint8))
    'R = 0.12 m'
    """
    if isinstance(array, str):
        return array
    values = np.asarray(array)
    if values.dtype.kind in "US":  # a string array (VTK's reader on older files)
        return str(values.ravel()[0])
    codes = values.ravel().astype(np.int64) % 256  # int8 (VTK char) or uint8 bytes
    return bytes(codes.astype(np.uint8)).decode("utf-8")


def _text_codes(text: str) -> np.ndarray:
    return np.frombuffer(text.encode("utf-8"), dtype=np.uint8)


# --------------------------------------------------------------------------- VTU
def _field_element(field_data: Mapping[str, float], text: Mapping[str, str] = {}) -> ET.Element:  # noqa: B006
    element = ET.Element("FieldData")
    for name, value in text.items():  # UTF-8 bytes: meshio refuses VTK string arrays
        codes = _text_codes(value)
        array = ET.SubElement(
            element,
            "DataArray",
            type="UInt8",
            Name=name,
            NumberOfTuples=str(codes.size),
            format="ascii",
        )
        array.text = " ".join(str(b) for b in codes.tolist())
    for name, value in field_data.items():
        if not math.isfinite(value):  # VTK's ASCII parser rejects nan: leave the entry out
            continue
        array = ET.SubElement(
            element,
            "DataArray",
            type="Float64",
            Name=name,
            NumberOfTuples="1",
            format="ascii",
        )
        array.text = repr(float(value))
    return element


def _write_vtu_file(
    target: Path, series: TimeSeries, k: int, field_data: Mapping[str, float]
) -> None:
    """One frame as VTU (meshio), with VTK field data inserted into the grid element."""
    mesh = meshio.Mesh(series.points, [(series.cell_type, series.cells)], series.frame(k))
    meshio.write(str(target), mesh, file_format="vtu")
    tree = ET.parse(target)
    grid = tree.getroot().find("UnstructuredGrid")
    if grid is None:  # pragma: no cover - meshio always writes one
        raise ValueError(f"{target}: no UnstructuredGrid element")
    grid.insert(0, _field_element(field_data, series.text))
    tree.write(target, xml_declaration=True, encoding="utf-8")


def write_vtu(path: str | os.PathLike[str], series: TimeSeries, frame: int = 0) -> list[Path]:
    """Write frame ``frame`` of ``series`` as one ``.vtu`` file.

    Field data: the series-wide scalars and ``TimeValue`` (the frame's time).

    Returns
    -------
    list of Path
        The file written.
    """
    with staged_file(path) as target:
        _write_vtu_file(target, series, frame, series.frame_fields(frame))
    return [Path(path).expanduser()]


# --------------------------------------------------------------------------- PVD
def frame_name(path: str | os.PathLike[str], k: int) -> str:
    """File name of frame ``k`` of a PVD collection: ``NAME_0000.vtu`` (in ``NAME_frames-ID/``)."""
    return f"{Path(path).stem}_{k:04d}.vtu"


def _frames_pattern(out: Path) -> re.Pattern[str]:
    return re.compile(rf"{re.escape(out.stem)}_frames-[0-9a-f]{{12}}")


def _pvd_files(path: Path) -> list[str]:
    """Files listed by an existing PVD collection (names relative to its folder)."""
    try:
        root = ET.parse(path).getroot()
    except (OSError, ET.ParseError):
        return []
    return [d.get("file", "") for d in root.iter("DataSet") if d.get("file")]


def _earlier_frames(out: Path, new: Sequence[str]) -> list[Path]:
    """Frame folders of earlier collections at ``out`` (removed after the commit if ours)."""
    pattern = _frames_pattern(out)
    with contextlib.suppress(OSError):
        return [
            entry
            for entry in out.parent.iterdir()
            if pattern.fullmatch(entry.name) and entry.name not in new and entry.is_dir()
        ]
    return []


def write_pvd(path: str | os.PathLike[str], series: TimeSeries) -> list[Path]:
    """Write a ParaView collection: ``NAME.pvd`` and its frames in ``NAME_frames-ID/``.

    The collection is replaced as a whole: the new frames go into a new folder
    (named by their hash), then ``NAME.pvd`` is replaced in one rename, then the
    frame folders of earlier collections are removed.  An interrupt at any
    point leaves the earlier or the new collection, complete.

    Returns
    -------
    list of Path
        The PVD file, then the VTU files.
    """
    out = Path(path).expanduser()
    names = [frame_name(out, k) for k in range(len(series))]
    check_side_entries(out, "pvd")
    with staged_collection(out, retire=_earlier_frames) as scratch:
        frames = scratch / "frames"
        frames.mkdir()
        digest = hashlib.sha256()
        for k, name in enumerate(names):
            _write_vtu_file(frames / name, series, k, series.frame_fields(k))
            digest.update(name.encode() + b"\0" + (frames / name).read_bytes())
        folder = f"{out.stem}_frames-{digest.hexdigest()[:12]}"
        write_marker(frames, "twoball export (PVD frames)")
        frames.rename(scratch / folder)
        root = ET.Element("VTKFile", type="Collection", version="0.1", byte_order="LittleEndian")
        collection = ET.SubElement(root, "Collection")
        for k, name in enumerate(names):
            ET.SubElement(
                collection,
                "DataSet",
                timestep=repr(float(series.times[k])),
                group="",
                part="0",
                file=f"{folder}/{name}",
            )
        ET.indent(root)
        ET.ElementTree(root).write(scratch / out.name, xml_declaration=True, encoding="utf-8")
    return [out] + [out.parent / folder / name for name in names]


# --------------------------------------------------------------------------- XDMF
class _XdmfWriter(TimeSeriesWriter):
    """meshio's XDMF time-series writer, the HDF5 file beside the XML file, one mesh block.

    meshio opens ``stem + ".h5"`` relative to the current directory (meshio
    issue #1442); here it is opened next to ``filename``.  The XML refers to the
    HDF5 file by its base name, as meshio's reader and ParaView expect.  meshio
    also writes the mesh as a grid of its own beside the time steps, which
    readers show as a second block; here every step carries the geometry and
    topology (references to the same two datasets) instead.
    """

    def __enter__(self) -> _XdmfWriter:
        import h5py

        self.h5_filename = str(self.filename.with_suffix(".h5"))
        # Built in memory and written by Python at the end: a full disk is then an
        # OSError, not a cascade of HDF5 errors ending in a crash.
        self.h5_file = h5py.File(self.h5_filename, "w", driver="core", backing_store=False)
        self.h5_file.attrs[H5_MARK] = H5_MARK_VALUE
        self.series_holder = ET.Element("Information", Name=SERIES_HOLDER)
        return self

    def __exit__(self, kind: object, *exc: object) -> None:
        try:
            if kind is None:
                ET.register_namespace("xi", XINCLUDE)  # meshio maps the prefix elsewhere
                write_xml(self.filename, self.xdmf_file)
                self.h5_file.flush()
                image = self.h5_file.id.get_file_image()
        finally:
            self.h5_file.close()
        if kind is None:
            with open(self.h5_filename, "wb") as handle:
                handle.write(image)

    def write_points_cells(self, points: np.ndarray, cells: list) -> None:
        super().write_points_cells(points, cells)
        mesh = self.domain[-1]  # meshio's separate mesh grid: keep its parts for every step
        self.domain.remove(mesh)
        self.mesh_parts = list(mesh)

    def write_metadata(self, field_data: Mapping[str, float], text: Mapping[str, str]) -> None:
        """Series-wide scalars and texts: grid attributes of every step (through the
        domain's holder :data:`SERIES_HOLDER`), domain Information, HDF5 root
        attributes.  Call before the first :meth:`write_data`."""
        h5_name = os.path.basename(self.h5_filename)
        for name, value in text.items():
            codes = _text_codes(value)
            self.h5_file.create_dataset(f"text/{name}", data=codes)
            self.h5_file.attrs[name] = value
            ET.SubElement(self.domain, "Information", Name=name, Value=value)
            self.series_holder.append(
                _grid_attribute(name, "UChar", "1", str(codes.size), f"{h5_name}:/text/{name}")
            )
        for name, value in field_data.items():
            ET.SubElement(self.domain, "Information", Name=name, Value=repr(value))
            self.h5_file.attrs[name] = value
            if math.isfinite(value):
                self.series_holder.append(_grid_attribute(name, "Float", "8", "1", repr(value)))
        self.domain.append(self.series_holder)

    def write_data(
        self,
        t: float,
        point_data: dict | None = None,
        cell_data: None = None,
        step_data: Mapping[str, float] | None = None,
    ) -> None:
        """One time step: node data, and ``step_data`` (this step's own scalars)."""
        super().write_data(t, point_data, cell_data)
        k = len(self.collection) - 1
        grid = self.collection[-1]
        grid.set("GridType", "Uniform")
        grid.remove(grid[0])  # meshio's xi:include of the separate mesh grid
        for j, part in enumerate(self.mesh_parts):
            grid.insert(j, copy.deepcopy(part))
        _include(grid, SERIES_HOLDER)
        if step_data:
            holder = ET.SubElement(self.domain, "Information", Name=STEP_HOLDER.format(k=k))
            for name, value in step_data.items():
                holder.append(_grid_attribute(name, "Float", "8", "1", repr(float(value))))
            _include(grid, STEP_HOLDER.format(k=k))


def _include(grid: ET.Element, holder: str) -> None:
    """``xi:include`` of the attributes in the domain's ``<Information Name=holder>``."""
    pointer = f"xpointer(//Information[@Name='{holder}']/*)"
    ET.SubElement(grid, f"{{{XINCLUDE}}}include", xpointer=pointer)


def _grid_attribute(name: str, kind: str, precision: str, size: str, data: str) -> ET.Element:
    """A grid-centred XDMF attribute (VTK field data); ``data`` inline or ``file.h5:/path``."""
    attribute = ET.Element("Attribute", Name=name, AttributeType="Scalar", Center="Grid")
    item = ET.SubElement(
        attribute,
        "DataItem",
        DataType=kind,
        Dimensions=size,
        Format="HDF" if ":/" in data else "XML",
        Precision=precision,
    )
    item.text = data
    return attribute


def write_xdmf(path: str | os.PathLike[str], series: TimeSeries) -> list[Path]:
    """Write an XDMF 3 time series, ``NAME.xdmf`` with ``NAME.h5`` beside it.

    Readable with VTK's ``vtkXdmfReader`` (ParaView, ``pyvista.read``: one
    unstructured grid per time, the series-wide scalars and texts as field
    data), with meshio's ``TimeSeriesReader`` (points, cells and the node data of
    every step; it skips the ``xi:include`` of the grid-centred attributes) and
    with :func:`read_series`.  ``NAME.h5`` is replaced only if twoball wrote it
    (:func:`check_side_entries`).

    Returns
    -------
    list of Path
        The XDMF and the HDF5 file.
    """
    out = Path(path).expanduser()
    h5_name = out.with_suffix(".h5").name
    check_side_entries(out, "xdmf")
    with staged_collection(out, ours=is_twoball_h5) as scratch:
        target = scratch / out.name
        with _XdmfWriter(target) as writer:
            writer.write_points_cells(series.points, [(series.cell_type, series.cells)])
            writer.write_metadata(series.field_data, series.text)
            for k, time in enumerate(series.times):
                own = {name: values[k] for name, values in series.frame_data.items()}
                writer.write_data(float(time), point_data=series.frame(k), step_data=own)
        if not (scratch / h5_name).is_file():  # pragma: no cover - guards the workaround
            raise OSError(f"the HDF5 file {h5_name} was not written beside {out.name}")
    return [out, out.with_name(h5_name)]


# --------------------------------------------------------------------------- dispatch
WRITERS = {"xdmf": write_xdmf, "pvd": write_pvd}


def write_series(
    path: str | os.PathLike[str], series: TimeSeries, fmt: str | None = None
) -> list[Path]:
    """Write ``series`` in the format given by ``fmt`` or by the suffix of ``path``.

    A ``.vtu`` file holds one frame, so ``series`` must have exactly one frame.

    Returns
    -------
    list of Path
        Every file written, the main file first.
    """
    fmt = series_format(path, fmt)
    if fmt == "vtu":
        if len(series) != 1:
            raise ParameterError("times", "exactly one time for a single .vtu file", len(series))
        return write_vtu(path, series, 0)
    return WRITERS[fmt](path, series)


# --------------------------------------------------------------------------- reading back
def read_series(path: str | os.PathLike[str]) -> TimeSeries:
    """Read a series written by :func:`write_series` (any of the three formats).

    A thin layer over meshio: XDMF through ``meshio.xdmf.TimeSeriesReader``
    (points, cells, times, node data), the field data and texts from the
    domain's ``<Information>`` elements, the per-frame scalars from the step
    holders; PVD and VTU through ``meshio.read`` of each VTU, the texts decoded
    from their bytes.  Files of twoball 0.2 (XDMF steps with grid-centred
    attributes, VTU string arrays: both refused by meshio) are read too.
    """

    path = Path(path)
    fmt = series_format(path)
    if fmt == "xdmf":
        return read_xdmf(path)
    files = [path.name] if fmt == "vtu" else _pvd_files(path)
    meshes = [read_vtu(path.parent / name) for name in files]
    fields = dict(meshes[0][1])
    names = [n for n in meshes[0][2].get(FRAME_DATA, "").split(",") if n]
    frame_data = {n: np.array([f.pop(n) for _, f, _ in meshes]) for n in [*names, TIME_VALUE]}
    for name in frame_data:
        fields.pop(name, None)
    times = frame_data.pop(TIME_VALUE)
    mesh = meshes[0][0]
    point_data = stack([m.point_data for m, _, _ in meshes])
    return TimeSeries(
        mesh.points, mesh.cells[0].data, times, point_data, fields, meshes[0][2], frame_data
    )


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
    root = ET.parse(path).getroot()
    domain = root.find("Domain")
    if domain is None:
        raise ValueError(f"{path}: no XDMF domain")
    collection = next(g for g in domain.iter("Grid") if g.get("GridType") == "Collection")
    steps = collection.findall("Grid")
    try:
        points, cells, times, frames = _meshio_steps(path)
    except meshio.ReadError:  # twoball 0.2: grid-centred attributes among the steps' own
        points, cells, times, frames = _parsed_steps(path, domain, steps)
    info = {
        i.get("Name", ""): i.get("Value", "nan")
        for i in domain.findall("Information")
        if i.get("Value") is not None
    }
    field_data, text = _split_text(info)
    names = [n for n in text.get(FRAME_DATA, "").split(",") if n]
    frame_data = {
        n: np.array([_step_value(domain, g, k, n) for k, g in enumerate(steps)]) for n in names
    }
    return TimeSeries(
        points, cells.astype(np.int64), times, stack(frames), field_data, text, frame_data
    )


def _meshio_steps(path: Path) -> tuple[np.ndarray, np.ndarray, list[float], list[dict]]:
    """Points, cells, times and node data of every step, read by meshio."""
    with meshio.xdmf.TimeSeriesReader(str(path)) as reader:
        points, cells = reader.read_points_cells()
        times, frames = [], []
        for k in range(reader.num_steps):
            t, point_data, _ = reader.read_data(k)
            times.append(float(t))
            frames.append({name: np.asarray(v) for name, v in point_data.items()})
    return np.asarray(points), np.asarray(cells[0].data), times, frames


def _parsed_steps(
    path: Path, domain: ET.Element, steps: list[ET.Element]
) -> tuple[np.ndarray, np.ndarray, list[float], list[dict]]:
    """As :func:`_meshio_steps`, parsed here (files meshio refuses)."""
    import h5py

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
            {
                a.get("Name", ""): values(a.find("DataItem"))
                for a in g.iter("Attribute")
                if a.get("Center") == "Node"
            }
            for g in steps
        ]
    finally:
        for handle in files.values():
            handle.close()
    return points, cells, times, frames


def _step_value(domain: ET.Element, step: ET.Element, k: int, name: str) -> float:
    """The scalar grid attribute ``name`` of XDMF time step ``k`` (per-frame field data)."""
    holder = domain.find(f"Information[@Name='{STEP_HOLDER.format(k=k)}']")
    for place in (holder, step):
        for attribute in [] if place is None else place.iter("Attribute"):
            if attribute.get("Name") == name and attribute.get("Center") == "Grid":
                return float((attribute.findtext("DataItem") or "nan").strip())
    raise ValueError(f"frame data {name!r} missing in an XDMF time step")


def read_vtu(path: Path) -> tuple[meshio.Mesh, dict[str, float], dict[str, str]]:
    """One VTU read by ``meshio.read``: mesh, numbers, and the texts (decoded from bytes).

    A VTK string array (files of twoball 0.2), which meshio refuses, is taken out
    and read here first.
    """
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
    fields = {}
    for name, values in mesh.field_data.items():
        values = np.asarray(values)
        if values.dtype == np.uint8:
            text[name] = text_value(values)
        else:
            fields[name] = float(values.ravel()[0])
    return mesh, fields, text


def stack(frames: list[dict[str, np.ndarray]]) -> dict[str, np.ndarray]:
    return {name: np.stack([f[name] for f in frames]) for name in frames[0]}


# --------------------------------------------------------------------------- side entries
def is_twoball_h5(path: Path) -> bool:
    """True if ``path`` is an HDF5 file :func:`write_xdmf` wrote (root attribute
    :data:`H5_MARK`, or, from twoball 0.2, a twoball provenance block)."""
    import json

    import h5py

    try:
        with h5py.File(path, "r") as h5:
            if h5.attrs.get(H5_MARK) == H5_MARK_VALUE:
                return True
            provenance = h5.attrs.get("provenance")
            if provenance is None:
                return False
            block = json.loads(provenance)
    except (OSError, ValueError, TypeError):
        return False
    versions = block.get("versions") if isinstance(block, dict) else None
    return isinstance(versions, dict) and "twoball" in block


def check_side_entries(
    path: str | os.PathLike[str], fmt: str | None = None, param: str = "out"
) -> None:
    """Refuse, before any work, a side entry of ``path`` that twoball did not write.

    ``NAME.xdmf`` writes ``NAME.h5`` beside it: an existing ``NAME.h5`` must be
    an HDF5 file of :func:`write_xdmf` (:func:`is_twoball_h5`).  ``NAME.pvd``
    writes a folder ``NAME_frames-ID``: every existing entry of that pattern
    must be a folder twoball wrote (its marker, nothing else).  A ``.vtu`` has
    no side entries.

    Raises
    ------
    ParameterError
        Naming ``param`` (the option of the path) and the entry, for the one-line
        command-line error.
    """
    from twoball._common.staging import foreign_entry, mount_point

    out = Path(path).expanduser().absolute()
    fmt = series_format(out, fmt)
    if fmt == "xdmf":
        side = out.with_suffix(".h5")
        if side.is_symlink() or side.is_dir() or (side.exists() and not is_twoball_h5(side)):
            raise ParameterError(
                param,
                "a path whose side file NAME.h5 is missing or one twoball wrote",
                f"{path} ({side.name} is there and twoball did not write it)",
            )
        if side.exists() and mount_point(side):  # a rename cannot replace it
            raise ParameterError(
                param,
                "a path whose side file NAME.h5 is not a mount point",
                f"{path} ({side.name} is one)",
            )
    elif fmt == "pvd":
        pattern = _frames_pattern(out)
        with contextlib.suppress(OSError):
            for entry in sorted(out.parent.iterdir()):
                if not pattern.fullmatch(entry.name):
                    continue
                ours = entry.is_dir() and not entry.is_symlink() and foreign_entry(entry) is None
                if not ours:
                    raise ParameterError(
                        param,
                        "a path whose side folders NAME_frames-* are ones twoball wrote",
                        f"{path} ({entry.name} is there and twoball did not write it)",
                    )
