"""Independent collision model (ICM): the rigid-body baseline of §2.

Two rigid balls are dropped in vertical alignment.  The lower ball (mass m2)
hits the floor and rebounds with restitution ``e2``; some time later it meets
the still-falling upper ball (mass m1) and the two collide with restitution
``e12``.  Both impacts are instantaneous and independent of each other.

Units are SI throughout: metres, seconds, m/s.  Velocities are positive
upwards, so the impact velocity ``v0`` is negative.

Sign convention of the limits: eqs. (2.6) and (2.7) write the post-impact
velocities as multiples of ``v0`` (``v1 = k1 v0``). Because ``v0 < 0``, the
rebound ratio that experiments quote, ``v1 / |v0|``, is ``-k1``.
:func:`touching_limit` and :func:`light_touching_limit` return the multipliers
``k`` exactly as printed; :func:`touching_ratios` returns the ratios
``v / |v0|``.

Table 1: the header of Table 1 normalises by ``|u0|``, but the printed ICM
columns are ``v / |v0|`` (impact speed), not ``v / |u0|`` with ``u0 = e2 |v0|``:
rows 1-3 reproduce to the printed two significant figures only with ``|v0|``,
and the ``|u0|`` reading misses all of them (for example row 1 gives
``v1/|u0| = 1.83`` against the printed 1.5). Rows 4-6 do not reproduce under either reading;
see :func:`table1_check` and the documentation page on the ICM.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from .errors import ParameterError
from .parameters import STANDARD_GRAVITY

# The paper's value (§2).  twoball.modal.parameters defines the same constant for the
# continuum model; it is repeated here so the ICM has no dependency on it.

#: Significant figures of the ICM columns in Table 1.
TABLE1_DIGITS = 2


# ---------------------------------------------------------------------------
# validation
# ---------------------------------------------------------------------------


def _as_float(name: str, valid: str, value: object) -> float:
    try:
        out = float(value)  # type: ignore[arg-type]
    except (TypeError, ValueError):
        raise ParameterError(name, valid, value) from None
    if not math.isfinite(out):
        raise ParameterError(name, valid, value)
    return out


def _check_mu(mu: float) -> float:
    valid = "a finite number >= 0"
    mu = _as_float("mu", valid, mu)
    if not mu >= 0.0:
        raise ParameterError("mu", valid, mu)
    return mu


def _check_restitution(name: str, value: float) -> float:
    valid = "in [0, 1]"
    value = _as_float(name, valid, value)
    if not 0.0 <= value <= 1.0:
        raise ParameterError(name, valid, value)
    return value


def _check_dx(dx: float) -> float:
    valid = "a finite number >= 0 [m]"
    dx = _as_float("dx", valid, dx)
    if not dx >= 0.0:
        raise ParameterError("dx", valid, dx)
    return dx


def _check_positive(name: str, value: float, unit: str) -> float:
    valid = f"a finite number > 0 [{unit}]"
    value = _as_float(name, valid, value)
    if not value > 0.0:
        raise ParameterError(name, valid, value)
    return value


def _check_drop_height(drop_height: float) -> float:
    return _check_positive("drop_height", drop_height, "m")


def _check_g(g: float) -> float:
    return _check_positive("g", g, "m/s^2")


# ---------------------------------------------------------------------------
# first impact: lower ball on the floor
# ---------------------------------------------------------------------------


def impact_velocity(drop_height: float, g: float = STANDARD_GRAVITY) -> float:
    """Velocity of both balls when the lower one reaches the floor (§2).

    ``v0 = -sqrt(2 g H)`` with ``H = x2 - r2``, the text preceding eq. (2.1).

    Parameters
    ----------
    drop_height : float
        Fall height ``H = x2 - r2`` of the lower ball's underside [m], > 0.
    g : float, optional
        Gravitational acceleration [m/s^2], > 0.

    Returns
    -------
    float
        ``v0`` [m/s]; negative (downwards).
    """
    drop_height = _check_drop_height(drop_height)
    g = _check_g(g)
    return -float(np.sqrt(2.0 * g * drop_height))


def impact_time(drop_height: float, g: float = STANDARD_GRAVITY) -> float:
    """Time ``t0 = sqrt(2 H / g)`` of the lower ball's impact on the floor [s] (§2).

    Parameters
    ----------
    drop_height : float
        Fall height ``H = x2 - r2`` [m], > 0.
    g : float, optional
        Gravitational acceleration [m/s^2], > 0.

    Returns
    -------
    float
        ``t0`` [s], measured from release.
    """
    drop_height = _check_drop_height(drop_height)
    g = _check_g(g)
    return float(np.sqrt(2.0 * drop_height / g))


def rebound_velocity(drop_height: float, e2: float, g: float = STANDARD_GRAVITY) -> float:
    """Rebound velocity ``u0 = -e2 v0 = e2 sqrt(2 g H)`` of the lower ball, eq. (2.1).

    Parameters
    ----------
    drop_height : float
        Fall height ``H = x2 - r2`` [m], > 0.
    e2 : float
        Restitution coefficient between the lower ball and the floor, in [0, 1].
    g : float, optional
        Gravitational acceleration [m/s^2], > 0.

    Returns
    -------
    float
        ``u0`` [m/s]; >= 0 (upwards).
    """
    e2 = _check_restitution("e2", e2)
    return -e2 * impact_velocity(drop_height, g)


# ---------------------------------------------------------------------------
# second impact: the two balls
# ---------------------------------------------------------------------------


def max_separation(drop_height: float, e2: float) -> float:
    """Largest separation for which (2.2) holds: ``4 e2 (1 + e2) H`` [m].

    Eq. (2.2) assumes the lower ball is still in flight when it meets the
    upper one.  It lands again ``2 u0 / g`` after its rebound; the gap closes
    at the constant speed ``(1 + e2) |v0|``, so the collision happens in flight
    only for ``dx <= 2 u0 (1 + e2) |v0| / g = 4 e2 (1 + e2) H``.  The bound does
    not depend on g.  For ``e2 = 0`` only ``dx = 0`` is admissible.

    Parameters
    ----------
    drop_height : float
        Fall height ``H = x2 - r2`` [m], > 0.
    e2 : float
        Restitution coefficient with the floor, in [0, 1].

    Returns
    -------
    float
        The bound [m].
    """
    drop_height = _check_drop_height(drop_height)
    e2 = _check_restitution("e2", e2)
    return 4.0 * e2 * (1.0 + e2) * drop_height


def second_impact_delay(
    dx: float, drop_height: float, e2: float, g: float = STANDARD_GRAVITY
) -> float:
    """Delay ``dt = -dx / ((1 + e2) v0)`` between the two impacts [s], eq. (2.2).

    Parameters
    ----------
    dx : float
        Initial gap ``x1 - x2 - r1 - r2`` between the balls [m], in
        ``[0, max_separation(drop_height, e2)]``.
    drop_height : float
        Fall height ``H = x2 - r2`` [m], > 0.
    e2 : float
        Restitution coefficient with the floor, in [0, 1].
    g : float, optional
        Gravitational acceleration [m/s^2], > 0.

    Returns
    -------
    float
        ``dt`` [s]; the second impact happens at ``t1 = t0 + dt``.

    Raises
    ------
    ParameterError
        For any input out of range, including ``dx`` beyond
        :func:`max_separation` (the lower ball would have landed again).
    """
    dx = _check_dx(dx)
    e2 = _check_restitution("e2", e2)
    v0 = impact_velocity(drop_height, g)
    if dx == 0.0:
        return 0.0
    limit = max_separation(drop_height, e2)
    if dx > limit:
        raise ParameterError(
            "dx",
            f"<= 4 e2 (1 + e2) H = {limit:.6g} m (lower ball airborne at 2nd impact)",
            dx,
        )
    return -dx / ((1.0 + e2) * v0)


def post_impact_velocities(u1: float, u2: float, mu: float, e12: float) -> tuple[float, float]:
    """Velocities after a collinear restitution impact of two bodies, eq. (2.5).

    Solves momentum conservation (2.3) and the restitution law (2.4).

    Parameters
    ----------
    u1, u2 : float
        Velocities of the upper (1) and lower (2) body just before the impact
        [m/s], positive upwards.
    mu : float
        Mass ratio ``m1 / m2``, >= 0 (0 is the limit of a massless upper body).
    e12 : float
        Restitution coefficient between the bodies, in [0, 1].

    Returns
    -------
    v1, v2 : float
        Velocities just after the impact [m/s].
    """
    mu = _check_mu(mu)
    e12 = _check_restitution("e12", e12)
    u1 = float(u1)
    u2 = float(u2)
    v1 = (mu * u1 + u2 + e12 * (u2 - u1)) / (mu + 1.0)
    v2 = (mu * u1 + u2 + mu * e12 * (u1 - u2)) / (mu + 1.0)
    return v1, v2


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
        If any input is out of range; the name is the CLI flag
        (``--mu``, ``--e2``, ``--e12``, ``--dx``, ``--drop-height``, ``--g``).
    """
    mu = _check_mu(mu)
    e2 = _check_restitution("e2", e2)
    e12 = _check_restitution("e12", e12)
    dx = _check_dx(dx)
    drop_height = _check_drop_height(drop_height)
    g = _check_g(g)

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


# ---------------------------------------------------------------------------
# limits
# ---------------------------------------------------------------------------


def touching_limit(mu: float, e2: float, e12: float) -> tuple[float, float]:
    """Multipliers ``(k1, k2)`` with ``v1 -> k1 v0``, ``v2 -> k2 v0`` as dx -> 0, eq. (2.6).

    ``k1 = (mu - e2 - e12 (1 + e2)) / (mu + 1)`` and
    ``k2 = (mu - e2 + mu e12 (1 + e2)) / (mu + 1)``.  Independent of the drop
    height.  Since ``v0 < 0`` the rebound ratios are ``v / |v0| = -k``; see
    :func:`touching_ratios`.

    Parameters
    ----------
    mu : float
        Mass ratio ``m1 / m2``, >= 0.
    e2, e12 : float
        Restitution coefficients (floor, between balls), in [0, 1].

    Returns
    -------
    k1, k2 : float
        Dimensionless multipliers of ``v0``.
    """
    mu = _check_mu(mu)
    e2 = _check_restitution("e2", e2)
    e12 = _check_restitution("e12", e12)
    k1 = (mu - e2 - e12 * (1.0 + e2)) / (mu + 1.0)
    k2 = (mu - e2 + mu * e12 * (1.0 + e2)) / (mu + 1.0)
    return k1, k2


def touching_ratios(mu: float, e2: float, e12: float) -> tuple[float, float]:
    """Rebound ratios ``(v1 / |v0|, v2 / |v0|)`` in the limit dx -> 0, eq. (2.6).

    Parameters
    ----------
    mu : float
        Mass ratio ``m1 / m2``, >= 0.
    e2, e12 : float
        Restitution coefficients (floor, between balls), in [0, 1].

    Returns
    -------
    r1, r2 : float
        ``-k1`` and ``-k2`` of :func:`touching_limit` (positive = upwards).
    """
    k1, k2 = touching_limit(mu, e2, e12)
    return -k1, -k2


def light_touching_limit(e2: float, e12: float) -> tuple[float, float]:
    """Multipliers of ``v0`` for dx -> 0 and mu -> 0, eq. (2.7).

    ``v1 -> -((1 + e2) e12 + e2) v0`` and ``v2 -> -e2 v0``.  For
    ``e2 = e12 = 1`` this is the classic ``v1 = -3 v0`` (nine times the drop
    height).

    Parameters
    ----------
    e2, e12 : float
        Restitution coefficients (floor, between balls), in [0, 1].

    Returns
    -------
    k1, k2 : float
        Dimensionless multipliers of ``v0`` (both <= 0).
    """
    e2 = _check_restitution("e2", e2)
    e12 = _check_restitution("e12", e12)
    return -((1.0 + e2) * e12 + e2), -e2


# ---------------------------------------------------------------------------
# Table 1
# ---------------------------------------------------------------------------


@dataclass(frozen=True)
class Table1Row:
    """One row of Table 1 (§4), values as printed.

    Attributes
    ----------
    lower, upper : str
        The lower and upper body.
    mu, e2, e12 : float
        Mass ratio and restitution coefficients.
    measured_v1, icm_v1 : float
        Measured upper-ball rebound ratio and the printed ICM value.
    measured_v2, icm_v2 : float
        Measured lower-ball rebound ratio and the printed ICM value.

    Notes
    -----
    The header says the ratios are ``v / |u0|``; the printed ICM values are in
    fact ``v / |v0|`` (see the module docstring).
    """

    lower: str
    upper: str
    mu: float
    e2: float
    e12: float
    measured_v1: float
    icm_v1: float
    measured_v2: float
    icm_v2: float


#: Table 1 of the paper, all six rows in printed order.
TABLE1: tuple[Table1Row, ...] = (
    Table1Row("Tennis", "Coin", 0.062, 0.83, 0.46, 1.6, 1.5, 0.69, 0.67),
    Table1Row("Tennis", "Nut", 0.035, 0.83, 0.41, 1.5, 1.5, 0.74, 0.74),
    Table1Row("Tennis", "Table tennis", 0.050, 0.83, 0.59, 1.5, 1.8, 0.77, 0.69),
    Table1Row("Basketball", "Tennis", 0.101, 0.80, 0.89, 1.8, 2.1, 0.61, 0.56),
    Table1Row("Basketball", "Tissue", 0.004, 0.90, 0.56, 1.1, 1.8, 0.84, 0.83),
    Table1Row("Basketball", "Table tennis", 0.005, 0.90, 0.60, 1.2, 1.9, 0.84, 0.83),
)


def round_significant(x: float, digits: int = TABLE1_DIGITS) -> float:
    """Round ``x`` to ``digits`` significant figures (decimal, as printed).

    Parameters
    ----------
    x : float
        Value to round.
    digits : int, optional
        Significant figures, >= 1.

    Returns
    -------
    float
        The nearest float to the decimal rounding, so it compares equal to
        the printed literal (``round_significant(1.5158) == 1.5``).
    """
    if digits < 1:
        raise ParameterError("digits", "an integer >= 1", digits)
    return float(f"{float(x):.{digits}g}")


@dataclass(frozen=True)
class Table1Check:
    """Our ICM values for one row of Table 1 beside the printed ones.

    Attributes
    ----------
    index : int
        Row number in the table, from 1.
    row : Table1Row
        The printed row.
    v1, v2 : float
        Our ``v / |v0|`` from eq. (2.6), unrounded.
    v1_rounded, v2_rounded : float
        The same rounded to the printed two significant figures.
    v1_differs, v2_differs : bool
        Whether the rounded value differs from the printed ICM value.
    """

    index: int
    row: Table1Row
    v1: float
    v2: float
    v1_rounded: float
    v2_rounded: float
    v1_differs: bool
    v2_differs: bool

    @property
    def differs(self) -> bool:
        """True if either ICM column differs from the printed value."""
        return self.v1_differs or self.v2_differs

    @property
    def v1_difference(self) -> float:
        """Unrounded ours minus printed, upper ball."""
        return self.v1 - self.row.icm_v1

    @property
    def v2_difference(self) -> float:
        """Unrounded ours minus printed, lower ball."""
        return self.v2 - self.row.icm_v2


def table1_check(rows: tuple[Table1Row, ...] = TABLE1) -> tuple[Table1Check, ...]:
    """Recompute the ICM columns of Table 1 from mu, e2, e12 via eq. (2.6).

    The ratios are ``v / |v0|`` (see the module docstring for why not
    ``v / |u0|``), rounded to :data:`TABLE1_DIGITS` significant figures and
    compared with the printed values.  Nothing is fitted or adjusted.

    Findings: rows 1-3 (tennis ball below) agree with the printed values in
    both columns.  Row 4 (basketball / tennis) agrees in ``v1`` (2.1) but gives
    ``v2 = 0.488`` against the printed 0.56.  Rows 5 and 6 (basketball /
    tissue, basketball / table tennis) differ in both columns: 1.95 and 0.888
    against 1.8 and 0.83, and 2.02 and 0.885 against 1.9 and 0.83.

    Parameters
    ----------
    rows : tuple of Table1Row, optional
        Rows to check; default the whole table.

    Returns
    -------
    tuple of Table1Check
        One entry per row, in order.
    """
    out = []
    for i, row in enumerate(rows, start=1):
        v1, v2 = touching_ratios(row.mu, row.e2, row.e12)
        r1 = round_significant(v1)
        r2 = round_significant(v2)
        out.append(
            Table1Check(
                index=i,
                row=row,
                v1=v1,
                v2=v2,
                v1_rounded=r1,
                v2_rounded=r2,
                v1_differs=r1 != row.icm_v1,
                v2_differs=r2 != row.icm_v2,
            )
        )
    return tuple(out)
