"""The independent collision model for one drop (§2): :func:`icm` and its :class:`ICMResult`.

SI units; velocities positive upwards, times from release.
"""

from __future__ import annotations

from dataclasses import dataclass

from twoball._common.keywords import checked
from twoball.modal.icm.impacts import (
    impact_time,
    impact_velocity,
    post_impact_velocities,
    rebound_velocity,
    second_impact_delay,
)
from twoball.modal.icm.inputs import (
    check_drop_height,
    check_dx,
    check_g,
    check_mu,
    check_restitution,
)
from twoball.modal.scalings import STANDARD_GRAVITY


@checked
@dataclass(frozen=True)
class ICMResult:
    """Outcome of the independent collision model for one drop (§2), SI units.

    Velocities are positive upwards; times are measured from release.

    Attributes
    ----------
    mu, e2, e12, dx, drop_height, g : float
        The inputs (mass ratio, restitution coefficients, gap [m], fall height
        [m], gravity [m/s^2]).
    v0 : float
        Impact velocity of both balls at the first impact [m/s], < 0.
    u0 : float
        Rebound velocity of the lower ball, eq. (2.1) [m/s].
    t0 : float
        Time of the first impact [s].
    dt : float
        Delay between the two impacts, eq. (2.2) [s].
    t1 : float
        Time of the second impact, ``t0 + dt``, eq. (2.2) [s].
    u1, u2 : float
        Velocities of the upper and lower ball just before the second impact
        [m/s]: ``u1 = -g t1``, ``u2 = u0 - g dt``.
    v1, v2 : float
        Velocities just after the second impact, eq. (2.5) [m/s].
    v1_ratio, v2_ratio : float
        ``v1 / |v0|`` and ``v2 / |v0|`` (dimensionless).

    Examples
    --------
    >>> import twoball
    >>> result = twoball.icm(0.1, e2=0.8, e12=0.89)
    >>> round(result.v1_ratio, 4), round(result.v2_ratio, 4)
    (2.0927, 0.4907)
    """

    mu: float
    e2: float
    e12: float
    dx: float
    drop_height: float
    g: float
    v0: float
    u0: float
    t0: float
    dt: float
    t1: float
    u1: float
    u2: float
    v1: float
    v2: float
    v1_ratio: float
    v2_ratio: float

    #: JSON key of each field: its name with the SI unit appended.
    UNITS = {
        "dx": "m",
        "drop_height": "m",
        "g": "m_s2",
        **dict.fromkeys(("v0", "u0", "u1", "u2", "v1", "v2"), "m_s"),
        **dict.fromkeys(("t0", "dt", "t1"), "s"),
    }

    def as_dict(self) -> dict[str, float]:
        """JSON-ready, SI, the unit in every key (``v0_m_s``, ``dt_s``; ratios bare)."""
        return {
            (f"{name}_{self.UNITS[name]}" if name in self.UNITS else name): value
            for name, value in self.__dict__.items()
        }


@checked
def icm(
    mu: float,
    e2: float,
    e12: float,
    dx: float = 0.0,
    drop_height: float = 1.0,
    g: float = STANDARD_GRAVITY,
) -> ICMResult:
    """Run the independent collision model of §2, eqs. (2.1), (2.2) and (2.5).

    Parameters
    ----------
    mu : float
        Mass ratio ``m1 / m2`` (upper over lower), >= 0.
    e2 : float
        Restitution coefficient between the lower ball and the floor, in [0, 1].
    e12 : float
        Restitution coefficient between the balls, in [0, 1].
    dx : float, optional
        Initial gap ``x1 - x2 - r1 - r2`` [m], in ``[0, max_separation(H, e2)]``.
    drop_height : float, optional
        Fall height ``H = x2 - r2`` of the lower ball [m], > 0.
    g : float, optional
        Gravitational acceleration [m/s^2], > 0.

    Returns
    -------
    ICMResult
        All intermediate and final velocities and times.

    Raises
    ------
    ParameterError
        If any input is out of range, naming the parameter (``mu``, ``e2``,
        ``e12``, ``dx``, ``drop_height``, ``g``).

    Examples
    --------
    >>> import twoball
    >>> touching = twoball.icm(0.101, e2=0.80, e12=0.89)  # basketball and tennis ball
    >>> round(touching.v1_ratio, 3)
    2.09
    >>> round(twoball.icm(0.0, 1.0, 1.0).v1_ratio, 6)  # the classic three times, eq. (2.7)
    3.0
    """
    mu = check_mu(mu)
    e2 = check_restitution("e2", e2)
    e12 = check_restitution("e12", e12)
    dx = check_dx(dx)
    drop_height = check_drop_height(drop_height)
    g = check_g(g)

    v0 = impact_velocity(drop_height, g)
    u0 = rebound_velocity(drop_height, e2, g)
    t0 = impact_time(drop_height, g)
    dt = second_impact_delay(dx, drop_height, e2, g)
    t1 = t0 + dt
    u1 = -g * t1
    u2 = u0 - g * dt
    v1, v2 = post_impact_velocities(u1, u2, mu, e12)
    return ICMResult(
        mu=mu,
        e2=e2,
        e12=e12,
        dx=dx,
        drop_height=drop_height,
        g=g,
        v0=v0,
        u0=u0,
        t0=t0,
        dt=dt,
        t1=t1,
        u1=u1,
        u2=u2,
        v1=v1,
        v2=v2,
        v1_ratio=v1 / abs(v0),
        v2_ratio=v2 / abs(v0),
    )
