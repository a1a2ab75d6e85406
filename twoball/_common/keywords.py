"""The arguments of a public verb or option object, refused by name before its work.

Python refuses an unknown keyword, a missing argument or one too many with a
bare :class:`TypeError` naming the function (``bounce() got an unexpected
keyword argument 'bogus'``); the public API refuses every bad argument with a
:class:`~twoball.ParameterError` naming the argument instead, so one ``except``
catches them all and the command line prints them as one line.  The errors
raised here are :class:`TypeError` too, as Python's own are, so code that
catches those keeps working.

:func:`checked` decorates a function, a method or a class (its ``__init__``,
the one a dataclass writes included)::

    @checked
    @dataclass(frozen=True)
    class Drop: ...

Only the standard library is imported here.
"""

from __future__ import annotations

import functools
from collections.abc import Callable
from typing import Any, TypeVar

from twoball._common.errors import ParameterError, UnknownKeywordError

__all__ = ["ArgumentError", "checked"]

_T = TypeVar("_T")


class ArgumentError(ParameterError, TypeError):
    """A missing argument, one given twice or too many positional arguments.

    A :class:`~twoball.ParameterError` naming the argument (``arguments`` for
    too many positional ones), and a :class:`TypeError` as Python's own.
    """

    def __init__(self, name: str, valid: str, got: object = None) -> None:
        ParameterError.__init__(self, name, valid, got)


class _Shape:
    """The arguments a function takes, read on its first call for a check on every call.

    (:mod:`inspect` is imported then, not when the decorated module is: the
    command line's start-up stays light.)
    """

    def __init__(self, function: Callable[..., Any], skip_first: bool) -> None:
        import inspect

        params = list(inspect.signature(function).parameters.values())[1 if skip_first else 0 :]
        kinds = inspect.Parameter
        self.positional = [
            p.name for p in params if p.kind in (kinds.POSITIONAL_ONLY, kinds.POSITIONAL_OR_KEYWORD)
        ]
        self.any_positional = any(p.kind is kinds.VAR_POSITIONAL for p in params)
        self.any_keyword = any(p.kind is kinds.VAR_KEYWORD for p in params)
        self.keywords = frozenset(
            p.name for p in params if p.kind in (kinds.POSITIONAL_OR_KEYWORD, kinds.KEYWORD_ONLY)
        )
        self.required = [
            (k if p.kind is not kinds.KEYWORD_ONLY else None, p.name)
            for k, p in enumerate(params)
            if p.default is p.empty and p.kind not in (kinds.VAR_POSITIONAL, kinds.VAR_KEYWORD)
        ]

    def check(self, where: str, args: tuple[Any, ...], kwargs: dict[str, Any]) -> None:
        """Refuse the first bad argument of a call ``where(*args, **kwargs)``."""
        if not self.any_keyword:
            for key in kwargs:
                if key not in self.keywords:
                    raise UnknownKeywordError(key, where)
        count = len(args)
        if count > len(self.positional) and not self.any_positional:
            names = ", ".join(self.positional) or "none"
            raise ArgumentError(
                "arguments", f"at most {len(self.positional)} positional to {where}() ({names})"
            )
        for name in self.positional[:count]:
            if name in kwargs:
                raise ArgumentError(name, f"given once to {where}() (by position or by name)")
        for index, name in self.required:
            if name not in kwargs and (index is None or index >= count):
                raise ArgumentError(name, f"given to {where}()")


def checked(target: _T | None = None, *, name: str | None = None) -> Any:
    """Refuse a bad call of ``target`` (a function or a class) by the argument's name.

    ``name`` is the public name the message gives (default ``twoball.`` and the
    function's or class's name; a method: ``Class.method``).  Usable as
    ``@checked`` or ``@checked(name="twoball.table1")``.
    """

    def decorate(target: Any) -> Any:
        if isinstance(target, type):
            return _checked_class(target, name)
        return _checked_function(target, name)

    return decorate if target is None else decorate(target)


def _public(function: Callable[..., Any]) -> str:
    qualname = function.__qualname__
    return qualname if "." in qualname else f"twoball.{qualname}"


def _checked_function(function: Callable[..., Any], name: str | None) -> Callable[..., Any]:
    code = getattr(function, "__code__", None)
    method = "." in function.__qualname__ and "<locals>" not in function.__qualname__
    method = method and code is not None and code.co_varnames[:1] == ("self",)
    where = name or _public(function)
    shapes: list[_Shape] = []

    if method:

        @functools.wraps(function)
        def bound(self: Any, *args: Any, **kwargs: Any) -> Any:
            shape = shapes[0] if shapes else _first(shapes, function, True)
            shape.check(where, args, kwargs)
            return function(self, *args, **kwargs)

        return bound

    @functools.wraps(function)
    def wrapper(*args: Any, **kwargs: Any) -> Any:
        shape = shapes[0] if shapes else _first(shapes, function, False)
        shape.check(where, args, kwargs)
        return function(*args, **kwargs)

    return wrapper


def _first(shapes: list[_Shape], function: Callable[..., Any], skip_first: bool) -> _Shape:
    """The shape of ``function``, read now and kept in ``shapes``."""
    shapes.append(_Shape(function, skip_first))
    return shapes[0]


def _checked_class(cls: type, name: str | None) -> type:
    init = cls.__init__
    where = name or f"twoball.{cls.__name__}"
    shapes: list[_Shape] = []

    @functools.wraps(init)
    def __init__(self: Any, *args: Any, **kwargs: Any) -> None:  # noqa: N807 -- the wrapped one
        if type(self).__init__ is __init__:  # not a subclass's own __init__ calling this one
            shape = shapes[0] if shapes else _first(shapes, init, True)
            shape.check(where, args, kwargs)
        init(self, *args, **kwargs)

    cls.__init__ = __init__  # type: ignore[misc]
    return cls
