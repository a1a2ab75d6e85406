"""Imports run one way, top to bottom, with no circle between modules.

The layers, from the top: the command line (``twoball/cli``), the face (the
public verbs and objects in ``twoball/``), ``verify``, ``fem_membrane``,
``modal``, and the ground floor of stdlib-only helpers (``twoball/_common``).
Every import of every module is read from its source, those inside functions
and under ``TYPE_CHECKING`` included, and so are the imports made by name at
run time: the lazy name maps of :func:`twoball._common.lazy.attach` (a
package's ``{"Case": ".parameters", ...}``) and ``importlib.import_module``
with a constant name.  A module may import its own layer or any layer below,
and the command line only the face and the ground floor.
"""

from __future__ import annotations

import ast
import functools
import sys
from pathlib import Path

import pytest

from tests import ROOT

#: Source folder -> dotted name of the package it installs as (pyproject.toml).
PARTS = {
    "twoball": "twoball",
    "modal": "twoball.modal",
    "fem_membrane": "twoball.fem_membrane",
    "fem_shell": "twoball.fem_shell",
    "fem_solid": "twoball.fem_solid",
    "verify": "twoball.verify",
}
#: Layers from the bottom; a module may import from its own layer and those below.
#: The finite-element parts (the membrane, the shell, the solid) share one layer.
RANKS = {"ground": 0, "modal": 1, "fem": 2, "verify": 3, "face": 4, "cli": 5}
FEM_PARTS = ("fem_membrane", "fem_shell", "fem_solid")
#: Arrows allowed against the rule, with the reason (at most two).
EXCEPTIONS: dict[tuple[str, str], str] = {}


def modules(root: Path = ROOT) -> dict[str, Path]:
    """Dotted module name -> source file, for every module of the package."""
    found = {}
    for folder, dotted in PARTS.items():
        for path in sorted((root / folder).rglob("*.py")):
            parts = [dotted, *path.relative_to(root / folder).with_suffix("").parts]
            if parts[-1] == "__init__":
                parts.pop()
            found[".".join(parts)] = path
    return found


def layer(module: str) -> str:
    """The layer of a dotted module name of the package."""
    parts = module.split(".")
    if module == "twoball.__main__" or parts[1:2] == ["cli"]:
        return "cli"
    if parts[1:2] == ["_common"] or module == "twoball._version":
        return "ground"
    if len(parts) > 1 and parts[1] in FEM_PARTS:
        return "fem"
    if len(parts) > 1 and parts[1] in ("modal", "verify"):
        return parts[1]
    return "face"


#: The module of the lazy name maps, and the functions that import a module by name.
LAZY = "twoball._common.lazy"
BY_NAME = ("import_module", "__import__")


def _resolve(name: str, anchor: str) -> str:
    """``name`` as importlib resolves it against the package ``anchor`` (``.x``, ``..x``)."""
    level = len(name) - len(name.lstrip("."))
    if not level:
        return name
    base = anchor.rsplit(".", level - 1)[0] if level > 1 else anchor
    rest = name[level:]
    return f"{base}.{rest}" if rest else base


def _strings(node: ast.AST | None) -> str | None:
    """A constant string, or the first one of a constant tuple (``(module, attribute)``)."""
    if isinstance(node, ast.Constant) and isinstance(node.value, str):
        return node.value
    if isinstance(node, ast.Tuple) and node.elts:
        return _strings(node.elts[0])
    return None


def by_name(module: str, tree: ast.Module, package: str) -> list[str]:
    """The modules ``module`` imports at run time by name.

    The values of every mapping handed to ``attach`` (imported from
    :data:`LAZY`; the mapping written in the call or bound to a module-level
    name), resolved against the module's ``__name__`` as ``attach`` does, and
    the constant first argument of ``import_module`` or ``__import__``.
    """
    attach_names: set[str] = set()
    mappings: dict[str, ast.Dict] = {}
    for node in ast.walk(tree):
        if isinstance(node, ast.ImportFrom):
            base = node.module or ""
            if node.level:
                base = _resolve("." * node.level + base, package)
            if base == LAZY:
                attach_names |= {a.asname or a.name for a in node.names if a.name == "attach"}
    for node in tree.body:  # module-level mappings (``_NAMES = {...}``)
        value = node.value if isinstance(node, (ast.Assign, ast.AnnAssign)) else None
        targets = node.targets if isinstance(node, ast.Assign) else [getattr(node, "target", None)]
        if isinstance(value, ast.Dict):
            mappings |= {t.id: value for t in targets if isinstance(t, ast.Name)}
    names: list[str] = []
    for node in ast.walk(tree):
        if not isinstance(node, ast.Call):
            continue
        func = node.func
        called = func.id if isinstance(func, ast.Name) else getattr(func, "attr", None)
        if called in attach_names and len(node.args) >= 2:
            table = node.args[1]
            table = mappings.get(table.id) if isinstance(table, ast.Name) else table
            if isinstance(table, ast.Dict):
                values = [_strings(v) for v in table.values]
                names += [_resolve(v, module) for v in values if v]
        elif called in BY_NAME and node.args:
            name = _strings(node.args[0])
            if name:
                names.append(_resolve(name, module) if name.startswith(".") else name)
    return names


@functools.cache
def _parse(text: str) -> ast.Module:
    """The syntax tree of a source text (the planted copies share their unchanged files')."""
    return ast.parse(text)


def imports(module: str, path: Path, known: dict[str, Path]) -> set[str]:
    """The package's modules that ``module`` imports, anywhere in its source or by name."""
    package = module if path.name == "__init__.py" else module.rpartition(".")[0]
    found: set[str] = set()
    tree = _parse(path.read_text(encoding="utf-8"))
    for node in [*ast.walk(tree), None]:
        names: list[str] = []
        if node is None:  # after the import statements, the imports by name
            names = by_name(module, tree, package)
        elif isinstance(node, ast.Import):
            names = [alias.name for alias in node.names]
        elif isinstance(node, ast.ImportFrom):
            base = node.module or ""
            if node.level:
                anchor = package.split(".")[: len(package.split(".")) - node.level + 1]
                base = ".".join([*anchor, base] if base else anchor)
            names = [f"{base}.{alias.name}" for alias in node.names] + [base]
        for name in names:
            while name and name not in known:  # the module itself, not an attribute of it
                name = name.rpartition(".")[0]
            if name.startswith("twoball") and name != module:
                found.add(name)
    # importing a submodule runs its parents' __init__: only the target counts here
    return found


def graph(root: Path = ROOT) -> dict[str, set[str]]:
    """Every module of the package and the package modules it imports."""
    known = modules(root)
    return {name: imports(name, path, known) for name, path in known.items()}


def upward(edges: dict[str, set[str]]) -> list[tuple[str, str]]:
    """Arrows that point to a higher layer, or from the command line below the face."""
    bad = []
    for source, targets in edges.items():
        for target in targets:
            low, high = layer(source), layer(target)
            wrong = RANKS[high] > RANKS[low] or (
                low == "cli" and high not in ("cli", "face", "ground")
            )
            if wrong and (source, target) not in EXCEPTIONS:
                bad.append((source, target))
    return sorted(bad)


def circles(edges: dict[str, set[str]]) -> list[list[str]]:
    """Strongly connected groups of more than one module (Tarjan)."""
    index: dict[str, int] = {}
    low: dict[str, int] = {}
    stack: list[str] = []
    found: list[list[str]] = []
    counter = [0]

    def visit(node: str) -> None:
        index[node] = low[node] = counter[0]
        counter[0] += 1
        stack.append(node)
        for target in edges.get(node, ()):
            if target not in index:
                visit(target)
                low[node] = min(low[node], low[target])
            elif target in stack:
                low[node] = min(low[node], index[target])
        if low[node] == index[node]:
            group = []
            while True:
                member = stack.pop()
                group.append(member)
                if member == node:
                    break
            if len(group) > 1:
                found.append(sorted(group))

    limit = sys.getrecursionlimit()
    sys.setrecursionlimit(max(limit, 10000))
    try:
        for node in edges:
            if node not in index:
                visit(node)
    finally:
        sys.setrecursionlimit(limit)
    return found


#: The runtime policy of the ground floor: time and memory limits, held signals, child
#: processes, progress lines and the monitor that watches them (twoball/_common/watch.py).
RUNTIME = tuple(
    f"twoball._common.{name}" for name in ("budget", "signals", "child", "progress", "watch")
)
#: The cost models below the face may read the budget's estimate types (refuse-before-work
#: estimates): a module named ``cost`` imports ``twoball._common.budget`` and nothing else
#: of the runtime.
COST_MODELS = {"twoball._common.budget"}


@functools.cache
def _package_graph() -> dict[str, frozenset[str]]:
    """:func:`graph` of the checkout, read once for the runtime checks."""
    return {name: frozenset(targets) for name, targets in graph().items()}


def runtime_imports(edges: dict[str, set[str]]) -> list[tuple[str, str]]:
    """Arrows from a numerical module (modal, the finite elements) into the runtime policy."""
    bad = []
    for source, targets in edges.items():
        if layer(source) not in ("modal", "fem"):
            continue
        allowed = COST_MODELS if source.rpartition(".")[2] == "cost" else set()
        bad += [(source, t) for t in targets if t in RUNTIME and t not in allowed]
    return sorted(bad)


def test_numerical_modules_import_no_runtime_policy():
    """Solvers take a monitor (twoball._common.monitor) and import no budget, signal, child,
    progress or watch module; the cost models only the budget's estimates."""
    edges = _package_graph()
    assert {m for m in edges if m.startswith("twoball._common.")} >= set(RUNTIME)
    assert runtime_imports(edges) == []


@pytest.mark.parametrize(
    ("source", "target", "caught"),
    [
        ("twoball.modal.floor.planted", "twoball._common.watch", True),
        ("twoball.fem_membrane.planted", "twoball._common.child", True),
        ("twoball.fem_shell.planted", "twoball._common.signals", True),
        ("twoball.modal.planted.cost", "twoball._common.progress", True),
        ("twoball.modal.planted.cost", "twoball._common.budget", False),
        ("twoball.modal.planted", "twoball._common.budget", True),
        ("twoball.modal.planted", "twoball._common.monitor", False),
        ("twoball.verify.planted", "twoball._common.watch", False),
    ],
)
def test_a_planted_runtime_import_is_found(source, target, caught):
    """One more arrow on the package's graph (finding imports is tested above)."""
    edges = {**_package_graph(), source: {target}}
    assert runtime_imports(edges) == ([(source, target)] if caught else [])


def test_every_module_is_in_one_layer():
    edges = graph()
    assert len(edges) > 100  # the whole package was read
    assert {layer(m) for m in edges} == set(RANKS)


def test_no_import_points_up():
    assert upward(graph()) == []


def test_no_circle_between_modules():
    assert circles(graph()) == []


def test_at_most_two_exceptions_each_with_a_reason():
    assert len(EXCEPTIONS) <= 2
    assert all(reason.strip() for reason in EXCEPTIONS.values())


@pytest.mark.parametrize(
    ("folder", "line", "arrow"),
    [
        ("modal", "from twoball.verify.output.fields import ball_model", "verify"),
        ("twoball/_common", "    import twoball.modal.parameters", "modal"),
        ("twoball/cli", "from twoball.fem_membrane.options import MeshOptions", "fem"),
        ("fem_shell", "from twoball.verify.output.fields import ball_model", "verify"),
        ("modal", "    from twoball.fem_solid.eigen import axisymmetric_eigen", "fem"),
        # imports by name: a lazy name map (written in the call or bound to a name), and
        # import_module inside a function
        (
            "modal",
            "from twoball._common.lazy import attach\n"
            "__getattr__, __dir__ = attach(__name__, {'f': 'twoball.verify.output.fields'})",
            "verify",
        ),
        (
            "fem_membrane",
            "from twoball._common.lazy import attach as _attach\n"
            "_NAMES = {'figure': ('twoball.verify.output.figures', 'save_figure')}\n"
            "_getattr, _dir = _attach(__name__, _NAMES)",
            "verify",
        ),
        (
            "twoball/_common",
            "    importlib.import_module('twoball.fem_membrane.mesh')",
            "fem",
        ),
    ],
)
def test_a_planted_upward_import_is_found(tmp_path, folder, line, arrow):
    """Copy the sources, plant one upward import (also inside a function), see it caught."""
    import shutil

    for part in PARTS:
        shutil.copytree(ROOT / part, tmp_path / part, ignore=shutil.ignore_patterns("__pycache__"))
    target = tmp_path / folder / "planted_module.py"
    body = line if not line.startswith(" ") else "def planted():\n" + line + "\n"
    target.write_text(f'"""Planted."""\n\n{body}\n', encoding="utf-8")
    bad = upward(graph(tmp_path))
    assert len(bad) == 1 and layer(bad[0][1]) == arrow
    assert upward(graph(ROOT)) == []


@pytest.mark.parametrize(
    "second",
    [
        "from twoball.modal import planted_a\n",
        "from twoball._common.lazy import attach\n"
        "__getattr__, __dir__ = attach(__name__, {'a': '..planted_a'})\n",
        "import importlib\n\ndef late():\n    importlib.import_module('twoball.modal.planted_a')\n",
    ],
    ids=["import", "lazy-map", "import_module"],
)
def test_a_planted_circle_is_found(tmp_path, second):
    import shutil

    for part in PARTS:
        shutil.copytree(ROOT / part, tmp_path / part, ignore=shutil.ignore_patterns("__pycache__"))
    (tmp_path / "modal" / "planted_a.py").write_text("from twoball.modal import planted_b\n")
    if "attach" in second:  # a lazy map is a package's: planted_b is one, '..' its parent
        (tmp_path / "modal" / "planted_b").mkdir()
        (tmp_path / "modal" / "planted_b" / "__init__.py").write_text(second)
    else:
        (tmp_path / "modal" / "planted_b.py").write_text(second)
    assert circles(graph(tmp_path)) == [["twoball.modal.planted_a", "twoball.modal.planted_b"]]


def test_relative_names_resolve_as_importlib_resolves_them():
    assert _resolve(".parameters", "twoball.modal") == "twoball.modal.parameters"
    assert _resolve("..options", "twoball.modal.floor") == "twoball.modal.options"
    assert _resolve("twoball.fem", "twoball") == "twoball.fem"


def test_the_ground_floor_imports_the_standard_library_only():
    """``twoball/_common`` needs nothing installed: no numpy, scipy, rich or other package."""
    allowed = set(sys.stdlib_module_names) | {"twoball"}
    for path in sorted((ROOT / "twoball" / "_common").glob("*.py")):
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
            if isinstance(node, ast.Import):
                tops = [alias.name.split(".")[0] for alias in node.names]
            elif isinstance(node, ast.ImportFrom) and not node.level:
                tops = [(node.module or "").split(".")[0]]
            else:
                continue
            assert set(tops) <= allowed, f"{path.name} imports {tops}"
