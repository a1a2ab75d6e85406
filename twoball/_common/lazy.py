"""Lazy package attributes (PEP 562): a name imports its module on first use.

Keeps ``import twoball`` and ``twoball --help`` free of numpy, scipy,
scikit-fem and matplotlib until a computation needs them.
"""

from __future__ import annotations

import importlib
from collections.abc import Callable


def attach(
    package: str, names: dict[str, str | tuple[str, str]]
) -> tuple[Callable[[str], object], Callable[[], list[str]]]:
    """``__getattr__`` and ``__dir__`` for ``package``, mapping each name to its module.

    Parameters
    ----------
    package : str
        The package's ``__name__``.
    names : dict
        Public name -> module path (absolute, or relative to ``package`` such as
        ``".parameters"``), or -> ``(module, attribute)`` when the name differs
        from the attribute's name in its module.
    """

    def __getattr__(name: str) -> object:
        try:
            module = names[name]
        except KeyError:
            raise AttributeError(f"module {package!r} has no attribute {name!r}") from None
        module, attribute = module if isinstance(module, tuple) else (module, name)
        value = getattr(importlib.import_module(module, package), attribute)
        globals_of_package = importlib.import_module(package).__dict__
        globals_of_package[name] = value  # later look-ups are plain attribute reads
        return value

    def __dir__() -> list[str]:
        return sorted(names)

    return __getattr__, __dir__
