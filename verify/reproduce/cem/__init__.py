"""Reproduction of the continuum elastic model results: Figs. 6, 10, 11, 12 and §5 thresholds.

Each ``part_*`` function computes one group, draws its figure(s) into the output
directory and returns a :class:`~twoball.verify.reproduce.common.Section`; one
module per figure (:mod:`~twoball.verify.reproduce.cem.fig6`,
:mod:`~twoball.verify.reproduce.cem.fig10`, :mod:`~twoball.verify.reproduce.cem.fig11`,
:mod:`~twoball.verify.reproduce.cem.fig12`) and one for the §5 thresholds
(:mod:`~twoball.verify.reproduce.cem.thresholds`).  Work that is a list of
independent solves goes through the context's runner
(:mod:`~twoball.verify.reproduce.cem.tasks`), so it runs serially, on local
processes or on Dask with the same numbers.
"""

from twoball.verify.reproduce.cem.fig6 import part_fig6
from twoball.verify.reproduce.cem.fig10 import part_fig10
from twoball.verify.reproduce.cem.fig11 import part_fig11
from twoball.verify.reproduce.cem.fig12 import part_fig12
from twoball.verify.reproduce.cem.thresholds import part_thresholds

__all__ = ["part_fig6", "part_fig10", "part_fig11", "part_fig12", "part_thresholds"]
