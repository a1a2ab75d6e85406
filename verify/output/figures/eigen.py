"""Finite-element eigenvalues of the unit sphere against l (l + 1), eq. (3.11)."""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np

from twoball._common.errors import ParameterError
from twoball._common.watch import Watch
from twoball.verify.output.figures import new_figure
from twoball.verify.output.figures.style import chunks, label, styled

if TYPE_CHECKING:
    from matplotlib.figure import Figure


@dataclass(frozen=True)
class EigenTable:
    """Finite-element eigenvalues grouped by spherical-harmonic degree l (dimensionless).

    Attributes
    ----------
    label : str
        Discretisation, e.g. ``"P1, level 3 (642 dofs)"``.
    degrees : ndarray, shape (L + 1,)
        l = 0 .. L.
    errors : ndarray, shape (L + 1,)
        Largest relative error ``|lambda_h - l (l + 1)| / (l (l + 1))`` over the
        2 l + 1 discrete eigenvalues of degree l (absolute error for l = 0).
    """

    label: str
    degrees: np.ndarray
    errors: np.ndarray


def eigen_table(level: int, order: int, max_degree: int | None = None) -> EigenTable:
    """Eigenvalues of the icosphere discretisation against ``l (l + 1)``, eq. (3.11).

    The ``(L + 1)^2`` smallest eigenvalues of ``K phi = lambda M phi`` on the unit
    sphere are grouped in clusters of ``2 l + 1`` (the multiplicity of degree l).
    ``max_degree`` defaults to the degree at which ``(L + 1)^2`` reaches half the
    number of unknowns, capped at 30.
    """
    from twoball.fem_membrane.build import build_space
    from twoball.fem_membrane.eigen import lowest_eigenpairs

    space = build_space("sphere", level=level, order=order)
    n = space.dofs
    if max_degree is None:
        max_degree = min(30, int(math.isqrt(n // 2)) - 1)
    if isinstance(max_degree, bool) or int(max_degree) != max_degree or max_degree < 1:
        raise ParameterError("max_degree", "an integer >= 1", max_degree)
    if (max_degree + 1) ** 2 > n:
        raise ParameterError(
            "max_degree", f"at most {math.isqrt(n) - 1} on this mesh ({n} unknowns)", max_degree
        )
    count = (max_degree + 1) ** 2
    values = lowest_eigenpairs(space.stiffness, space.mass, count, Watch()).values
    degrees = np.arange(max_degree + 1)
    errors = np.empty(degrees.size)
    for degree in degrees:
        cluster = values[degree * degree : (degree + 1) * (degree + 1)]
        exact = degree * (degree + 1.0)
        errors[degree] = np.abs(cluster - exact).max() / (exact if exact > 0 else 1.0)
    return EigenTable(f"P{order}, level {level} ({n} unknowns)", degrees, errors)


@styled
def eigen_figure(tables: Sequence[EigenTable]) -> Figure:
    """Relative eigenvalue error against the degree l, one line per discretisation (log scale).

    More than :data:`~.style.MAX_CURVES` discretisations are split over panels
    side by side (sharing the axes).
    """
    return _error_panels(
        [(t.label, t.degrees[1:], t.errors[1:]) for t in tables],
        r"Finite-element eigenvalues of the unit sphere against $\ell(\ell+1)$, eq. (3.11)",
        r"degree $\ell$ (eigenvalue $\ell(\ell+1)$, multiplicity $2\ell+1$)",
    )


ERROR_LABEL = label(r"$\max\,|\lambda_h - \ell(\ell+1)|\,/\,\ell(\ell+1)$", None)


def _error_panels(
    lines: Sequence[tuple[str, np.ndarray, np.ndarray]], title: str, xlabel: str
) -> Figure:
    groups = chunks(lines) or [[]]
    figure = new_figure(min(6.5 * len(groups), 16.0), 4.6)
    axes = figure.subplots(1, len(groups), sharey=True, squeeze=False)[0]
    markers = "osd^v<>ph"
    for axis, group in zip(axes, groups, strict=True):
        for k, (name, degrees, errors) in enumerate(group):
            shown = np.where(errors > 0, errors, np.nan)
            axis.semilogy(degrees, shown, marker=markers[k % len(markers)], label=name)
        axis.set_xlabel(label(xlabel, None))
        if group:
            axis.legend()
    axes[0].set_ylabel(ERROR_LABEL)
    figure.suptitle(title)
    return figure


@dataclass(frozen=True)
class EigenErrors:
    """Relative eigenvalue errors of one discretisation against ``l (l + 1)``.

    ``degrees`` are the l of each entry, ``errors`` the largest relative error
    over the 2l + 1 discrete eigenvalues of that degree (one on the axisymmetric line).
    """

    label: str
    degrees: np.ndarray
    errors: np.ndarray


@styled
def eigen_errors_figure(tables: Sequence[EigenErrors]) -> Figure:
    """Relative eigenvalue error against the degree l for each discretisation (log scale)."""
    return _error_panels(
        [(t.label, t.degrees, t.errors) for t in tables],
        r"Eigenvalue error of the finite elements against $\ell(\ell+1)$",
        r"degree $\ell$",
    )
