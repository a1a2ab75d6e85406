"""twoball.verify -- cross-checks, studies, reproduction, sweeps and every output.

``checks`` (what ``twoball verify`` runs), ``studies`` (convergence studies),
``reproduce`` (the paper recomputed), ``sweeps`` (parameter sweeps on a pool or
Dask) and ``output`` (fields, series files, renders, figures, report files).
The public verb :func:`twoball.verify` shares this package's name; :mod:`twoball`
makes the package callable (see there).
"""

__all__ = ["checks", "output", "reproduce", "studies", "sweeps"]
