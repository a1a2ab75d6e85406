"""Finite elements on their own: ``twoball.fem.eigen``, the membrane's spectrum on a mesh,
``twoball.fem.shell_eigen``, the thin shell's (closed form or the meridian's elements), and
``twoball.fem.solid_eigen``, the elastic sphere's (Lamb's roots or the (r, z) elements).

The lift-off on finite elements is :func:`twoball.liftoff` with the solvers
:class:`~twoball.Superposition` and :class:`~twoball.GeneralizedAlpha`.
"""

from __future__ import annotations

from numbers import Integral
from typing import Any

from twoball._common.budget import timed
from twoball._common.errors import ParameterError
from twoball._common.keywords import checked
from twoball._common.progress import Step, check_progress, silent
from twoball._common.watch import Watch
from twoball.fem_membrane.options import MeshOptions

__all__ = ["eigen", "shell_eigen", "solid_eigen"]


@checked(name="twoball.fem.eigen")
@timed
def eigen(
    mesh: Any = None,
    *,
    count: int = 25,
    membrane: Any = "paper",
    progress: Step | None = None,
) -> list[dict[str, float | int]]:
    """The lowest ``count`` nonzero eigenvalues of -Laplace-Beltrami beside l (l + 1), eq. (3.11).

    With ``membrane="pressurised"``: those of ``K - 2 M`` beside ``(l - 1)(l + 2)``
    (:class:`~twoball.Membrane`; l = 1, the free translation, is 0 up to the
    mesh's eigenvalue error at l = 1).

    Parameters
    ----------
    mesh : MeshOptions, kind name or the user's mesh, optional
        :class:`~twoball.MeshOptions` (default the level-3 P2 icosphere), a kind
        name, or the user's sphere: a file in any format meshio reads, a
        ``meshio.Mesh`` or a ``MeshTri`` (any radius and centre; it is scaled to
        the unit sphere).
    count : int
        Nonzero eigenvalues listed, >= 1.
    membrane : Membrane or {"paper", "pressurised"}
        The membrane operator.
    progress : callable, optional
        Called with a short text as the solve starts (:class:`~twoball.Reporter`).

    Returns
    -------
    list of dict
        One row per eigenvalue (``index``, ``l``, ``value``, ``exact``,
        ``relative_error``, ``multiplicity``, ``expected_multiplicity``),
        dimensionless.

    Examples
    --------
    >>> import twoball
    >>> rows = twoball.fem.eigen(twoball.MeshOptions("axisym", elements=100), count=3)
    >>> [(row["l"], row["exact"]) for row in rows]
    [(0, 0.0), (1, 2.0), (2, 6.0), (3, 12.0)]
    """
    check_progress(progress)
    from twoball._common.budget import check
    from twoball._common.estimate import options
    from twoball.fem_membrane.cost import fem_dofs, fem_estimate
    from twoball.fem_membrane.eigen import eigen_table
    from twoball.modal.membrane import Membrane

    spec = MeshOptions.of(mesh)
    membrane = Membrane.of(membrane)
    if isinstance(count, bool) or not isinstance(count, Integral) or count < 1:
        raise ParameterError("count", "an integer >= 1", count)
    if spec.kind != "file":  # refuse absurd meshes before building them
        dofs = fem_dofs(spec.kind, spec.level, spec.elements, spec.order)
        size = options(level=spec.level, elements=spec.elements, order=spec.order)
        dimension = 1 if spec.kind == "axisym" else 2
        check(size, fem_estimate(dofs, 30, "krylov", dimension, spec.order))
    (progress or silent)(f"{count} eigenvalues on {spec.label}")
    loaded = spec.load()
    if loaded is not None:
        return eigen_table(
            mesh=loaded.mesh,
            order=None,
            count=count,
            geometry=spec.geometry,
            membrane=membrane,
            monitor=Watch(),
        )
    return eigen_table(
        mesh=spec.kind,
        level=spec.level,
        elements=spec.elements,
        order=spec.order,
        count=count,
        geometry=spec.geometry,
        membrane=membrane,
        monitor=Watch(),
    )


#: Highest degree the shell's eigen lists by default.
SHELL_DEGREES = 10


@checked(name="twoball.fem.shell_eigen")
def shell_eigen(
    *,
    poisson: float = 0.5,
    thickness_ratio: float = 0.0,
    prestress_ratio: float = 0.0,
    gas: float | str | None = None,
    case: Any = None,
    wall: Any = None,
    backend: str = "legendre",
    count: int = SHELL_DEGREES,
    elements: int | None = None,
    order: int | None = None,
    progress: Step | None = None,
) -> list[dict[str, Any]]:
    """The thin shell's spectrum, degrees 0..count, both branches, beside the closed form.

    Dimensionless (``poisson``, ``thickness_ratio`` h/R, ``prestress_ratio`` p =
    N0/C, ``gas`` g = 3 kappa P_abs R / C), or physical: a ``case`` with its
    excess pressure (R, P, the mass through c, the gas law) and a
    :class:`~twoball.Wall` (default the case's preset's); then every row also has
    ``omega_rad_s`` and ``frequency_hz``.

    Parameters
    ----------
    poisson, thickness_ratio, prestress_ratio : float
        The dimensionless shell (left out with ``case``).
    gas : float or str, optional
        The dimensionless g (default 0); with ``case`` the gas law (``none``,
        ``isothermal``, ``adiabatic``; default the case's).
    case : Case, optional
        Physical inputs (its ``pressure`` must be known).
    wall : Wall, optional
        With ``case``: the wall (default the case's preset's).
    backend : {"legendre", "fem"}
        The closed form, or the meridian's finite elements.
    count : int
        Highest degree listed, >= 1 (``2 count + 1`` rows).
    elements, order : int
        With ``backend="fem"``: meridian elements (default 64) and v's Lagrange order
        (default 2); left out with the closed form, which has no mesh.
    progress : callable, optional
        Told what is solved.

    Returns
    -------
    list of dict
        One row per mode: ``degree``, ``branch`` (1 lower, 2 upper; n = 0 has one
        row), ``value`` Omega = omega R sqrt(rho_s / C), ``exact`` (the closed
        form), ``relative_error``; physical inputs add ``omega_rad_s`` and
        ``frequency_hz`` (of ``value``).

    Examples
    --------
    >>> import twoball
    >>> rows = twoball.fem.shell_eigen(poisson=0.3, count=3)
    >>> [(r["degree"], r["branch"], round(r["value"], 4)) for r in rows[3:5]]
    [(2, 1, 0.7009), (2, 2, 2.7219)]
    >>> rows[1]["value"]  # the rigid translation
    0.0
    """
    import numpy as np

    from twoball.modal.shell.modes import shell_modes

    check_progress(progress)
    if isinstance(count, bool) or not isinstance(count, Integral) or not 1 <= count <= 400:
        raise ParameterError("count", "an integer in [1, 400] (the highest degree)", count)
    if backend not in ("legendre", "fem"):
        raise ParameterError("backend", "one of legendre, fem", backend)
    if backend == "legendre":
        for name, value in (("elements", elements), ("order", order)):
            if value is not None:
                valid = "left out with backend legendre (the closed form has no mesh)"
                raise ParameterError(name, valid, value)
    time_unit = None
    if case is not None:
        from twoball.modal.balls.shell import Wall, _wall_of
        from twoball.modal.parameters import Case

        if not isinstance(case, Case):
            raise ParameterError("case", "a twoball.Case or None", type(case).__name__)

        given = {"thickness_ratio": thickness_ratio, "prestress_ratio": prestress_ratio}
        for name, value in given.items():
            if value:
                raise ParameterError(name, "left out with a case (the physical inputs)", value)
        if wall is not None and not isinstance(wall, Wall):
            raise ParameterError("wall", "a twoball.Wall", type(wall).__name__)
        chosen = _wall_of(wall, case)
        if gas is not None and not isinstance(gas, str):
            raise ParameterError("gas", "a gas law with a case: none, isothermal, adiabatic", gas)
        parameters = chosen.parameters(case, gas)
        time_unit = case.radius / chosen.extensional_speed(case)
    else:
        if wall is not None:
            raise ParameterError("wall", "given with a case (the physical inputs)", wall)
        parameters = _shell_ratios(poisson, thickness_ratio, prestress_ratio, gas)
    exact = shell_modes(parameters, count)
    values = np.array(exact.omega, dtype=float)
    if backend == "fem":
        from twoball.fem_shell.ball import DEFAULT_SHELL_ELEMENTS, FEShellBall
        from twoball.fem_shell.modes import fem_shell_modes

        order = 2 if order is None else order
        mesh = FEShellBall(elements=elements, order=order)  # validates elements and order
        e = DEFAULT_SHELL_ELEMENTS if elements is None else mesh.mesh_elements
        (progress or silent)(f"shell eigenpairs on {e} elements, v P{order}")
        fe = fem_shell_modes(parameters, e, v_order=order)
        degree, _ = fe.degrees
        degree = np.asarray(degree).copy()
        degree[fe.translation] = 1
        order_ = np.argsort(fe.omega, kind="stable")
        values = np.full(exact.count, np.nan)
        for k in range(exact.count):
            n, b = int(exact.degree[k]), int(exact.branch[k])
            if n == 1 and b == 1:
                values[k] = 0.0
                continue
            same = [j for j in order_ if degree[j] == n and j != fe.translation]
            rank = b - 1 if n == 1 else b  # degree 1's lower branch is the translation
            if len(same) >= rank:
                values[k] = float(fe.omega[same[rank - 1]])
    else:
        (progress or silent)(f"shell spectrum, degrees 0..{count}")
    rows: list[dict[str, Any]] = []
    for k in range(exact.count):
        value, reference = float(values[k]), float(exact.omega[k])
        if exact.degree[k] == 1 and exact.branch[k] == 1:
            value = reference = 0.0
        row: dict[str, Any] = {
            "degree": int(exact.degree[k]),
            "branch": int(exact.branch[k]),
            "value": None if np.isnan(value) else value,
            "exact": reference,
            "relative_error": None
            if np.isnan(value)
            else (0.0 if reference == 0.0 else abs(value - reference) / reference),
        }
        if time_unit is not None:
            omega = None if np.isnan(value) else value / time_unit
            row["omega_rad_s"] = omega
            row["frequency_hz"] = None if omega is None else omega / (2.0 * np.pi)
        rows.append(row)
    return rows


def _shell_ratios(poisson: Any, thickness_ratio: Any, prestress_ratio: Any, gas: Any) -> Any:
    """The dimensionless shell of :func:`shell_eigen`, each ratio refused by its own name.

    h / R in [0, 0.5] (:data:`~twoball.modal.balls.shell.MAX_THICKNESS_RATIO`, as
    :class:`~twoball.Wall`); p = N0 / C >= 0 with the breathing mode stable,
    ``Omega_0^2 = 2 (1 + nu) - 2 p + g > 0`` (the n = 0 row of the shell's spectrum).
    """
    from twoball._common.errors import bounded, real_number
    from twoball.modal.balls.shell import MAX_THICKNESS_RATIO
    from twoball.modal.shell.parameters import ShellParameters

    ratio = bounded("thickness_ratio", thickness_ratio, 0.0, MAX_THICKNESS_RATIO)
    p = real_number("prestress_ratio", prestress_ratio, "a number >= 0")
    if p < 0.0:
        raise ParameterError("prestress_ratio", "a number >= 0", prestress_ratio)
    if isinstance(gas, str):
        raise ParameterError("gas", "the dimensionless g >= 0 without a case", gas)
    shell = ShellParameters.from_ratios(poisson, ratio, None, gas=gas or 0.0)
    limit = 1.0 + shell.poisson + 0.5 * shell.gas  # Omega_0^2 > 0
    if not p < limit:
        valid = (
            f"a number in [0, {limit:g}) at nu = {shell.poisson:g}, g = {shell.gas:g}: the "
            "breathing mode stable, 2 (1 + nu) - 2 p + g > 0"
        )
        raise ParameterError("prestress_ratio", valid, prestress_ratio)
    return ShellParameters.from_ratios(
        poisson, ratio, None if p == 0.0 else 1.0 / p, gas=gas or 0.0
    )


@checked(name="twoball.fem.solid_eigen")
@timed
def solid_eigen(
    poisson: float,
    count: int = 5,
    backend: str = "legendre",
    *,
    level: int = 4,
    max_degree: int = 10,
) -> list[dict[str, Any]]:
    """Rows ``degree``, ``radial_order``, ``value`` (omega R / c_s) and ``exact`` (Lamb's root).

    ``legendre``: the closed form's roots (:func:`~twoball.modal.balls.solid.lamb_table`,
    the drop's) beside :func:`~twoball.modal.solid.lamb.lamb_roots`, with
    ``residual`` ``|F_n|`` of Lamb's equation at the value; ``fem``: the (r, z) P2
    eigenvalues on the half disc of ``level`` (classified by degree and radial
    order) beside Lamb's root of the same degree and order.  ``count`` radial
    orders of degrees 0..``max_degree`` (the rigid translation left out).

    Examples
    --------
    >>> import twoball
    >>> row = twoball.fem.solid_eigen(0.25, 2, max_degree=2)[-2]
    >>> row["degree"], row["radial_order"], round(row["value"], 4)
    (2, 1, 2.6399)
    """
    import numpy as np

    from twoball.modal.balls.solid import SolidMaterial

    SolidMaterial(1.0, 1.0, poisson)  # nu in (-1, 0.5)
    if backend not in ("legendre", "fem"):
        raise ParameterError("backend", "one of legendre, fem", backend)
    for name, value, low, high in (
        ("count", count, 1, 40),
        ("max_degree", max_degree, 0, 60),
        ("level", level, 1, 6),
    ):
        if isinstance(value, bool) or not isinstance(value, Integral) or not low <= value <= high:
            raise ParameterError(name, f"an integer in [{low}, {high}]", value)

    from twoball.modal.balls.solid import lamb_table
    from twoball.modal.solid.lamb import lamb_function, lamb_roots

    rows: list[dict[str, Any]] = []
    if backend == "legendre":
        table = lamb_table(poisson, max_degree, count)
        for n in range(max_degree + 1):
            exact = lamb_roots(n, poisson, count)
            chosen = (table.degree == n) & (table.radial_order > 0)
            roots = table.eta[chosen][np.argsort(table.radial_order[chosen])]
            residual = np.abs(lamb_function(n, roots, poisson))
            for k, (eta, ref, res) in enumerate(zip(roots, exact, residual, strict=True), 1):
                rows.append(
                    {
                        "degree": n,
                        "radial_order": k,
                        "value": float(eta),
                        "exact": float(ref),
                        "relative_error": abs(float(eta) / float(ref) - 1.0),
                        "residual": float(res),
                    }
                )
        return rows
    from twoball.fem_solid.eigen import axisymmetric_eigen
    from twoball.fem_solid.mesh import half_disc

    # enough eigenpairs for `count` orders of every degree up to max_degree
    pairs = (max_degree + 1) * count + 1
    exact_top = max(lamb_roots(n, poisson, count)[-1] for n in range(max_degree + 1))
    while True:
        fe = axisymmetric_eigen(half_disc(level), poisson, pairs, max_degree=max_degree + 6)
        if fe.eta[-1] > 1.05 * exact_top or pairs > 4000:
            break
        pairs = int(pairs * 1.5)
    for n in range(max_degree + 1):
        exact = lamb_roots(n, poisson, count)
        chosen = (fe.degree == n) & ~fe.rigid
        values = np.sort(fe.eta[chosen])[:count]
        for k in range(count):
            value = float(values[k]) if k < values.size else None
            rows.append(
                {
                    "degree": n,
                    "radial_order": k + 1,
                    "value": value,
                    "exact": float(exact[k]),
                    "relative_error": None if value is None else abs(value / exact[k] - 1.0),
                }
            )
    return rows
