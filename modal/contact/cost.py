"""Cost model of the contact solver: memory and time of the event loop before it runs.

The event-driven solver (:func:`twoball.modal.contact.events.integrate`) works on
the augmented state of ``n = 2 K + 3`` entries for K modes with dense ``n x n``
matrices: two phase matrices, their one-step propagators ``exp(A h)`` and the
scratch of :func:`scipy.linalg.expm`.  It steps a grid of ``samples_per_period``
points per shortest modal period over the window; each step is one dense
matrix-vector product plus the event checks.

Calibration (wall time on the 2-core build machine, one BLAS thread, Legendre
modes, mass ratio 0.1, default window): N = 100 / 200 / 300 / 400 took 0.38 /
1.7 / 10 / 31 s with 3 events; the bare matrix-vector product costs 0.4-1.0 ns
per matrix entry, the solver's step 1-1.9 ns (checks, slices, cache misses), and
``expm`` 0.9-1.2 ns x n^3.  The model takes ``10 us + 2 ns x n^2`` per step and
``3 ns x n^3`` for the two propagators (an upper bound within a factor of about
two, which is all a refusal needs), and ``80 n^2`` bytes (ten dense n x n arrays
of doubles; N = 400 measured 61 MiB above the interpreter, the model 52 MB).
"""

from __future__ import annotations

import math

from twoball._common.budget import BASE_MEMORY, Estimate, check, options

__all__ = ["check_contact", "contact_estimate"]

STEP_SECONDS = 1e-5  # per grid step: Python overhead of the event checks
STEP_SECONDS_PER_ENTRY = 2e-9  # per entry of the dense one-step propagator
EXPM_SECONDS_PER_CUBE = 3e-9  # the two propagators exp(A h), per n^3
BYTES_PER_ENTRY = 80  # ten dense n x n arrays of doubles


def contact_estimate(
    modes_kept: int, omega_max: float, t_end: float, samples_per_period: int = 32
) -> Estimate:
    """The contact solver on ``modes_kept`` modes up to ``omega_max`` over ``t_end``.

    All arguments are dimensionless (frequencies in units of c, times in 1/c).
    """
    n = 2.0 * int(modes_kept) + 3.0
    steps = math.ceil(t_end * max(float(omega_max), 1.0) * samples_per_period / (2.0 * math.pi))
    seconds = steps * (STEP_SECONDS + STEP_SECONDS_PER_ENTRY * n * n)
    seconds += EXPM_SECONDS_PER_CUBE * n**3
    return Estimate(BASE_MEMORY + BYTES_PER_ENTRY * n * n, seconds)


def check_contact(
    modes_kept: int,
    omega_max: float,
    t_end: float,
    *,
    modes: int | None = None,
    mass_ratio: float | None = None,
    samples_per_period: int = 32,
) -> Estimate:
    """Refuse a contact run that cannot fit, naming the options that set its size.

    ``modes`` (the case's N) and ``mass_ratio`` only name the work in the message.
    """
    estimate = contact_estimate(modes_kept, omega_max, t_end, samples_per_period)
    named = options(modes=modes, mass_ratio=mass_ratio) or f"a contact system of {modes_kept} modes"
    return check(named, estimate)
