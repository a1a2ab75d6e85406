"""Build a finite-element space from a mesh kind and its options, or from a sphere mesh."""

from __future__ import annotations

from twoball._common.choices import DEFAULT_ELEMENTS, DEFAULT_LEVEL, MESH_KINDS
from twoball._common.errors import ParameterError
from twoball.fem_membrane.axisym import axisym_space
from twoball.fem_membrane.mesh import SphereMesh, icosphere, ring_sphere
from twoball.fem_membrane.space import Discretisation, sphere_space
from twoball.fem_membrane.validate import (
    GEOMETRIES,
    check_choice,
    check_elements,
    check_level,
    check_order,
)
from twoball.modal.initial import check_phi_a


def build_space(
    mesh: str | SphereMesh = "sphere",
    *,
    level: int | None = None,
    elements: int | None = None,
    order: int | None = 2,
    phi_a: float = 2.6,
    geometry: str = "isoparametric",
) -> Discretisation:
    """The finite-element space of eq. (3.9) for a mesh kind or a sphere mesh (dimensionless).

    Parameters
    ----------
    mesh : {"sphere", "ring", "axisym"} or SphereMesh
        ``sphere``: icosphere of ``level``; ``ring``: sphere with a ring of
        edges on the latitude ``phi_a``; ``axisym``: line x = cos(phi) with
        ``elements`` elements and a node at cos(phi_a); a
        :class:`~twoball.fem_membrane.mesh.SphereMesh` (e.g. the ``mesh`` of
        :func:`twoball.fem_membrane.mesh_input.load_sphere_mesh`) is used as it is.
    level : int, optional
        Refinement level of the generated sphere meshes, in [0, 10] (default 3).
    elements : int, optional
        Elements >= 2 of the axisymmetric mesh (default 400).
    order : {1, 2, 3, 4}, optional
        Element (and geometry) order; None for a SphereMesh: its own.
    phi_a : float
        Contact angle [rad] in (pi/2, pi).
    geometry : {"isoparametric", "exact"}
        Discrete sphere (see :func:`~twoball.fem_membrane.space.sphere_space`):
        ``exact`` on the icosphere and a given SphereMesh only; the ring keeps
        its edges on phi_a and the straight axisymmetric line is exact already.

    Returns
    -------
    Discretisation
    """
    phi_a = check_phi_a(phi_a)
    geometry = check_choice("geometry", geometry, GEOMETRIES)
    if isinstance(mesh, SphereMesh):
        for name, value in (("level", level), ("elements", elements)):
            if value is not None:
                raise ParameterError(name, "left out with a given sphere mesh", value)
        return sphere_space(mesh, None if order is None else check_order(order), geometry)
    mesh = check_choice("mesh", mesh, MESH_KINDS)
    order = check_order(2 if order is None else order)
    if mesh == "axisym":  # the size that applies (callers may pass one number as both)
        elements = DEFAULT_ELEMENTS if elements is None else check_elements(elements)
    else:
        level = DEFAULT_LEVEL if level is None else check_level(level)
    if mesh != "sphere" and geometry == "exact":
        why = "its ring edges follow phi_a" if mesh == "ring" else "its line is exact"
        raise ParameterError("geometry", f"isoparametric with mesh {mesh} ({why})", geometry)
    if mesh == "axisym":
        return axisym_space(elements, phi_a, order)
    if mesh == "ring":
        return sphere_space(ring_sphere(level, phi_a, order))
    if geometry == "exact":  # the order-1 mesh: nodes are rebuilt as exact images
        return sphere_space(icosphere(level), order, geometry)
    return sphere_space(icosphere(level, order))
