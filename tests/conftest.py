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
        name: twoball.liftoff(basketball, solver=twoball.Superposition(ball_files[name]))
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


class _FileLines:
    """One line per test file as it finishes, when the suite runs on several workers.

    pytest-xdist's own output is a stream of dots; with ``--dist loadfile`` each
    file runs whole on one worker, so the line says which file is done, its
    counts and how long it took.
    """

    def __init__(self, config) -> None:
        import collections
        import time

        self.config = config
        self.clock = time.monotonic
        self.total: dict[str, int] = {}
        self.seen: dict[str, int] = collections.Counter()
        self.outcomes: dict[str, collections.Counter] = collections.defaultdict(collections.Counter)
        self.started: dict[str, float] = {}

    @pytest.hookimpl
    def pytest_xdist_node_collection_finished(self, node, ids) -> None:
        if not self.total:  # every worker collects the same items
            for nodeid in ids:
                name = nodeid.split("::")[0]
                self.total[name] = self.total.get(name, 0) + 1

    @pytest.hookimpl
    def pytest_report_teststatus(self, report):
        if not report.passed:
            return None  # failures, errors and skips as pytest shows them
        return ("passed" if report.when == "call" else ""), "", ""  # the file's line says it

    @pytest.hookimpl
    def pytest_runtest_logreport(self, report) -> None:
        name = report.nodeid.split("::")[0]
        self.started.setdefault(name, self.clock())
        if report.when == "call" or (report.when == "setup" and not report.passed):
            self.outcomes[name][report.outcome] += 1
        elif report.when == "teardown" and report.failed:
            self.outcomes[name]["errors at teardown"] += 1
        if report.when != "teardown":
            return
        self.seen[name] += 1
        if self.seen[name] == self.total.get(name):
            counts = ", ".join(f"{n} {k}" for k, n in sorted(self.outcomes[name].items()))
            seconds = self.clock() - self.started[name]
            done = sum(self.seen.values())
            share = 100 * done // max(1, sum(self.total.values()))
            reporter = self.config.pluginmanager.get_plugin("terminalreporter")
            reporter.ensure_newline()  # after a skip's or a failure's letter
            reporter.write_line(f"[{share:3d}%] {name}: {counts} ({seconds:.1f} s)")


def pytest_configure(config) -> None:
    """On the controller of several workers, report progress one file at a time."""
    if getattr(config.option, "numprocesses", None) and not hasattr(config, "workerinput"):
        if config.option.collectonly:
            return
        if config.option.verbose <= 0:
            config.pluginmanager.register(_FileLines(config), "twoball-file-lines")
