"""The thin spherical shell as a lower ball: its wall, its closed-form modes and the ball object.

The shell (:mod:`twoball.modal.shell`, docs/shell.rst) moves radially *and*
meridionally, so its rigid translation is a motion of its material: the mode of
degree 1 on the lower branch, ``(W, V) = (1, 1)``, with ``Omega = 0`` exactly.
That mode is the drop's centre (:attr:`~twoball.modal.balls.description.ModalBall.centre`):
there is no separate coordinate Z, and a floor force reaches the top only through
the shell's own waves (the fastest, in-plane, at ``c_e = sqrt(C / rho_s)``).

Physics from the case as the drop resolves it (:func:`twoball.modal.floor.inputs.resolve_drop`):
the radius R, the excess pressure P (the inflation tension ``N0 = P R / 2``), the
wave speed c of that tension (``c^2 = N0 / (rho_s R^2)``, so the mass is the
membrane's ``2 pi R P / c^2``), the enclosed gas and the damping law.  The wall
(:class:`Wall`) adds the in-plane stiffness ``C = E h / (1 - nu^2)``, the bending
``D_b = E h^3 / (12 (1 - nu^2))`` and Poisson's ratio.  Dimensionless numbers
(:class:`~twoball.modal.shell.ShellParameters`): ``p = N0 / C``, ``beta_h = (h /
R)^2 / 12``, ``g = 3 kappa P_abs R / C``; the shell's ``Omega^2`` (units ``C /
(rho_s R^2)``) is ``omega^2 / c^2`` times p, so the drop's ``omega^2`` in units of
c^2 is ``Omega^2 / p``.

Coordinates: every mode of degrees 0..N (both branches; ``2 N + 1`` modes), of
modal mass m (so ``masses == 1``), frequencies ``Omega^2 / p``, decays from the
damping law (:func:`~twoball.modal.balls.membrane.mode_decay`; 0 on the
translation), the gas's share ``g / p`` on the breathing mode.  Rows: the
vertical displacement ``u_z = w cos(phi) - v sin(phi)`` of each mode at the floor
points (the Gauss-Radau nodes of :func:`~twoball.modal.balls.membrane.floor_angles`,
as for the membrane), at the north pole and over a cap (exact in ``cos(phi)``).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

import numpy as np

from twoball._common.errors import ParameterError, check_labels, real_number
from twoball._common.keywords import checked
from twoball.modal.balls.description import ModalBall

if TYPE_CHECKING:
    from twoball.modal.parameters import Case
    from twoball.modal.shell.parameters import ShellParameters

__all__ = [
    "DEFAULT_SHELL_MODES",
    "SHELL_MODES_RANGE",
    "WALLS",
    "ShellBall",
    "Wall",
    "shell_ball",
    "shell_description",
    "shell_summary",
]

#: Legendre degree N of the shell's drop (2 N + 1 modes; floor points at its ~N/2
#: Gauss-Radau nodes on the lower hemisphere).
DEFAULT_SHELL_MODES = 128
#: Degrees N a shell ball takes.
SHELL_MODES_RANGE = (8, 1000)
#: The largest thickness ratio h / R a thin shell takes here.
MAX_THICKNESS_RATIO = 0.5

_VALID = {
    "youngs_modulus": "a Young's modulus in (0, 1e12] Pa",
    "thickness": "a wall thickness in (0, 1] m",
    "poisson": "Poisson's ratio in (0, 0.5]",
    "wall_stiffness_ratio": "C / N0 in (0, 1e6]",
    "thickness_ratio": f"h / R in [0, {MAX_THICKNESS_RATIO:g}]",
}


def _in(name: str, value: object, low: float, high: float, *, low_open: bool = True) -> float:
    number = real_number(name, value, _VALID[name])
    ok = (low < number if low_open else low <= number) and number <= high
    if not (ok and math.isfinite(number)):
        raise ParameterError(name, _VALID[name], value)
    return number


@checked
@dataclass(frozen=True)
class Wall:
    """The shell's wall: SI (E, h, nu) or dimensionless (C / N0, h / R, nu).

    Give either ``youngs_modulus`` and ``thickness`` (SI; the in-plane stiffness
    ``C = E h / (1 - nu^2)``) or ``wall_stiffness_ratio`` C / N0 (the in-plane
    stiffness over the inflation tension ``N0 = P R / 2`` of the case) with
    ``thickness_ratio`` h / R (default 0: no bending).  Validated when built.

    Parameters
    ----------
    youngs_modulus : float, optional
        E [Pa] in (0, 1e12].
    thickness : float, optional
        h [m] in (0, 1]; at most half the ball's radius (checked with the case).
    poisson : float
        nu in (0, 0.5] (default 0.5, rubber).
    wall_stiffness_ratio : float, optional
        C / N0 in (0, 1e6].
    thickness_ratio : float, optional
        h / R in [0, 0.5] (with ``wall_stiffness_ratio`` only).
    source : str
        Where the values come from (the presets'; not compared).

    Raises
    ------
    ParameterError
        Naming the field: out of range, a pair given half, or both kinds at once.

    Examples
    --------
    >>> import twoball
    >>> twoball.Wall(youngs_modulus=6e6, thickness=3.2e-3).as_dict()["poisson"]
    0.5
    >>> twoball.Wall(wall_stiffness_ratio=4.0, thickness_ratio=0.03).dimensionless
    True
    >>> twoball.Wall(youngs_modulus=6e6)
    Traceback (most recent call last):
    ...
    twoball.ParameterError: thickness must be given with youngs_modulus (SI wall)
    """

    youngs_modulus: float | None = None
    thickness: float | None = None
    poisson: float = 0.5
    wall_stiffness_ratio: float | None = None
    thickness_ratio: float | None = None
    source: str = field(default="", compare=False)

    def __post_init__(self) -> None:
        check_labels(self, "source")
        set_ = object.__setattr__
        set_(self, "poisson", _in("poisson", self.poisson, 0.0, 0.5))
        si = self.youngs_modulus is not None or self.thickness is not None
        if si:
            if self.youngs_modulus is None:
                raise ParameterError("youngs_modulus", "given with thickness (SI wall)", None)
            if self.thickness is None:
                raise ParameterError("thickness", "given with youngs_modulus (SI wall)", None)
            for name in ("wall_stiffness_ratio", "thickness_ratio"):
                if getattr(self, name) is not None:
                    valid = "left out with youngs_modulus and thickness (one kind of wall)"
                    raise ParameterError(name, valid, getattr(self, name))
            set_(self, "youngs_modulus", _in("youngs_modulus", self.youngs_modulus, 0.0, 1e12))
            set_(self, "thickness", _in("thickness", self.thickness, 0.0, 1.0))
            return
        if self.wall_stiffness_ratio is None:
            valid = (
                "given (a wall: youngs_modulus and thickness, or wall_stiffness_ratio "
                "with thickness_ratio)"
            )
            raise ParameterError("wall_stiffness_ratio", valid, None)
        ratio = _in("wall_stiffness_ratio", self.wall_stiffness_ratio, 0.0, 1e6)
        set_(self, "wall_stiffness_ratio", ratio)
        thick = 0.0 if self.thickness_ratio is None else self.thickness_ratio
        set_(
            self,
            "thickness_ratio",
            _in("thickness_ratio", thick, 0.0, MAX_THICKNESS_RATIO, low_open=False),
        )

    @classmethod
    def preset(cls, name: str) -> Wall:
        """The wall of a preset ball (:data:`WALLS`), with its source."""
        try:
            return WALLS[name]
        except KeyError:
            valid = "a preset with a wall: " + ", ".join(WALLS)
            raise ParameterError("wall", valid, name) from None

    @property
    def dimensionless(self) -> bool:
        """True when given by C / N0 and h / R (not SI)."""
        return self.youngs_modulus is None

    @staticmethod
    def tension(case: Case) -> float:
        """The inflation tension ``N0 = P R / 2`` [N/m] of the case (its excess pressure)."""
        if case.pressure is None:
            raise ParameterError("pressure", "known for the shell (its tension N0 = P R / 2)", None)
        return float(case.pressure) * case.radius / 2.0

    def stiffness(self, case: Case) -> float:
        """In-plane stiffness C [N/m]: ``E h / (1 - nu^2)``, or ``(C / N0) N0``."""
        if self.dimensionless:
            return float(self.wall_stiffness_ratio) * self.tension(case)
        return float(self.youngs_modulus) * float(self.thickness) / (1.0 - self.poisson**2)

    def thickness_m(self, case: Case) -> float:
        """Wall thickness h [m] (``(h / R) R`` for a dimensionless wall)."""
        if self.dimensionless:
            return float(self.thickness_ratio) * case.radius
        return float(self.thickness)

    def bending_stiffness(self, case: Case) -> float:
        """``D_b = C h^2 / 12`` [N m] (``E h^3 / (12 (1 - nu^2))``)."""
        return self.stiffness(case) * self.thickness_m(case) ** 2 / 12.0

    def youngs_modulus_pa(self, case: Case) -> float | None:
        """E [Pa]: given, or ``C (1 - nu^2) / h`` of a dimensionless wall (None when h = 0)."""
        if not self.dimensionless:
            return float(self.youngs_modulus)
        h = self.thickness_m(case)
        return None if h == 0.0 else self.stiffness(case) * (1.0 - self.poisson**2) / h

    def parameters(self, case: Case, gas: str | None = None) -> ShellParameters:
        """The dimensionless shell of ``case``: nu, ``beta_h``, ``p = N0 / C`` and the gas g.

        The gas ``g = 3 kappa (P + P_atm) R / C`` of the case's gas law, or of
        ``gas`` when given (kappa of :data:`twoball.modal.stiffness.GAS_MODELS`).

        Raises
        ------
        ParameterError
            A wall thicker than half the radius, or one too soft for its tension
            (the breathing mode unstable: ``2 (1 + nu) - 2 p + g <= 0``).
        """
        from twoball.modal.shell.parameters import ShellParameters
        from twoball.modal.stiffness import GAS_MODELS

        ratio = self.thickness_m(case) / case.radius
        if ratio > MAX_THICKNESS_RATIO:
            raise ParameterError(
                "thickness",
                f"a thin wall, h <= {MAX_THICKNESS_RATIO:g} R = "
                f"{MAX_THICKNESS_RATIO * case.radius:g} m",
                self.thickness_m(case),
            )
        stiffness = self.stiffness(case)
        law = case.gas if gas is None else gas
        if law not in GAS_MODELS:
            raise ParameterError("gas", "one of " + ", ".join(GAS_MODELS), law)
        kappa = GAS_MODELS[law]
        absolute = float(case.pressure) + case.atmosphere
        try:
            return ShellParameters(
                poisson=self.poisson,
                bending=ratio**2 / 12.0,
                prestress=self.tension(case) / stiffness,
                gas=3.0 * kappa * absolute * case.radius / stiffness,
            )
        except ParameterError as error:
            name = "wall_stiffness_ratio" if self.dimensionless else "youngs_modulus"
            raise ParameterError(name, error.valid, error.got) from None

    def extensional_speed(self, case: Case) -> float:
        """In-plane wave speed ``c_e = sqrt(C / rho_s)`` [m/s], ``rho_s = N0 / (c R)^2``."""
        density = self.tension(case) / (case.wave_speed * case.radius) ** 2
        return math.sqrt(self.stiffness(case) / density)

    def in_plane_arrival(self, case: Case) -> float:
        """``pi R / c_e`` [s]: an in-plane wave from the south pole to the north pole."""
        return math.pi * case.radius / self.extensional_speed(case)

    def summary(self, case: Case) -> dict[str, Any]:
        """The wall in SI and dimensionless, for the JSON's ``model`` block.

        ``youngs_modulus_Pa`` E, ``thickness_m`` h, ``poisson`` nu,
        ``wall_stiffness_N_m`` C, ``bending_stiffness_N_m`` D_b, ``tension_N_m``
        N0, ``wall_stiffness_ratio`` C / N0, ``thickness_ratio`` h / R,
        ``extensional_speed_m_s`` c_e, ``in_plane_arrival_s`` ``pi R / c_e``,
        ``given`` (``si`` or ``ratios``) and ``source``.
        """
        stiffness, tension = self.stiffness(case), self.tension(case)
        return {
            "given": "ratios" if self.dimensionless else "si",
            "youngs_modulus_Pa": self.youngs_modulus_pa(case),
            "thickness_m": self.thickness_m(case),
            "poisson": self.poisson,
            "wall_stiffness_N_m": stiffness,
            "bending_stiffness_N_m": self.bending_stiffness(case),
            "tension_N_m": tension,
            "wall_stiffness_ratio": stiffness / tension,
            "thickness_ratio": self.thickness_m(case) / case.radius,
            "extensional_speed_m_s": self.extensional_speed(case),
            "in_plane_arrival_s": self.in_plane_arrival(case),
            "source": self.source,
        }

    def as_dict(self) -> dict[str, Any]:
        """The wall as given (None: not given)."""
        return {
            "youngs_modulus": self.youngs_modulus,
            "thickness": self.thickness,
            "poisson": self.poisson,
            "wall_stiffness_ratio": self.wall_stiffness_ratio,
            "thickness_ratio": self.thickness_ratio,
        }


#: The basketball's default wall stiffness ratio C / N0 (docs/shell.rst, "The
#: basketball's wall"): ``2 / (1 - nu)`` with nu = 1/2, the wall whose lower branch
#: is the pressurised membrane's ``(n - 1)(n + 2) c^2`` at every degree (without
#: bending; within 0.1-0.9 % for n = 2..5 with h/R = 1/30), so the c = 320 1/s
#: that the paper's own data fit stays the ball's; inside the range those data
#: allow (C/N0 in [0.53, 6.0]: c of degree 2 within Fig. 10's 220-350 1/s).
BASKETBALL_WALL_RATIO = 4.0
#: The basketball's assumed wall: 4 mm on R = 0.12 m.
BASKETBALL_THICKNESS_RATIO = 4.0e-3 / 0.12

#: Walls of the presets.  tennis: its preset's E, h and nu; basketball: a stated
#: choice (the paper gives no wall); volleyball: the basketball's ratios (no data).
WALLS: dict[str, Wall] = {
    "tennis": Wall(
        youngs_modulus=6.0e6,
        thickness=3.2e-3,
        poisson=0.5,
        source="the tennis preset's wall: rubber E = 6 MPa (assumed), h = 3.2 mm (Cross 1999; "
        "Brody, Cross & Lindsey 2002), nu = 0.5",
    ),
    "basketball": Wall(
        wall_stiffness_ratio=BASKETBALL_WALL_RATIO,
        thickness_ratio=BASKETBALL_THICKNESS_RATIO,
        poisson=0.5,
        source="a stated choice, not measured (the paper gives no wall): C/N0 = 2/(1 - nu) = "
        "4, the wall whose lower branch is the pressurised membrane's spectrum, keeping the "
        "c = 320 1/s the paper's data fit (Fig. 10, Table 2), inside the range those data "
        "allow (docs/shell.rst); h = 4 mm and nu = 0.5 assumed",
    ),
    "volleyball": Wall(
        wall_stiffness_ratio=BASKETBALL_WALL_RATIO,
        thickness_ratio=BASKETBALL_THICKNESS_RATIO,
        poisson=0.5,
        source="no measured wall: the basketball's stated C/N0 = 4 and h/R = 1/30 (h = 3.5 "
        "mm), both pressurised bladders under a cover",
    ),
}


def _wall_of(wall: Wall | None, case: Case) -> Wall:
    """The ball's wall, else the case's preset's."""
    if wall is not None:
        return wall
    name = case.preset_name or ""
    if name not in WALLS:
        valid = "given for a case without a preset wall (" + ", ".join(WALLS) + " have one)"
        raise ParameterError("wall", valid, None)
    return WALLS[name]


def _check_wall(wall: object) -> Wall | None:
    if wall is not None and not isinstance(wall, Wall):
        raise ParameterError("wall", "a twoball.Wall or None (the preset's)", type(wall).__name__)
    return wall


def shell_summary(wall: Wall, case: Case) -> dict[str, Any]:
    """The shell's block of the JSON's ``model``: the membrane drop's keys and the wall.

    ``ball`` ``"shell"``; ``membrane`` None (no membrane operator);
    ``bending_N_m`` D_b and ``bending_beta`` ``D_b / (N0 R^2)`` (the membrane's
    definition, ``B / (T R^2)``); ``omega0_squared`` the breathing mode's
    ``omega_0^2`` in units of ``c^2``; ``wall`` (:meth:`Wall.summary`);
    ``in_plane_arrival_s`` ``pi R / c_e`` beside ``pressure_wave_arrival_s`` ``pi / c``.
    """
    parameters = wall.parameters(case)
    tension = wall.tension(case)
    return {
        "ball": "shell",
        "membrane": None,
        "bending_N_m": wall.bending_stiffness(case),
        "bending_beta": wall.bending_stiffness(case) / (tension * case.radius**2),
        "omega0_squared": parameters.breathing_squared / parameters.prestress,
        "wall": wall.summary(case),
        "in_plane_arrival_s": wall.in_plane_arrival(case),
        "pressure_wave_arrival_s": math.pi / case.wave_speed,
    }


def shell_description(
    *,
    omega: np.ndarray,
    degree: np.ndarray,
    translation: int,
    parameters: ShellParameters,
    law: Any,
    phi: np.ndarray,
    vertical: Any,
    radial: Any,
    meridional: Any,
    cap_average: Any,
    label: str,
) -> ModalBall:
    """The :class:`ModalBall` of shell modes of unit modal mass (closed form or finite elements).

    Parameters
    ----------
    omega : ndarray, shape (K,)
        ``Omega_k`` (units ``c_e / R``); the translation's is set to 0.
    degree : ndarray of int, shape (K,)
        Each mode's (dominant) Legendre degree: 0 marks the breathing mode (the gas's).
    translation : int
        Index of the rigid translation: the drop's centre.
    parameters : ShellParameters
        ``p`` converts ``Omega^2`` to units of ``c^2``; ``g`` is the gas.
    law : ModalRatio or Rayleigh
        The damping law in units of c.
    phi : ndarray
        Floor points, ascending in (pi/2, pi].
    vertical, radial, meridional : callable
        ``f(angles) -> (K, len(angles))``: u_z, w and v of each mode.
    cap_average : callable
        ``f(theta) -> (K,)``: u_z averaged over the polar cap.
    label : str
    """
    from twoball.modal.balls.membrane import mode_decay

    p = parameters.prestress
    k = omega.size
    w2 = omega**2 / p
    w2[translation] = 0.0
    gas2 = np.where(degree == 0, parameters.gas / p, 0.0)
    gas2[translation] = 0.0
    decay = np.asarray(mode_decay(law, w2), dtype=float).copy()
    decay[translation] = 0.0
    rows = np.asarray(vertical(phi), dtype=float).T.copy()
    rows[:, translation] = 1.0
    top = np.asarray(vertical(np.array([0.0])), dtype=float)[:, 0].copy()
    top[translation] = 1.0

    def deformation(function: Any) -> Any:
        def sample(angles: np.ndarray) -> np.ndarray:
            out = np.asarray(function(np.asarray(angles, dtype=float)), dtype=float).T.copy()
            out[:, translation] = 0.0
            return out

        return sample

    def averager(theta: float) -> np.ndarray:
        out = np.asarray(cap_average(theta), dtype=float).copy()
        out[translation] = 1.0
        return out

    return ModalBall(
        masses=np.ones(k),
        omega_squared=w2,
        gas_squared=gas2,
        decay=decay,
        centre=translation,
        phi=phi,
        floor_rows=rows,
        top=top,
        label=label,
        bending=parameters.bending > 0.0,
        sampler=deformation(radial),
        tangential=deformation(meridional),
        averager=averager,
    )


def shell_ball(parameters: ShellParameters, modes: int, law: Any, label: str = "") -> ModalBall:
    """The closed-form shell on degrees 0..N as a :class:`ModalBall` (dimensionless: R, 1/c, m).

    Floor points at the Gauss-Radau nodes of degree N on the lower hemisphere
    (:func:`~twoball.modal.balls.membrane.floor_angles`).
    """
    from twoball.modal.balls.membrane import floor_angles
    from twoball.modal.shell.modes import shell_modes

    shell = shell_modes(parameters, modes)
    return shell_description(
        omega=np.array(shell.omega, dtype=float),
        degree=shell.degree,
        translation=shell.translation,
        parameters=parameters,
        law=law,
        phi=floor_angles(modes),
        vertical=shell.vertical,
        radial=shell.radial,
        meridional=shell.meridional,
        cap_average=shell.cap_average,
        label=label or f"shell legendre N = {modes}",
    )


@checked
@dataclass(frozen=True)
class ShellBall:
    """The thin spherical shell on its closed-form modes: a lower ball for the drop.

    Parameters
    ----------
    wall : Wall, optional
        The wall (default: the case's preset's, :data:`WALLS`).
    modes : int, optional
        Legendre degree N in [8, 1000] (default :data:`DEFAULT_SHELL_MODES`, 128):
        ``2 N + 1`` modes, both branches of degrees 0..N; floor points at the
        Gauss-Radau nodes of degree N on the lower hemisphere (about N / 2).

    Examples
    --------
    >>> import twoball
    >>> twoball.ShellBall(modes=64).label
    'shell legendre N = 64'
    >>> twoball.ShellBall(modes=4)
    Traceback (most recent call last):
    ...
    twoball.ParameterError: modes must be an integer in [8, 1000], got 4
    """

    wall: Wall | None = None
    modes: int | None = None

    #: The physics of this ball (the JSON's ``ball``) and its discretisation.
    kind = "shell"
    backend = "legendre"

    def __post_init__(self) -> None:
        _check_wall(self.wall)
        if self.modes is not None:
            low, high = SHELL_MODES_RANGE
            if (
                isinstance(self.modes, bool)
                or not isinstance(self.modes, int | np.integer)
                or not low <= int(self.modes) <= high
            ):
                raise ParameterError("modes", f"an integer in [{low}, {high}]", self.modes)
            object.__setattr__(self, "modes", int(self.modes))

    @property
    def degree(self) -> int:
        """N (the default when none was given)."""
        return DEFAULT_SHELL_MODES if self.modes is None else self.modes

    @property
    def label(self) -> str:
        """``shell legendre N = 128``."""
        return f"shell legendre N = {self.degree}"

    def size(self, case: Case | None = None) -> tuple[int, int]:
        """Coordinates (``2 N + 1`` modes) and floor points (about N / 2) of the drop."""
        return 2 * self.degree + 1, self.degree // 2 + 1

    def mass(self, case: Case) -> float:
        """The ball's mass ``2 pi R P / c^2`` [kg]: c is the wave speed of the tension PR/2."""
        from twoball.modal.scalings import membrane_mass

        return membrane_mass(case.radius, case.pressure, case.wave_speed)

    def wall_of(self, case: Case) -> Wall:
        """The wall in use: the ball's, else the case's preset's."""
        return _wall_of(self.wall, case)

    def summary(self, case: Case) -> dict[str, Any]:
        """The shell's block of the JSON's ``model`` (:func:`shell_summary`)."""
        return shell_summary(self.wall_of(case), case)

    def describe(self, case: Case, monitor: Any = None) -> ModalBall:
        """The shell of ``case`` on degrees 0..N (dimensionless: R, 1/c, m)."""
        parameters = self.wall_of(case).parameters(case)
        return shell_ball(parameters, self.degree, case.damping_law, self.label)

    def as_dict(self) -> dict[str, Any]:
        """``{"ball": "shell", "discretisation": "legendre", "modes": N, "wall": {...}}``."""
        wall = None if self.wall is None else self.wall.as_dict()
        return {"ball": self.kind, "discretisation": "legendre", "modes": self.modes, "wall": wall}
