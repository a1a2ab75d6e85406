"""The rules of the truncated modal series and its lift-off: the option object :class:`Series`.

Two rules travel together through every verb that solves for the lift-off: the
spectral filter sigma of eq. (3.16), which weights each mode of the truncated
series (closed form and finite-element modes alike), and the re-contact horizon
of criterion (ii), §3(a).  No numerical library is imported here.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

from twoball._common.choices import FILTER_KINDS, HORIZONS
from twoball._common.errors import ParameterError

__all__ = ["FILTER_KINDS", "HORIZONS", "Series"]



@dataclass(frozen=True)
class Series:
    """The filter of the truncated series and the re-contact horizon, validated when built.

    Parameters
    ----------
    sigma : {"lanczos", "printed", "none"}
        Spectral filter of eq. (3.16) on every mode: ``lanczos`` (default), the
        sigma factor ``sinc(pi omega / omega_N)``, zero at the cutoff;
        ``printed``, ``sin(omega / omega_N) / (omega / omega_N)`` as printed in
        the paper; ``none``, plain truncation at degree N.
    recontact : {"window", "paper"}
        Re-contact horizon of criterion (ii), §3(a): a candidate lift-off is
        refused if the pole catches the body again anywhere in the modelled
        window (``window``, default), or only within the lift-off time after
        it (``paper``, dt < t_l as in the paper).

    Raises
    ------
    ParameterError
        Naming the field and its valid values.

    Examples
    --------
    >>> import twoball
    >>> series = twoball.Series(sigma="none", recontact="paper")
    >>> series.as_dict()
    {'sigma': 'none', 'recontact': 'paper'}
    >>> twoball.Series() == twoball.Series("lanczos", "window")
    True
    >>> report = twoball.liftoff(series=twoball.Series(sigma="printed"))
    >>> report.sigma
    'printed'
    >>> twoball.Series(sigma="gauss")
    Traceback (most recent call last):
    ...
    twoball.ParameterError: sigma must be one of lanczos, printed, none, got 'gauss'
    """

    sigma: str = "lanczos"
    recontact: str = "window"

    #: Valid values of each field, in words.
    VALID = {  # noqa: RUF012 -- a class constant, not a field
        "sigma": "one of " + ", ".join(FILTER_KINDS),
        "recontact": "one of " + ", ".join(HORIZONS),
    }

    def __post_init__(self) -> None:
        for name, choices in (("sigma", FILTER_KINDS), ("recontact", HORIZONS)):
            value = getattr(self, name)
            if not isinstance(value, str) or value not in choices:
                raise ParameterError(name, self.VALID[name], value)

    def as_dict(self) -> dict[str, Any]:
        """``{"sigma": ..., "recontact": ...}``, for JSON and provenance."""
        return {"sigma": self.sigma, "recontact": self.recontact}

    def changed(self) -> dict[str, str]:
        """The fields that differ from the defaults (``lanczos``, ``window``)."""
        default = Series()
        return {k: v for k, v in self.as_dict().items() if v != getattr(default, k)}

    def refuse(self, reason: str, *names: str) -> None:
        """Refuse the first of ``names`` that differs from its default:
        ``NAME must be left out REASON``."""
        changed = self.changed()
        for name in names:
            if name in changed:
                raise ParameterError(name, f"left out {reason}", changed[name])
