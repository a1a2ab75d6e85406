"""Kinds of lower ball: the protocol, the modal description the contact core consumes, the membrane.

:mod:`~twoball.modal.balls.protocol` says what a ball is to the drop
(:class:`~twoball.modal.balls.protocol.Ball`);
:mod:`~twoball.modal.balls.description` is what it builds
(:class:`~twoball.modal.balls.description.ModalBall`: modes, spectrum, damping,
vertical rows at the floor points, the top and its caps, the centre);
:mod:`~twoball.modal.balls.membrane` is the membrane on its Legendre modes and
:mod:`~twoball.modal.balls.shell` the thin shell on its closed-form modes.  The
finite-element membrane is :mod:`twoball.fem_membrane.ball`, the finite-element
shell :mod:`twoball.fem_shell.ball`.  Names load on
first use.
"""

from twoball._common.lazy import attach

_NAMES = {
    "Ball": "twoball.modal.balls.protocol",
    "check_ball": "twoball.modal.balls.protocol",
    "ModalBall": "twoball.modal.balls.description",
    "DEFAULT_MODES": "twoball.modal.balls.membrane",
    "LegendreBall": "twoball.modal.balls.membrane",
    "floor_angles": "twoball.modal.balls.membrane",
    "legendre_ball": "twoball.modal.balls.membrane",
    "mode_decay": "twoball.modal.balls.membrane",
    "mode_spectrum": "twoball.modal.balls.membrane",
    "Wall": "twoball.modal.balls.shell",
    "ShellBall": "twoball.modal.balls.shell",
    "WALLS": "twoball.modal.balls.shell",
}
__getattr__, __dir__ = attach(__name__, _NAMES)
__all__ = sorted(_NAMES)
