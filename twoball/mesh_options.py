"""The one definition of the finite-element mesh options (kind, size, order).

Every entry point that takes a mesh -- :func:`twoball.liftoff` with the FE
backend, :func:`twoball.fem.solve`, :func:`twoball.fem.eigen`,
:func:`twoball.export`, :func:`twoball.render`, :func:`twoball.plot` and the
command-line subcommands built on them -- resolves its ``mesh``, ``level``,
``elements`` and ``order`` arguments here, so the defaults and the refusals
(``level`` on the axisymmetric line, ``elements`` on a sphere) are the same
everywhere.  No numerical library is imported by this module.
"""

from __future__ import annotations

from dataclasses import dataclass
from numbers import Integral

from twoball.modal.errors import ParameterError

#: Mesh kinds: icosphere, sphere with a ring of edges at phi_a, axisymmetric line.
MESH_KINDS: tuple[str, ...] = ("sphere", "ring", "axisym")
SPHERE_KINDS: tuple[str, ...] = ("sphere", "ring")
DEFAULT_LEVEL = 3  # icosphere refinement level (1280 triangles)
DEFAULT_ELEMENTS = 400  # elements of the axisymmetric line
DEFAULT_ORDER = 2  # isoparametric P2


def _integer(name: str, value: object, low: int, valid: str) -> int:
    if isinstance(value, bool) or not isinstance(value, Integral) or int(value) < low:
        raise ParameterError(name, valid, value)
    return int(value)


@dataclass(frozen=True)
class MeshOptions:
    """A validated choice of finite-element mesh (dimensionless, unit sphere).

    Attributes
    ----------
    kind : {"sphere", "ring", "axisym"}
        Icosphere, ring sphere (edges along phi = phi_a) or the line x = cos(phi).
    level : int or None
        Sphere refinement level >= 0 (None on the axisymmetric line).
    elements : int or None
        Line elements >= 2 of ``axisym`` (None on the spheres).
    order : {1, 2}
        Element and geometry order.
    """

    kind: str = "sphere"
    level: int | None = DEFAULT_LEVEL
    elements: int | None = None
    order: int = DEFAULT_ORDER

    @classmethod
    def resolve(
        cls,
        mesh: str | None = None,
        *,
        level: int | None = None,
        elements: int | None = None,
        order: int | None = None,
        kinds: tuple[str, ...] = MESH_KINDS,
    ) -> MeshOptions:
        """Check the options against each other and fill in the defaults.

        Parameters
        ----------
        mesh : str, optional
            Mesh kind among ``kinds`` (default ``sphere``).
        level : int, optional
            Sphere refinement level >= 0 (default 3); refused with ``axisym``.
        elements : int, optional
            Elements >= 2 of ``axisym`` (default 400); refused on a sphere.
        order : int, optional
            1 or 2 (default 2).
        kinds : tuple of str
            The kinds the caller can use (export and render need a sphere).
        """
        kind = "sphere" if mesh is None else mesh
        if not isinstance(kind, str) or kind not in kinds:
            raise ParameterError("mesh", "one of " + ", ".join(kinds), mesh)
        if order is None:
            order = DEFAULT_ORDER
        elif isinstance(order, bool) or not isinstance(order, Integral) or order not in (1, 2):
            raise ParameterError("order", "1 or 2", order)
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
        return cls(kind, _integer("level", size, 0, "an integer >= 0"), None, int(order))

    @property
    def label(self) -> str:
        """Short description, e.g. ``sphere L3 P2`` or ``axisym 400 P2``."""
        size = f"L{self.level}" if self.elements is None else f"{self.elements}"
        return f"{self.kind} {size} P{self.order}"


def refuse_mesh_options(reason: str, **given: object) -> None:
    """Raise :class:`ParameterError` for the first of ``given`` that is not None.

    Used where no mesh is involved (the closed-form backend).
    """
    for name, value in given.items():
        if value is not None:
            raise ParameterError(name, f"left out {reason}", value)
