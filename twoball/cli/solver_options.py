"""The command line's flags mapped onto the solver objects (:mod:`twoball._solvers`).

The flags stay as they were (``--backend``, ``--scheme``, ``--route``, ``--dt``,
``--t-end``, ``--sigma``, ``--recontact``, the mesh options, ``--mass-ratio``); here
they become one solver object that carries exactly the options that apply.  A flag
that no solver of the command takes is refused by its own name, with the reason.
"""

from __future__ import annotations

import argparse
from typing import Any

import twoball
from twoball._common.errors import ParameterError
from twoball.cli.mesh_options import mesh_options, refuse_mesh_flags

__all__ = ["closed_form", "field_solver", "liftoff_solver", "series_fields"]


def series_fields(args: argparse.Namespace, *names: str) -> dict[str, Any]:
    """``--sigma``, ``--recontact``, ``--t-end`` (those of ``names`` given) as solver fields."""
    names = names or ("sigma", "recontact", "t_end")
    return {n: getattr(args, n) for n in names if getattr(args, n, None) is not None}


def closed_form(args: argparse.Namespace) -> twoball.ClosedForm | None:
    """``--sigma``, ``--recontact``, ``--t-end`` as a :class:`~twoball.ClosedForm` (None: none)."""
    fields = series_fields(args)
    return twoball.ClosedForm(**fields) if fields else None


def _refuse(args: argparse.Namespace, names: tuple[str, ...], why: str) -> None:
    for name in names:
        value = getattr(args, name, None)
        if value is not None:
            raise ParameterError(name, f"left out {why}", value)


def liftoff_solver(args: argparse.Namespace, body: Any) -> Any:
    """The solver of ``twoball liftoff``'s flags (None: the verb's default).

    ``--backend legendre``: :class:`~twoball.ClosedForm` (no mesh, no time steps);
    with ``--mass-ratio`` > 0: :class:`~twoball.MoreauJean` on the Legendre modes
    (``--dt`` its step).  ``--backend fem``: :class:`~twoball.Superposition`
    (``--scheme modal``, ``--route``) or :class:`~twoball.GeneralizedAlpha`
    (``--scheme alpha``, ``--dt``); with ``--mass-ratio`` > 0:
    :class:`~twoball.MoreauJean` on the :class:`~twoball.FEBall` of the mesh.
    """
    massive = body is not None and body.mass_ratio > 0.0
    backend = args.backend
    if backend not in ("legendre", "fem"):
        raise ParameterError("backend", "one of legendre, fem", backend)
    if massive:
        _refuse(args, ("scheme", "route"), "with --mass-ratio (its contacts are stepped)")
        if args.recontact not in (None, "window"):
            raise ParameterError("recontact", "window with --mass-ratio", args.recontact)
        fields = series_fields(args, "sigma", "t_end")
        if backend == "legendre":
            refuse_mesh_flags(args, "with backend legendre (no mesh)")
            ball = None
        else:
            ball = twoball.FEBall(mesh_options(args))
        return twoball.MoreauJean(ball, dt=args.dt, **fields)
    if backend == "legendre":
        refuse_mesh_flags(args, "with backend legendre (no mesh)")
        _refuse(args, ("scheme", "dt", "route"), "with backend legendre (no time steps)")
        return closed_form(args)
    mesh = mesh_options(args)
    fields = series_fields(args)
    scheme = args.scheme or "modal"
    if scheme == "alpha":
        if args.route not in (None, "full", "auto"):
            raise ParameterError("route", "full or auto with scheme alpha", args.route)
        return twoball.GeneralizedAlpha(mesh, dt=args.dt, **fields)
    if scheme != "modal":
        raise ParameterError("scheme", "one of modal, alpha", scheme)
    if args.dt is not None:
        raise ParameterError("dt", "left out with scheme modal (no time steps)", args.dt)
    return twoball.Superposition(mesh, route=args.route or "auto", **fields)


def field_solver(args: argparse.Namespace) -> twoball.Superposition:
    """The fields' solver: the mesh, ``--route``, ``--sigma``, ``--recontact``, ``--t-end``
    (:class:`~twoball.Superposition`: the finite elements, the closed form beside them)."""
    route = getattr(args, "route", None)
    return twoball.Superposition(mesh_options(args), route=route or "auto", **series_fields(args))
