"""The membrane on finite elements as a lower ball: the object that builds its modal description.

:class:`FEBall` is the finite-element implementation of the
:class:`~twoball.modal.balls.protocol.Ball` protocol, beside the Legendre modes
of :class:`~twoball.modal.balls.membrane.LegendreBall`: the same physics (the
case's membrane), a different discretisation.  On the axisymmetric line it is
the drop's ball (:func:`~twoball.fem_membrane.floor.axisym_ball`: the centre's
height, the eigenvectors of the whole space, the floor at the lower nodes); on
a sphere mesh it serves a body's contact on the paper's start
(:func:`~twoball.fem_membrane.contact.sphere_ball`), where no floor is needed.
No numerical library is imported until :meth:`FEBall.describe` runs.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

from twoball._common.errors import ParameterError
from twoball._common.keywords import checked
from twoball.fem_membrane.options import MeshOptions

if TYPE_CHECKING:
    from twoball.modal.balls.description import ModalBall
    from twoball.modal.parameters import Case

__all__ = ["DEFAULT_ELEMENTS", "FEBall", "drop_elements"]

#: Axisymmetric elements of the drop's line at P2: node spacing pi / 192, as N = 192.
DEFAULT_ELEMENTS = 96
#: Nodes of the drop's default line at every order: ``NODE_INTERVALS / order`` elements.
NODE_INTERVALS = 2 * DEFAULT_ELEMENTS


@checked
def drop_elements(order: int) -> int:
    """Default axisymmetric elements of the drop at ``order``: the node spacing pi / 192.

    192 at P1, 96 at P2, 64 at P3, 48 at P4: the floor points (the nodes of the
    lower hemisphere) are the same 96 whatever the order, so the contact is
    resolved alike and an order given explicitly changes the polynomial, not
    the floor.

    Examples
    --------
    >>> import twoball
    >>> [twoball.drop_elements(p) for p in (1, 2, 3, 4)]
    [192, 96, 64, 48]
    """
    from numbers import Integral

    if isinstance(order, bool) or not isinstance(order, Integral) or not 1 <= order <= 4:
        raise ParameterError("order", "an element order 1, 2, 3 or 4", order)
    return -(-NODE_INTERVALS // int(order))


@checked
@dataclass(frozen=True)
class FEBall:
    """The case's membrane on finite elements: a lower ball for the drop and the body's contact.

    Parameters
    ----------
    mesh : MeshOptions or "axisym", optional
        The axisymmetric line (default, or ``"axisym"``: 96 P2 elements, node
        spacing pi / 192; :func:`drop_elements` gives that spacing at every
        order), or any :class:`~twoball.MeshOptions` used as given (a sphere
        mesh serves the body on the paper's start, not the drop: the floor's
        contact is axisymmetric).  ``MeshOptions("axisym")`` without
        ``elements`` is the lift-off's line, 400 elements: for the drop's
        spacing at another order give ``elements=drop_elements(order)``, as
        ``--backend fem --order P`` does.

    Examples
    --------
    >>> import twoball
    >>> twoball.FEBall().label
    'axisym 96 P2'
    >>> twoball.FEBall(twoball.MeshOptions("axisym", elements=64, order=3)).size(None)
    (192, 96)
    >>> from twoball.modal.floor.bounce import bounce_problem
    >>> case = bounce_problem().case  # the basketball as it drops (pressure, gas, operator)
    >>> ball = twoball.FEBall().describe(case)
    >>> ball.modes, ball.points, ball.centre  # the centre's height, 192 eigenvectors; 96 points
    (193, 96, 0)
    """

    mesh: Any = None

    #: The physics of this ball (the JSON's ``ball``) and its discretisation.
    kind = "membrane"
    backend = "fem"

    def __post_init__(self) -> None:
        mesh = self.mesh
        if mesh is None or (isinstance(mesh, str) and mesh == "axisym"):
            mesh = MeshOptions("axisym", elements=DEFAULT_ELEMENTS)
        object.__setattr__(self, "mesh", MeshOptions.of(mesh))

    @property
    def label(self) -> str:
        """The mesh in words (``axisym 96 P2``)."""
        return self.mesh.label

    @property
    def dense(self) -> bool:
        """Its build solves a dense eigenproblem of the whole space (the axisymmetric line)."""
        return self.mesh.kind == "axisym"

    def size(self, case: Case | None = None) -> tuple[int, int] | None:
        """The drop's size as its cost model counts it: unknowns and floor points.

        ``elements * order`` (the line's nodes but one, the degree-1 vector the
        centre replaces; :meth:`describe` adds the centre) and half of them on
        the floor.  None on a sphere mesh (its size is known once it is built).
        """
        if self.mesh.kind != "axisym":
            return None
        dofs = self.mesh.elements * self.mesh.order
        return dofs, dofs // 2

    def mass(self, case: Case) -> float:
        """The ball's mass ``m2 = 2 pi R P / c^2`` [kg] (``membrane_mass`` of the scalings).

        The tension ``T = P R / 2`` with ``c^2 = T / (rho R^2)``, eq. (3.8).
        """
        from twoball.modal.scalings import membrane_mass

        return membrane_mass(case.radius, case.pressure, case.wave_speed)

    def summary(self, case: Case) -> dict[str, Any]:
        """The membrane's spectrum for the JSON (:func:`~twoball.modal.balls.membrane.summary`)."""
        from twoball.modal.balls.membrane import summary

        return summary(case)

    def describe(self, case: Case, monitor: Any = None, *, anchored: bool = False) -> ModalBall:
        """The membrane of ``case`` on this mesh (dimensionless: R, 1/c, m2).

        The axisymmetric line with the centre free is the drop's ball; ``anchored``
        (degree 1 a mode about a centre that does not move, no floor) is the body
        on the paper's start.  A sphere mesh is refused here: a body on its start
        runs on the finite elements' modal series
        (:func:`~twoball.fem_membrane.contact.fem_contact_solution`).
        """
        if self.mesh.kind == "axisym":
            from twoball.fem_membrane.floor import axisym_ball

            return axisym_ball(
                self.mesh.elements,
                self.mesh.order,
                case.stiffness,
                case.damping_law,
                anchored=anchored,
                monitor=monitor,
            )
        valid = (
            "axisym for a ball described here (the floor contact is axisymmetric; a body "
            "on a sphere mesh's start is solved on its modal series by liftoff)"
        )
        raise ParameterError("mesh", valid, self.label)

    def as_dict(self) -> dict[str, Any]:
        """``{"ball": "membrane", "discretisation": "fem", "mesh": {...}}``."""
        return {"ball": self.kind, "discretisation": self.backend, "mesh": self.mesh.as_dict()}
