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

from twoball.modal.icm.impacts import (
    impact_time,
    impact_velocity,
    max_separation,
    post_impact_velocities,
    rebound_velocity,
    second_impact_delay,
)
from twoball.modal.icm.limits import light_touching_limit, touching_limit, touching_ratios
from twoball.modal.icm.model import ICMResult, icm
from twoball.modal.icm.table1 import (
    TABLE1,
    TABLE1_DIGITS,
    Table1Check,
    Table1Row,
    round_significant,
    table1_check,
)

__all__ = [
    "TABLE1",
    "TABLE1_DIGITS",
    "ICMResult",
    "Table1Check",
    "Table1Row",
    "icm",
    "impact_time",
    "impact_velocity",
    "light_touching_limit",
    "max_separation",
    "post_impact_velocities",
    "rebound_velocity",
    "round_significant",
    "second_impact_delay",
    "table1_check",
    "touching_limit",
    "touching_ratios",
]
