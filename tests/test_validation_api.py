"""The table of invalid values through the Python API: ParameterError every time (issue 11).

Each bad value of :mod:`validation_table` that the command line refuses for a
flag is given, as the value the parser would produce (an int for an integer
option when the text is one, else a float or the text itself), to every public
function that takes the matching parameter.  Each call must raise
:class:`twoball.ParameterError` naming the parameter -- not a TypeError,
ValueError, OverflowError or a numpy warning (warnings are errors here) --
before any work (a CPU-time alarm stops a call that started it).
"""

from __future__ import annotations

import math
import signal
import warnings
from collections.abc import Callable
from pathlib import Path
from typing import Any

import pytest
import validation_table as table
from twoball.modal import icm
from twoball.modal.stiffness import flexural_rigidity

import twoball
from twoball.cli.flags import FLAGS

CPU_LIMIT_S = 3.0


class Ran(BaseException):
    """The call was still working when the alarm rang."""


def _alarm(signum: int, frame: object) -> None:
    raise Ran


def python_value(flag: str, text: str) -> Any:
    """The value the command-line parser gives for ``text`` (a float, an int or the text)."""
    if table.RANGES[flag].integer:
        try:
            return int(text)
        except ValueError:
            pass
    try:
        return float(text)
    except ValueError:
        return text


CASE = twoball.Case.preset("basketball")
#: parameter -> a function that passes the value to the public API, per entry point.
CALLS: dict[str, dict[str, Callable[[Any, Path], Any]]] = {
    "radius": {
        "Case": lambda v, _: twoball.Case(radius=v),
        "Case.preset": lambda v, _: twoball.Case.preset("basketball", radius=v),
        "Scalings": lambda v, _: __import__("twoball.modal.parameters").modal.parameters.Scalings(
            v, 320.0
        ),
    },
    "wave_speed": {
        "Case": lambda v, _: twoball.Case(wave_speed=v),
        "Case.from_measurements": lambda v, _: twoball.Case.from_measurements(
            radius=0.12, v0=4.1, wave_speed=v
        ),
    },
    "pressure": {"Case.from_pressure": lambda v, _: twoball.Case.from_pressure(v, 0.567)},
    "mass": {"Case.from_pressure": lambda v, _: twoball.Case.from_pressure(77200.0, v)},
    "v0": {
        "Case": lambda v, _: twoball.Case(v0=v),
        "phi_a_from_v0": lambda v, _: __import__(
            "twoball.modal.initial"
        ).modal.initial.phi_a_from_v0(v, 0.12, 320.0),
    },
    "phi_a": {
        "Case": lambda v, _: twoball.Case(phi_a=v),
        "v0_from_phi_a": lambda v, _: __import__(
            "twoball.modal.initial"
        ).modal.initial.v0_from_phi_a(v, 0.12, 320.0),
        "initial_displacement": lambda v, _: __import__(
            "twoball.modal.initial"
        ).modal.initial.initial_displacement([3.0], v),
    },
    "damping": {"Case": lambda v, _: twoball.Case(damping=v)},
    "modes": {
        "Case": lambda v, _: twoball.Case(modes=v),
        "Drop": lambda v, _: twoball.Drop(modes=v),
    },
    "g": {"Case": lambda v, _: twoball.Case(g=v)},
    "t_end": {
        "liftoff": lambda v, _: twoball.liftoff(CASE, t_end=v),
        "fem.solve": lambda v, _: twoball.fem.solve(CASE, level=1, t_end=v),
        "sweep": lambda v, _: twoball.sweep({"damping": [0.1]}, CASE, t_end=v),
        "export": lambda v, tmp: twoball.export(tmp / "x.vtu", CASE, level=1, t_end=v),
        "render": lambda v, tmp: twoball.render(tmp / "x.png", CASE, level=1, t_end=v),
        "plot": lambda v, tmp: twoball.plot("pole", tmp / "p.png", CASE, level=1, t_end=v),
        "converge": lambda v, tmp: twoball.converge(
            CASE, study="modes", modes_list="30,60,120", t_end=v, out=tmp / "c"
        ),
        "verify": lambda v, tmp: twoball._studies.verify(CASE, fast=True, t_end=v, out=tmp / "r"),
    },
    "level": {
        "liftoff": lambda v, _: twoball.liftoff(CASE, backend="fem", level=v),
        "fem.solve": lambda v, _: twoball.fem.solve(CASE, level=v),
        "fem.eigen": lambda v, _: twoball.fem.eigen(level=v, count=3),
        "export": lambda v, tmp: twoball.export(tmp / "x.vtu", CASE, level=v),
        "render": lambda v, tmp: twoball.render(tmp / "x.png", CASE, level=v),
        "plot": lambda v, tmp: twoball.plot("pole", tmp / "p.png", CASE, level=v),
    },
    "elements": {
        "fem.solve": lambda v, _: twoball.fem.solve(CASE, mesh="axisym", elements=v),
        "bounce": lambda v, _: twoball.bounce(
            CASE, backend="fem", mesh=twoball.MeshOptions("axisym", elements=v)
        ),
        "fem.eigen": lambda v, _: twoball.fem.eigen(mesh="axisym", elements=v),
    },
    "order": {
        "fem.solve": lambda v, _: twoball.fem.solve(CASE, level=1, order=v),
        "fem.eigen": lambda v, _: twoball.fem.eigen(level=1, order=v),
        "export": lambda v, tmp: twoball.export(tmp / "x.vtu", CASE, level=1, order=v),
        "converge": lambda v, tmp: twoball.converge(CASE, study="h", order=v, out=tmp / "c"),
    },
    "dt": {
        "fem.solve": lambda v, _: twoball.fem.solve(CASE, mesh="axisym", scheme="alpha", dt=v),
        "liftoff": lambda v, _: twoball.liftoff(
            CASE, backend="fem", mesh="axisym", scheme="alpha", dt=v
        ),
        "bounce": lambda v, _: twoball.bounce(
            CASE, stepping=twoball.Stepping(scheme="moreau-jean", dt=v)
        ),
    },
    "count": {"fem.eigen": lambda v, _: twoball.fem.eigen(level=1, count=v)},
    "workers": {"sweep": lambda v, _: twoball.sweep({"damping": [0.1, 0.2]}, CASE, workers=v)},
    "mu": {"icm": lambda v, _: icm.icm(v, 0.8, 0.9)},
    "e2": {"icm": lambda v, _: icm.icm(0.5, v, 0.9)},
    "e12": {"icm": lambda v, _: icm.icm(0.5, 0.8, v)},
    "dx": {"icm": lambda v, _: icm.icm(0.5, 0.8, 0.9, dx=v, drop_height=1.0)},
    "drop_height": {
        "icm": lambda v, _: icm.icm(0.5, 0.8, 0.9, drop_height=v),
        "Drop": lambda v, _: twoball.Drop(drop_height=v),
    },
    "floor_restitution": {"Drop": lambda v, _: twoball.Drop(floor_restitution=v)},
    "gap": {"Drop": lambda v, _: twoball.Drop(gap=v)},
    "frames": {
        "export": lambda v, tmp: twoball.export(tmp / "x.pvd", CASE, level=1, frames=v),
        "render": lambda v, tmp: twoball.render(tmp / "x.gif", CASE, level=1, frames=v),
    },
    "time": {"render": lambda v, tmp: twoball.render(tmp / "x.png", CASE, level=1, time=v)},
    "fps": {"render": lambda v, tmp: twoball.render(tmp / "x.gif", CASE, level=1, fps=v)},
    "instants": {
        "plot": lambda v, tmp: twoball.plot("waterfall", tmp / "p.png", CASE, level=1, instants=v)
    },
    "max_degree": {"plot": lambda v, tmp: twoball.plot("eigen", tmp / "p.png", max_degree=v)},
    "dpi": {"plot": lambda v, tmp: twoball.plot("eigen", tmp / "p.png", dpi=v)},
    "mass_ratio": {
        "liftoff": lambda v, _: twoball.liftoff(CASE, mass_ratio=v),
        "export": lambda v, tmp: twoball.export(tmp / "x.vtu", CASE, level=1, mass_ratio=v),
        "render": lambda v, tmp: twoball.render(tmp / "x.png", CASE, level=1, mass_ratio=v),
        "plot": lambda v, tmp: twoball.plot("pole", tmp / "p.png", CASE, level=1, mass_ratio=v),
        "bounce": lambda v, _: twoball.bounce(CASE, body=twoball.Body(v)),
    },
    "contact_radius": {
        "liftoff": lambda v, _: twoball.liftoff(CASE, mass_ratio=0.01, contact_radius=v),
        "export": lambda v, tmp: twoball.export(
            tmp / "x.vtu", CASE, level=1, mass_ratio=0.01, contact_radius=v
        ),
        "render": lambda v, tmp: twoball.render(
            tmp / "x.png", CASE, level=1, mass_ratio=0.01, contact_radius=v
        ),
        "plot": lambda v, tmp: twoball.plot(
            "pole", tmp / "p.png", CASE, level=1, mass_ratio=0.01, contact_radius=v
        ),
        "bounce": lambda v, _: twoball.bounce(CASE, body=twoball.Body(0.01, contact_radius=v)),
    },
    "restitution": {
        "liftoff": lambda v, _: twoball.liftoff(CASE, mass_ratio=0.01, restitution=v),
        "export": lambda v, tmp: twoball.export(
            tmp / "x.vtu", CASE, level=1, mass_ratio=0.01, restitution=v
        ),
        "render": lambda v, tmp: twoball.render(
            tmp / "x.png", CASE, level=1, mass_ratio=0.01, restitution=v
        ),
        "plot": lambda v, tmp: twoball.plot(
            "pole", tmp / "p.png", CASE, level=1, mass_ratio=0.01, restitution=v
        ),
        "bounce": lambda v, _: twoball.bounce(CASE, body=twoball.Body(0.01, restitution=v)),
    },
    "bending": {"Case": lambda v, _: twoball.Case.preset("tennis").derive(bending=v)},
    "atmosphere": {"Case": lambda v, _: twoball.Case.preset("tennis").derive(atmosphere=v)},
    "youngs_modulus": {"flexural_rigidity": lambda v, _: flexural_rigidity(v, 0.003)},
    "thickness": {"flexural_rigidity": lambda v, _: flexural_rigidity(6e6, v)},
    "poisson": {"flexural_rigidity": lambda v, _: flexural_rigidity(6e6, 0.003, v)},
}


def api_cases() -> list[tuple[str, str, Any]]:
    """(parameter, entry point, value) for each bad value of the parameter's flag."""
    cases = []
    for name, calls in CALLS.items():
        flag = FLAGS[name]
        for text in table.bad_values(flag):
            for entry in calls:
                cases.append((name, entry, python_value(flag, text)))
    return cases


def call_refused(name: str, entry: str, value: Any, tmp: Path) -> str | None:
    """None if the call raised ParameterError naming ``name`` in time; else what happened."""
    signal.signal(signal.SIGPROF, _alarm)
    signal.setitimer(signal.ITIMER_PROF, CPU_LIMIT_S)
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("error")
            CALLS[name][entry](value, tmp)
        return "returned"
    except twoball.ParameterError as error:
        return None if error.name in (name, FLAGS[name]) else f"named {error.name!r}: {error}"
    except Ran:
        return "started the work"
    except (Exception, Warning) as error:  # noqa: BLE001 -- reported
        return f"{type(error).__name__}: {error}"
    finally:
        signal.setitimer(signal.ITIMER_PROF, 0)


def test_every_numeric_flag_has_api_calls() -> None:
    """Each numeric option of the CLI is tried through the API (names through FLAGS)."""
    from twoball.cli.main import full_parser

    flags = {f for fl in table.numeric_options(full_parser()).values() for f in fl}
    covered = {FLAGS[name] for name in CALLS}
    assert flags <= covered, sorted(flags - covered)


def test_bad_values_raise_parameter_error(tmp_path: Path) -> None:
    cases = api_cases()
    assert len(cases) > 300
    failures = []
    for name, entry, value in cases:
        got = call_refused(name, entry, value, tmp_path)
        if got is not None:
            failures.append(f"{entry}({name}={value!r}): {got}")
    assert not failures, f"{len(failures)} of {len(cases)}:\n" + "\n".join(failures[:40])
    assert sorted(p.name for p in tmp_path.iterdir()) == []  # nothing written


EXTRA: list[tuple[str, Callable[[Path], Any]]] = [
    # values of the wrong type are refused, never stored or coerced
    ("phi_a", lambda _: twoball.Case(phi_a="2.6")),
    ("damping", lambda _: twoball.Case(damping="0.1")),
    ("modes", lambda _: twoball.Case(modes=True)),
    ("modes", lambda _: twoball.Case(modes=30.5)),
    ("v0", lambda _: twoball.Case(v0=None)),
    ("mu", lambda _: icm.icm("0.5", 0.8, 0.9)),
    ("e2", lambda _: icm.icm(0.5, True, 0.9)),
    ("case", lambda _: twoball.liftoff("basketball")),
    ("case", lambda _: twoball.sweep({"damping": [0.1]}, "basketball")),
    # the membrane operator and the damping law (docs/pressurised.rst)
    ("membrane", lambda _: twoball.Case(membrane="flat")),
    ("gas", lambda _: twoball.Case(membrane="pressurised")),
    ("membrane", lambda _: twoball.Membrane("flat")),
    ("membrane", lambda _: twoball.fem.eigen(membrane="flat")),
    ("alpha", lambda _: twoball.Rayleigh(-1.0, 0.0)),
    ("beta", lambda _: twoball.Rayleigh(0.0, -1.0)),
    ("rayleigh", lambda _: twoball.Case(rayleigh=(1.0, 0.0))),
    (
        "rayleigh",
        lambda _: twoball.liftoff(damping=twoball.Rayleigh(1.0, 0.0), body=twoball.Body(0.1)),
    ),
    (
        "damping",
        lambda _: twoball.liftoff(
            twoball.Case(rayleigh=twoball.Rayleigh(1.0, 0.0)), damping=twoball.ModalRatio(0.2)
        ),
    ),
    (
        "membrane",
        lambda tmp: twoball.converge(
            twoball.Case(pressure=77200.0, gas="adiabatic", membrane="pressurised"),
            study="modes",
            out=tmp / "c",
        ),
    ),
    (
        "rayleigh",
        lambda tmp: twoball._studies.verify(
            twoball.Case(rayleigh=twoball.Rayleigh()), fast=True, out=tmp / "r"
        ),
    ),
    ("backends", lambda tmp: twoball.plot("precursor", tmp / "p.png", CASE, backends=["fem"])),
    (
        "param",
        lambda _: twoball.sweep(
            {"damping": [0.1, 0.2]}, twoball.Case(rayleigh=twoball.Rayleigh(1.0, 0.0))
        ),
    ),
    # options that do not apply
    ("level", lambda _: twoball.liftoff(CASE, level=3)),
    ("mesh", lambda _: twoball.liftoff(CASE, mesh="sphere")),
    ("dt", lambda _: twoball.liftoff(CASE, dt=1e-5)),
    ("level", lambda _: twoball.fem.solve(CASE, mesh="axisym", level=2)),
    ("elements", lambda _: twoball.fem.solve(CASE, mesh="ring", elements=50)),
    ("dt", lambda _: twoball.fem.solve(CASE, scheme="modal", dt=1e-5)),
    ("route", lambda _: twoball.fem.solve(CASE, scheme="alpha", route="krylov")),
    ("order", lambda tmp: twoball.converge(CASE, study="order", order=2, out=tmp / "c")),
    ("levels", lambda tmp: twoball.converge(CASE, study="modes", levels="1:2", out=tmp / "c")),
    ("modes_list", lambda tmp: twoball.converge(CASE, study="h", modes_list="30,60,120")),
    ("levels", lambda tmp: twoball.converge(CASE, study="h", levels="0:1", out=tmp / "c")),
    ("fast", lambda tmp: twoball._studies.verify(CASE, fast=True, thorough=True)),
    ("workers", lambda _: twoball.sweep({"damping": [0.1]}, CASE, workers=2, scheduler="x:1")),
    ("fps", lambda tmp: twoball.render(tmp / "x.png", CASE, level=1, fps=10)),
    ("frames", lambda tmp: twoball.render(tmp / "x.png", CASE, level=1, frames=5)),
    ("time", lambda tmp: twoball.render(tmp / "x.gif", CASE, level=1, time=0.001)),
    (
        "initial",
        lambda tmp: twoball.render(
            tmp / "x.png", CASE, backend="legendre", initial="interpolation"
        ),
    ),  # noqa: E501
    ("case", lambda tmp: twoball.plot("eigen", tmp / "p.png", CASE)),
    ("sigma", lambda tmp: twoball.plot("eigen", tmp / "p.png", sigma="none")),
    ("backends", lambda tmp: twoball.plot("eigen", tmp / "p.png", backends=["fem"])),
    ("levels", lambda tmp: twoball.plot("pole", tmp / "p.png", CASE, levels=[1, 2])),
    ("max_degree", lambda tmp: twoball.plot("waterfall", tmp / "p.png", CASE, max_degree=5)),
    ("instants", lambda tmp: twoball.plot("pole", tmp / "p.png", CASE, instants=5)),
    ("levels", lambda tmp: twoball.plot("eigen", tmp / "p.png", levels=[-1])),
    ("orders", lambda tmp: twoball.plot("eigen", tmp / "p.png", orders=[7])),
    ("frames", lambda tmp: twoball.export(tmp / "x.vtu", CASE, level=1, frames=5)),
    (
        "route",
        lambda tmp: twoball.export(
            tmp / "x.vtu", CASE, backend="legendre", stepping=twoball.Stepping(route="full")
        ),
    ),
    # mesh files of the field commands
    ("pole", lambda tmp: twoball.export(tmp / "x.vtu", CASE, level=1, pole=(0, 0, 1))),
    ("pole", lambda tmp: twoball.render(tmp / "x.png", CASE, pole="0,0,1")),
    ("pole", lambda tmp: twoball.plot("pole", tmp / "p.png", CASE, pole=(0, 0, 1))),
    ("pole", lambda tmp: twoball.plot("eigen", tmp / "p.png", pole=(0, 0, 1))),
    ("geometry", lambda tmp: twoball.export(tmp / "x.vtu", CASE, mesh="ring", geometry="exact")),
    ("geometry", lambda tmp: twoball.render(tmp / "x.png", CASE, geometry="bogus")),
    ("geometry", lambda tmp: twoball.plot("eigen", tmp / "p.png", geometry="exact")),
    ("mesh", lambda tmp: twoball.plot("eigen", tmp / "p.png", mesh=tmp / "ball.msh")),
    ("level", lambda tmp: twoball.render(tmp / "x.png", CASE, mesh=tmp / "ball.msh", level=1)),
    ("order", lambda tmp: twoball.export(tmp / "x.vtu", CASE, level=1, order=3)),
    ("times", lambda tmp: twoball.export(tmp / "x.pvd", CASE, level=1, times=[math.nan])),
    ("times", lambda tmp: twoball.export(tmp / "x.pvd", CASE, level=1, times=[1.0])),
    # paths: empty, over-long, unwritable, unreadable
    *[
        ("out", call)
        for path in ("", "a" * 300 + ".png", table.LONG_PATH + ".png", "/proc/x/y.png")
        for call in (
            lambda tmp, p=path: twoball.plot("pole", _under(tmp, p), CASE, level=1),
            lambda tmp, p=path: twoball.render(_under(tmp, p), CASE, level=1),
            lambda tmp, p=path: twoball.export(_under(tmp, p[:-4] + ".vtu"), CASE, level=1),
            lambda tmp, p=path: twoball.converge(CASE, study="modes", out=_under(tmp, p[:-4])),
            lambda tmp, p=path: twoball._studies.verify(CASE, fast=True, out=_under(tmp, p[:-4])),
        )
    ],
    *[
        ("mesh", call)
        for path in ("a" * 300 + ".msh", table.LONG_PATH + ".msh", "/proc/x/y.msh")
        for call in (
            lambda tmp, p=path: twoball.fem.eigen(mesh=_under(tmp, p)),
            lambda tmp, p=path: twoball.export(tmp / "x.vtu", CASE, mesh=_under(tmp, p)),
            lambda tmp, p=path: twoball.render(tmp / "x.png", CASE, mesh=_under(tmp, p)),
            lambda tmp, p=path: twoball.plot("pole", tmp / "p.png", CASE, mesh=_under(tmp, p)),
        )
    ],
]


def _under(tmp: Path, path: str) -> str:
    """``path`` inside ``tmp`` unless absolute or empty."""
    return path if not path or path.startswith("/") else str(tmp / path)


@pytest.mark.parametrize(
    ("name", "call"), EXTRA, ids=[f"{n}-{k}" for k, (n, _) in enumerate(EXTRA)]
)
def test_wrong_types_options_that_do_not_apply_and_paths(
    name: str, call: Any, tmp_path: Path
) -> None:  # noqa: E501
    signal.signal(signal.SIGPROF, _alarm)
    signal.setitimer(signal.ITIMER_PROF, CPU_LIMIT_S)
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("error")
            with pytest.raises(twoball.ParameterError) as caught:
                call(tmp_path)
    finally:
        signal.setitimer(signal.ITIMER_PROF, 0)
    assert caught.value.name in (name, FLAGS.get(name)), str(caught.value)
    assert list(tmp_path.iterdir()) == []


def test_extremes_inside_the_ranges_give_finite_numbers() -> None:
    """Values at the edges of the ranges run without overflow warnings (formulas stay finite)."""
    from twoball.modal.initial import phi_a_from_v0, v0_from_phi_a
    from twoball.modal.parameters import wave_speed_from_pressure

    with warnings.catch_warnings():
        warnings.simplefilter("error")
        for radius in (1e-6, 1e6):
            for c in (1e-6, 1e9):
                case = twoball.Case(radius=radius, wave_speed=c, phi_a=2.6)
                assert math.isfinite(case.gamma) and case.gamma > 0
                v0 = v0_from_phi_a(2.6, radius, c)
                if v0 <= 1e6:
                    assert phi_a_from_v0(v0, radius, c) == pytest.approx(2.6, abs=1e-12)
                else:  # faster than any impact the model takes
                    with pytest.raises(twoball.ParameterError, match="^v0 must be"):
                        phi_a_from_v0(v0, radius, c)
        # eq. (3.8) against its closed form c = sqrt(2 pi P R / m) at the corners
        for p, m, r in ((1e12, 1e-12, 1e-6), (1e-6, 1e12, 1e6), (77200.0, 0.567, 0.12)):
            expected = math.sqrt(2 * math.pi * p * r / m)
            if 1e-6 <= expected <= 1e9:
                assert wave_speed_from_pressure(p, m, r) == pytest.approx(expected, rel=1e-14)
            else:
                with pytest.raises(twoball.ParameterError, match="pressure"):
                    wave_speed_from_pressure(p, m, r)
        near_pi = twoball.liftoff(twoball.Case(phi_a=table.PHI_A_HIGH))
        assert near_pi.t_liftoff_s is None or math.isfinite(near_pi.t_liftoff_s)
