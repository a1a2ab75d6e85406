"""The thin spherical shell on finite elements of the meridian as a lower ball for the drop.

:class:`FEShellBall` is the finite-element implementation of the shell beside the
closed form of :class:`~twoball.modal.balls.shell.ShellBall`: the same physics
(the case's tension, gas and damping law and the :class:`~twoball.modal.balls.shell.Wall`),
another discretisation (:func:`twoball.fem_shell.modes.fem_shell_modes`: cubic
Hermite w, Lagrange v of order 1-3, the rigid translation added exactly).  Every
eigenpair of the finite-element space is a coordinate (a change of coordinates,
exact to rounding: the contact core integrates the finite-element equations);
the translation's mode is the drop's centre, cleaned to the exact rigid motion
(its finite-element part and every other mode's share of the translation, both
at rounding, are set to zero).  The floor points are the mesh nodes of the
lower hemisphere (phi > pi/2).  No numerical library is imported until
:meth:`FEShellBall.describe` runs.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

from twoball._common.errors import ParameterError
from twoball._common.keywords import checked
from twoball.modal.balls.shell import Wall, _check_wall, _wall_of, shell_summary

if TYPE_CHECKING:
    from twoball.fem_shell.modes import ShellFEModes
    from twoball.modal.balls.description import ModalBall
    from twoball.modal.parameters import Case
    from twoball.modal.shell.parameters import ShellParameters

__all__ = ["DEFAULT_SHELL_ELEMENTS", "FEShellBall", "fe_shell_ball", "exact_translation"]

#: Elements of the meridian by default (v P2): node spacing pi / 64, 4 E modes.
DEFAULT_SHELL_ELEMENTS = 64
#: Elements the meridian takes.
SHELL_ELEMENTS_RANGE = (4, 1000)
#: Lagrange orders of v.
SHELL_ORDERS = (1, 2, 3)


def exact_translation(modes: ShellFEModes) -> ShellFEModes:
    """The modes with the translation exact: ``t`` alone in its mode, no ``t`` in the others.

    With ``exact_translation`` the eigensolver returns the translation's mode and
    every other mode M-orthogonal to it up to rounding (its finite-element part
    ~1e-15, the others' amounts of t ~1e-14); here those are set to zero, so the
    centre's row is 1 at every point to the bit, the other modes move the centre
    of mass by exactly nothing, and ``Omega`` of the translation is 0.
    """
    from dataclasses import replace

    import numpy as np

    k = modes.translation
    vectors = modes.vectors.copy()
    vectors[:, k] = 0.0
    amplitude = np.zeros_like(modes.translation_amplitude)
    amplitude[k] = 1.0
    omega = modes.omega.copy()
    omega[k] = 0.0
    return replace(modes, vectors=vectors, translation_amplitude=amplitude, omega=omega)


def fe_shell_ball(
    parameters: ShellParameters,
    elements: int,
    order: int,
    law: Any,
    label: str = "",
) -> ModalBall:
    """The shell on ``elements`` meridian elements (v of ``order``) as a :class:`ModalBall`.

    Dimensionless (R, 1/c, m).  Floor points: the nodes with phi > pi/2.
    """
    import numpy as np

    from twoball.fem_shell.modes import fem_shell_modes
    from twoball.modal.balls.shell import shell_description

    modes = exact_translation(fem_shell_modes(parameters, elements, v_order=order))
    degree, _ = modes.degrees
    degree = np.asarray(degree).copy()
    degree[modes.translation] = 1
    nodes = modes.nodes
    phi = np.asarray(nodes[nodes > 0.5 * np.pi], dtype=float)
    return shell_description(
        omega=np.array(modes.omega, dtype=float),
        degree=degree,
        translation=modes.translation,
        parameters=parameters,
        law=law,
        phi=phi,
        vertical=modes.vertical,
        radial=modes.radial,
        meridional=modes.meridional,
        cap_average=modes.cap_average,
        label=label or f"shell meridian {elements} P{order}",
    )


@checked
@dataclass(frozen=True)
class FEShellBall:
    """The thin spherical shell on finite elements of the meridian: a lower ball for the drop.

    Parameters
    ----------
    wall : Wall, optional
        The wall (default: the case's preset's, :data:`twoball.modal.balls.shell.WALLS`).
    elements : int, optional
        Equal elements on ``phi in [0, pi]``, in [4, 1000] (default
        :data:`DEFAULT_SHELL_ELEMENTS`, 64); about ``2 (order + 1) E`` modes.
    order : {1, 2, 3}
        Lagrange order of the meridional displacement v (default 2); the radial
        displacement w is cubic Hermite (C^1, for the bending).

    Examples
    --------
    >>> import twoball
    >>> twoball.FEShellBall(elements=32).label
    'shell meridian 32 P2'
    >>> twoball.FEShellBall(order=4)
    Traceback (most recent call last):
    ...
    twoball.ParameterError: order must be one of 1, 2, 3 (the Lagrange order of v), got 4
    """

    wall: Wall | None = None
    elements: int | None = None
    order: int = 2

    #: The physics of this ball (the JSON's ``ball``) and its discretisation.
    kind = "shell"
    backend = "fem"
    #: Its build solves a dense eigenproblem (for the cost estimate).
    dense = True

    def __post_init__(self) -> None:
        _check_wall(self.wall)
        if self.elements is not None:
            low, high = SHELL_ELEMENTS_RANGE
            if (
                isinstance(self.elements, bool)
                or not isinstance(self.elements, int)
                or not low <= self.elements <= high
            ):
                raise ParameterError("elements", f"an integer in [{low}, {high}]", self.elements)
        if isinstance(self.order, bool) or self.order not in SHELL_ORDERS:
            valid = "one of 1, 2, 3 (the Lagrange order of v)"
            raise ParameterError("order", valid, self.order)

    @property
    def mesh_elements(self) -> int:
        """E (the default when none was given)."""
        return DEFAULT_SHELL_ELEMENTS if self.elements is None else self.elements

    @property
    def label(self) -> str:
        """``shell meridian 64 P2``."""
        return f"shell meridian {self.mesh_elements} P{self.order}"

    def size(self, case: Case | None = None) -> tuple[int, int]:
        """Coordinates (every eigenpair of the space) and floor points (the lower nodes)."""
        e = self.mesh_elements
        dofs = 2 * (e + 1) - 2 + self.order * e - 1
        return dofs, e // 2 + (0 if e % 2 == 0 else 1)

    def mass(self, case: Case) -> float:
        """The ball's mass ``2 pi R P / c^2`` [kg]: c is the wave speed of the tension PR/2."""
        from twoball.modal.scalings import membrane_mass

        return membrane_mass(case.radius, case.pressure, case.wave_speed)

    def wall_of(self, case: Case) -> Wall:
        """The wall in use: the ball's, else the case's preset's."""
        return _wall_of(self.wall, case)

    def summary(self, case: Case) -> dict[str, Any]:
        """The shell's block of the JSON's ``model``
        (:func:`~twoball.modal.balls.shell.shell_summary`)."""
        return shell_summary(self.wall_of(case), case)

    def describe(self, case: Case, monitor: Any = None) -> ModalBall:
        """The shell of ``case`` on the meridian's elements (dimensionless: R, 1/c, m)."""
        parameters = self.wall_of(case).parameters(case)
        if monitor is not None:
            monitor(f"eigenpairs of {self.label}")
        return fe_shell_ball(
            parameters, self.mesh_elements, self.order, case.damping_law, self.label
        )

    def as_dict(self) -> dict[str, Any]:
        """``{"ball": "shell", "discretisation": "fem", "elements": E, "order": p, ...}``."""
        wall = None if self.wall is None else self.wall.as_dict()
        return {
            "ball": self.kind,
            "discretisation": self.backend,
            "elements": self.elements,
            "order": self.order,
            "wall": wall,
        }
