"""The upper body as a body of its own: rigid, lumped elastic, or a second modal ball.

:mod:`~twoball.modal.upper.laws` is a body's own contact law (stiffness,
restitution against a rigid floor, contact disc);
:mod:`~twoball.modal.upper.options` the body objects (:class:`LumpedBody`,
:class:`BallBody`); :mod:`~twoball.modal.upper.system` their place in the
drop's contact problem; :mod:`~twoball.modal.upper.build` builds it from SI;
:mod:`~twoball.modal.upper.measure` their measures; :mod:`~twoball.modal.upper.alone`
a body dropped alone on a rigid floor; :mod:`~twoball.modal.upper.collide` two
balls colliding in free space.  The presets of Table 1's bodies are
:mod:`twoball.modal.bodies`.  Names load on first use.
"""

from twoball._common.lazy import attach

_NAMES = {
    "ContactLaw": "twoball.modal.upper.laws",
    "LumpedBody": "twoball.modal.upper.options",
    "BallBody": "twoball.modal.upper.options",
    "BODY_KINDS": "twoball.modal.upper.options",
    "body_kind": "twoball.modal.upper.options",
}
__getattr__, __dir__ = attach(__name__, _NAMES)
__all__ = sorted(_NAMES)
