"""One drop of a lumped model: its inputs (impact speed, gap, gravity) and its run.

Both bodies are released together; the lower ball reaches the floor at
``|v0| = sqrt(2 g H)`` (the text before eq. (2.1)), the body ``dx`` above its top
and falling at the same speed.  :class:`TwoContacts` is the run every model with
two force laws shares (the event-driven solver of
:mod:`twoball.modal.lumped.solver`).
"""

from __future__ import annotations

from typing import Any

from twoball._common.errors import ParameterError, bounded
from twoball.modal.icm import impact_velocity
from twoball.modal.scalings import STANDARD_GRAVITY, V0_MAX

__all__ = ["DX_MAX", "TwoContacts", "check_gap", "check_gravity", "impact_speed"]

#: Largest gap [m]: far beyond any drop tower, far from overflow.
DX_MAX = 1e3


def impact_speed(
    v0: float | None = None, drop_height: float | None = None, g: float = STANDARD_GRAVITY
) -> float:
    """``|v0|`` [m/s] from the impact velocity or from the drop height (one of the two).

    Parameters
    ----------
    v0 : float, optional
        Impact velocity [m/s]; its sign is ignored.
    drop_height : float, optional
        Fall height H of the lower ball's underside [m]; ``|v0| = sqrt(2 g H)``.
    g : float, optional
        Gravitational acceleration [m/s^2]; must be > 0 when ``drop_height`` is given
        (ParameterError naming ``g`` otherwise).

    Returns
    -------
    float
        The impact speed, > 0.

    Examples
    --------
    >>> round(impact_speed(drop_height=0.92), 4)
    4.2486
    >>> impact_speed(v0=-4.1)
    4.1
    """
    if (v0 is None) == (drop_height is None):
        raise ParameterError("v0", "given, or drop_height given, but not both", v0)
    if drop_height is not None:
        return -impact_velocity(drop_height, g)
    return bounded(
        "v0", abs(bounded("v0", v0, -V0_MAX, V0_MAX, "m/s")), 0.0, V0_MAX, "m/s", low_open=True
    )


def check_gap(dx: float) -> float:
    """The gap ``dx`` [m] between the body and the lower ball's top at the impact, in [0, 1e3]."""
    return bounded("dx", dx, 0.0, DX_MAX, "m")


def check_gravity(g: float) -> float:
    """Gravitational acceleration [m/s^2] in [0, 1e6] (0 allowed: the contacts alone)."""
    return bounded("g", g, 0.0, 1e6, "m/s^2")


class TwoContacts:
    """A lumped model of two contacts, the floor's and the body's: the one shared run.

    A subclass has the masses ``m1``, ``m2`` [kg], the isolated contacts'
    durations ``tau2``, ``tau12`` [s], the force laws ``floor_law`` and
    ``pair_law`` and its ``label``; :meth:`run` hands them to
    :func:`~twoball.modal.lumped.solver.simulate`.
    """

    m1: float
    m2: float
    tau2: float
    tau12: float
    floor_law: Any
    pair_law: Any

    @property
    def label(self) -> str:
        """The model's name in the results."""
        raise NotImplementedError

    def run(
        self,
        v0: float | None = None,
        *,
        drop_height: float | None = None,
        dx: float = 0.0,
        g: float = STANDARD_GRAVITY,
    ) -> Any:
        """One drop: both bodies hit at ``|v0|`` (or fall from ``drop_height``), the body ``dx`` up.

        Parameters
        ----------
        v0 : float, optional
            Impact velocity [m/s] (sign ignored); or give ``drop_height``.
        drop_height : float, optional
            Fall height of the lower ball [m]; ``|v0| = sqrt(2 g H)``.
        dx : float, optional
            Gap between the body and the lower ball's top at the impact [m], >= 0.
        g : float, optional
            Gravitational acceleration [m/s^2], >= 0.

        Returns
        -------
        LumpedResult
            Rebound velocities, contact events and energy budget.
        """
        from twoball.modal.lumped.solver import simulate

        g = check_gravity(g)
        speed = impact_speed(v0, drop_height, g)
        dx = check_gap(dx)
        laws = (self.floor_law, self.pair_law)
        return simulate(self.label, self.m1, self.m2, *laws, speed, dx, g, (self.tau2, self.tau12))
