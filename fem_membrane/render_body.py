"""The upper body of finite mass in pictures: where it is and whether it touches (issue 13).

:class:`ContactScene` is a :class:`~twoball.fem_membrane.render.BallScene` whose
body follows the contact solution (its height ``s(t)`` above the undeformed
pole, in flight or resting on the cap of the coupled membrane) and whose
caption says, frame by frame, whether the body is on the membrane, how many
impacts it has had and when it finally leaves.  SI (m, s).
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np
from twoball.fem_membrane.render import BallScene


@dataclass(frozen=True)
class ContactScene(BallScene):
    """A scene with a body of finite mass (SI).

    Parameters
    ----------
    contact : ndarray of bool, shape (F,)
        True in the frames where the body is on the membrane.
    impacts : ndarray, shape (I,)
        Times [s] of the body's impacts on the membrane.
    mass_ratio : float
        ``mu = m1 / m2`` of the body.

    The other parameters are those of :class:`BallScene`; ``body`` is the
    body's height ``s(t)`` [m] and ``t_liftoff`` the final separation [s].
    """

    contact: np.ndarray = field(default_factory=lambda: np.zeros(0, dtype=bool))
    impacts: np.ndarray = field(default_factory=lambda: np.zeros(0))
    mass_ratio: float = 0.0

    def __post_init__(self) -> None:
        super().__post_init__()
        contact = np.atleast_1d(np.asarray(self.contact, dtype=bool))
        if contact.shape != self.times.shape:
            raise ValueError("contact must have one flag per frame, shape (F,)")
        object.__setattr__(self, "contact", contact)
        object.__setattr__(self, "impacts", np.atleast_1d(np.asarray(self.impacts, dtype=float)))

    def caption(self, k: int, warp: float) -> str:
        """Time; the body in contact or in flight and its impacts so far; lift-off; warp."""
        t = float(self.times[k])
        text = f"t = {t * 1e3:6.2f} ms\nmu = {self.mass_ratio:g}"
        text += "\nbody IN CONTACT" if self.contact[k] else "\nbody in flight"
        text += f"\nimpacts so far: {int(np.sum(self.impacts <= t + 1e-12))}"
        if self.t_liftoff is not None:
            text += f"\nlift-off {self.t_liftoff * 1e3:.2f} ms"
        return text + (f"\nwarp x{warp:.3g}" if warp != 1.0 else "")
