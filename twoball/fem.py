"""Finite elements on their own: ``twoball.fem.eigen``, the membrane's spectrum on a mesh.

The lift-off on finite elements is :func:`twoball.liftoff` with the solvers
:class:`~twoball.Superposition` and :class:`~twoball.GeneralizedAlpha`.
"""

from __future__ import annotations

from numbers import Integral
from typing import Any

from twoball._common.budget import timed
from twoball._common.errors import ParameterError
from twoball._common.progress import Step, check_progress, silent
from twoball._common.watch import Watch
from twoball.fem_membrane.options import MeshOptions

__all__ = ["eigen"]


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
