"""Small helpers shared by tests in several folders (command line, orders, pictures)."""

from __future__ import annotations

import json
import math
import os
import subprocess
import sys
import textwrap

import matplotlib.image as mpimg
import numpy as np
import pytest

from tests import ROOT
from twoball.cli.main import main
from twoball.modal.filters import SpectralFilter
from twoball.modal.legendre import legendre_series
from twoball.modal.series import ModalSeries


def cli_run(capsys, *argv):
    """Run ``twoball ARGV`` in process: exit status, standard output and standard error."""
    code = main(list(argv))
    out = capsys.readouterr()
    return code, out.out, out.err


def cli_json(capsys, *argv: str) -> tuple[object, str]:
    """Run ``twoball ARGV --json`` in process; the parsed JSON and standard error."""
    code = main([*argv, "--json"])
    captured = capsys.readouterr()
    assert code == 0, captured.err
    data = json.loads(captured.out)
    # every JSON output names its command line; a list comes as {"results", "provenance"}
    assert data["provenance"]["command"] == "twoball " + " ".join([*argv, "--json"])
    if set(data) == {"results", "provenance"}:
        return data["results"], captured.err
    return data, captured.err


def same_numbers(api: dict, cli: dict) -> None:
    """API and CLI results identical, bit for bit (wall-clock timings, provenance aside)."""
    api = json.loads(json.dumps(api))  # the CLI's own serialisation: repr round-trips floats
    assert api["provenance"]["call"]["function"].startswith("twoball.")
    assert api["provenance"]["case"] == cli["provenance"]["case"]
    for data in (api, cli):
        data.pop("seconds", None)
        data.pop("provenance")
    assert api == cli
    assert api["t_liftoff_s"] == cli["t_liftoff_s"] and api["v_liftoff_m_s"] == cli["v_liftoff_m_s"]


def run_json(capsys: pytest.CaptureFixture[str], *argv: str) -> tuple[dict, list[str]]:
    """``twoball liftoff --json ...``: the JSON object and the stderr warning lines."""
    assert main(["liftoff", "--json", *argv]) == 0
    out, err = capsys.readouterr()
    # a finite-element solve longer than 2 s also reports progress (twoball._common.progress)
    progress = "twoball: liftoff: "
    return json.loads(out), [line for line in err.splitlines() if line and progress not in line]


def assert_printed(data: dict, lines: list[str]) -> None:
    """Every warning of the JSON is printed once on stderr, nothing else."""
    assert lines == [f"twoball: warning: {text}" for text in data["warnings"]]


def rates(errors: np.ndarray, ratio: float = 2.0) -> np.ndarray:
    """Observed orders between successive rows of ``errors`` (h halves per row)."""
    errors = np.asarray(errors, dtype=float)
    return np.log(errors[:-1] / errors[1:]) / math.log(ratio)


def by_key(study):
    """The quantities of a refinement study by key."""
    return {q.spec.key: q for q in study.quantities}


def drawn(path) -> float:
    """Share of non-white pixels of a PNG."""
    image = mpimg.imread(path)[..., :3]
    return float(np.mean(np.any(image < 0.95, axis=-1)))


def text_of(array) -> str:
    """A VTK character array (XDMF texts through vtkXdmfReader) as text."""
    return bytes(np.asarray(array, dtype=np.int8).view(np.uint8)).decode("utf-8")


def closed_form_series(case, modes: int) -> ModalSeries:
    """The Legendre series of eq. (3.16) of ``case`` with ``modes`` modes, Lanczos filter."""
    return legendre_series(case.phi_a, case.damping, SpectralFilter("lanczos", modes))


def peak_child(code: str) -> tuple[float, float]:
    """Peak RSS [bytes] (VmHWM) and CPU time [s] of ``code`` run in a fresh interpreter.

    CPU time (user + system), not wall time: on a shared machine the wall time
    of a single-threaded run grows with the others' load, its CPU time does not.
    """
    wrapper = textwrap.dedent(
        """
        import resource, sys
        import numpy, scipy.sparse.linalg, skfem  # imports are not the work measured
        def cpu():
            usage = resource.getrusage(resource.RUSAGE_SELF)
            return usage.ru_utime + usage.ru_stime
        start = cpu()
        exec(sys.argv[1])
        used = cpu() - start
        # VmHWM: this program's own peak; ru_maxrss keeps the forking parent's
        # peak across exec (Linux), so a large pytest process would be measured
        with open("/proc/self/status") as status:
            hwm = next(int(line.split()[1]) for line in status if line.startswith("VmHWM:"))
        print(hwm * 1024, used)
        """
    )
    env = dict(os.environ, OPENBLAS_NUM_THREADS="1")
    done = subprocess.run(
        [sys.executable, "-c", wrapper, code], cwd=ROOT, env=env, capture_output=True, text=True
    )
    assert done.returncode == 0, done.stderr[-2000:]
    peak, wall = done.stdout.split()[-2:]
    return float(peak), float(wall)
