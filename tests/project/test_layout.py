"""twoball owns exactly one top-level import name, the parts map under it, the tests mirror it."""

from __future__ import annotations

import importlib.metadata
import pathlib
import sysconfig
import tomllib

from tests import ROOT

PARTS = {"twoball": "twoball", "modal": "twoball.modal", "fem_membrane": "twoball.fem_membrane"}
PARTS |= {"fem_shell": "twoball.fem_shell", "fem_solid": "twoball.fem_solid"}
PARTS["verify"] = "twoball.verify"


def _pyproject() -> dict:
    return tomllib.loads((ROOT / "pyproject.toml").read_text())


def test_every_source_package_is_installed_under_twoball():
    """Each folder with an __init__.py under a part is listed, under its dotted name."""
    config = _pyproject()["tool"]["setuptools"]
    assert config["package-dir"] == {dotted: folder for folder, dotted in PARTS.items()}
    expected = set()
    for folder, dotted in PARTS.items():
        for init in (ROOT / folder).rglob("__init__.py"):
            relative = init.parent.relative_to(ROOT / folder).parts
            expected.add(".".join((dotted, *relative)))
    assert set(config["packages"]) == expected


def test_installed_distribution_has_one_top_level_name():
    """The installed files (RECORD) put nothing at the top of site-packages but twoball."""
    site = [sysconfig.get_paths()["purelib"]]  # not the checkout's twoball.egg-info
    (dist,) = [d for d in importlib.metadata.distributions(path=site) if d.name == "twoball"]
    files = [pathlib.PurePosixPath(str(f)) for f in dist.files or []]
    editable = any("__editable__" in f.name for f in files)
    files = [f for f in files if "__editable__" not in f.name]  # an editable install's finder
    top = {f.parts[0] for f in files if not f.parts[0].endswith((".dist-info", ".pth"))}
    top = {name.removesuffix(".py") for name in top if name != ".."}
    assert top <= {"twoball"}, f"unexpected top-level names {sorted(top)}"
    if not editable:  # a regular install holds the package itself
        assert "twoball" in top
        names = {f.parts[1] for f in files if f.parts[0] == "twoball" and len(f.parts) > 2}
        assert {"modal", "fem_membrane", "verify"} <= names


def test_console_script_points_into_twoball():
    scripts = _pyproject()["project"]["scripts"]
    assert scripts == {"twoball": "twoball.cli.main:main"}


#: Test folder -> the source folder it mirrors (tests/api and tests/project aside).
MIRRORS = {
    "modal": ROOT / "modal",
    "fem_membrane": ROOT / "fem_membrane",
    "fem_shell": ROOT / "fem_shell",
    "fem_solid": ROOT / "fem_solid",
    "verify": ROOT / "verify",
    "_common": ROOT / "twoball" / "_common",
    "cli": ROOT / "twoball" / "cli",
}
PROJECT_CHECKS = {
    "test_layout.py",
    "test_layers.py",
    "test_runtime_edge.py",
    "test_docs.py",
    "test_examples.py",
    "test_startup.py",
    "test_removed.py",
}


def test_each_test_file_is_named_after_the_module_or_verb_it_tests():
    """tests/<part>/<path>/test_<name>.py tests <part>/<path>/<name>.py or its subpackage <name>.

    ``test_init.py`` tests the folder's own ``__init__.py``;

    tests/api holds one file per public verb or face module of ``twoball``;
    tests/project the project-wide checks and the bad-input tables.
    """
    import twoball

    orphans = []
    for path in sorted((ROOT / "tests").rglob("test_*.py")):
        relative = path.relative_to(ROOT / "tests")
        top, name = relative.parts[0], path.stem.removeprefix("test_")
        inner = relative.parent.parts[1:]
        if top in MIRRORS:
            folder = MIRRORS[top].joinpath(*inner)
            found = (
                (folder / f"{name}.py").is_file()
                or (folder / name / "__init__.py").is_file()
                or (name == "init" and (folder / "__init__.py").is_file())
            )
        elif top == "api":
            face = ROOT / "twoball"
            found = (
                name in twoball.__all__
                or name == "init"
                or (face / f"{name}.py").is_file()
                or (face / f"_{name}.py").is_file()
            )
        elif top == "project":
            found = path.name in PROJECT_CHECKS or name.startswith("validation")
        else:
            found = False
        if not found:
            orphans.append(str(relative))
    assert not orphans, f"test files named after no module or verb: {orphans}"
    assert not list((ROOT / "tests").glob("test_*.py"))  # none left at the top
