"""The homogeneous elastic sphere as a lower ball: its material, Lamb's modes and the ball object.

The solid ball (docs/solid.rst) moves radially *and* meridionally through its
whole volume.  Its modes are Lamb's spheroidal modes of degree n and radial
order k (:mod:`twoball.modal.solid`): axisymmetric (m = 0), of unit modal mass in
units of the ball's mass (eq. (M2) of :mod:`twoball.modal.solid.modes`), at the
roots ``eta_nk = omega R / c_s`` of Lamb's frequency equation (eq. (L3) of
:mod:`twoball.modal.solid.lamb`).  The rigid translation (n = 1, k = 0, ``U = V =
1``) is the drop's centre: its coordinate is the displacement of the centre of
mass, so its value is the centre's height.

Time unit.  A solid ball has no tension: its case's wave speed is defined as
``c = c_s / R`` (the shear speed over the radius, [1/s]), so that ``eta`` is
omega in units of c and Hertz's contact time is a few units (eq. (S1)).  A
case with another c is mapped consistently: ``omega^2 / c^2 = eta^2 (c_s / (R
c))^2``, so the physics never depends on the unit (only the default time step
and window, which are fractions of ``1 / c``, do).  :func:`solid_case` builds the
case of a material and a radius with ``c = c_s / R``.

Mass: ``(4/3) pi R^3 rho`` (:meth:`SolidMaterial.mass`), the run's unit of mass.

Coordinates: the translation and every mode of degrees 0..N, radial orders
1..K (``(N + 1) K + 1`` coordinates), masses 1, ``omega^2 = eta^2 (c_s / (R
c))^2``, decays from the damping law (:func:`~twoball.modal.balls.membrane.mode_decay`).
Rows: the vertical displacement ``u_z = u_r cos(phi) - u_theta sin(phi)`` of each
mode at the floor points, the Gauss-Radau nodes of degree N on the lower
hemisphere (:func:`~twoball.modal.balls.membrane.floor_angles`: ``u_z`` of a
mode of degree n is a polynomial of degree n + 1 in ``cos(phi)``), at the pole
and averaged over a cap (exact Gauss-Legendre in ``cos(phi)``).

Resolution of the floor contact (docs/solid.rst, "The drop against Hertz"): the
contact of a solid is Hertz-like, of radius ``a ~ sqrt(R delta)``; the floor
points are ``~ pi / N`` apart near the south pole, so the contact holds about
``a / (R pi / N)`` of them.  :func:`hertz_reference` gives Hertz's numbers for
the case and :meth:`SolidBall.summary` the expected points in the contact; the
drop warns when the largest contact holds fewer than 6
(:data:`~twoball.modal.floor.bounce.MIN_CONTACT_POINTS`).

Speed.  The roots come from a vectorised scan of Lamb's function per degree
(:func:`lamb_table`, the same function and grid as
:func:`~twoball.modal.solid.lamb.lamb_roots`, the sign changes refined together
by the Illinois rule) and are cached per (nu, n, count): a default superball's
520 modes build in about a second.
"""

from __future__ import annotations

import functools
import math
import weakref
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

import numpy as np

from twoball._common.errors import NumericalError, ParameterError, check_labels, real_number
from twoball._common.keywords import checked
from twoball.modal.presets import SUPERBALL_MATERIAL, SUPERBALL_RADIUS

if TYPE_CHECKING:
    from twoball.modal.balls.description import ModalBall
    from twoball.modal.parameters import Case
    from twoball.modal.solid.modes import SphereMode

__all__ = [
    "CutGrid",
    "DEFAULT_RADIAL_ORDERS",
    "DEFAULT_SOLID_MODES",
    "MATERIALS",
    "LambTable",
    "SolidBall",
    "SolidMaterial",
    "hertz_reference",
    "cut_of",
    "lamb_table",
    "register_cut",
    "solid_case",
]

#: Highest Legendre degree N of the solid's drop (floor points ~N/2, spacing ~pi/N).
DEFAULT_SOLID_MODES = 64
#: Radial orders K per degree.
DEFAULT_RADIAL_ORDERS = 8
#: Degrees N a solid ball takes.
SOLID_MODES_RANGE = (4, 400)
#: Radial orders K a solid ball takes.
RADIAL_ORDERS_RANGE = (1, 40)
#: Grid step of the root scan in eta (as :func:`~twoball.modal.solid.lamb.lamb_roots`).
ROOT_STEP = 0.02

_VALID = {
    "density": "a density in (0, 1e5] kg/m^3",
    "youngs_modulus": "a Young's modulus in (0, 1e12] Pa",
    "poisson": "Poisson's ratio in (-1, 0.5)",
}


def _in(name: str, value: object, low: float, high: float, *, high_open: bool = False) -> float:
    number = real_number(name, value, _VALID[name])
    ok = low < number and (number < high if high_open else number <= high)
    if not (ok and math.isfinite(number)):
        raise ParameterError(name, _VALID[name], value)
    return number


@checked
@dataclass(frozen=True)
class SolidMaterial:
    """A homogeneous isotropic linearly elastic material (SI).

    Parameters
    ----------
    density : float
        rho [kg/m^3] in (0, 1e5].
    youngs_modulus : float
        E [Pa] in (0, 1e12].
    poisson : float
        nu in (-1, 0.5).
    source : str
        Where the values come from (the presets'; not compared).

    Examples
    --------
    >>> import twoball
    >>> m = twoball.SolidMaterial(density=1000.0, youngs_modulus=3e6, poisson=0.25)
    >>> round(m.shear_speed, 3), round(m.wave_speed(0.02), 1)
    (34.641, 1732.1)
    >>> twoball.SolidMaterial(density=1000.0, youngs_modulus=3e6, poisson=0.5)
    Traceback (most recent call last):
    ...
    twoball.ParameterError: poisson must be Poisson's ratio in (-1, 0.5), got 0.5
    """

    density: float
    youngs_modulus: float
    poisson: float
    source: str = field(default="", compare=False)

    def __post_init__(self) -> None:
        check_labels(self, "source")
        set_ = object.__setattr__
        set_(self, "density", _in("density", self.density, 0.0, 1e5))
        set_(self, "youngs_modulus", _in("youngs_modulus", self.youngs_modulus, 0.0, 1e12))
        set_(self, "poisson", _in("poisson", self.poisson, -1.0, 0.5, high_open=True))

    @classmethod
    def preset(cls, name: str) -> SolidMaterial:
        """The material of a preset ball (:data:`MATERIALS`), with its source."""
        try:
            return MATERIALS[name]
        except KeyError:
            valid = "a preset with a solid material: " + ", ".join(MATERIALS)
            raise ParameterError("material", valid, name) from None

    @property
    def shear_modulus(self) -> float:
        """mu = E / (2 (1 + nu)) [Pa]."""
        return self.youngs_modulus / (2.0 * (1.0 + self.poisson))

    @property
    def shear_speed(self) -> float:
        """c_s = sqrt(mu / rho) [m/s]."""
        return math.sqrt(self.shear_modulus / self.density)

    @property
    def pressure_speed(self) -> float:
        """c_p = c_s sqrt(2 (1 - nu) / (1 - 2 nu)) [m/s]."""
        from twoball.modal.solid.lamb import speed_ratio

        return self.shear_speed * speed_ratio(self.poisson)

    @property
    def effective_modulus(self) -> float:
        """E* = E / (1 - nu^2) [Pa] of the sphere on a rigid flat (Hertz)."""
        return self.youngs_modulus / (1.0 - self.poisson**2)

    def wave_speed(self, radius: float) -> float:
        """The solid's case wave speed ``c = c_s / R`` [1/s] (the module's time unit)."""
        return self.shear_speed / float(radius)

    def mass(self, radius: float) -> float:
        """``(4/3) pi R^3 rho`` [kg]."""
        return 4.0 / 3.0 * math.pi * float(radius) ** 3 * self.density

    def as_dict(self) -> dict[str, Any]:
        """The material as given (SI)."""
        return {
            "density_kg_m3": self.density,
            "youngs_modulus_Pa": self.youngs_modulus,
            "poisson": self.poisson,
        }

    def summary(self, radius: float) -> dict[str, Any]:
        """The material with its derived speeds and moduli for the JSON (SI), and its source."""
        return {
            **self.as_dict(),
            "shear_modulus_Pa": self.shear_modulus,
            "effective_modulus_Pa": self.effective_modulus,
            "shear_speed_m_s": self.shear_speed,
            "pressure_speed_m_s": self.pressure_speed,
            "wave_speed_c_s_over_R_1_s": self.wave_speed(radius),
            "source": self.source,
        }


#: Materials of the presets.
MATERIALS: dict[str, SolidMaterial] = {"superball": SolidMaterial(**SUPERBALL_MATERIAL)}


def material_of(material: SolidMaterial | None, case: Case) -> SolidMaterial:
    """The ball's material, else the case's preset's (:data:`MATERIALS`)."""
    if material is not None:
        return material
    name = case.preset_name or ""
    if name not in MATERIALS:
        valid = "given for a case without a preset material (" + ", ".join(MATERIALS) + " has one)"
        raise ParameterError("material", valid, None)
    return MATERIALS[name]


def check_material(material: object) -> SolidMaterial | None:
    """``material`` if it is a :class:`SolidMaterial` or None, else a ParameterError."""
    if material is not None and not isinstance(material, SolidMaterial):
        valid = "a twoball.SolidMaterial or None (the preset's)"
        raise ParameterError("material", valid, type(material).__name__)
    return material


def solid_case(
    material: SolidMaterial | str = "superball",
    *,
    radius: float | None = None,
    v0: float | None = None,
    damping: float = 0.0,
    **changes: Any,
) -> Case:
    """The case of a solid ball: ``c = c_s / R`` (eq. (S1) of docs/solid.rst), no pressure.

    Parameters
    ----------
    material : SolidMaterial or str
        The material, or a preset's name (``"superball"``, whose R and ``|v0|``
        are the defaults).
    radius : float, optional
        R [m] (default the preset's, else :data:`SUPERBALL_RADIUS`).
    v0 : float, optional
        Impact speed [m/s] (default the preset's 4.1 m/s).
    damping : float
        The modal damping ratio D (default 0: undamped).
    **changes
        Further fields of :class:`~twoball.Case` (``g``, ``modes``, ``rayleigh``).

    Examples
    --------
    >>> from twoball.modal.balls.solid import solid_case
    >>> case = solid_case("superball", v0=1.0)
    >>> case.preset_name, round(case.wave_speed, 1), case.pressure is None
    ('superball', 2003.1, True)
    """
    from twoball.modal.parameters import Case

    preset = None
    if isinstance(material, str):
        preset = material
        material = SolidMaterial.preset(material)
    check_material(material)
    base = Case.preset(preset) if preset is not None else None
    r = radius if radius is not None else (base.radius if base else SUPERBALL_RADIUS)
    speed = v0 if v0 is not None else (base.v0 if base else 4.1)
    wave = material.wave_speed(r)
    if base is not None:
        return base.derive(radius=r, wave_speed=wave, v0=speed, damping=damping, **changes)
    return Case(r, wave, speed, damping=damping, preset_name=None, **changes)


# --- Lamb's modes, many at once -----------------------------------------------------------


@dataclass(frozen=True, eq=False)
class LambTable:
    """Lamb's axisymmetric modes of degrees and radial orders, as arrays (R = 1).

    Attributes
    ----------
    poisson : float
    degree, radial_order : ndarray of int, shape (K,)
        The translation is degree 1, radial order 0 (eta 0, ``U = V = 1``); a
        static correction (eq. (S3)) has radial order -1.
    eta : ndarray, shape (K,)
        ``omega R / c_s``.
    amplitude_p, amplitude_s : ndarray, shape (K,)
        A and B of eq. (M1), normalised by eq. (M2) (unit modal mass).
    surface_u, surface_v : ndarray, shape (K,)
        ``U(1)`` and ``V(1)``: the surface's radial and meridional amplitudes.
    translation : int
        Index of the translation.
    """

    poisson: float
    degree: np.ndarray
    radial_order: np.ndarray
    eta: np.ndarray
    amplitude_p: np.ndarray
    amplitude_s: np.ndarray
    surface_u: np.ndarray
    surface_v: np.ndarray
    translation: int

    @property
    def size(self) -> int:
        """Number of modes K (the translation included)."""
        return int(self.eta.size)

    def _angular(self, phi: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """``P_n(cos phi)`` and ``dP_n/dphi`` of each mode's degree, shape (len(phi), K)."""
        from numpy.polynomial.legendre import legvander
        from scipy.special import lpmv

        x = np.cos(np.asarray(phi, dtype=float).reshape(-1))
        top = int(self.degree.max())
        p = legvander(x, top)
        dp = np.column_stack([lpmv(1, n, x) for n in range(top + 1)])
        return p[:, self.degree], dp[:, self.degree]

    def surface(self, phi: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """``(u_r, u_theta, u_z)`` of every mode at the surface points ``phi``, (len(phi), K)."""
        phi = np.asarray(phi, dtype=float).reshape(-1)
        p, dp = self._angular(phi)
        ur = p * self.surface_u
        ut = dp * self.surface_v
        uz = ur * np.cos(phi)[:, None] - ut * np.sin(phi)[:, None]
        return ur, ut, uz

    def cap_average(self, theta: float) -> np.ndarray:
        """``u_z`` of every mode averaged over the cap ``phi <= theta`` (exact in ``cos(phi)``)."""
        if theta == 0.0:
            return self.surface(np.array([0.0]))[2][0]
        count = int(self.degree.max()) + 4
        x, w = np.polynomial.legendre.leggauss(count)
        low = math.cos(theta)
        x = 0.5 * (1.0 - low) * x + 0.5 * (1.0 + low)
        w = 0.5 * (1.0 - low) * w
        uz = self.surface(np.arccos(np.clip(x, -1.0, 1.0)))[2]
        return (w @ uz) / (1.0 - low)

    def modes(self) -> list[SphereMode]:
        """The modes as :class:`~twoball.modal.solid.modes.SphereMode` (for interior fields)."""
        from twoball.modal.solid.modes import SphereMode

        return [
            SphereMode(int(n), int(k), float(e), self.poisson, float(a), float(b))
            for n, k, e, a, b in zip(
                self.degree,
                self.radial_order,
                self.eta,
                self.amplitude_p,
                self.amplitude_s,
                strict=True,
            )
        ]

    def field(self, rho: np.ndarray, theta: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """``(u_r, u_theta)`` of every mode at interior points, shape (len, K) (for cut views)."""
        rho = np.asarray(rho, dtype=float).reshape(-1)
        theta = np.asarray(theta, dtype=float).reshape(-1)
        ur = np.empty((rho.size, self.size))
        ut = np.empty((rho.size, self.size))
        for j, mode in enumerate(self.modes()):
            ur[:, j], ut[:, j] = mode.displacement(rho, theta)
        return ur, ut


def _refine(n: int, poisson: float, a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """Roots of F_n in the brackets [a, b] (sign change), all at once: Illinois regula falsi."""
    from twoball.modal.solid.lamb import lamb_function

    fa = lamb_function(n, a, poisson)
    fb = lamb_function(n, b, poisson)
    a, b = a.copy(), b.copy()
    side = np.zeros(a.size, dtype=int)
    out = np.where(np.abs(fa) <= np.abs(fb), a, b)
    best = np.minimum(np.abs(fa), np.abs(fb))
    active = np.ones(a.size, dtype=bool)
    for _ in range(100):
        i = np.flatnonzero(active)
        if i.size == 0:
            break
        x = (a[i] * fb[i] - b[i] * fa[i]) / (fb[i] - fa[i])
        bad = ~((x > a[i]) & (x < b[i]))
        x[bad] = 0.5 * (a[i][bad] + b[i][bad])
        fx = lamb_function(n, x, poisson)
        better = np.abs(fx) < best[i]  # the evaluated point of least |F| so far
        out[i] = np.where(better, x, out[i])
        best[i] = np.where(better, np.abs(fx), best[i])
        left = np.sign(fx) == np.sign(fa[i])
        # Illinois: halve the value of the end that stays twice in a row
        fb[i] = np.where(left & (side[i] == 1), 0.5 * fb[i], fb[i])
        fa[i] = np.where(~left & (side[i] == -1), 0.5 * fa[i], fa[i])
        a[i] = np.where(left, x, a[i])
        fa[i] = np.where(left, fx, fa[i])
        b[i] = np.where(left, b[i], x)
        fb[i] = np.where(left, fb[i], fx)
        side[i] = np.where(left, 1, -1)
        done = (np.abs(fx) <= 5e-14) | ((b[i] - a[i]) <= 4e-16 * np.maximum(1.0, b[i]))
        active[i[done]] = False
    return out


@functools.lru_cache(maxsize=4096)
def _degree_roots(n: int, poisson: float, count: int) -> tuple[float, ...]:
    """The first ``count`` roots of Lamb's function of degree n: the scan of ``lamb_roots``."""
    from twoball.modal.solid.lamb import lamb_function

    roots: list[float] = []
    lo = 1e-3
    window = max(8.0, 2.0 * n + 8.0)
    while len(roots) < count:
        hi = lo + window
        grid = np.arange(lo, hi + 0.5 * ROOT_STEP, ROOT_STEP)
        grid[-1] = hi
        values = lamb_function(n, grid, poisson)
        change = np.flatnonzero(np.sign(values[:-1]) * np.sign(values[1:]) < 0)
        exact = grid[:-1][values[:-1] == 0.0]
        found = list(exact)
        if change.size:
            found += list(_refine(n, poisson, grid[change], grid[change + 1]))
        found = sorted(r for r in found if r > 1e-3 and not (roots and r <= roots[-1]))
        roots.extend(found)
        lo = hi
        if lo > 50.0 * (n + count + 10):
            raise NumericalError(f"Lamb's equation n = {n}: only {len(roots)} roots found")
    return tuple(roots[:count])


def _amplitudes(
    n: int, poisson: float, eta: np.ndarray
) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """Normalised A, B and the surface values U(1), V(1) of the modes of degree n at ``eta``."""
    from scipy.special import spherical_jn

    from twoball.modal.solid.lamb import boundary_matrix, speed_ratio

    ratio = speed_ratio(poisson)
    x, y = eta / ratio, eta
    if n == 0:
        a = np.ones_like(eta)
        b = np.zeros_like(eta)
    else:
        m = boundary_matrix(n, eta, poisson)
        r0 = np.hypot(m[:, 0, 0], m[:, 0, 1])
        r1 = np.hypot(m[:, 1, 0], m[:, 1, 1])
        row = np.where((r0 >= r1)[:, None], m[:, 0, :], m[:, 1, :])
        a, b = row[:, 1], -row[:, 0]
    sx = np.hypot(spherical_jn(n, x), spherical_jn(n + 1, x))
    sy = np.hypot(spherical_jn(n, y), spherical_jn(n + 1, y))
    if np.any(sx == 0.0) or np.any(sy == 0.0):
        raise ParameterError("degree", "small enough that j_n(x) does not underflow", n)
    big_a, big_b = a / sx, b / sy
    # eq. (M2): the volume mean of |u|^2, Gauss-Legendre in rho (all modes of the degree)
    points = int(32 + n // 2 + math.ceil(1.2 * float(eta.max())))
    rho, w = _gauss(8 * -(-points // 8))
    u, v = _radial(n, x, y, big_a, big_b, rho)
    mean = 3.0 / (2 * n + 1) * ((w * rho**2) @ (u * u + n * (n + 1) * v * v))
    u1, v1 = _radial(n, x, y, big_a, big_b, np.ones(1))
    u1, v1 = u1[0], v1[0]
    sign = np.where(np.abs(u1) > 1e-12 * np.abs(v1), np.sign(u1), np.sign(v1))
    scale = sign / np.sqrt(mean)
    return big_a * scale, big_b * scale, u1 * scale, v1 * scale


@functools.lru_cache(maxsize=64)
def _gauss(points: int) -> tuple[np.ndarray, np.ndarray]:
    """Gauss-Legendre nodes and weights on [0, 1]."""
    rho, w = np.polynomial.legendre.leggauss(points)
    return 0.5 * (rho + 1.0), 0.5 * w


def _radial(
    n: int, x: np.ndarray, y: np.ndarray, a: np.ndarray, b: np.ndarray, rho: np.ndarray
) -> tuple[np.ndarray, np.ndarray]:
    """U(rho), V(rho) of eq. (M1) for modes (columns) at radii rho (rows)."""
    from scipy.special import spherical_jn

    rho = np.maximum(rho, 1e-8)[:, None]
    xr, yr = x[None, :] * rho, y[None, :] * rho
    jx, jx1 = spherical_jn(n, xr), spherical_jn(n + 1, xr)
    jy, jy1 = spherical_jn(n, yr), spherical_jn(n + 1, yr)
    u = a * (n * jx - xr * jx1) / rho + b * n * (n + 1) * jy / rho
    v = a * jx / rho + b * ((n + 1) * jy - yr * jy1) / rho
    if n == 0:
        v = np.zeros_like(u)
    return u, v


#: The small frequency at which the static compliance is read (eq. (S2)).
STATIC_ETA = 1e-3


def surface_compliance(n: int, poisson: float, eta: float = STATIC_ETA) -> np.ndarray:
    """The sphere's surface response of degree n to a surface traction at frequency eta (R = 1).

    A traction ``mu (tau_r P_n e_r + tau_theta dP_n/dtheta e_theta)`` on the
    surface drives the field of eq. (M1) whose potentials solve eq. (L1) with that
    right-hand side; the surface amplitudes ``(U(1), V(1))`` are ``C (tau_r,
    tau_theta)`` (eq. (S2)).  In Lamb's modes (unit modal mass, volume 4 pi / 3)
    the same response is ``3 / (2n + 1) sum_k a_k a_k^T w / (eta_k^2 - eta^2)``
    with ``a_k = (U_k(1), V_k(1))`` and ``w = diag(1, n (n + 1))`` (the
    translation's ``eta_0 = 0`` included for n = 1), so ``C w^-1`` is symmetric.
    """
    from twoball.modal.solid.lamb import boundary_matrix, scaled_bessel_pair, speed_ratio

    x, y = eta / speed_ratio(poisson), eta
    m = boundary_matrix(n, np.array([eta]), poisson)[0]
    jx, jx1 = (v[0] for v in scaled_bessel_pair(n, np.array([x])))
    jy, jy1 = (v[0] for v in scaled_bessel_pair(n, np.array([y])))
    if n == 0:
        return np.array([[(n * jx - x * jx1) / m[0, 0], 0.0], [0.0, 0.0]])
    shape = np.array([[n * jx - x * jx1, n * (n + 1) * jy], [jx, (n + 1) * jy - y * jy1]])
    return shape @ np.linalg.inv(m)


def _residual(
    n: int, poisson: float, u: np.ndarray, v: np.ndarray, eta: np.ndarray, tail: float
) -> list[tuple[float, float]]:
    """Surface amplitudes of the static correction of degree n: what the kept modes miss.

    ``S = (C - C_kept) w^-1`` (eq. (S3)) is symmetric and, for a complete sum,
    positive; each eigenpair ``(s, e)`` with ``s > 0`` becomes one coordinate of
    unit mass and frequency ``tail`` (the first root left out) whose surface
    amplitudes ``e sqrt(s (2n + 1) / 3) tail`` carry the compliance ``s e e^T``.
    """
    weight = np.diag([1.0, max(n * (n + 1), 1)])
    factor = 3.0 / (2 * n + 1)
    kept = sum(
        factor * np.outer([uk, vk], [uk, vk]) @ weight / (ek**2 - STATIC_ETA**2)
        for uk, vk, ek in zip(u, v, eta, strict=True)
    )
    if n == 1:  # the translation, (U, V) = (1, 1) at eta = 0
        kept = kept - np.outer([1.0, 1.0], [1.0, 1.0]) @ weight / STATIC_ETA**2
    missing = (surface_compliance(n, poisson) - kept) @ np.linalg.inv(weight)
    if n == 0:
        missing = missing[:1, :1]
    missing = 0.5 * (missing + missing.T)
    values, vectors = np.linalg.eigh(missing)
    out = []
    for s, e in zip(values, vectors.T, strict=True):
        if s > 1e-12 * max(1.0, float(np.abs(values).max())):
            amp = e * math.sqrt(s / factor) * tail
            out.append((float(amp[0]), float(amp[1]) if n > 0 else 0.0))
    return out


@functools.lru_cache(maxsize=32)
def _table(poisson: float, degrees: int, count: int, static: bool = False) -> LambTable:
    from twoball.modal.solid.lamb import speed_ratio

    speed_ratio(poisson)  # validates
    deg, order, eta, big_a, big_b, su, sv = [], [], [], [], [], [], []
    for n in range(degrees + 1):
        if n == 1:
            deg.append(1)
            order.append(0)
            eta.append(0.0)
            big_a.append(1.0)
            big_b.append(0.0)
            su.append(1.0)
            sv.append(1.0)
        found = np.array(_degree_roots(n, poisson, count + 1 if static else count))
        roots = found[:count]
        a, b, u1, v1 = _amplitudes(n, poisson, roots)
        deg += [n] * count
        order += list(range(1, count + 1))
        eta += list(roots)
        big_a += list(a)
        big_b += list(b)
        su += list(u1)
        sv += list(v1)
        if static:
            for ur, vr in _residual(n, poisson, u1, v1, roots, float(found[count])):
                deg.append(n)
                order.append(-1)
                eta.append(float(found[count]))
                big_a.append(0.0)
                big_b.append(0.0)
                su.append(ur)
                sv.append(vr)
    return LambTable(
        float(poisson),
        np.array(deg),
        np.array(order),
        np.array(eta),
        np.array(big_a),
        np.array(big_b),
        np.array(su),
        np.array(sv),
        translation=int(np.flatnonzero(np.array(order) == 0)[0]),
    )


def lamb_table(poisson: float, degrees: int, count: int, static: bool = False) -> LambTable:
    """Lamb's modes of degrees 0..``degrees`` and radial orders 1..``count``, with the translation.

    The roots are those of :func:`~twoball.modal.solid.lamb.lamb_roots` (the same
    function F_n and grid; sign changes only: a double root closer than the grid
    step is not looked for here) refined together; the shapes as
    :func:`~twoball.modal.solid.modes.spheroidal_modes` normalises them (eq. (M2)).
    ``static``: one or two more coordinates per degree (radial order -1), the
    static correction of eq. (S3): the surface compliance the left-out radial
    orders carry, at the frequency of the first one left out (their interior
    field is not known here: zero in :meth:`LambTable.field`).  Cached per (nu,
    degrees, count, static).

    Examples
    --------
    >>> from twoball.modal.balls.solid import lamb_table
    >>> table = lamb_table(0.25, 3, 2)
    >>> table.size, [round(float(e), 4) for e in table.eta[table.degree == 2]]
    (9, [2.6399, 4.8653])
    """
    return _table(float(poisson), int(degrees), int(count), bool(static))


# --- Hertz -------------------------------------------------------------------------------


def hertz_reference(material: SolidMaterial, radius: float, speed: float) -> dict[str, float]:
    """Hertz's impact of the sphere on a rigid flat at ``speed`` [m/s], SI (eqs. (H1)-(H4)).

    ``contact_time_s``, ``peak_force_N``, ``max_compression_m``,
    ``contact_radius_m`` ``sqrt(R delta)``, the regime numbers
    ``compression_ratio`` delta / R, ``contact_angle_rad`` a / R,
    ``speed_ratio`` ``|v0| / c_s`` and ``quasi_static_ratio``: the contact time
    over the lowest period ``2 pi R / (eta_21 c_s)`` (Hertz holds when it is
    large and delta / R small).
    """
    from twoball.modal.solid.hertz import (
        hertz_contact_time,
        hertz_max_compression,
        hertz_peak_force,
    )

    mass = material.mass(radius)
    modulus = material.effective_modulus
    time = hertz_contact_time(mass, radius, modulus, speed)
    delta = hertz_max_compression(mass, radius, modulus, speed)
    lowest = _degree_roots(2, float(material.poisson), 1)[0]
    period = 2.0 * math.pi * radius / (lowest * material.shear_speed)
    return {
        "contact_time_s": time,
        "peak_force_N": hertz_peak_force(mass, radius, modulus, speed),
        "max_compression_m": delta,
        "contact_radius_m": math.sqrt(radius * delta),
        "compression_ratio": delta / radius,
        "contact_angle_rad": math.sqrt(delta / radius),
        "speed_ratio": speed / material.shear_speed,
        "lowest_period_s": period,
        "quasi_static_ratio": time / period,
    }


def solid_summary(material: SolidMaterial, case: Case, spacing: float) -> dict[str, Any]:
    """The solid's block of the JSON's ``model``: the material, the time unit, Hertz.

    ``ball`` ``"solid"``, ``membrane`` None, ``omega0_squared`` the breathing
    mode's ``omega^2`` (units c^2), ``material`` (:meth:`SolidMaterial.summary`),
    ``time_unit`` (how c maps), ``hertz`` (:func:`hertz_reference` at the case's
    ``|v0|``) with ``contact_points_expected`` ``a / (R spacing)`` for the
    floor points' spacing near the south pole.
    """
    ratio = material.wave_speed(case.radius) / case.wave_speed
    breathing = _degree_roots(0, float(material.poisson), 1)[0]
    hertz = hertz_reference(material, case.radius, case.v0)
    hertz["contact_points_expected"] = hertz["contact_angle_rad"] / spacing
    return {
        "ball": "solid",
        "membrane": None,
        "bending_N_m": None,
        "bending_beta": None,
        "omega0_squared": (breathing * ratio) ** 2,
        "material": material.summary(case.radius),
        "mass_kg": material.mass(case.radius),
        "time_unit": {
            "wave_speed_1_s": case.wave_speed,
            "c_s_over_R_1_s": material.wave_speed(case.radius),
            "ratio": ratio,
            "rule": "omega^2 / c^2 = eta^2 (c_s / (R c))^2, eta = omega R / c_s",
        },
        "hertz": hertz,
    }


@dataclass(frozen=True)
class CutGrid:
    """The half meridian plane (r >= 0) and every coordinate's field there (units R).

    Attributes
    ----------
    points : ndarray, shape (P, 2)
        (r, z) of the nodes.
    triangles : ndarray, shape (T, 3)
    radial, axial : ndarray, shape (P, K)
        The cylindrical ``u_r`` and ``u_z`` of each coordinate's deformation (0 in
        the translation's column).
    """

    points: np.ndarray
    triangles: np.ndarray
    radial: np.ndarray
    axial: np.ndarray


#: The cut of each described ball with a volume (weak: it goes with the ball).
_CUTS: weakref.WeakKeyDictionary[Any, Any] = weakref.WeakKeyDictionary()


def register_cut(ball: Any, cut: Any) -> None:
    """Say how to cut the described ``ball`` (a :class:`ModalBall`): ``cut() -> CutGrid``."""
    _CUTS[ball] = cut


def cut_of(ball: Any) -> CutGrid | None:
    """The cut of a described ball through its volume (None: a ball without a volume)."""
    cut = _CUTS.get(ball)
    return None if cut is None else cut()


def lamb_cut(table: LambTable, rings: int = 20, sectors: int = 48) -> CutGrid:
    """Eq. (M1) of every mode on a polar grid of the half disc (``rings`` x ``sectors``);
    the static correction's coordinates carry no interior field here."""
    rho = np.linspace(0.0, 1.0, rings + 1)
    theta = np.linspace(0.0, np.pi, sectors + 1)
    rr, tt = np.meshgrid(rho, theta, indexing="ij")
    ur, ut = table.field(rr.ravel(), tt.ravel())
    s, c = np.sin(tt.ravel())[:, None], np.cos(tt.ravel())[:, None]
    radial, axial = ur * s + ut * c, ur * c - ut * s
    radial[:, table.translation] = 0.0
    axial[:, table.translation] = 0.0
    index = np.arange(rr.size).reshape(rr.shape)
    a, b = index[:-1, :-1].ravel(), index[1:, :-1].ravel()
    cc, d = index[1:, 1:].ravel(), index[:-1, 1:].ravel()
    triangles = np.vstack([np.column_stack([a, b, cc]), np.column_stack([a, cc, d])])
    points = np.column_stack([(rr * np.sin(tt)).ravel(), (rr * np.cos(tt)).ravel()])
    return CutGrid(points, triangles, radial, axial)


def solid_description(
    table: LambTable,
    ratio: float,
    law: Any,
    phi: np.ndarray,
    label: str,
) -> ModalBall:
    """The :class:`ModalBall` of Lamb's modes in ``table`` (units R, 1/c with ``c_s / (R c) =
    ratio``, the ball's mass): the translation is the centre."""
    from twoball.modal.balls.description import ModalBall
    from twoball.modal.balls.membrane import mode_decay

    t = table.translation
    k = table.size
    w2 = (table.eta * ratio) ** 2
    w2[t] = 0.0
    decay = np.asarray(mode_decay(law, w2), dtype=float).copy()
    decay[t] = 0.0
    rows = table.surface(phi)[2].copy()
    rows[:, t] = 1.0
    top = table.surface(np.array([0.0]))[2][0].copy()
    top[t] = 1.0

    def sample(index: int):
        def sampler(angles: np.ndarray) -> np.ndarray:
            out = table.surface(np.asarray(angles, dtype=float))[index].copy()
            out[:, t] = 0.0
            return out

        return sampler

    def averager(theta: float) -> np.ndarray:
        out = table.cap_average(theta).copy()
        out[t] = 1.0
        return out

    ball = ModalBall(
        masses=np.ones(k),
        omega_squared=w2,
        gas_squared=np.zeros(k),
        decay=decay,
        centre=t,
        phi=phi,
        floor_rows=rows,
        top=top,
        label=label,
        bending=True,
        sampler=sample(0),
        tangential=sample(1),
        averager=averager,
    )
    register_cut(ball, lambda: lamb_cut(table))
    return ball


def _check_int(name: str, value: object, bounds: tuple[int, int]) -> int | None:
    if value is None:
        return None
    low, high = bounds
    if (
        isinstance(value, bool)
        or not isinstance(value, int | np.integer)
        or not (low <= int(value) <= high)
    ):
        raise ParameterError(name, f"an integer in [{low}, {high}]", value)
    return int(value)


@checked
@dataclass(frozen=True)
class SolidBall:
    """The homogeneous elastic sphere on Lamb's modes (closed form): a lower ball for the drop.

    Parameters
    ----------
    material : SolidMaterial, optional
        The material (default: the case's preset's, :data:`MATERIALS`).
    modes : int, optional
        Highest degree N in [4, 400] (default :data:`DEFAULT_SOLID_MODES`, 64);
        floor points at the Gauss-Radau nodes of degree N on the lower
        hemisphere (about N / 2, spacing ~pi / N near the south pole).
    radial_orders : int, optional
        Radial orders K per degree in [1, 40] (default :data:`DEFAULT_RADIAL_ORDERS`, 8).
    static_correction : bool
        Add the static correction of each degree (eq. (S3) of docs/solid.rst; default
        True): the floor's local (Hertz) compliance that the left-out radial
        orders carry, one or two coordinates per degree at the frequency of the
        first root left out.  Without it the truncated ball is too stiff at the
        floor (2-10 % of each degree's compliance missing at K = 8).

    Examples
    --------
    >>> import twoball
    >>> ball = twoball.SolidBall(modes=16, radial_orders=4)
    >>> ball.label, ball.size()
    ('solid lamb N = 16, K = 4 + static', (102, 9))
    >>> twoball.SolidBall(modes=2)
    Traceback (most recent call last):
    ...
    twoball.ParameterError: modes must be an integer in [4, 400], got 2
    """

    material: SolidMaterial | None = None
    modes: int | None = None
    radial_orders: int | None = None
    static_correction: bool = True

    #: The physics of this ball (the JSON's ``ball``) and its discretisation.
    kind = "solid"
    backend = "legendre"
    #: No excess pressure and no enclosed gas: the drop takes none.
    pressurised = False

    def __post_init__(self) -> None:
        check_material(self.material)
        object.__setattr__(self, "modes", _check_int("modes", self.modes, SOLID_MODES_RANGE))
        orders = _check_int("radial_orders", self.radial_orders, RADIAL_ORDERS_RANGE)
        object.__setattr__(self, "radial_orders", orders)
        if not isinstance(self.static_correction, bool):
            raise ParameterError("static_correction", "True or False", self.static_correction)

    @property
    def degree(self) -> int:
        """N (the default when none was given)."""
        return DEFAULT_SOLID_MODES if self.modes is None else self.modes

    @property
    def orders(self) -> int:
        """K (the default when none was given)."""
        return DEFAULT_RADIAL_ORDERS if self.radial_orders is None else self.radial_orders

    @property
    def label(self) -> str:
        """``solid lamb N = 64, K = 8 + static``."""
        static = " + static" if self.static_correction else ""
        return f"solid lamb N = {self.degree}, K = {self.orders}{static}"

    def size(self, case: Case | None = None) -> tuple[int, int]:
        """Coordinates (``(N + 1) K + 1``, and ``2 N + 1`` static corrections) and floor
        points (about N / 2)."""
        from twoball.modal.balls.membrane import floor_angles

        static = 2 * self.degree + 1 if self.static_correction else 0
        return (self.degree + 1) * self.orders + 1 + static, int(floor_angles(self.degree).size)

    def material_of(self, case: Case) -> SolidMaterial:
        """The material in use: the ball's, else the case's preset's."""
        return material_of(self.material, case)

    def mass(self, case: Case) -> float:
        """``(4/3) pi R^3 rho`` [kg] with R the case's radius."""
        return self.material_of(case).mass(case.radius)

    def spacing(self) -> float:
        """The floor points' spacing at the south pole [rad]."""
        from twoball.modal.balls.membrane import floor_angles

        phi = floor_angles(self.degree)
        return float(phi[-1] - phi[-2])

    def summary(self, case: Case) -> dict[str, Any]:
        """The solid's block of the JSON's ``model`` (:func:`solid_summary`)."""
        return solid_summary(self.material_of(case), case, self.spacing())

    def table(self, case: Case) -> LambTable:
        """Lamb's modes of this ball for the case's material."""
        poisson = self.material_of(case).poisson
        return lamb_table(poisson, self.degree, self.orders, self.static_correction)

    def describe(self, case: Case, monitor: Any = None) -> ModalBall:
        """The solid of ``case`` on Lamb's modes (dimensionless: R, 1/c, its mass)."""
        from twoball.modal.balls.membrane import floor_angles

        material = self.material_of(case)
        if monitor is not None:
            monitor(f"Lamb's roots for {self.label}")
        table = self.table(case)
        ratio = material.wave_speed(case.radius) / case.wave_speed
        return solid_description(
            table, ratio, case.damping_law, floor_angles(self.degree), self.label
        )

    def as_dict(self) -> dict[str, Any]:
        """``{"ball": "solid", "discretisation": "legendre", "modes": N, ...}``."""
        material = None if self.material is None else self.material.as_dict()
        return {
            "ball": self.kind,
            "discretisation": "legendre",
            "modes": self.modes,
            "radial_orders": self.radial_orders,
            "static_correction": self.static_correction,
            "material": material,
        }
