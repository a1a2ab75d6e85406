"""twoball.liftoff: the same numbers as the command line, bit for bit; refusals by name."""

from __future__ import annotations

import dataclasses
import math

import pytest

import twoball
from tests.helpers import cli_json, same_numbers
from twoball import Body
from twoball.cli.main import main
from twoball.modal.parameters import Case

BASKETBALL = Case.preset("basketball")


def _contact(body: Body, **kwargs):
    return twoball.liftoff(BASKETBALL, body=body, **kwargs)


# --------------------------------------------------------------------------- API = CLI
@pytest.mark.parametrize(
    ("argv", "case"),
    [
        ((), lambda: twoball.Case.preset("basketball")),
        (("--v0", "3"), lambda: twoball.Case.preset("basketball", v0=3.0)),
        (("--phi-a", "2.5"), lambda: twoball.Case.preset("basketball", phi_a=2.5)),
        (("--v0", "4.1"), lambda: twoball.Case.preset("basketball")),
        (
            ("--pressure", "77200", "--mass", "0.567"),
            lambda: twoball.Case.from_pressure(77200, 0.567),
        ),
        (("--damping", "0.2", "--modes", "60"), lambda: twoball.Case(damping=0.2, modes=60)),
    ],
    ids=["default", "v0-3", "phi-a-2.5", "preset-own-v0", "pressure-mass", "damping-modes"],
)
def test_closed_form_api_equals_cli(capsys, argv, case):
    cli, _ = cli_json(capsys, "liftoff", *argv)
    api = twoball.liftoff(case())
    same_numbers(api.as_dict(), cli)


def test_default_is_the_basketball_preset_with_its_pinned_numbers(capsys):
    result = twoball.liftoff(twoball.Case.preset("basketball"))
    assert result.t_liftoff_s * 1e3 == pytest.approx(9.8825, abs=5e-5)
    assert result.v_liftoff_m_s == pytest.approx(3.8322, abs=5e-5)
    again, first = twoball.liftoff().as_dict(), result.as_dict()
    assert again.pop("provenance")["case"] == first.pop("provenance")["case"]
    assert again == first
    cli, err = cli_json(capsys, "liftoff", "--v0", "4.1")
    assert cli["phi_a_source"] == "measured (basketball)" and cli["phi_a_rad"] == 2.6
    assert err == ""  # the preset's own value: nothing to note


def test_fem_axisym_api_equals_cli(capsys):
    cli, _ = cli_json(capsys, "liftoff", "--backend", "fem", "--mesh", "axisym")
    api = twoball.liftoff(twoball.Case.preset("basketball"), solver=twoball.Superposition("axisym"))
    same_numbers(api.as_dict(), cli)
    assert cli["backend"] == "fem" and cli["mesh"].startswith("axisym")


def test_mesh_file_api_equals_cli(capsys, ball_file):
    path, points, cells = ball_file
    argv = ("--backend", "fem", "--mesh-file", str(path), "--order", "2", "--v0", "3")
    cli, _ = cli_json(capsys, "liftoff", *argv)
    case = twoball.Case.preset("basketball", v0=3.0)
    solver = twoball.Superposition(twoball.MeshOptions(file=str(path), order=2))
    api = twoball.liftoff(case, solver=solver)
    same_numbers(api.as_dict(), cli)
    assert cli["mesh_file"]["radius"] == pytest.approx(0.12, rel=1e-12)
    assert cli["mesh_file"]["center"] == pytest.approx([1.0, 2.0, 3.0], rel=1e-12)
    # the same mesh as an object (meshio.Mesh, scikit-fem MeshTri): the same numbers up to
    # round-off (the readers hand over the points in different layouts)
    import meshio
    from skfem import MeshTri1

    for source in (meshio.read(path), MeshTri1(points.T, cells.T)):
        again = twoball.liftoff(
            case, solver=twoball.Superposition(twoball.MeshOptions(file=source, order=2))
        )
        assert again.t_liftoff_s == pytest.approx(api.t_liftoff_s, rel=1e-12)
        assert again.v_liftoff_m_s == pytest.approx(api.v_liftoff_m_s, rel=1e-12)
    # second method: the generated icosphere it was written from, up to round-off of the
    # translation and scaling (a discretisation difference would be ~1e-3)
    generated = twoball.liftoff(
        case, solver=twoball.Superposition(twoball.MeshOptions("sphere", level=2, order=2))
    )
    assert api.t_liftoff_s == pytest.approx(generated.t_liftoff_s, rel=1e-9)
    assert api.v_liftoff_m_s == pytest.approx(generated.v_liftoff_m_s, rel=1e-9)


def test_results_state_phi_a_source_and_notes(capsys):
    result = twoball.liftoff(twoball.Case(v0=3.0))
    data = result.as_dict()
    assert data["phi_a_source"] == "eq. (3.7)" and data["notes"] == [result.case.phi_a_note]
    code = main(["liftoff", "--v0", "3"])
    captured = capsys.readouterr()
    assert code == 0 and "phi_a from" in captured.out and "eq. (3.7)" in captured.out
    assert captured.err.startswith("twoball: note: phi_a = ")


# --------------------------------------------------------------------------- refusals
@pytest.mark.parametrize(
    ("call", "name"),
    [
        (lambda: twoball.liftoff(solver="spectral"), "solver"),
        (lambda: twoball.liftoff(solver=twoball.MeshOptions("axisym")), "solver"),
        (lambda: twoball.Superposition(twoball.MeshOptions("axisym", level=2)), "level"),
        (lambda: twoball.Superposition(twoball.MeshOptions("sphere", elements=100)), "elements"),
        (lambda: twoball.GeneralizedAlpha("axisym", dt=0.0), "dt"),
        (lambda: twoball.Superposition("axisym", route="lanczos"), "route"),
        (lambda: twoball.ClosedForm(t_end=-1.0), "t_end"),
        (lambda: twoball.liftoff(solver=twoball.MoreauJean()), "body"),  # a massless body
        (lambda: twoball.liftoff(body=twoball.Body(-0.1)), "mass_ratio"),
        (lambda: twoball.Superposition("cube"), "mesh"),
        (lambda: twoball.Case(damping=2.0), "damping"),
        (lambda: twoball.Case.preset("squash"), "preset"),
        (lambda: twoball.Case.preset("basketball", pressure=7e4), "pressure"),
    ],
)
def test_api_errors_name_parameters(call, name):
    with pytest.raises(twoball.ParameterError) as error:
        call()
    assert error.value.name == name and str(error.value).startswith(f"{name} must be ")


@pytest.mark.parametrize(
    ("solver", "field"),
    [
        (twoball.ClosedForm, "mesh"),  # the closed form has no mesh ...
        (twoball.ClosedForm, "dt"),  # ... and no time steps
        (twoball.ClosedForm, "scheme"),
        (twoball.Superposition, "dt"),  # modal superposition takes no step
        (twoball.GeneralizedAlpha, "route"),  # generalized-alpha starts from every eigenpair
        (twoball.MoreauJean, "recontact"),  # a stepped body has events, not criteria
        (twoball.MoreauJean, "mesh"),  # its ball carries the mesh
    ],
)
def test_a_combination_that_does_not_apply_cannot_be_written(solver, field):
    """The options that used to be refused at run time ("left out with ...") are no field
    of the solver they do not apply to."""
    assert field not in {f.name for f in dataclasses.fields(solver)}
    with pytest.raises(TypeError, match=f"unexpected keyword argument '{field}'"):
        solver(**{field: "axisym" if field == "mesh" else 1e-5})


def test_liftoff_without_mass_ratio_is_unchanged():
    """The contact options leave the massless path bit-identical."""
    from twoball.modal.report import legendre_liftoff

    a = twoball.liftoff(BASKETBALL)
    b = legendre_liftoff(BASKETBALL)
    assert (a.t_liftoff_s, a.v_liftoff_m_s) == (b.t_liftoff_s, b.v_liftoff_m_s)


@pytest.mark.parametrize(
    ("call", "name"),
    [
        (lambda: _contact(Body(-1.0)), "mass_ratio"),
        (lambda: _contact(Body(float("nan"))), "mass_ratio"),
        (lambda: _contact(Body(0.1, contact_radius=0.2)), "contact_radius"),  # a >= R = 0.12 m
        (lambda: _contact(Body(0.1, contact_radius=0.0)), "contact_radius"),
        (lambda: _contact(Body(0.1, restitution=1.5)), "restitution"),
        (lambda: _contact(Body(0.1, energy="all")), "energy"),
        (lambda: _contact(Body(0.1), solver="spectral"), "solver"),
        # a body of finite mass is stepped: the massless body's solvers are refused
        (lambda: _contact(Body(0.1), solver=twoball.ClosedForm()), "solver"),
        (lambda: _contact(Body(0.1), solver=twoball.Superposition("axisym")), "solver"),
        (lambda: _contact(Body(0.1), solver=twoball.GeneralizedAlpha("axisym")), "solver"),
        (lambda: twoball.MoreauJean(twoball.MeshOptions("axisym")), "ball"),  # not a ball
        (lambda: twoball.MoreauJean("legendre"), "ball"),
        (
            lambda: twoball.MoreauJean(twoball.FEBall(twoball.MeshOptions("axisym", level=2))),
            "level",
        ),
        # the massless body on its cap: its criteria's events need the whole window
        (lambda: _contact(Body(0.0), solver=twoball.ClosedForm(recontact="paper")), "recontact"),
        (lambda: _contact(Body(0.1), damping=twoball.Rayleigh()), "rayleigh"),
    ],
)
def test_bad_contact_input_names_the_parameter(call, name):
    with pytest.raises(twoball.ParameterError) as info:
        call()
    assert info.value.name == name


#: A body of finite mass on the basketball, stepped (Moreau-Jean, dt = 0.005 / c, the verb's
#: default) against the event-driven solution in closed form (``exact=True``): relative
#: distance of t_l and v1 (measured 2.4e-5 and 3.7e-4 at e = 0; 7.0e-5 and 3.6e-4 at
#: e = 0.5, where the bounces come closer than a step and merge; first order at the impacts).
FROM_EXACT = {0.0: (5e-5, 5e-4), 0.5: (1.5e-4, 5e-4)}


@pytest.mark.parametrize("restitution", sorted(FROM_EXACT))
def test_a_body_of_finite_mass_is_stepped_near_the_exact_events(restitution):
    """``liftoff(body=Body(0.1))`` runs on the contact core; the exact event-driven solver is
    the reference.  A bouncing body (e = 0.5) ends its Zeno chains of bounces (it ran into
    the time limit while the start at rest left the core without a Zeno speed)."""
    from twoball.modal.contact.report import legendre_contact

    body = Body(0.1, restitution=restitution)
    stepped = _contact(body)
    exact = legendre_contact(BASKETBALL, body, exact=True, reference=False)
    assert stepped.extra["integrator"] == "moreau-jean" and stepped.lifted and exact.lifted
    t_tolerance, v_tolerance = FROM_EXACT[restitution]
    assert stepped.t_liftoff_s == pytest.approx(exact.t_liftoff_s, rel=t_tolerance)
    assert stepped.v_liftoff_m_s == pytest.approx(exact.v_liftoff_m_s, rel=v_tolerance)
    step = 0.005  # units 1/c
    times = [event.t for event in exact.history.impacts]
    for event in stepped.history.impacts:  # each an exact impact, resolved to one step
        assert min(abs(event.t - t) for t in times) < step, (event.t, times)


def test_a_pressure_that_acts_on_nothing_is_noted():
    """On the paper's membrane with c given, P enters no equation of the lift-off: the
    result equals the one without it, and a note says so; through Case.from_pressure P
    sets c (eq. (3.8)) and no such note is made."""
    plain = twoball.liftoff(twoball.Case())
    pressed = twoball.liftoff(twoball.Case(pressure=70000.0))
    assert pressed.t_liftoff_s == plain.t_liftoff_s and pressed.v_liftoff_m_s == plain.v_liftoff_m_s
    (note,) = [n for n in pressed.notes if n.startswith("P = ")]
    assert note.startswith("P = 70000 Pa has no effect on this lift-off")
    assert not [n for n in plain.notes if n.startswith("P = ")]
    measured = twoball.Case.from_pressure(77200.0, 0.567)
    assert measured.wave_speed == pytest.approx(math.sqrt(2 * math.pi * 77200.0 * 0.12 / 0.567))
    assert not [n for n in twoball.liftoff(measured).notes if n.startswith("P = ")]
    moved = measured.derive(wave_speed=300.0)  # c no longer P's: the note is back
    assert [n for n in moved.notes if n.startswith("P = ")]
    stiff = twoball.Case.preset("tennis")  # bending and gas: P acts
    assert stiff.pressure is not None and not [n for n in stiff.notes if n.startswith("P = ")]


def test_converge_carries_the_case_notes_once():
    case = twoball.Case(v0=-4.1)
    study = twoball.converge(case, study="modes", modes_list="30,60,120")
    assert study.notes.count(case.v0_note) == 1 and study.as_dict()["notes"][0] == case.v0_note


def test_the_closed_form_reports_its_step():
    """The closed form says what it does (its converged reference may sum thousands of modes),
    so the command line's progress line starts with it."""
    steps = []
    case = twoball.Case.preset("basketball")
    twoball.liftoff(case, progress=steps.append)
    assert steps == [f"the closed form on {case.modes} Legendre modes"]


@pytest.mark.parametrize(
    ("preset", "dampings"),
    [
        ("tennis", (0.01, 0.02, 0.05)),
        ("volleyball", (0.002, 0.01, 0.02, 0.05)),
    ],
)
def test_small_damping_gives_a_liftoff_or_reasons(preset, dampings):
    """Valid damping ratios near the presets' end in an answer, never a failed root search.

    Tennis at D = 0.01 stopped with "a bracket does not change sign": a re-contact
    bracket of the truncation reference (N = 3840) had gaps of 1e-18 at both ends
    (rounding), of one sign.  Each answer lifts off, v_l falls as D grows (the damped
    membrane returns less), and t_l stays within 5 % across the range.
    """
    reports = [twoball.liftoff(twoball.Case.preset(preset, damping=d)) for d in dampings]
    assert all(r.lifted for r in reports), [r.warnings for r in reports]
    speeds = [r.v_liftoff_m_s for r in reports]
    assert speeds == sorted(speeds, reverse=True), speeds
    times = [r.t_liftoff_s for r in reports]
    assert max(times) / min(times) < 1.05, times


def test_a_grazing_recontact_bracket_is_closed_at_rounding():
    """The reference series of tennis at D = 0.01, N = 3840: its lift-off is found."""
    from twoball.modal.converged import filtered_liftoff

    case = twoball.Case.preset("tennis", damping=0.01)
    result = filtered_liftoff(case, 3840)
    assert result.t is not None and 0.02 < result.t < 0.025  # 0.0218 (units 1/c)
