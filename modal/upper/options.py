"""The elastic upper bodies as option objects (SI): a lumped body and a ball body.

Three kinds of upper body ride the whole bounce (docs: *Elastic bodies*):

``rigid``
    :class:`twoball.Body`: Newton's e12 on a cap of fixed radius (eqs. (B1)-(B2)
    of :mod:`twoball.modal.floor.system`), the reference.
:class:`LumpedBody` (``lumped``)
    A point mass with its own contact law against the lower ball
    (:class:`~twoball.modal.upper.laws.ContactLaw`: its stiffness, its
    dissipation from its own restitution against a rigid floor, a contact disc
    that grows with its compression); the collision's e12 is an output.
:class:`BallBody` (``ball``)
    A second modal ball (any :class:`~twoball.modal.balls.protocol.Ball` with
    its own :class:`~twoball.Case`), whose lower surface meets the lower ball's
    top through unilateral rows across a disc: both balls' modes, one contact
    problem, the same integrator.

Every object checks its fields when built (:class:`~twoball.ParameterError`
naming the field) and gives ``as_dict()`` for the JSON and the provenance.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any

from twoball._common.errors import ParameterError, bounded, check_labels
from twoball._common.keywords import checked
from twoball.modal.upper.laws import ContactLaw

__all__ = ["BODY_KINDS", "BallBody", "LumpedBody", "body_kind"]

#: The kinds of upper body, by the name ``--body`` takes.
BODY_KINDS = ("rigid", "lumped", "ball")
#: Default substeps per contact time of a lumped body on a rigid floor.
DEFAULT_STEPS = 100
#: Default Legendre degree of a ball body.
DEFAULT_BODY_MODES = 64
#: Default polar half-angle [rad] of a ball body's contact rows around its south pole.
DEFAULT_REACH = 1.0


def body_kind(body: object) -> str:
    """``rigid``, ``lumped`` or ``ball`` of a body object (a :class:`twoball.Body` is rigid)."""
    return str(getattr(body, "kind", "rigid"))


@checked
@dataclass(frozen=True)
class LumpedBody:
    """An elastic upper body lumped to a point mass with its own contact law (SI).

    Parameters
    ----------
    mass_ratio : float
        mu = m1 / m2 in (0, 100].
    law : ContactLaw
        Its stiffness law, restitution against a rigid floor and size.
    steps : int
        Steps per contact time on a rigid floor while it is compressed (default
        100, at most 10000; the step error of e is then below 1e-4).
    name, source : str
        What it is and where its values come from (the presets say).

    Examples
    --------
    >>> import twoball
    >>> law = twoball.ContactLaw("pressure", 0.83, radius=0.0335, pressure=82700.0)
    >>> body = twoball.LumpedBody(0.101, law)
    >>> body.kind, body.restitution
    ('lumped', 0.83)
    >>> twoball.LumpedBody(0.0, law)
    Traceback (most recent call last):
    ...
    twoball.ParameterError: mass_ratio must be a number in (0, 100], got 0.0
    """

    mass_ratio: float
    law: ContactLaw
    steps: int = DEFAULT_STEPS
    name: str = ""
    source: str = field(default="", repr=False)

    kind = "lumped"

    def __post_init__(self) -> None:
        check_labels(self, "name", "source")
        object.__setattr__(
            self, "mass_ratio", bounded("mass_ratio", self.mass_ratio, 0.0, 100.0, low_open=True)
        )
        if not isinstance(self.law, ContactLaw):
            raise ParameterError("law", "a twoball.ContactLaw", type(self.law).__name__)
        steps = self.steps
        if isinstance(steps, bool) or not isinstance(steps, int) or not 8 <= steps <= 10_000:
            raise ParameterError("steps", "an integer in [8, 10000]", self.steps)

    @property
    def restitution(self) -> float:
        """Its coefficient of restitution against a rigid floor."""
        return self.law.restitution

    def as_dict(self) -> dict[str, Any]:
        """The body for the JSON (SI)."""
        return {
            "kind": self.kind,
            "mass_ratio": self.mass_ratio,
            "law": self.law.as_dict(),
            "body_restitution": self.restitution,
            "steps": self.steps,
            "name": self.name,
            "source": self.source,
        }


@checked
@dataclass(frozen=True)
class BallBody:
    """A second modal ball as the upper body (SI); its mass is its own ball's.

    Parameters
    ----------
    case : Case, optional
        The body's own ball (radius, wave speed, pressure, damping; default the
        ``tennis`` preset).  Its |v0| is not used (the body falls with the lower
        ball, or at the drop's speed when dropped alone).
    ball : Ball, optional
        Its discretisation (default ``LegendreBall(64)``).
    damping : ModalRatio or Rayleigh, optional
        Its damping law (default the case's own).
    reach : float
        Polar half-angle [rad] around its south pole of the points that may
        touch the lower ball (default 1.0; one row each).
    restitution : float, optional
        The restitution against a rigid floor its damping was set to give (a
        preset's; stated in the JSON as ``body_restitution``; None: not stated,
        its drop alone says).
    name, source : str
        What it is and where its values come from.

    Examples
    --------
    >>> import twoball
    >>> body = twoball.BallBody()
    >>> body.kind, body.ball.label
    ('ball', 'legendre N = 64')
    """

    case: Any = None
    ball: Any = None
    damping: Any = None
    reach: float = DEFAULT_REACH
    restitution: float | None = None
    name: str = ""
    source: str = field(default="", repr=False)

    kind = "ball"

    def __post_init__(self) -> None:
        check_labels(self, "name", "source")
        from twoball.modal.balls.membrane import LegendreBall
        from twoball.modal.balls.protocol import check_ball
        from twoball.modal.damping import ModalRatio, Rayleigh
        from twoball.modal.parameters import Case

        case = Case.preset("tennis") if self.case is None else self.case
        if not isinstance(case, Case):
            raise ParameterError("case", "a twoball.Case (the body's ball)", type(case).__name__)
        object.__setattr__(self, "case", case)
        ball = LegendreBall(DEFAULT_BODY_MODES) if self.ball is None else self.ball
        object.__setattr__(self, "ball", check_ball(ball, "ball"))
        if self.damping is not None and not isinstance(self.damping, (ModalRatio, Rayleigh)):
            raise ParameterError("damping", "a twoball.ModalRatio or Rayleigh", self.damping)
        reach = bounded("reach", self.reach, 0.0, 0.5 * math.pi, "rad", low_open=True)
        object.__setattr__(self, "reach", reach)
        if self.restitution is not None:
            e = bounded("restitution", self.restitution, 0.0, 1.0, low_open=True)
            object.__setattr__(self, "restitution", e)

    def as_dict(self) -> dict[str, Any]:
        """The body for the JSON (SI)."""
        law = self.damping.as_dict() if self.damping is not None else None
        return {
            "kind": self.kind,
            "preset": self.case.preset_name,
            "radius_m": self.case.radius,
            "wave_speed_1_s": self.case.wave_speed,
            "pressure_Pa": self.case.pressure,
            "ball": self.ball.as_dict(),
            "damping": law if law is not None else {"law": "modal", "ratio": self.case.damping},
            "reach_rad": self.reach,
            "body_restitution": self.restitution,
            "name": self.name,
            "source": self.source,
        }
