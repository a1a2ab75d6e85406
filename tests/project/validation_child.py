"""Run command lines through ``twoball.cli.main.main`` in this one interpreter.

Usage: ``python validation_child.py CASES.json RESULTS.json``; each case is
``{"argv": [...], "folder": "..."}``; the command runs with its folder as the
working directory (``{tmp}`` in ``argv`` is that folder) and a CPU-time alarm,
so a value that slips through the checks and starts the work is reported as
``"status": "ran"`` instead of taking minutes.  Each result holds the exit
status, standard error and output, the CPU seconds used and the files left in
the folder.
"""

from __future__ import annotations

import contextlib
import io
import json
import os
import resource
import signal
import sys
import time
import warnings

CPU_LIMIT_S = 5.0


class Ran(BaseException):
    """The command was still working when its CPU-time alarm rang."""


def _alarm(signum: int, frame: object) -> None:
    raise Ran


def cpu() -> float:
    usage = resource.getrusage(resource.RUSAGE_SELF)
    return usage.ru_utime + usage.ru_stime


def left_in(folder: str, seeded: set[str]) -> list[str]:
    found = []
    for root, dirs, files in os.walk(folder):
        for name in dirs + files:
            path = os.path.relpath(os.path.join(root, name), folder)
            if path not in seeded:
                found.append(path)
    return sorted(found)


def main() -> None:
    cases = json.load(open(sys.argv[1]))
    warnings.simplefilter("default")  # every warning shows on stderr (one-line check)
    from twoball.cli.main import main as twoball_main

    signal.signal(signal.SIGPROF, _alarm)
    results = []
    home = os.getcwd()
    for case in cases:
        folder = case["folder"]
        seeded = set(left_in(folder, set()))
        argv = [w.replace("{tmp}", folder) for w in case["argv"]]
        err, out = io.StringIO(), io.StringIO()
        os.chdir(folder)
        start, wall = cpu(), time.perf_counter()
        signal.setitimer(signal.ITIMER_PROF, CPU_LIMIT_S)
        try:
            with contextlib.redirect_stderr(err), contextlib.redirect_stdout(out):
                try:
                    status: object = twoball_main(argv)
                except SystemExit as stop:
                    status = stop.code
                except Ran:
                    status = "ran"
                except Exception as error:  # noqa: BLE001 -- reported, never raised
                    import traceback

                    traceback.print_exc()
                    status = f"raised {type(error).__name__}"
        except Ran:
            status = "ran"
        finally:
            signal.setitimer(signal.ITIMER_PROF, 0)
            os.chdir(home)
        results.append(
            {
                "status": status,
                "stderr": err.getvalue(),
                "stdout": out.getvalue(),
                "cpu_s": cpu() - start,
                "wall_s": time.perf_counter() - wall,
                "left": left_in(folder, seeded),
            }
        )
    with open(sys.argv[2], "w") as stream:
        json.dump(results, stream)


if __name__ == "__main__":
    main()
