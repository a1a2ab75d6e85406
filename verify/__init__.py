"""twoball.verify -- cross-checks, studies, reports and the ``twoball`` command line.

The package is also the public verb :func:`twoball.verify`: calling it,
``twoball.verify(case, out="report")``, runs :func:`twoball.reports.verify`.
(A subpackage and a function cannot share the name ``twoball.verify``; the
import system sets the attribute to this package whenever one of its modules is
imported, so the package itself is made callable.)
"""

from __future__ import annotations

import sys
import types
from typing import Any


class _CallableModule(types.ModuleType):
    """This package, callable as :func:`twoball.reports.verify`."""

    def __call__(self, *args: Any, **kwargs: Any) -> Any:
        from twoball.reports import verify

        return verify(*args, **kwargs)


sys.modules[__name__].__class__ = _CallableModule
