"""Errors raised for invalid model input and for numerical trouble."""

from __future__ import annotations


class ParameterError(ValueError):
    """An input parameter is outside its valid range.

    The message always names the parameter and the valid range, so the
    command line can print it as a single line.

    Parameters
    ----------
    name : str
        The parameter's name in the Python API (for example ``"damping"``); the
        command line prints its flag instead (``--damping``).
    valid : str
        The valid range or set, in words (for example ``"[0, 1)"``).
    got : object, optional
        The offending value.

    Examples
    --------
    >>> import twoball
    >>> try:
    ...     twoball.Case.preset("basketball", damping=1.5)
    ... except twoball.ParameterError as error:
    ...     print(error.name, "|", error.valid)
    damping | in [0, 1)
    """

    def __init__(self, name: str, valid: str, got: object = None) -> None:
        self.name = name
        self.valid = valid
        self.got = got
        text = f"{name} must be {valid}"
        if got is not None:
            text += f", got {got!r}"
        super().__init__(text)

    def __reduce__(self) -> tuple[type, tuple[str, str, object]]:
        """Pickled with its three fields (process pools send errors back)."""
        return (type(self), (self.name, self.valid, self.got))


class UnknownKeywordError(ParameterError, TypeError):
    """A keyword the function does not take: a :class:`ParameterError` naming it.

    Also a :class:`TypeError`, what Python raises for an unexpected keyword, so
    code that catches that keeps working.

    Examples
    --------
    >>> import twoball
    >>> try:
    ...     twoball.liftoff(bogus=1)
    ... except twoball.ParameterError as error:
    ...     print(error.name, "|", error)
    bogus | bogus must be left out: twoball.liftoff() got an unexpected keyword argument 'bogus'
    """

    def __init__(self, name: str, function: str, got: object = None) -> None:
        valid = f"left out: {function}() got an unexpected keyword argument {name!r}"
        ParameterError.__init__(self, name, valid, None)
        self.function = function

    def __reduce__(self) -> tuple[type, tuple[str, str, object]]:
        """Pickled with its name and function."""
        return (type(self), (self.name, self.function))


class NumericalError(RuntimeError):
    """A computation produced NaN/inf or did not converge; never passed on silently.

    Examples
    --------
    >>> import twoball
    >>> issubclass(twoball.NumericalError, RuntimeError)
    True
    """


# Public as twoball.ParameterError and twoball.NumericalError: tracebacks and reprs say so.
ParameterError.__module__ = NumericalError.__module__ = "twoball"


def real_number(name: str, value: object, valid: str) -> float:
    """``value`` as a finite float, or :class:`ParameterError` (``valid`` in words).

    Refuses booleans, strings and other non-real types as well as NaN and +-inf.
    """
    from numbers import Real

    if isinstance(value, bool) or not isinstance(value, Real):
        raise ParameterError(name, valid, value)
    out = float(value)
    if out != out or out in (float("inf"), float("-inf")):
        raise ParameterError(name, valid, value)
    return out


def bounded(
    name: str,
    value: object,
    low: float,
    high: float,
    unit: str = "",
    *,
    low_open: bool = False,
) -> float:
    """A finite float in ``[low, high]`` (``(low, high]`` if ``low_open``), else ParameterError.

    The bounds keep every derived dimensionless number (``gamma = g / (R c^2)``,
    ``|v0| / (R c)``, ``t_end c``) far from overflow and underflow; ``unit`` is
    named in the message.
    """
    valid = f"a number in {'(' if low_open else '['}{low:g}, {high:g}]" + (
        f" [{unit}]" if unit else ""
    )
    out = real_number(name, value, valid)
    if not ((out > low if low_open else out >= low) and out <= high):
        raise ParameterError(name, valid, value)
    return out


def check_labels(owner: object, *names: str) -> None:
    """Refuse a label field of ``owner`` (``name``, ``source``) that is not a str, naming it."""
    for name in names:
        value = getattr(owner, name)
        if not isinstance(value, str):
            raise ParameterError(name, "a str (a label, in the JSON as written)", value)


def refuse_given(valid: str, **options: object) -> None:
    """Refuse the first of ``options`` that is not None: ``name must be VALID``.

    For options that only act together with another, e.g.
    ``refuse_given("given only with mass_ratio", restitution=...)``.
    """
    for name, value in options.items():
        if value is not None:
            raise ParameterError(name, valid, value)
