"""
Eigenvalue convergence of the sphere discretisation
===================================================

The eigenvalues of the Laplace-Beltrami operator on the unit sphere are
``l (l + 1)`` with multiplicity ``2 l + 1`` (eq. (3.11)); every frequency of
the finite-element modal series comes from the discrete eigenproblem
``K phi = lambda M phi``.  Refining the icosphere halves the mesh size h per
level, so the error of a fixed eigenvalue should fall by ``2^(2p)``: order 2
for linear (P1) and order 4 for isoparametric quadratic (P2) elements.
"""

# %%
# :func:`twoball.fem.eigen` lists the lowest nonzero eigenvalues of a mesh
# beside ``l (l + 1)``; 24 of them reach the whole cluster ``l = 4`` (exact
# eigenvalue 20, nine members).  The eigenvalues are dimensionless: mode ``l``
# oscillates at ``c sqrt(lambda)`` [1/s].  The error of a cluster is the
# largest relative error of its members.
import math

import matplotlib.pyplot as plt

import twoball

DEGREE = 4  # the cluster l = 4
COUNT = (DEGREE + 1) ** 2 - 1  # nonzero eigenvalues up to and including it
levels = {1: (1, 2, 3, 4), 2: (1, 2, 3)}


def cluster_error(level: int, order: int) -> float:
    """Largest relative error of the cluster ``DEGREE`` on the icosphere [–]."""
    rows = twoball.fem.eigen(twoball.MeshOptions("sphere", level=level, order=order), count=COUNT)
    return max(row["relative_error"] for row in rows if row["l"] == DEGREE)


errors = {order: [cluster_error(level, order) for level in lv] for order, lv in levels.items()}

for order, errs in errors.items():
    rates = [math.log2(a / b) for a, b in zip(errs, errs[1:], strict=False)]
    print(f"P{order}: errors {', '.join(f'{e:.2e}' for e in errs)}")
    print(f"     observed orders {', '.join(f'{r:.2f}' for r in rates)} (theory {2 * order})")

# %%
# The relative error of the ``l = 4`` cluster against the refinement level,
# with the slopes of theory for comparison.  (``twoball.plot("eigen", ...)``
# draws the error of every cluster for several meshes in the package's own
# figure style.)
fig, ax = plt.subplots(figsize=(6, 4), layout="constrained")
for order, errs in errors.items():
    lv = levels[order]
    ax.semilogy(lv, errs, "o-", label=f"P{order}")
    slope = [errs[0] * 2.0 ** (-2 * order * (k - lv[0])) for k in lv]
    ax.semilogy(lv, slope, ":", color="gray", label=f"slope {2 * order} (theory, P{order})")
ax.set_xlabel("icosphere level ($h$ halves per level) [–]")
ax.set_ylabel(rf"relative error of $\lambda$, $\ell$ = {DEGREE} [–]")
ax.legend()
plt.show()
