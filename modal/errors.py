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
    """

    def __init__(self, name: str, valid: str, got: object = None) -> None:
        self.name = name
        self.valid = valid
        self.got = got
        text = f"{name} must be {valid}"
        if got is not None:
            text += f", got {got!r}"
        super().__init__(text)


class NumericalError(RuntimeError):
    """A computation produced NaN/inf or did not converge; never passed on silently."""
