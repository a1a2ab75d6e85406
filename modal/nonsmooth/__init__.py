"""Nonsmooth time integration of linear elastodynamics with unilateral constraints.

One contact core for every backend (Legendre modes, axisymmetric finite
elements, the bar benchmark): :class:`ContactProblem` bundles

    M q'' + C q' + K q = f + G^T lambda,   g = G q + g0 >= 0,   lambda >= 0,   lambda . g = 0

with Newton's restitution e per constraint, and :class:`MoreauJean` integrates
it.  M, C, K may be diagonal (modes), dense or sparse (finite elements).

Why Moreau-Jean (Jean 1999; Acary 2016, ZAMM 96:585) with localised touches:

* Newmark or generalized-alpha with an active set gain energy at impacts
  (Acary 2016); excluded.
* Mass redistribution (Khenous, Laborde & Renard 2008) and Nitsche's method
  (Chouly, Hild & Renard 2015) are built for contact on a boundary: the
  redistribution removes the inertia of the contact nodes, Nitsche combines
  the boundary traction with the gap.  The floor touches the membrane itself:
  every node (every point) of the lower hemisphere may touch, so removing
  their inertia removes that of half the ball, and modal coordinates have no
  nodal mass to move.
* The theta-scheme with a velocity-level Newton law takes diagonal and sparse
  M alike (an LCP with the Delassus matrix ``G W^-1 G^T`` per step), carries a
  restitution per constraint (the floor's points and a body on top), updates
  the momentum exactly (floor impulse = change of momentum + weight impulse,
  to rounding) and has an exact energy identity at theta = 1/2: the energy
  lost is the impacts' work, booked separately (eq. (MJ5) of
  :mod:`~twoball.modal.nonsmooth.moreau_jean`).
* Localising touches (the step ends where a gap reaches zero, the impact is
  applied there) raises the classical scheme's first order to second order
  between events.

At fixed resolution the floor's points have inertia, so an impact with
restitution 0 loses energy that no time step removes; it shrinks as the
points' effective masses shrink with the resolution.  Restitution 1 conserves
the mechanical energy exactly but makes the points rattle.
"""

from twoball.modal.nonsmooth.lcp import LCPSolution, solve_lcp
from twoball.modal.nonsmooth.moreau_jean import (
    ContactEvent,
    MoreauJean,
    StepperState,
    StepRecord,
    Trajectory,
)
from twoball.modal.nonsmooth.problem import ContactProblem

__all__ = [
    "ContactEvent",
    "ContactProblem",
    "LCPSolution",
    "MoreauJean",
    "StepRecord",
    "StepperState",
    "Trajectory",
    "solve_lcp",
]
