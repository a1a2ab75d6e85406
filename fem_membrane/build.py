"""Build a finite-element space from command-line style options (validated)."""

from __future__ import annotations

from twoball.modal.initial import _check_phi_a

from .axisym import axisym_space
from .checks import MESH_KINDS, check_choice, check_elements, check_level, check_order
from .mesh import icosphere, ring_sphere
from .space import Discretisation, sphere_space

DEFAULT_LEVEL = 3
DEFAULT_ELEMENTS = 400


def build_space(
    mesh: str = "sphere",
    *,
    level: int | None = None,
    elements: int | None = None,
    order: int = 2,
    phi_a: float = 2.6,
) -> Discretisation:
    """The finite-element space of eq. (3.9) for a mesh kind (dimensionless).

    Parameters
    ----------
    mesh : {"sphere", "ring", "axisym"}
        ``sphere``: icosphere of ``level``; ``ring``: sphere with a ring of
        edges on the latitude ``phi_a``; ``axisym``: line x = cos(phi) with
        ``elements`` elements and a node at cos(phi_a).
    level : int, optional
        Refinement level >= 0 of the sphere meshes (``--level``; default 3).
    elements : int, optional
        Elements >= 2 of the axisymmetric mesh (``--elements``; default 400).
    order : {1, 2, 3, 4}
        Element (and geometry) order (``--order``).
    phi_a : float
        Contact angle [rad] in (pi/2, pi).

    Returns
    -------
    Discretisation
    """
    mesh = check_choice("--mesh", mesh, MESH_KINDS)
    order = check_order(order)
    phi_a = _check_phi_a(phi_a)
    level = DEFAULT_LEVEL if level is None else check_level(level)
    elements = DEFAULT_ELEMENTS if elements is None else check_elements(elements)
    if mesh == "axisym":
        return axisym_space(elements, phi_a, order)
    if mesh == "ring":
        return sphere_space(ring_sphere(level, phi_a, order))
    return sphere_space(icosphere(level, order))
