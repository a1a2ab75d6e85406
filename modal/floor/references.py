"""What a drop on the floor is compared with: pressure x area and the measurements (SI).

Pressure x area (Cross 1999, Am. J. Phys. 67 222; Hubbard & Stronge 2001,
Sports Eng. 4 49), Table 1's measured e2 of the lower balls (Berdeni et al.
2015) and a basketball's measured compression per unit impact speed (Dowell &
Krebs 1991, Br. J. Sports Med. 25 34).
"""

from __future__ import annotations

import math

__all__ = ["MEASURED_COMPRESSION", "TABLE1_E2", "pressure_area"]

#: Table 1's measured e2 of the lower balls (Berdeni et al. 2015).
TABLE1_E2: dict[str, tuple[float, ...]] = {"basketball": (0.80, 0.90), "tennis": (0.83,)}
#: Compression of a basketball per unit impact speed [m per m/s] (Dowell & Krebs 1991).
MEASURED_COMPRESSION = 3.07e-3


def pressure_area(v0: float, radius: float, wave_speed: float) -> dict[str, float]:
    """The pressure x area spring of a ball on the floor, in SI.

    Cross 1999, Am. J. Phys. 67 222; Hubbard & Stronge 2001, Sports Eng. 4 49.

    The floor force ``F = P pi (2 R x)`` for a flattening x is a spring ``k = 2 pi
    R P`` with ``k / m2 = c^2``: contact time ``pi / c``, largest flattening
    ``|v0| / c`` and the contact cap through the plane at depth x, ``cos psi = 1
    - x / R``, i.e. ``phi_a = pi - psi``.
    """
    flattening = v0 / wave_speed
    cosine = max(1.0 - flattening / radius, -1.0)
    return {
        "contact_time_s": math.pi / wave_speed,
        "flattening_max_m": flattening,
        "phi_a_max_rad": math.pi - math.acos(cosine),
        "e2": 1.0,
    }
