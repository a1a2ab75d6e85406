"""The option bundles of the public verbs, and the keyword spellings they replace.

Every verb takes its options as small validated objects: the mesh as
:class:`~twoball.MeshOptions` (or a kind name, or the user's mesh), the time
options as :class:`~twoball.Stepping`, an upper body as :class:`~twoball.Body`,
the damping law as :class:`~twoball.ModalRatio` or :class:`~twoball.Rayleigh`
and the filter and re-contact horizon as :class:`~twoball.Series`.  The loose
keywords of version 0.2 (``level=3``, ``t_end=0.02``, ``mass_ratio=0.1``,
``damping_model="rayleigh"``, ``sigma="none"``, ...) are still taken for one
release, with a :class:`DeprecationWarning`, and turned into those objects here.
"""

from __future__ import annotations

import warnings
from typing import Any

from twoball._common.errors import ParameterError, UnknownKeywordError

__all__ = ["Bundles", "bundles", "warn_deprecated", "with_damping"]


def warn_deprecated(message: str) -> None:
    """A :class:`DeprecationWarning` attributed to the caller's line, outside twoball.

    The verbs reach here through wrappers and helpers of different depths, so the
    stack level is found by walking out of the package's frames.
    """
    import sys

    level, frame = 2, sys._getframe(1)  # stacklevel 2 is the frame that called this one
    while frame is not None and frame.f_globals.get("__name__", "").split(".")[0] == "twoball":
        frame, level = frame.f_back, level + 1
    warnings.warn(message, DeprecationWarning, stacklevel=level)


MESH_KEYS = ("level", "elements", "order", "pole", "geometry", "initial")
STEPPING_KEYS = ("t_end", "dt", "scheme", "route")
BODY_KEYS = ("mass_ratio", "contact_radius", "restitution", "energy")
SERIES_KEYS = ("sigma", "recontact")
OLD_KEYS = (*MESH_KEYS, *STEPPING_KEYS, *BODY_KEYS, "damping_model", *SERIES_KEYS)
#: What each bundle's old keywords are replaced by, as the warning names it.
REPLACEMENTS = {
    "mesh": "mesh=MeshOptions(...)",
    "stepping": "stepping=Stepping(...)",
    "body": "body=Body(...)",
    "damping": "damping=Rayleigh() (or ModalRatio(...))",
    "series": "series=Series(...)",
}
#: Every bundle a verb may take.
ALL = ("mesh", "stepping", "body", "damping", "series")


class Bundles:
    """The mesh, stepping, body, damping and series of one call, each None when not given."""

    __slots__ = ALL

    def __init__(self, mesh: Any, stepping: Any, body: Any, damping: Any, series: Any) -> None:
        self.mesh, self.stepping, self.body, self.damping = mesh, stepping, body, damping
        self.series = series

    @property
    def rules(self) -> Any:
        """The series rules given, or the defaults (:class:`~twoball.Series`)."""
        from twoball.modal.series_options import Series

        return Series() if self.series is None else self.series

    def as_dict(self) -> dict[str, Any]:
        """Each given bundle's ``as_dict()`` (a mesh kind name as it is), for provenance."""
        out: dict[str, Any] = {}
        for name in ALL:
            value = getattr(self, name)
            if value is not None:
                out[name] = value.as_dict() if hasattr(value, "as_dict") else value
        return out


def bundles(
    verb: str,
    *,
    mesh: Any = None,
    stepping: Any = None,
    body: Any = None,
    damping: Any = None,
    series: Any = None,
    old: dict[str, Any] | None = None,
    takes: tuple[str, ...] = ALL,
) -> Bundles:
    """Check the bundles' types and fold the old keywords ``old`` into them.

    Parameters
    ----------
    verb : str
        The verb's name, for the warning (``twoball.liftoff``).
    mesh, stepping, body, damping, series
        As the verb received them.
    old : dict, optional
        Keywords outside the signature: each of :data:`OLD_KEYS` is folded in
        with a :class:`DeprecationWarning`; any other is refused by name
        (:class:`~twoball._common.errors.UnknownKeywordError`, a ParameterError
        that is also the ``TypeError`` Python gives for an unknown keyword).
    takes : tuple of str
        The bundles this verb has (an old keyword of another is unknown).
    """
    from twoball.fem_membrane.options import MeshOptions
    from twoball.modal.contact.body import Body
    from twoball.modal.damping import ModalRatio, Rayleigh
    from twoball.modal.series_options import Series
    from twoball.modal.stepping import Stepping

    old = {k: v for k, v in (old or {}).items()}
    known = {
        "mesh": MESH_KEYS,
        "stepping": STEPPING_KEYS,
        "body": BODY_KEYS,
        "damping": ("damping_model",),
        "series": SERIES_KEYS,
    }
    allowed = {k for bundle in takes for k in known[bundle]}
    for key in old:
        if key not in allowed:
            raise UnknownKeywordError(key, verb)
    given = {k: v for k, v in old.items() if v is not None}
    if given:
        instead = [REPLACEMENTS[b] for b in known if any(k in known[b] for k in given)]
        warn_deprecated(
            f"{verb}: the keyword{'s' if len(given) > 1 else ''} {', '.join(sorted(given))} "
            f"{'are' if len(given) > 1 else 'is'} deprecated; pass {' and '.join(instead)} "
            "instead"
        )
    fields = {k: old.get(k) for k in MESH_KEYS}
    if any(v is not None for v in fields.values()) or (mesh is not None and "mesh" in takes):
        mesh = MeshOptions.of(mesh, **fields)
    step = {k: old[k] for k in STEPPING_KEYS if old.get(k) is not None}
    if step:
        if stepping is not None:
            raise ParameterError(next(iter(step)), "left out with stepping (set it there)", None)
        stepping = Stepping(**step)
    if stepping is not None and not isinstance(stepping, Stepping):
        raise ParameterError("stepping", "a twoball.Stepping", type(stepping).__name__)
    mass = {k: old[k] for k in BODY_KEYS if old.get(k) is not None}
    if mass:
        if body is not None:
            raise ParameterError(next(iter(mass)), "left out with body (set it there)", None)
        if "mass_ratio" not in mass:
            key = next(iter(mass))
            raise ParameterError(key, "given only with mass_ratio", mass[key])
        body = Body(**mass)
    if body is not None and not isinstance(body, Body):
        raise ParameterError("body", "a twoball.Body", type(body).__name__)
    model = old.get("damping_model")
    if model is not None:
        if damping is not None:
            raise ParameterError("damping_model", "left out with damping (set it there)", model)
        if model not in ("modal", "rayleigh"):
            raise ParameterError("damping_model", "one of modal, rayleigh", model)
        damping = Rayleigh() if model == "rayleigh" else None
    if damping is not None and not isinstance(damping, (ModalRatio, Rayleigh)):
        raise ParameterError("damping", "a twoball.ModalRatio or twoball.Rayleigh", damping)
    rules = {k: old[k] for k in SERIES_KEYS if old.get(k) is not None}
    if rules:
        if series is not None:
            raise ParameterError(next(iter(rules)), "left out with series (set it there)", None)
        series = Series(**rules)
    if series is not None and not isinstance(series, Series):
        raise ParameterError("series", "a twoball.Series", type(series).__name__)
    return Bundles(mesh, stepping, body, damping, series)


def with_damping(case: Any, law: Any) -> Any:
    """``case`` with the verb's damping law folded in (None: the case as it is).

    A :class:`ModalRatio` sets the paper's ratio D; a :class:`Rayleigh` law (SI,
    or ``Rayleigh()`` fitted to D) becomes the case's ``rayleigh``, which every
    solver reads through
    :attr:`twoball.Case.damping_law`.  A law that contradicts the case's own
    Rayleigh law is refused.
    """
    from twoball.modal.damping import ModalRatio, Rayleigh

    if law is not None and case.rayleigh is not None and law != case.rayleigh:
        valid = "left out when the case has its own Rayleigh law (one damping law)"
        raise ParameterError("damping", valid, law.as_dict())
    if isinstance(law, ModalRatio) and law.ratio != case.damping:
        return case.derive(damping=law.ratio)
    if isinstance(law, Rayleigh) and law != case.rayleigh:
        return case.derive(rayleigh=law)
    return case
