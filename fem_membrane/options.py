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
from numbers import Integral
from pathlib import Path
from typing import Any

from twoball._common.errors import ParameterError

#: Mesh kinds: icosphere, sphere with a ring of edges at phi_a, axisymmetric line.
MESH_KINDS: tuple[str, ...] = ("sphere", "ring", "axisym")
SPHERE_KINDS: tuple[str, ...] = ("sphere", "ring")
DEFAULT_LEVEL = 3  # icosphere refinement level (1280 triangles)
DEFAULT_ELEMENTS = 400  # elements of the axisymmetric line
DEFAULT_ORDER = 2  # isoparametric P2
ORDERS: tuple[int, ...] = (1, 2, 3, 4)
#: Discrete sphere: the order-p interpolant through the nodes, or the sphere itself.
GEOMETRIES: tuple[str, ...] = ("isoparametric", "exact")
DEFAULT_GEOMETRY = "isoparametric"
FILE = "file"  # the kind of a user's mesh (path, meshio.Mesh, scikit-fem MeshTri)


def _integer(name: str, value: object, low: int, valid: str) -> int:
    if isinstance(value, bool) or not isinstance(value, Integral) or int(value) < low:
        raise ParameterError(name, valid, value)
    return int(value)


@dataclass(frozen=True)
class MeshOptions:
    """A validated choice of finite-element mesh (dimensionless, unit sphere).

    Attributes
    ----------
    kind : {"sphere", "ring", "axisym", "file"}
        Icosphere, ring sphere (edges along phi = phi_a), the line x = cos(phi),
        or the user's mesh (``source``).
    level : int or None
        Sphere refinement level >= 0 (None on the axisymmetric line and files).
    elements : int or None
        Line elements >= 2 of ``axisym`` (None on the spheres).
    order : {1, 2, 3, 4} or None
        Element and geometry order (None for a file: the file's own).
    source : path, meshio.Mesh or scikit-fem mesh, optional
        The user's mesh (kind ``file``).
    pole : (float, float, float) or "X,Y,Z", optional
        Pole direction in the frame of ``source`` (default +z).
    geometry : {"isoparametric", "exact"}
        Discrete sphere: the Lagrange interpolant of order ``order`` through the
        nodes, or the exact sphere (radial projection of the flat triangles;
        sphere and file meshes only).
    """

    kind: str = "sphere"
    level: int | None = DEFAULT_LEVEL
    elements: int | None = None
    order: int | None = DEFAULT_ORDER
    source: Any = None
    pole: Any = None
    geometry: str = DEFAULT_GEOMETRY

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
        """Check the options against each other and fill in the defaults.

        Parameters
        ----------
        mesh : str, path, meshio.Mesh or scikit-fem mesh, optional
            Mesh kind among ``kinds`` (default ``sphere``), or the user's sphere
            mesh: a file path (str or Path), a ``meshio.Mesh`` or a ``MeshTri``.
        level : int, optional
            Sphere refinement level >= 0 (default 3); refused with ``axisym`` and files.
        elements : int, optional
            Elements >= 2 of ``axisym`` (default 400); refused on a sphere.
        order : int, optional
            1, 2, 3 or 4 (default 2; a file: its own order).
        pole : (x, y, z) or "X,Y,Z", optional
            Pole direction of a mesh file (default +z); refused with a kind name.
        geometry : {"isoparametric", "exact"}, optional
            Default isoparametric; ``exact`` is refused on the ring sphere (its
            ring edges follow the latitude phi_a) and the axisymmetric line
            (straight, exact already).
        kinds : tuple of str
            The kinds the caller can use (export and render need a sphere).
        files : bool
            Whether the caller takes the user's meshes.
        """
        if order is not None and (
            isinstance(order, bool) or not isinstance(order, Integral) or order not in ORDERS
        ):
            raise ParameterError("order", "1, 2, 3 or 4", order)
        geometry = DEFAULT_GEOMETRY if geometry is None else geometry
        if geometry not in GEOMETRIES:
            raise ParameterError("geometry", "one of " + ", ".join(GEOMETRIES), geometry)
        if _is_source(mesh):
            if not files:
                raise ParameterError("mesh", "one of " + ", ".join(kinds) + " here", str(mesh))
            for name, value in (("level", level), ("elements", elements)):
                if value is not None:
                    raise ParameterError(name, "left out with a mesh file (its own size)", value)
            order = None if order is None else int(order)
            return cls(FILE, None, None, order, mesh, pole, geometry)
        kind = "sphere" if mesh is None else mesh
        if kind not in kinds:
            valid = "one of " + ", ".join(kinds)
            raise ParameterError("mesh", valid + (" or a mesh file" if files else ""), mesh)
        if pole is not None:
            raise ParameterError("pole", "left out unless the mesh is a file", pole)
        order = DEFAULT_ORDER if order is None else order
        if geometry == "exact" and kind != "sphere":
            why = "its ring edges follow phi_a" if kind == "ring" else "its line is exact"
            raise ParameterError("geometry", f"isoparametric with mesh {kind} ({why})", geometry)
        if kind == "axisym":
            if level is not None:
                raise ParameterError(
                    "level", "left out with mesh axisym (its size is elements)", level
                )
            size = DEFAULT_ELEMENTS if elements is None else elements
            return cls(kind, None, _integer("elements", size, 2, "an integer >= 2"), int(order))
        if elements is not None:
            raise ParameterError(
                "elements", f"left out with mesh {kind} (its size is level)", elements
            )
        size = DEFAULT_LEVEL if level is None else level
        level = _integer("level", size, 0, "an integer >= 0")
        return cls(kind, level, None, int(order), geometry=geometry)

    @property
    def label(self) -> str:
        """Short description, e.g. ``sphere L3 P2``, ``axisym 400 P2`` or ``file ball.msh``.

        ``exact`` is appended with the exact geometry.
        """
        exact = " exact" if self.geometry == "exact" else ""
        if self.kind == FILE:
            name = self.source if isinstance(self.source, (str, os.PathLike)) else "mesh"
            order = "" if self.order is None else f" P{self.order}"
            return f"file {Path(name).name}{order}{exact}"
        size = f"L{self.level}" if self.elements is None else f"{self.elements}"
        return f"{self.kind} {size} P{self.order}{exact}"

    def load(self) -> Any:
        """The user's mesh, checked and on the unit sphere (:class:`MeshInput`), or None."""
        if self.kind != FILE:
            return None
        from twoball.fem_membrane.mesh_input import load_sphere_mesh

        return load_sphere_mesh(self.source, pole=self.pole, order=self.order)


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
