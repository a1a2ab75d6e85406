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
import math

import matplotlib.pyplot as plt
from twoball.verify.output.figures.eigen import eigen_table
from twoball.verify.output.figures.style import STYLE

plt.rcParams.update(STYLE)  # the style of the package's own figures

DEGREE = 4  # the cluster l = 4, exact eigenvalue 20
levels = {1: (1, 2, 3, 4), 2: (1, 2, 3)}
errors = {
    order: [eigen_table(level, order, max_degree=DEGREE).errors[DEGREE] for level in lv]
    for order, lv in levels.items()
}

for order, errs in errors.items():
    rates = [math.log2(a / b) for a, b in zip(errs, errs[1:], strict=False)]
    print(f"P{order}: errors {', '.join(f'{e:.2e}' for e in errs)}")
    print(f"     observed orders {', '.join(f'{r:.2f}' for r in rates)} (theory {2 * order})")

# %%
# The relative error of the l = 4 cluster against the refinement level, with
# the slopes of theory for comparison.
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
