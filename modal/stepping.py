"""The time options of every solve: the modelled window, the time step, the scheme, the route.

One validated bundle, :class:`Stepping`, in SI (seconds).  Which fields act
depends on the solver: the window acts everywhere; ``scheme``, ``dt`` and
``route`` choose how the finite elements advance in time (modal superposition,
eqs. (3.14)-(3.16), on the ``full`` or ``krylov`` eigen route, or
generalized-alpha stepping with step ``dt``).  A field that does not act where
it is given is refused by the verb that receives it.
"""

from __future__ import annotations

import math
from dataclasses import asdict, dataclass
from typing import Any

from twoball._common.errors import ParameterError, real_number

__all__ = ["ROUTES", "SCHEMES", "Stepping"]

#: Time schemes: modal superposition (closed form in time) or generalized-alpha steps.
SCHEMES: tuple[str, ...] = ("modal", "alpha")
#: Eigen routes of modal superposition on finite elements: every pair below the
#: cutoff, the rational Krylov route, or Krylov from 2000 unknowns on.
ROUTES: tuple[str, ...] = ("full", "krylov", "auto")


@dataclass(frozen=True)
class Stepping:
    """How a solve advances in time (SI), validated when built.

    Parameters
    ----------
    t_end : float, optional
        Modelled window [s] from t = 0 (default 4 pi / c, two periods of the
        slowest membrane mode); its upper and lower bounds depend on c and are
        checked by the solve.
    dt : float, optional
        Time step [s] of generalized-alpha (default omega_cut dt = 0.2); only
        with ``scheme="alpha"``.
    scheme : {"modal", "alpha"}, optional
        Modal superposition (default) or generalized-alpha stepping (finite
        elements only).
    route : {"auto", "full", "krylov"}, optional
        Eigen route of modal superposition on finite elements (default
        ``auto``); ``alpha`` needs the full eigenpairs.

    Raises
    ------
    ParameterError
        Naming the field and its valid range.

    Examples
    --------
    >>> import twoball
    >>> twoball.Stepping(scheme="alpha", dt=2e-6).as_dict()
    {'t_end': None, 'dt': 2e-06, 'scheme': 'alpha', 'route': None}
    >>> twoball.Stepping(dt=-1.0)
    Traceback (most recent call last):
    ...
    twoball.ParameterError: dt must be a time step > 0 [s], got -1.0
    """

    t_end: float | None = None
    dt: float | None = None
    scheme: str | None = None
    route: str | None = None

    #: Valid range of each field, in words (the command line names its flags).
    VALID = {  # noqa: RUF012 -- a class constant, not a field
        "t_end": "a window > 0 [s]",
        "dt": "a time step > 0 [s]",
        "scheme": "one of " + ", ".join(SCHEMES),
        "route": "one of " + ", ".join(ROUTES),
    }

    def __post_init__(self) -> None:
        for name in ("t_end", "dt"):
            value = getattr(self, name)
            if value is not None:
                number = real_number(name, value, self.VALID[name])
                if not (number > 0.0 and math.isfinite(number)):
                    raise ParameterError(name, self.VALID[name], value)
                object.__setattr__(self, name, number)
        if self.scheme is not None and self.scheme not in SCHEMES:
            raise ParameterError("scheme", self.VALID["scheme"], self.scheme)
        if self.route is not None and self.route not in ROUTES:
            raise ParameterError("route", self.VALID["route"], self.route)
        if self.dt is not None and self.scheme in (None, "modal"):
            raise ParameterError("dt", "left out with scheme modal (no time steps)", self.dt)
        if self.scheme == "alpha" and self.route == "krylov":
            raise ParameterError("route", "full or auto with scheme alpha", self.route)

    def as_dict(self) -> dict[str, Any]:
        """The fields as given (None: the solver's default), for JSON and provenance."""
        return asdict(self)

    def refuse(self, reason: str, *names: str) -> None:
        """Refuse the first of ``names`` that was given: ``NAME must be left out REASON``."""
        for name in names:
            value = getattr(self, name)
            if value is not None:
                raise ParameterError(name, f"left out {reason}", value)
