"""Runtime policy stays at the edge: the numerical modules import none of it.

The numerics (``modal/`` and ``fem_membrane/``, installed as ``twoball.modal``
and ``twoball.fem_membrane``) take one optional monitor
(:mod:`twoball._common.monitor`) and estimate their costs
(:mod:`twoball._common.estimate`); the time limit, the budget's refusals, held
signals, progress lines and child processes belong to the verbs and the command
line.  Every import of every numerical module is read from its source as
``tests/project/test_layers.py`` reads it: those inside functions and under
``TYPE_CHECKING`` included, and those made by name (lazy name maps,
``importlib.import_module``).
"""

from __future__ import annotations

import shutil
from pathlib import Path

import pytest

from tests import ROOT
from tests.project.test_layers import PARTS, graph

#: The numerical parts: source folder -> the package they install as.
NUMERICS = {"modal": "twoball.modal", "fem_membrane": "twoball.fem_membrane"}
#: The runtime machinery of the edge, which no numerical module may import.
RUNTIME = (
    "twoball._common.budget",
    "twoball._common.signals",
    "twoball._common.child",
    "twoball._common.progress",
    "twoball._common.watch",
)


def numerical(module: str) -> bool:
    """Whether ``module`` (a dotted name) is one of the numerical modules."""
    return any(module == p or module.startswith(p + ".") for p in NUMERICS.values())


def runtime_imports(root: Path = ROOT) -> list[tuple[str, str]]:
    """(numerical module, runtime module it imports), sorted; empty when the rule holds."""
    return sorted(
        (source, target)
        for source, targets in graph(root).items()
        if numerical(source)
        for target in targets
        if target in RUNTIME
    )


def test_the_numerics_were_read() -> None:
    modules = [m for m in graph() if numerical(m)]
    assert len(modules) > 60
    assert {m.split(".")[1] for m in modules} == {"modal", "fem_membrane"}
    assert "twoball.modal.series" in modules and "twoball.fem_membrane.slicing" in modules


def test_no_numerical_module_imports_the_runtime_machinery() -> None:
    assert runtime_imports() == []


def test_the_numerics_use_the_monitor_and_the_estimates() -> None:
    """The two modules of the ground floor meant for the numerics are in use (the rule
    above is not met by a numerics that reached nothing of the ground floor)."""
    edges = graph()
    used = {target for source, targets in edges.items() if numerical(source) for target in targets}
    assert {"twoball._common.monitor", "twoball._common.estimate"} <= used


def _copy(tmp_path: Path) -> Path:
    for part in PARTS:
        shutil.copytree(ROOT / part, tmp_path / part, ignore=shutil.ignore_patterns("__pycache__"))
    return tmp_path


@pytest.mark.parametrize(
    ("path", "line", "target"),
    [
        # a deadline check put back into a loop, inside the function
        (
            "modal/series.py",
            "def _planted():\n    from twoball._common.budget import check_deadline\n",
            "twoball._common.budget",
        ),
        # the child process, at module level
        ("fem_membrane/slicing.py", "from twoball._common.child import in_child\n", None),
        # signals and progress, as a plain import and with an alias
        ("fem_membrane/krylov.py", "import twoball._common.signals\n", None),
        ("modal/contact/events.py", "from twoball._common import progress as _p\n", None),
        # the edge's monitor itself, by name at run time
        (
            "modal/converged.py",
            "def _planted():\n    import importlib\n"
            "    importlib.import_module('twoball._common.watch')\n",
            "twoball._common.watch",
        ),
    ],
)
def test_a_planted_runtime_import_is_found(tmp_path, path, line, target) -> None:
    """Copy the sources, plant one runtime import in a numerical module, see it caught."""
    root = _copy(tmp_path)
    source = root / path
    source.write_text(source.read_text(encoding="utf-8") + "\n\n" + line, encoding="utf-8")
    found = runtime_imports(root)
    module = ".".join([NUMERICS[path.split("/")[0]], *Path(path).with_suffix("").parts[1:]])
    assert len(found) == 1 and found[0][0] == module, found
    if target is not None:
        assert found[0][1] == target
    assert runtime_imports(ROOT) == []


def test_the_edge_may_import_it() -> None:
    """The rule is the numerics' only: the verbs and verify do import the machinery."""
    edges = graph()
    assert "twoball._common.watch" in edges["twoball._liftoff"]
    assert "twoball._common.budget" in edges["twoball._costs"]


def test_a_numerical_loop_tells_its_monitor_what_it_does() -> None:
    """The texts the deadline and the progress line show come from the monitor's calls."""
    import numpy as np

    from twoball.modal.filters import SpectralFilter
    from twoball.modal.legendre import legendre_series

    told: list[str] = []
    series = legendre_series(2.6, 0.13, SpectralFilter("lanczos", 30), monitor=told.append)
    series.pole(np.linspace(0.0, 12.0, 10_000))
    assert told == [
        "the modal series at sample 4096 of 10000",
        "the modal series at sample 8192 of 10000",
    ]
