"""The time limit is also a deadline: every long loop stops past it with one clear error.

Each loop is run for real on the clock of :func:`twoball._common.budget.running`
after the limit has passed; the first pass through the loop must raise
:class:`DeadlineError` naming that loop (and nothing else must be computed).
The cost models are compared with measured runs; the command line ends a run
at its deadline with exit status 3 and one line.
"""

from __future__ import annotations

import os
import subprocess
import sys
import time
from pathlib import Path

import numpy as np
import pytest
from twoball.modal.filters import SpectralFilter

import twoball
from twoball._common.budget import DeadlineError, check_deadline, limits, running

ROOT = Path(__file__).resolve().parents[2]
FILTER = SpectralFilter("lanczos", 30)


def past_the_deadline(call):
    """``call()`` on a clock whose one-second limit has already passed."""
    with limits(max_time="1s"), running():
        time.sleep(1.05)
        with pytest.raises(DeadlineError) as caught:
            call()
    return str(caught.value)


def test_no_clock_no_deadline() -> None:
    with limits(max_time="1s"):
        time.sleep(1.05)
        check_deadline("nothing")  # outside a verb nothing is timed


def test_contact_event_loop() -> None:
    text = past_the_deadline(lambda: twoball.liftoff(body=twoball.Body(0.1)))
    assert "while the contact event loop at t = 0 of 12.57" in text
    assert text.startswith("stopped at the time limit 1 s after") and "max_time" in text


def test_series_evaluation_chunks() -> None:
    from twoball.modal.legendre import legendre_series

    series = legendre_series(2.6, 0.13, SpectralFilter("lanczos", 60))
    times = np.linspace(0.0, 12.0, 10_000)
    series.pole(times[:100])  # one chunk: no check
    assert "while the modal series at sample 4096 of 10000" in past_the_deadline(
        lambda: series.pole(times)
    )


def test_generalized_alpha_steps() -> None:
    from twoball.fem_membrane.alpha import GeneralizedAlpha
    from twoball.fem_membrane.axisym import axisym_space

    space = axisym_space(50, 2.6, 1)
    stepper = GeneralizedAlpha(space.mass, space.stiffness, 1e-3)
    u0 = np.zeros(space.dofs)
    text = past_the_deadline(lambda: stepper.run(u0, u0, 1.0, space.pole_row))
    assert "while generalized-alpha step 0 of 1000" in text


def test_krylov_iterations() -> None:
    from twoball.fem_membrane.build import build_space
    from twoball.fem_membrane.initial import initial_moments
    from twoball.fem_membrane.krylov import krylov_modal_series

    space = build_space("sphere", level=2, order=1, phi_a=2.6)
    moments = initial_moments(space, 2.6)
    text = past_the_deadline(lambda: krylov_modal_series(space, moments, 0.13, FILTER))
    assert "while the rational Krylov iteration (basis 0 of at most" in text


def test_eigenpair_slices_and_sweep_points() -> None:
    from twoball.fem_membrane.build import build_space
    from twoball.fem_membrane.slicing import sliced_pairs

    space = build_space("sphere", level=2, order=2, phi_a=2.6)
    text = past_the_deadline(lambda: sliced_pairs(space.stiffness, space.mass, 200.0))
    assert "while eigenpairs of 642 unknowns: counting them" in text
    text = past_the_deadline(lambda: twoball.sweep({"damping": [0.1, 0.2]}))
    assert "while item 1 of 2" in text


def test_dense_eigenpairs_in_a_child_stop_at_the_deadline() -> None:
    from twoball.fem_membrane.build import build_space
    from twoball.fem_membrane.slicing import dense_pairs

    space = build_space("sphere", level=3, order=1, phi_a=2.6)  # 642 unknowns: in a child
    with limits(max_time="1s"), running():
        time.sleep(0.9)
        start = time.monotonic()
        with pytest.raises(DeadlineError, match="dense eigenpairs of 642 unknowns"):
            for _ in range(20):  # ~0.1 s each: the deadline falls inside one of them
                dense_pairs(space.stiffness, space.mass)
        assert time.monotonic() - start < 1.5


def run_cli(argv: list[str], cwd: Path, **kwargs) -> tuple[subprocess.CompletedProcess, float]:
    env = dict(os.environ, OPENBLAS_NUM_THREADS="1", MPLBACKEND="Agg", PYTHONPATH=str(ROOT))
    for name in ("TWOBALL_MAX_MEMORY", "TWOBALL_MAX_TIME"):
        env.pop(name, None)
    start = time.monotonic()
    done = subprocess.run(
        [sys.executable, "-m", "twoball", *argv],
        cwd=cwd,
        env=env,
        capture_output=True,
        text=True,
        timeout=600,
        **kwargs,
    )
    return done, time.monotonic() - start


def test_command_line_stops_at_the_deadline_with_one_line(tmp_path, monkeypatch, capsys):
    """With every estimate let through, only the deadline stops ``verify`` (about a minute)."""
    import contextlib

    from twoball._common.budget import Budget
    from twoball.cli.main import main

    monkeypatch.setattr(Budget, "check", lambda self, option, estimate: estimate)
    monkeypatch.chdir(tmp_path)
    start = time.monotonic()
    with contextlib.suppress(SystemExit):
        main(["--quiet", "verify", "--max-time", "1s", "--out", "r"])
    seconds = time.monotonic() - start
    err = capsys.readouterr().err
    [line] = err.splitlines()
    assert line.startswith("twoball: error: stopped at the time limit 1 s after 1")
    assert ", while " in line and line.endswith("(raise the time limit, --max-time)")
    assert seconds < 1 + 3.0  # the last pass of a loop, clean-up
    assert not (tmp_path / "r").exists() and list(tmp_path.iterdir()) == []


def _address_space(limit: int):
    def apply() -> None:
        import resource

        resource.setrlimit(resource.RLIMIT_AS, (limit, limit))

    return apply


def test_address_space_limit_refuses_before_work_or_ends_in_one_line(tmp_path: Path) -> None:
    """``ulimit -v 10000000``: level 5 order 4 reserved 9.5 GB (SuperLU) and died in a traceback."""
    argv = ["liftoff", "--backend", "fem", "--level", "5", "--order", "4"]
    done, seconds = run_cli(argv, tmp_path, preexec_fn=_address_space(10_000_000 * 1024))
    assert done.returncode == 2 and seconds < 5, done.stderr
    assert done.stderr.startswith("twoball: error: --level 5 --order 4 needs ~")
    # told to go ahead anyway: the allocation that fails is one line, exit 3
    argv = [*argv[:-4], "--level", "5", "--max-memory", "100GiB"]
    done, _ = run_cli(argv, tmp_path, preexec_fn=_address_space(1_500_000_000))
    assert done.returncode == 3, done.stderr
    assert done.stderr.splitlines()[-1].startswith("twoball: error: out of memory (")
    assert "Traceback" not in done.stderr
