"""The one definition of the finite-element mesh options (kind or file, size, order, pole).

Every entry point that takes a mesh -- :func:`twoball.liftoff` with the FE
backend, :func:`twoball.fem.solve`, :func:`twoball.fem.eigen`,
:func:`twoball.export`, :func:`twoball.render`, :func:`twoball.plot` and the
command-line subcommands built on them -- resolves its ``mesh``, ``level``,
``elements``, ``order``, ``pole`` and ``geometry`` arguments here, so the
defaults and the refusals (``level`` on the axisymmetric line or a mesh file,
``elements`` on a sphere, ``pole`` without a mesh file, the exact geometry on
the ring sphere and the line) are the same everywhere.  ``mesh`` is a
kind name or the user's own sphere: a file path (any format meshio reads), a
``meshio.Mesh`` or a scikit-fem ``MeshTri``, read by
:func:`twoball.fem_membrane.mesh_input.load_sphere_mesh`.  No numerical library
is imported by this module.
"""

from __future__ import annotations

import os
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from twoball._common.choices import (
    DEFAULT_ELEMENTS,
    DEFAULT_LEVEL,
    DEFAULT_ORDER,
    LEVEL_RANGE,
    MESH_KINDS,
    SPHERE_KINDS,
)
from twoball._common.errors import ParameterError
from twoball._common.keywords import checked
from twoball.fem_membrane.validate import (
    GEOMETRIES,
    INITIAL_METHODS,
    ORDERS,
    check_elements,
    check_level,
    check_mesh_source,
    check_order,
    check_pole,
)

#: Discrete sphere: the order-p interpolant through the nodes, or the sphere itself.
DEFAULT_GEOMETRY = "isoparametric"
FILE = "file"  # the kind of a user's mesh (path, meshio.Mesh, scikit-fem MeshTri)
#: Finite-element representation of F, eq. (3.10): L2 projection or nodal interpolation.
DEFAULT_INITIAL = "projection"

__all__ = [
    "DEFAULT_ELEMENTS",
    "DEFAULT_GEOMETRY",
    "DEFAULT_INITIAL",
    "DEFAULT_LEVEL",
    "DEFAULT_ORDER",
    "FILE",
    "GEOMETRIES",
    "INITIAL_METHODS",
    "LEVEL_RANGE",
    "MESH_KINDS",
    "ORDERS",
    "SPHERE_KINDS",
    "MeshOptions",
    "refuse_mesh_options",
]


@checked
@dataclass(frozen=True)
class MeshOptions:
    """A finite-element mesh choice (dimensionless, unit sphere), validated when built.

    Parameters
    ----------
    kind : {"sphere", "ring", "axisym", "file"}, optional
        Icosphere (default), sphere with a ring of edges along phi = phi_a, the
        axisymmetric line x = cos(phi), or the user's mesh (``file``; implied
        when ``file`` is given).
    level : int, optional
        Sphere refinement level in [0, 10] (default 3; :data:`LEVEL_RANGE`, the
        most any budget allows); not on the line or a file.
    elements : int, optional
        Elements >= 2 of the line ``axisym`` (default 400); not on a sphere.
    order : {1, 2, 3, 4}, optional
        Element and geometry order (default 2; a file: its own).
    file : path, meshio.Mesh or scikit-fem MeshTri, optional
        The user's sphere: an existing file in any format meshio reads (any
        radius and centre, 3- or 6-node triangles), a ``meshio.Mesh`` or a
        ``MeshTri``; its contents are checked when the mesh is loaded.
    pole : (x, y, z) or "X,Y,Z", optional
        Pole direction in the frame of ``file``, three finite numbers not all
        zero (default +z); a file only.
    geometry : {"isoparametric", "exact"}
        The order-p interpolant through the nodes (default), or the sphere
        itself (radial projection of the flat triangles; not on the ring
        sphere, whose ring edges follow phi_a, nor on the line, exact already).
    initial : {"projection", "interpolation"}, optional
        Finite-element representation of the initial displacement, eq. (3.10):
        Galerkin L2 projection (default) or nodal interpolation.

    Raises
    ------
    ParameterError
        Naming the field and its valid range, or the field that does not apply.

    Examples
    --------
    >>> import twoball
    >>> twoball.MeshOptions("sphere", level=3).label
    'sphere L3 P2'
    >>> twoball.MeshOptions("axisym").elements
    400
    >>> twoball.MeshOptions(kind="bogus")
    Traceback (most recent call last):
    ...
    twoball.ParameterError: mesh must be one of sphere, ring, axisym or a mesh file, got 'bogus'
    """

    kind: str | None = None
    level: int | None = None
    elements: int | None = None
    order: int | None = None
    file: Any = None
    pole: Any = None
    geometry: str = DEFAULT_GEOMETRY
    initial: str | None = None

    def __post_init__(self) -> None:
        order, geometry, level, elements = self.order, self.geometry, self.level, self.elements
        if order is not None:
            check_order(order)
        if not isinstance(geometry, str) or geometry not in GEOMETRIES:
            raise ParameterError("geometry", "one of " + ", ".join(GEOMETRIES), geometry)
        if self.initial is not None and (
            not isinstance(self.initial, str) or self.initial not in INITIAL_METHODS
        ):
            raise ParameterError("initial", "one of " + ", ".join(INITIAL_METHODS), self.initial)
        kind = self.kind
        if kind is None:
            kind = FILE if self.file is not None else "sphere"
        if not isinstance(kind, str) or kind not in (*MESH_KINDS, FILE):
            raise ParameterError(
                "mesh", "one of " + ", ".join(MESH_KINDS) + " or a mesh file", kind
            )
        if kind == FILE:
            if self.file is None:
                raise ParameterError("file", "a mesh file (path, meshio.Mesh or MeshTri)", None)
            for name, value in (("level", level), ("elements", elements)):
                if value is not None:
                    raise ParameterError(name, "left out with a mesh file (its own size)", value)
            check_mesh_source(self.file)
            if self.pole is not None:
                check_pole(self.pole)
            self._set(kind=FILE, order=None if order is None else int(order))
            return
        if self.file is not None:
            raise ParameterError("file", f"left out with mesh {kind}", self.file)
        if self.pole is not None:
            raise ParameterError("pole", "left out unless the mesh is a file", self.pole)
        if geometry == "exact" and kind != "sphere":
            why = "its ring edges follow phi_a" if kind == "ring" else "its line is exact"
            raise ParameterError("geometry", f"isoparametric with mesh {kind} ({why})", geometry)
        order = DEFAULT_ORDER if order is None else int(order)
        if kind == "axisym":
            if level is not None:
                raise ParameterError(
                    "level", "left out with mesh axisym (its size is elements)", level
                )
            size = DEFAULT_ELEMENTS if elements is None else elements
            self._set(kind=kind, order=order, elements=check_elements(size))
            return
        if elements is not None:
            raise ParameterError(
                "elements", f"left out with mesh {kind} (its size is level)", elements
            )
        size = DEFAULT_LEVEL if level is None else level
        self._set(kind=kind, order=order, level=check_level(size))

    def _set(self, **values: Any) -> None:
        for name, value in values.items():
            object.__setattr__(self, name, value)

    @classmethod
    def of(cls, mesh: Any = None, **fields: Any) -> MeshOptions:
        """``mesh`` as options: a :class:`MeshOptions`, a kind name or the user's mesh.

        ``fields`` (level, elements, order, pole, geometry, initial; None: not
        given) complete a kind name or a mesh file; with a :class:`MeshOptions`
        they are refused (it is complete).
        """
        given = {k: v for k, v in fields.items() if v is not None}
        if isinstance(mesh, cls):
            for name, value in given.items():
                raise ParameterError(name, "left out with a MeshOptions (set it there)", value)
            return mesh
        if _is_source(mesh):
            try:
                return cls(FILE, file=mesh, **given)
            except ParameterError as error:  # the verb's argument is mesh, not file
                if error.name != "file":
                    raise
                raise ParameterError("mesh", error.valid, error.got) from None
        return cls(mesh, **given)

    def require(self, kinds: tuple[str, ...] = MESH_KINDS, *, files: bool = True) -> MeshOptions:
        """Refuse a kind the caller cannot use (export and render need a sphere); return self."""
        if self.kind == FILE and not files:
            raise ParameterError("mesh", "one of " + ", ".join(kinds) + " here", self.label)
        if self.kind != FILE and self.kind not in kinds:
            valid = "one of " + ", ".join(kinds) + (" or a mesh file" if files else "")
            raise ParameterError("mesh", valid, self.kind)
        return self

    def as_dict(self) -> dict[str, Any]:
        """The options for JSON and provenance (a file as its path)."""
        if self.file is None or isinstance(self.file, (str, os.PathLike)):
            file = None if self.file is None else os.fspath(self.file)
        else:
            file = type(self.file).__name__
        pole = self.pole if self.pole is None or isinstance(self.pole, str) else list(self.pole)
        return {
            "kind": self.kind,
            "level": self.level,
            "elements": self.elements,
            "order": self.order,
            "file": file,
            "pole": pole,
            "geometry": self.geometry,
            "initial": self.initial,
        }

    @classmethod
    def resolve(
        cls,
        mesh: Any = None,
        *,
        level: int | None = None,
        elements: int | None = None,
        order: int | None = None,
        pole: Any = None,
        geometry: str | None = None,
        kinds: tuple[str, ...] = MESH_KINDS,
        files: bool = True,
    ) -> MeshOptions:
        """:meth:`of` with the loose fields, then :meth:`require` (``kinds``, ``files``)."""
        fields = {"level": level, "elements": elements, "order": order, "pole": pole}
        spec = cls.of(mesh, geometry=geometry, **fields)
        return spec.require(kinds, files=files)

    @property
    def label(self) -> str:
        """Short description, e.g. ``sphere L3 P2``, ``axisym 400 P2`` or ``file ball.msh``.

        ``exact`` is appended with the exact geometry.
        """
        exact = " exact" if self.geometry == "exact" else ""
        if self.kind == FILE:
            name = self.file if isinstance(self.file, (str, os.PathLike)) else "mesh"
            order = "" if self.order is None else f" P{self.order}"
            return f"file {Path(name).name}{order}{exact}"
        size = f"L{self.level}" if self.elements is None else f"{self.elements}"
        return f"{self.kind} {size} P{self.order}{exact}"

    def load(self) -> Any:
        """The user's mesh, checked and on the unit sphere (:class:`MeshInput`), or None."""
        if self.kind != FILE:
            return None
        from twoball.fem_membrane.mesh_input import load_sphere_mesh

        return load_sphere_mesh(self.file, pole=self.pole, order=self.order)


def _is_source(mesh: Any) -> bool:
    """True if ``mesh`` names the user's mesh rather than a kind."""
    if mesh is None:
        return False
    if isinstance(mesh, str):
        return mesh not in MESH_KINDS and (bool(Path(mesh).suffix) or os.path.exists(mesh))
    return isinstance(mesh, os.PathLike) or not isinstance(mesh, (int, float, bytes))


def refuse_mesh_options(reason: str, **given: object) -> None:
    """Raise :class:`ParameterError` for the first of ``given`` that is not None.

    Used where no mesh is involved (the closed-form backend).
    """
    for name, value in given.items():
        if value is not None:
            shown = os.fspath(value) if isinstance(value, os.PathLike) else value
            raise ParameterError(name, f"left out {reason}", shown)
