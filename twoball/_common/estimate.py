"""What a piece of work is expected to cost: the estimate a cost model returns.

The cost models sit beside what they estimate (the closed form's series, the
finite elements, the drop, the contact solver) and return an :class:`Estimate`
from the sizes of the work alone; whether it fits is decided at the edge, by
the verbs, against the budget in force (:mod:`twoball._common.budget`).  Only the
standard library is imported here.
"""

from __future__ import annotations

from dataclasses import dataclass

__all__ = ["BASE_MEMORY", "GiB", "KiB", "MiB", "TiB", "Estimate", "options"]

KiB, MiB, GiB, TiB = 2**10, 2**20, 2**30, 2**40
BASE_MEMORY = 100 * MiB  # interpreter, numpy, scipy (measured 89 MiB)


@dataclass(frozen=True)
class Estimate:
    """Peak memory [bytes] and wall time [s] a piece of work is expected to need.

    ``address``: the address space it maps [bytes] where that is far above its
    resident memory (sparse LU reserves its fill estimate: the finite elements'
    cost model), 0 when it maps about what it uses.
    """

    memory: float
    seconds: float
    address: float = 0.0

    def __add__(self, other: Estimate) -> Estimate:
        """Work done one after the other: memories of the larger, times added."""
        return Estimate(
            max(self.memory, other.memory),
            self.seconds + other.seconds,
            max(self.address, other.address),
        )


def options(**values: object) -> str:
    """``modes 100000 t_end 1e+06`` from keyword values (None skipped): the work asked for."""
    return " ".join(
        f"{name} {value:g}" if isinstance(value, float) else f"{name} {value}"
        for name, value in values.items()
        if value is not None
    )
