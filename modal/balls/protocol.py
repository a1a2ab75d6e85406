"""What a lower ball is to the drop: the protocol every kind of ball implements.

A ball object knows its physics and its discretisation.  Given the case (SI:
the radius R and the time unit ``1/c`` of the run, and for the membranes the
pressure, gas, operator, bending and damping law), it builds the dimensionless
:class:`~twoball.modal.balls.description.ModalBall` that the contact core
consumes, and it says what its mass is in SI (the unit of mass of the run).

Kinds today: the membrane on Legendre modes
(:class:`~twoball.modal.balls.membrane.LegendreBall`) and on axisymmetric finite
elements (:class:`twoball.fem_membrane.ball.FEBall`).  A shell with tangential
displacement, a solid ball or an elastic body are further classes with the
same four members; nothing in the contact core
(:mod:`twoball.modal.floor.system`, :mod:`twoball.modal.nonsmooth`), the
measures (:mod:`twoball.modal.floor.measure`, :mod:`twoball.modal.floor.body`)
or the reports changes for them (docs: *Architecture*, "a new ball").
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any, Protocol, runtime_checkable

if TYPE_CHECKING:
    from twoball.modal.balls.description import ModalBall
    from twoball.modal.parameters import Case

__all__ = ["Ball", "check_ball"]


@runtime_checkable
class Ball(Protocol):
    """A kind of lower ball on a discretisation (SI in, dimensionless inside).

    Attributes
    ----------
    kind : str
        The physics (``"membrane"``, ...), the JSON's ``ball``.
    backend : str
        The discretisation (``"legendre"``, ``"fem"``), the JSON's ``backend``.
    label : str
        The resolution in words (``"legendre N = 192"``, ``"axisym 96 P2"``).

    A ball may also have ``summary(case) -> dict`` (its physics for the JSON's
    ``model`` block) and ``dense`` (its build solves a dense eigenproblem: for
    the cost estimate).

    Examples
    --------
    >>> import twoball
    >>> isinstance(twoball.LegendreBall(64), twoball.Ball), isinstance(object(), twoball.Ball)
    (True, False)
    >>> solver = twoball.MoreauJean(twoball.LegendreBall(64))  # any Ball steps the same way
    >>> round(twoball.bounce(solver=solver).e2, 2)
    0.88
    """

    kind: str
    backend: str

    @property
    def label(self) -> str:
        """The resolution in words."""
        ...

    def mass(self, case: Case) -> float:
        """The ball's mass [kg]: the unit of mass of the run."""
        ...

    def size(self, case: Case) -> tuple[int, int] | None:
        """Coordinates and floor points of :meth:`describe`, known before it runs (None: not)."""
        ...

    def describe(self, case: Case, monitor: Any = None) -> ModalBall:
        """The ball in modal coordinates, in units of ``case.radius``, ``1 / case.wave_speed``
        and :meth:`mass`; ``monitor`` (a :class:`~twoball._common.monitor.Monitor`) is told
        what a long build does."""
        ...

    def as_dict(self) -> dict[str, Any]:
        """The ball's own options, for the JSON and provenance (``{"ball": kind, ...}``)."""
        ...


def check_ball(ball: object, name: str = "ball") -> Ball:
    """``ball`` if it implements :class:`Ball`, else a ParameterError naming ``name``."""
    from twoball._common.errors import ParameterError

    if not isinstance(ball, Ball):
        valid = "a ball object (twoball.LegendreBall, twoball.FEBall, or any twoball.Ball)"
        raise ParameterError(name, valid, type(ball).__name__)
    return ball
