"""Test-session setup (one BLAS thread, headless plotting) and the session's mesh files.

The matrices in these tests are small; on a 2-core machine BLAS threads only
contend with each other (measured 10-100x slower dense solves under load).
"""

import os

os.environ.setdefault("MPLBACKEND", "Agg")
os.environ.setdefault("VTK_DEFAULT_OPENGL_WINDOW", "vtkEGLRenderWindow")

from pathlib import Path  # noqa: E402

import pytest  # noqa: E402
from threadpoolctl import threadpool_limits  # noqa: E402

from tests.meshes import on_ball, write  # noqa: E402

threadpool_limits(limits=1, user_api="blas")


MM = 1000.0  # the .msh file of ball_files is in millimetres


@pytest.fixture
def read_only_folder(tmp_path):
    """A folder nobody may write to; root ignores permission bits, but not sysfs."""
    if os.geteuid() != 0:
        folder = tmp_path / "locked"
        folder.mkdir()
        folder.chmod(0o555)
        return folder
    try:
        os.mkdir("/sys/.twoball-probe")
    except OSError:
        return "/sys"
    os.rmdir("/sys/.twoball-probe")
    pytest.skip("no read-only folder available to root")


@pytest.fixture(scope="session")
def ball_files(tmp_path_factory) -> dict[str, Path]:
    """``vtu``: P2 ball of 0.12 m off the origin; ``msh``: P1 ball in mm; ``hole``: broken."""
    from twoball.fem_membrane.mesh import icosphere

    folder = tmp_path_factory.mktemp("meshes")
    quadratic, flat = icosphere(2, 2), icosphere(2)
    paths = {name: folder / f"ball.{name}" for name in ("vtu", "msh")}
    write(paths["vtu"], on_ball(quadratic), quadratic.cells)
    write(paths["msh"], on_ball(flat) * MM, flat.cells, file_format="gmsh22")
    paths["hole"] = folder / "hole.vtu"
    write(paths["hole"], on_ball(flat), flat.cells[2:])  # two triangles removed
    return paths


@pytest.fixture(scope="session")
def ball_files_liftoff(ball_files):
    """The finite-element lift-off on each of ``ball_files`` (twoball.liftoff, full eigen route)."""
    import twoball

    basketball = twoball.Case.preset("basketball")
    return {
        name: twoball.liftoff(basketball, backend="fem", mesh=ball_files[name])
        for name in ("vtu", "msh")
    }


@pytest.fixture(autouse=True)
def _signals_left_as_found():
    """Every test leaves the process's signal handlers and held-signal state as it found them.

    A leaked handler (SIGINT ignored, a run's status left decided) makes later
    tests of the signal mechanism fail far from their cause: this names the test.
    """
    import signal

    from twoball._common.signals import _deferral

    before = {s: signal.getsignal(s) for s in (signal.SIGINT, signal.SIGTERM)}
    yield
    after = {s: signal.getsignal(s) for s in (signal.SIGINT, signal.SIGTERM)}
    assert after == before, f"signal handlers changed: {before} -> {after}"
    assert not _deferral["finished"] and not _deferral["hold"], dict(_deferral)
