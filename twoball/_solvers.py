"""The solvers as objects: each carries its own options, so a combination that does not apply
cannot be written.

=========================  =============================================  ========================
solver                     what it integrates                             its options
=========================  =============================================  ========================
:class:`ClosedForm`        the Legendre series, eqs. (3.12)-(3.16)        sigma, recontact, t_end
:class:`Superposition`     finite-element modes, eqs. (3.14)-(3.16)       mesh, route, sigma,
                                                                          recontact, t_end
:class:`GeneralizedAlpha`  finite elements stepped in time                mesh, dt, sigma,
                                                                          recontact, t_end
:class:`MoreauJean`        any ball with unilateral contacts (the drop,   ball, dt, t_end, sigma
                           a body of finite mass), nonsmooth steps
=========================  =============================================  ========================

The first three solve the paper's lift-off of a massless body (criteria (i)-(ii)
of §3(a), so they carry the re-contact horizon); :class:`MoreauJean` carries the
ball it steps (:class:`~twoball.LegendreBall`, :class:`~twoball.FEBall` or any
:class:`~twoball.Ball`) and serves ``twoball.bounce`` and a body of finite mass
in ``twoball.liftoff``.  Every object is validated when built (SI: seconds) and
no numerical library is imported here.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, fields
from typing import Any

from twoball._common.choices import FILTER_KINDS, HORIZONS, ROUTES
from twoball._common.errors import ParameterError, real_number
from twoball._common.keywords import checked

__all__ = ["SOLVERS", "ClosedForm", "GeneralizedAlpha", "MoreauJean", "Superposition"]

VALID = {
    "sigma": "one of " + ", ".join(FILTER_KINDS),
    "recontact": "one of " + ", ".join(HORIZONS),
    "route": "one of " + ", ".join(ROUTES),
    "t_end": "a window > 0 [s]",
    "dt": "a time step > 0 [s]",
}


def _choice(name: str, value: object, choices: tuple[str, ...]) -> str:
    if not isinstance(value, str) or value not in choices:
        raise ParameterError(name, VALID[name], value)
    return value


def _seconds(name: str, value: object) -> float | None:
    if value is None:
        return None
    number = real_number(name, value, VALID[name])
    if not (number > 0.0 and math.isfinite(number)):
        raise ParameterError(name, VALID[name], value)
    return number


class _Solver:
    """What every solver object shares: validation of its fields, a dict for JSON."""

    #: The backend its results report (``legendre`` or ``fem``; a Moreau-Jean run: its ball's).
    backend = ""

    def _check(self) -> None:
        for name, choices in (("sigma", FILTER_KINDS), ("recontact", HORIZONS), ("route", ROUTES)):
            if hasattr(self, name) and not (name == "sigma" and getattr(self, name) is None):
                _choice(name, getattr(self, name), choices)
        for name in ("t_end", "dt"):
            if hasattr(self, name):
                object.__setattr__(self, name, _seconds(name, getattr(self, name)))

    def as_dict(self) -> dict[str, Any]:
        """The solver and its options as given (None: the default), for JSON and provenance."""
        out: dict[str, Any] = {"solver": type(self).__name__}
        for f in fields(self):  # type: ignore[arg-type]
            value = getattr(self, f.name)
            out[f.name] = value.as_dict() if hasattr(value, "as_dict") else value
        return out


@checked
@dataclass(frozen=True)
class ClosedForm(_Solver):
    """The closed-form Legendre series of the lift-off, eqs. (3.12)-(3.16), on the case's N modes.

    Parameters
    ----------
    sigma : {"lanczos", "printed", "none"}
        Spectral filter of eq. (3.16) on every mode: ``lanczos`` (default), the
        sigma factor ``sinc(pi omega / omega_N)``; ``printed``, ``sin(omega /
        omega_N) / (omega / omega_N)`` as printed in the paper; ``none``, plain
        truncation at degree N.
    recontact : {"window", "paper"}
        Re-contact horizon of criterion (ii), §3(a): a candidate is refused if
        the pole catches the body again anywhere in the window (default), or only
        within the lift-off time after it (``paper``).
    t_end : float, optional
        Modelled window [s] (default 4 pi / c).

    Examples
    --------
    >>> import twoball
    >>> twoball.ClosedForm(sigma="none").as_dict()
    {'solver': 'ClosedForm', 'sigma': 'none', 'recontact': 'window', 't_end': None}
    >>> twoball.ClosedForm(sigma="gauss")
    Traceback (most recent call last):
    ...
    twoball.ParameterError: sigma must be one of lanczos, printed, none, got 'gauss'
    """

    sigma: str = "lanczos"
    recontact: str = "window"
    t_end: float | None = None

    backend = "legendre"

    def __post_init__(self) -> None:
        self._check()


@checked
@dataclass(frozen=True)
class Superposition(_Solver):
    """Modal superposition on finite elements, eqs. (3.14)-(3.16), for the lift-off.

    Parameters
    ----------
    mesh : MeshOptions, kind name or the user's mesh, optional
        :class:`~twoball.MeshOptions` (default the level-3 P2 icosphere), a kind
        name (``"sphere"``, ``"ring"``, ``"axisym"``) or the user's sphere (a
        file path, ``meshio.Mesh`` or ``MeshTri``).
    route : {"auto", "full", "krylov"}
        Eigen route: every pair below the cutoff (``full``), the rational Krylov
        route (``krylov``), or Krylov from 2000 unknowns on (``auto``, default).
    sigma, recontact, t_end
        As :class:`ClosedForm` (the filter acts on the finite-element modes by
        their frequencies).

    Examples
    --------
    >>> import twoball
    >>> twoball.Superposition("axisym", route="full").mesh.label
    'axisym 400 P2'
    """

    mesh: Any = None
    route: str = "auto"
    sigma: str = "lanczos"
    recontact: str = "window"
    t_end: float | None = None

    backend = "fem"

    def __post_init__(self) -> None:
        from twoball.fem_membrane.options import MeshOptions

        object.__setattr__(self, "mesh", MeshOptions.of(self.mesh))
        self._check()


@checked
@dataclass(frozen=True)
class GeneralizedAlpha(_Solver):
    """Generalized-alpha time stepping on finite elements (Chung & Hulbert), for the lift-off.

    It starts from the filtered series at t = 0, so it needs every eigenpair
    below the cutoff (the full eigen route).

    Parameters
    ----------
    mesh : MeshOptions, kind name or the user's mesh, optional
        As :class:`Superposition`.
    dt : float, optional
        Time step [s] (default ``omega_cut dt = 0.2``).
    sigma, recontact, t_end
        As :class:`ClosedForm`.

    Examples
    --------
    >>> import twoball
    >>> twoball.GeneralizedAlpha("axisym", dt=2e-6).dt
    2e-06
    >>> twoball.GeneralizedAlpha(dt=-1.0)
    Traceback (most recent call last):
    ...
    twoball.ParameterError: dt must be a time step > 0 [s], got -1.0
    """

    mesh: Any = None
    dt: float | None = None
    sigma: str = "lanczos"
    recontact: str = "window"
    t_end: float | None = None

    backend = "fem"

    def __post_init__(self) -> None:
        from twoball.fem_membrane.options import MeshOptions

        object.__setattr__(self, "mesh", MeshOptions.of(self.mesh))
        self._check()


@checked
@dataclass(frozen=True)
class MoreauJean(_Solver):
    """Nonsmooth time stepping with unilateral contacts (Moreau-Jean, theta = 1/2), on a ball.

    The drop on the floor and the whole two-ball bounce (``twoball.bounce``),
    and an upper body of finite mass on the paper's start (``twoball.liftoff``
    with a body): impacts by Newton's law, touches localised inside a step
    (:mod:`twoball.modal.nonsmooth`).

    Parameters
    ----------
    ball : Ball, optional
        The lower ball and its discretisation: :class:`~twoball.LegendreBall`
        (default: N = 192 for the drop, the case's N for a body on the start),
        :class:`~twoball.FEBall`, or any object of the :class:`~twoball.Ball`
        protocol.
    dt : float, optional
        Time step [s] (default 0.005 / c).
    t_end : float, optional
        Modelled window [s] (default: the drop's 10 pi / c plus twice the gap's
        closing time; the lift-off's 4 pi / c).
    sigma : {"lanczos", "printed", "none"}, optional
        The spectral filter of the paper's start, eq. (3.16), for a body on it
        (default ``lanczos``); the drop starts undeformed and takes none.

    Examples
    --------
    >>> import twoball
    >>> solver = twoball.MoreauJean(twoball.FEBall(), dt=1e-5)
    >>> solver.backend, solver.ball.label
    ('fem', 'axisym 96 P2')
    """

    ball: Any = None
    dt: float | None = None
    t_end: float | None = None
    sigma: str | None = None

    def __post_init__(self) -> None:
        if self.ball is not None:
            from twoball.modal.balls.protocol import check_ball

            check_ball(self.ball)
        self._check()

    @property
    def backend(self) -> str:  # type: ignore[override]
        """The ball's discretisation (``legendre`` by default)."""
        return "legendre" if self.ball is None else str(self.ball.backend)


#: Every solver class, by the name the command line's ``--scheme`` and ``--backend`` map to.
SOLVERS = (ClosedForm, Superposition, GeneralizedAlpha, MoreauJean)
