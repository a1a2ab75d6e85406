"""The valid values of the finite-element inputs, checked once (no numerical library).

Every check raises :class:`twoball._common.errors.ParameterError` naming the
parameter and its valid range (``level must be an integer in [0, 10], got
11``); the command line prints the flag of that parameter instead.  The option
object :class:`~twoball.MeshOptions` and the mesh builders below it check their
fields here, so each range is written once.
"""

from __future__ import annotations

import math
import os
from numbers import Integral, Real
from pathlib import Path

from twoball._common.choices import LEVEL_RANGE
from twoball._common.errors import ParameterError

ORDERS: tuple[int, ...] = (1, 2, 3, 4)
ORDER_RANGE = "1, 2, 3 or 4"
GEOMETRIES: tuple[str, ...] = ("isoparametric", "exact")
TIME_SCHEMES: tuple[str, ...] = ("modal", "alpha")
DAMPING_MODELS: tuple[str, ...] = ("modal", "rayleigh")
INITIAL_METHODS: tuple[str, ...] = ("projection", "interpolation")
# Sphere refinement levels (LEVEL_RANGE).  Level L has 20 4^L triangles and 10 4^L p^2
# + 2 unknowns at order p: level 10 at P1 holds 1.0e7 of them, about 210 GB and two
# hours on the Krylov route by the cost model of twoball.fem_membrane.cost -- the most a
# budget raised to a large machine's memory can allow; the default budget stops earlier
# (level 7 at P1, level 6 at P2).
#: Elements of the axisymmetric line: at least two.
MIN_ELEMENTS = 2
#: What a user's mesh may be (the reader is :mod:`twoball.fem_membrane.mesh_input`).
MESH_SOURCES = "a readable mesh file (any format meshio reads), a meshio.Mesh or a MeshTri"
POLE_RANGE = "three finite numbers X,Y,Z, not all zero"


def _is_int(value: object) -> bool:
    return isinstance(value, Integral) and not isinstance(value, bool)


def check_level(level: object, name: str = "level") -> int:
    """Refinement level of a sphere mesh: an integer in :data:`LEVEL_RANGE`."""
    low, high = LEVEL_RANGE
    if not _is_int(level) or not low <= int(level) <= high:
        raise ParameterError(name, f"an integer in [{low}, {high}]", level)
    return int(level)


def check_order(order: object, name: str = "order") -> int:
    """Polynomial order of elements and geometry: 1, 2, 3 or 4."""
    if not _is_int(order) or int(order) not in ORDERS:
        raise ParameterError(name, ORDER_RANGE, order)
    return int(order)


def check_elements(elements: object) -> int:
    """Number of elements of the axisymmetric mesh: an integer >= 2."""
    if not _is_int(elements) or int(elements) < MIN_ELEMENTS:
        raise ParameterError("elements", f"an integer >= {MIN_ELEMENTS}", elements)
    return int(elements)


def check_mesh_source(source: object, name: str = "file") -> object:
    """A user's mesh: an existing readable file, a ``meshio.Mesh`` or a scikit-fem ``MeshTri``.

    Nothing is read or imported here: a mesh object can only be of a library
    that is loaded already (:data:`sys.modules`), and a path is checked for
    a readable file.  The reader checks the contents
    (:func:`twoball.fem_membrane.mesh_input.load_sphere_mesh`).
    """
    import sys

    if isinstance(source, (str, os.PathLike)):
        path = Path(source)
        try:
            readable = path.is_file() and os.access(path, os.R_OK)
        except (OSError, ValueError):  # a name too long, a loop of links, a NUL byte
            readable = False
        if not readable:
            shown = os.fspath(source)
            raise ParameterError(name, MESH_SOURCES, shown if len(shown) <= 200 else shown[:200])
        return source
    meshio, skfem = sys.modules.get("meshio"), sys.modules.get("skfem")
    grids = sys.modules.get("twoball.fem_membrane.mesh")
    kinds = (
        *(() if meshio is None else (meshio.Mesh,)),
        *(() if skfem is None else (skfem.MeshTri1, skfem.MeshTri2)),
        *(() if grids is None else (grids.SphereMesh,)),
    )
    if not kinds or not isinstance(source, kinds):
        raise ParameterError(name, MESH_SOURCES, type(source).__name__)
    return source


def check_pole(pole: object, name: str = "pole") -> tuple[float, float, float]:
    """A pole direction: three finite numbers, not all zero, or the text ``"X,Y,Z"``."""
    from twoball._common.ranges import decimal

    try:
        if isinstance(pole, str):
            values = tuple(decimal(part.strip()) for part in pole.split(","))
        elif isinstance(pole, (bytes, dict)) or not hasattr(pole, "__iter__"):
            raise TypeError
        else:
            values = tuple(float(v) for v in pole)  # type: ignore[union-attr]
    except (TypeError, ValueError):
        raise ParameterError(name, POLE_RANGE, pole) from None
    if len(values) != 3 or not all(math.isfinite(v) for v in values):
        raise ParameterError(name, POLE_RANGE, pole)
    if not any(values):
        raise ParameterError(name, POLE_RANGE, pole)
    return values  # type: ignore[return-value]


def check_dt(dt: object) -> float | None:
    """Time step of the direct integrator: None (automatic) or a finite number > 0."""
    if dt is None:
        return None
    if not _is_real(dt) or not math.isfinite(float(dt)) or float(dt) <= 0.0:
        raise ParameterError("dt", "a finite number > 0", dt)
    return float(dt)


DT_MIN = 1e-9  # dimensionless (time unit 1/c): below it the step count overflows any budget


def check_dt_in_window(dt: object, time_unit_s: float, t_end: float) -> float:
    """A time step ``dt`` [s] as a dimensionless step in [1e-9, ``t_end``].

    ``time_unit_s`` is 1/c [s]; ``t_end`` the dimensionless window.  A step
    longer than the window takes no step at all.
    """
    low, high = DT_MIN * time_unit_s, t_end * time_unit_s
    valid = f"a time step in [{low:.3g}, {high:.3g}] s (at most the modelled window)"
    if not _is_real(dt) or not (low <= float(dt) <= high):
        raise ParameterError("dt", valid, dt)
    return float(dt) / time_unit_s


def _is_real(value: object) -> bool:
    return isinstance(value, Real) and not isinstance(value, bool)


def check_rho_inf(rho_inf: object) -> float:
    """Spectral radius at infinite frequency of generalized-alpha: in [0, 1]."""
    if not _is_real(rho_inf) or not (0.0 <= float(rho_inf) <= 1.0):
        raise ParameterError("rho_inf", "in [0, 1]", rho_inf)
    return float(rho_inf)


def check_t_end(t_end: object) -> float:
    """End of the integration window (dimensionless): a finite number > 0."""
    if not _is_real(t_end) or not math.isfinite(float(t_end)) or float(t_end) <= 0.0:
        raise ParameterError("t_end", "a finite time > 0", t_end)
    return float(t_end)


def check_choice(name: str, value: object, choices: tuple[str, ...]) -> str:
    """``value`` must be one of ``choices`` (named ``name``)."""
    if value not in choices:
        raise ParameterError(name, "one of " + ", ".join(choices), value)
    return str(value)
